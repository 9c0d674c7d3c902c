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
#include <string>
#include <utility>
#include <vector>

#include "hapstab/numeric/result.hpp"

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

struct ClaimResult {
  std::string id;         ///< stable id, e.g. "001.eq44.identity" (paper.equation.what)
  std::string paper;      ///< "000", "001" or "002" (shared/papers numbering)
  std::string equation;   ///< e.g. "(44) = (35)"
  std::string statement;  ///< what is claimed, in words
  Status status;          ///< how the claim is checked: exact, certified or numeric
  bool holds;
  std::string evidence;   ///< what was computed: counts, maximum errors, enclosures
};

class Checker {
 public:
  explicit Checker(std::string paper) : paper_(std::move(paper)) {}
  /// Records one claim and its computed verdict. Returns `holds` for chaining.
  bool claim(std::string id, std::string equation, std::string statement, Status status, bool holds,
             std::string evidence) {
    results_.push_back({std::move(id), paper_, std::move(equation), std::move(statement), status, holds,
                        std::move(evidence)});
    return holds;
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
};

struct Proof {
  const char* id;
  const char* paper;
  const char* title;
  void (*run)(Checker&);
  const char* file = "";  ///< where it is defined (__FILE__, __LINE__): the registry's order
  int line = 0;
};

/// The proofs in the order of their files' names, then of their lines: the same whatever order the
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
      const int c = std::strcmp(a.file, b.file);
      return c < 0 || (c == 0 && a.line < b.line);
    };
    r.insert(std::upper_bound(r.begin(), r.end(), p, before), p);
  }
};

}  // namespace hapstab::proofs

#define HAPSTAB_PROOF(ident, paper, title)                                                       \
  static void ident(::hapstab::proofs::Checker&);                                                \
  static const ::hapstab::proofs::Register ident##_registered({#ident, paper, title, &ident, __FILE__, __LINE__}); \
  static void ident([[maybe_unused]] ::hapstab::proofs::Checker& check)
