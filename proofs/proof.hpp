// proofs/proof.hpp -- the registry of checked derivations.
//
// Each file in proofs/ re-derives claims of one paper and *checks* them with the toolbox:
//   HAPSTAB_PROOF(r_forms_identity, "001", "(35)-(38) and (44) are one rational function of t") {
//     check.claim("001.eq44.identity", "(44)=(38)", "T/(e^{jwT}-1) = ...", Status::exact, ok, "...");
// A claim's status is hapstab::Status (numeric/result.hpp): exact, certified or numeric.
//   }
// A claim checked on instances (random or enumerated) counts the ones that exercise it and
// states a minimum (Instances below): it cannot pass on nothing.
// Every claim id must have its row in proofs/README.md (the claim table); `hapstab proofs
// --table proofs/README.md` fails when a claim and the table disagree. `hapstab proofs` and
// `hapstab reproduce` run the registry; a claim that does not hold makes them exit 1.
#pragma once

#include <algorithm>
#include <cstring>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "hapstab/numeric/result.hpp"
#include "hapstab/report/registration.hpp"

namespace hapstab::proofs {

/// A claimed upper bound v of a quantity known by its enclosure e is proven only when e.hi <= v
/// (e.lo <= v merely fails to refute it); a lower bound only when e.lo >= v.
template <class T>
bool proves_upper_bound(const Enclosure<T>& e, const T& v) {
  return e.hi <= v;
}
template <class T>
bool proves_lower_bound(const Enclosure<T>& e, const T& v) {
  return e.lo >= v;
}

/// The instances a claim is checked on, and how many of them exercise it (issue 30, item 5). An
/// instance is non-trivial when the check could have failed there: the claim's premise holds and
/// both sides compared are finite (an implication with a false premise, a bound where both sides
/// are infinite, a skipped or degenerate case is trivial). A claim over instances holds only with
/// at least `minimum` non-trivial ones, and its evidence says "k of n <what>, minimum m".
struct Instances {
  std::string what;  ///< what a non-trivial instance is, e.g. "H satisfying Tsypkin's condition"
  long minimum = 1;  ///< fewer non-trivial instances fail the claim
  long total = 0;       ///< instances drawn or enumerated
  long nontrivial = 0;  ///< of them, those that exercise the claim
  /// Counts one instance; returns `exercises` (whether it is non-trivial).
  bool count(bool exercises) {
    ++total;
    nontrivial += exercises;
    return exercises;
  }
  bool enough() const { return nontrivial >= minimum; }
  std::string evidence() const {
    return std::to_string(nontrivial) + " of " + std::to_string(total) + " instances non-trivial (" + what +
           "), minimum " + std::to_string(minimum) + (enough() ? "" : ": TOO FEW, the claim is not exercised");
  }
};

/// A certificate of one instance of a claim, which `hapstab reproduce` writes and checks with both
/// checkers (issue 47, docs/certificates.md): the `hapstab` command line (without the program name,
/// --certificate and --json) that prints the instance's exact or certified verdict -- the model as
/// a user writes it, with the claim's numbers -- and what the certificate's claim must say for the
/// instance to be the claim's. Checked by reproduce on the written certificate:
///   contains  "p/q": the certified quantity (b* of `bound`, K_max of `bound --max`) equals it
///             (an exact claim) or its claimed enclosure [lo, hi] contains it;
///   at_most   "p/q": the claimed value, or the enclosure's upper end, is <= it;
///   at_least_value  "p/q": the claimed value, or the enclosure's lower end, is >= it;
///   flags     claim fields that must have these values ("stable", "wedge", "tsypkin", ...);
///   at_least  pairs {a, b} of claim fields, each an enclosure {lo, hi} or {infinite: true}: the
///             certificate proves a >= b (a infinite, or b finite and a.lo >= b.hi).
/// `input`, when not empty, is a file the command reads (a state space for `passivity-level --ss`):
/// reproduce writes it to certificates/inputs/<instance>.json and puts that path where args hold
/// "{input}".
struct CertificateRequest {
  std::vector<std::string> args;
  std::string contains{}, at_most{};
  std::vector<std::pair<std::string, bool>> flags{};
  std::string input{};
  std::vector<std::pair<std::string, std::string>> at_least{};
  std::string at_least_value{};
};

struct ClaimResult {
  std::string id;         ///< stable id, e.g. "001.eq44.identity" (paper.equation.what)
  std::string paper;      ///< "000", "001" or "002" (shared/papers numbering)
  std::string equation;   ///< e.g. "(44) = (35)"
  std::string statement;  ///< what is claimed, in words
  Status status;          ///< how the claim is checked: exact, certified or numeric
  bool holds;
  std::string evidence;   ///< what was computed: counts, maximum errors, enclosures
  /// The certificates of its instances (one per instance; empty: none, `no_certificate` says why
  /// when the proof says, else reproduce reports "no certificate kind yet (issue 47)").
  std::vector<CertificateRequest> certificates{};
  std::string no_certificate{};
};

class Checker {
 public:
  explicit Checker(std::string paper) : paper_(std::move(paper)) {}
  /// Records one claim and its computed verdict. Returns `holds` for chaining.
  bool claim(std::string id, std::string equation, std::string statement, Status status, bool holds,
             std::string evidence) {
    ClaimResult r{id, paper_, std::move(equation), std::move(statement), status, holds, std::move(evidence)};
    if (auto it = certificates_.find(id); it != certificates_.end()) {
      r.certificates = std::move(it->second);
      certificates_.erase(it);
    }
    if (auto it = no_certificate_.find(id); it != no_certificate_.end()) {
      r.no_certificate = std::move(it->second);
      no_certificate_.erase(it);
    }
    results_.push_back(std::move(r));
    return holds;
  }
  /// Asks reproduce for the certificate of one instance of the claim `id` (recorded before it).
  void certify(const std::string& id, CertificateRequest request) { certificates_[id].push_back(std::move(request)); }
  /// Why the claim `id` (exact or certified) has no certificate, when the proof can say more than
  /// "no certificate kind yet (issue 47)".
  void no_certificate(const std::string& id, std::string why) { no_certificate_[id] = std::move(why); }
  /// The ids that certify() or no_certificate() named but no claim recorded (a proof's slip).
  std::vector<std::string> unclaimed() const {
    std::vector<std::string> ids;
    for (const auto& [id, r] : certificates_) ids.push_back(id);
    for (const auto& [id, w] : no_certificate_) ids.push_back(id);
    return ids;
  }
  /// A claim checked on instances: it holds only when `holds` and every family of instances has
  /// its minimum of non-trivial ones; each family's count is appended to the evidence.
  bool claim(std::string id, std::string equation, std::string statement, Status status, bool holds,
             std::string evidence, const std::vector<Instances>& instances) {
    for (const auto& in : instances) {
      holds = holds && in.enough();
      evidence += "; " + in.evidence();
    }
    return claim(std::move(id), std::move(equation), std::move(statement), status, holds, std::move(evidence));
  }
  const std::vector<ClaimResult>& results() const { return results_; }
  const std::string& paper() const { return paper_; }

 private:
  std::string paper_;
  std::vector<ClaimResult> results_;
  std::map<std::string, std::vector<CertificateRequest>> certificates_;
  std::map<std::string, std::string> no_certificate_;
};

struct Proof {
  const char* id;
  const char* paper;
  const char* title;
  void (*run)(Checker&);
  const char* file = "";  ///< where it is defined (__FILE__, __LINE__): the registry's order
  int line = 0;
};

/// The proofs in the order of their files' names, then of their lines (report/registration.hpp): the same whatever order the
/// linker gave their static registrations (a unity build, CMakeLists.txt, merges files into one
/// object and orders the objects otherwise), so `hapstab proofs` and the report list them alike.
inline std::vector<Proof>& registry() {
  static std::vector<Proof> r;
  return r;
}

struct Register {
  explicit Register(Proof p) {
    auto& r = registry();
    const auto before = [](const Proof& a, const Proof& b) {
      return report::registered_before(a.file, a.line, b.file, b.line);
    };
    r.insert(std::upper_bound(r.begin(), r.end(), p, before), p);
  }
};

}  // namespace hapstab::proofs

#define HAPSTAB_PROOF(ident, paper, title)                                                       \
  static void ident(::hapstab::proofs::Checker&);                                                \
  static const ::hapstab::proofs::Register ident##_registered({#ident, paper, title, &ident, __FILE__, __LINE__}); \
  static void ident([[maybe_unused]] ::hapstab::proofs::Checker& check)
