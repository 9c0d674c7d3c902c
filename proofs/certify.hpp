// proofs/certify.hpp -- the command lines of the certificates a proof asks `hapstab reproduce` for
// (proof.hpp, CertificateRequest; issue 47): one instance's model as a user writes it for
// `hapstab bound`, `bound --max`, `wedge` or `passivity-level --ss`, so that the certificate reproduce writes is what that
// command writes with --certificate, for the claim's own numbers.
#pragma once

#include <optional>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "hapstab/lti/parse.hpp"
#include "hapstab/lti/state_space.hpp"
#include "hapstab/poly/rational_function.hpp"
#include "proofs/proof.hpp"

namespace hapstab::proofs {

/// One `hapstab bound` instance: H as written (parameters by name), the --set values, T, the
/// delays, eta; `max`/`damping` make it `bound --max NAME --damping b` (a `bound-max` certificate).
struct BoundInstance {
  std::string H;
  rational T;
  std::vector<std::pair<std::string, rational>> set{};
  int delay = 0;
  std::optional<rational> frac_delay{};  ///< t_d in seconds
  rational eta = 0;
  std::string max{};
  rational damping = 0;
};

/// The parameters of `values` that `H` names (a `--set` no expression names is refused: the proofs
/// that run one parameter set over many H pass each H its own).
inline std::vector<std::pair<std::string, rational>> named_sets(const std::string& H,
                                                                 const std::vector<std::pair<std::string, rational>>& values) {
  const std::set<std::string> names = names_in(H);
  std::vector<std::pair<std::string, rational>> out;
  for (const auto& v : values)
    if (names.count(v.first)) out.push_back(v);
  return out;
}

inline std::vector<std::string> bound_args(const BoundInstance& b) {
  std::vector<std::string> a{"bound", "--H", b.H, "--T", b.T.str()};
  for (const auto& [name, value] : b.set) a.insert(a.end(), {"--set", name + "=" + value.str()});
  if (b.delay != 0) a.insert(a.end(), {"--delay", std::to_string(b.delay)});
  if (b.frac_delay) a.insert(a.end(), {"--frac-delay", b.frac_delay->str()});
  if (b.eta != 0) a.insert(a.end(), {"--eta", b.eta.str()});
  if (!b.max.empty()) a.insert(a.end(), {"--max", b.max, "--damping", b.damping.str()});
  return a;
}

/// The certificate of b* (or K_max) of `b` whose claim must contain `value` (equal it when exact).
inline CertificateRequest bound_equals(const BoundInstance& b, const rational& value) {
  CertificateRequest r;
  r.args = bound_args(b);
  r.contains = value.str();
  return r;
}

/// The certificate of b* of `b` whose claim must lie at or below `bound`.
inline CertificateRequest bound_at_most(const BoundInstance& b, const rational& bound) {
  CertificateRequest r;
  r.args = bound_args(b);
  r.at_most = bound.str();
  return r;
}

/// p(z) as an expression of the --H grammar: "3/7*z^2 - z + 1/2" (exact rationals, descending powers).
inline std::string polynomial_text(const Polynomial<rational>& p) {
  if (p.is_zero()) return "0";
  std::string s;
  for (int k = p.degree(); k >= 0; --k) {
    const rational c = p.coeff(k);
    if (c == 0) continue;
    const rational a = c < 0 ? rational(-c) : c;
    s += s.empty() ? (c < 0 ? "-" : "") : (c < 0 ? " - " : " + ");
    const std::string power = k == 0 ? "" : k == 1 ? "z" : "z^" + std::to_string(k);
    if (k == 0 || a != 1) s += a.str() + (k == 0 ? "" : "*");
    s += power;
  }
  return s;
}

/// M as rows of exact "p/q" strings, [["p/q", ...], ...]: a JSON array and a TOML matrix alike.
inline std::string matrix_text(const Mat<rational>& M) {
  std::string t = "[";
  for (Eigen::Index i = 0; i < M.rows(); ++i) {
    t += i ? ", [" : "[";
    for (Eigen::Index j = 0; j < M.cols(); ++j) t += (j ? ", \"" : "\"") + M(i, j).str() + "\"";
    t += "]";
  }
  return t + "]";
}

/// The certificate of the ISP (or `kind`) level of a square state space (`passivity-level --ss FILE
/// --kind isp`, kind passivity-level-mimo; SISO: passivity-level): the model as the --ss JSON file
/// (exact "p/q" entries) that reproduce writes beside the certificates; `contains` the level when it
/// is known ("" otherwise).
inline CertificateRequest mimo_level_request(const StateSpace<rational>& s, const std::string& contains = "",
                                             const std::string& kind = "isp") {
  const auto rows = matrix_text;
  CertificateRequest r;
  r.args = {"passivity-level", "--ss", "{input}", "--kind", kind};
  r.input = "{\"A\": " + rows(s.A) + ", \"B\": " + rows(s.B) + ", \"C\": " + rows(s.C) + ", \"D\": " + rows(s.D) +
            ", \"T\": \"" + s.T.str() + "\"}";
  r.contains = contains;
  return r;
}

/// N(z)/D(z) as an expression of the --H grammar: "(N)/(D)".
inline std::string rational_function_text(const RationalFunction<rational>& H) {
  return "(" + polynomial_text(H.num()) + ")/(" + polynomial_text(H.den()) + ")";
}

}  // namespace hapstab::proofs
