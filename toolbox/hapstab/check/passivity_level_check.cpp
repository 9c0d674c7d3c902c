// hapstab/check/passivity_level_check.cpp -- see passivity_level_check.hpp.
#include "hapstab/check/passivity_level_check.hpp"

#include <algorithm>
#include <string>
#include <utility>

#include "hapstab/check/bound_objective.hpp"
#include "hapstab/check/max_positive.hpp"
#include "hapstab/check/nonnegative.hpp"
#include "hapstab/check/on_circle.hpp"
#include "hapstab/check/rational_matrix.hpp"
#include "hapstab/check/schur_cohn.hpp"
#include "hapstab/numeric/decimal.hpp"
#include "hapstab/numeric/error.hpp"

namespace hapstab::check {

namespace {
using P = Polynomial<rational>;
using rational_matrix::Mat;

struct Realisation {
  Mat A, B, C, D, P;
};

Realisation read_realisation(const nlohmann::json& evidence) {
  constexpr size_t max_states = 64;
  Realisation r;
  for (const auto& [key, M] : {std::pair<const char*, Mat*>{"A", &r.A}, {"B", &r.B}, {"C", &r.C}, {"D", &r.D}, {"P", &r.P}})
    *M = detail::exact_matrix(evidence, key, "evidence", max_states);
  const size_t n = r.A.size();
  const auto shape = [](const Mat& M, size_t rows, size_t cols) {
    return M.size() == rows && (rows == 0 || M[0].size() == cols);
  };
  if (n == 0 || !shape(r.A, n, n)) throw InputError("evidence.A: empty or not square");
  if (!shape(r.B, n, 1)) throw InputError("evidence.B: must be " + std::to_string(n) + " x 1 (one input)");
  if (!shape(r.C, 1, n)) throw InputError("evidence.C: must be 1 x " + std::to_string(n) + " (one output)");
  if (!shape(r.D, 1, 1)) throw InputError("evidence.D: must be 1 x 1");
  if (!shape(r.P, n, n)) throw InputError("evidence.P: must be " + std::to_string(n) + " x " + std::to_string(n) + " (the states)");
  return r;
}

// G_r(t) = D + C (tI - A)^-1 B = D + (det(tI - A + BC) - det(tI - A)) / det(tI - A) (the matrix determinant
// lemma); {G_r(t), false} where det(tI - A) = 0.
std::pair<rational, bool> realised_at(const Realisation& r, const rational& t) {
  using namespace rational_matrix;
  const size_t n = r.A.size();
  Mat tA = add(add(zeros(n, n), identity(n), t), r.A, -1);
  const rational d = rational_matrix::det(tA);
  if (d.is_zero()) return {0, false};
  const Mat closed = add(tA, mul(r.B, r.C));
  return {r.D[0][0] + (rational_matrix::det(closed) - d) / d, true};
}

// The realisation's transfer function is p/d with deg d = n, deg p <= n; G = N/D with deg N <= deg D = k.
// N d - p D has degree <= n + k, so G_r = G at n + k + 1 points t = 2, 3, ... where D(t) != 0 and d(t) !=
// 0 proves G_r = G. The number of points compared (realisation_points) or what differs.
size_t realisation_points(const Realisation& r, const TransferFunction& G) { return r.A.size() + G.den().degree() + 1; }

std::string realisation_fails(const Realisation& r, const TransferFunction& G) {
  size_t equal = 0;
  for (long t = 2; equal < realisation_points(r, G); ++t) {
    const rational tq(t);
    if (G.den()(tq).is_zero()) continue;
    const auto [g, ok] = realised_at(r, tq);
    if (!ok) continue;
    if (g != G.num()(tq) / G.den()(tq))
      return "evidence: (A, B, C, D) does not realise G as written: at z = " + std::to_string(t) + ", D + C (zI - A)^-1 B = " +
             detail::shortened(g) + ", G = " + detail::shortened(G.num()(tq) / G.den()(tq));
    ++equal;
  }
  return "";
}
}  // namespace

Verdict check_passivity_level(const nlohmann::json& cert) {
  using detail::exact_field;
  const auto [model, claim, evidence] = detail::certificate_parts(cert);
  detail::only_fields(model, {"H", "set", "num", "den", "T", "kind"}, "model");
  detail::only_fields(claim, {"quantity", "status", "value", "lo", "hi", "printed", "printed_lo", "printed_hi"}, "claim");
  const std::string status_written =
      claim.contains("status") && claim.at("status").is_string() ? claim.at("status").get<std::string>() : "";
  const bool lemma1 = status_written == "lower_bound" || status_written == "bounds";
  if (!lemma1) detail::only_fields(evidence, {"witness_c"}, "evidence");

  // ---- the model as written
  if (!model.contains("kind") || !model.at("kind").is_string() ||
      (model.at("kind") != "isp" && model.at("kind") != "osp"))
    throw InputError("model.kind: missing or neither \"isp\" nor \"osp\"");
  const bool osp = model.at("kind") == "osp";
  const rational T = exact_field(model, "T", "model");
  if (T <= 0) throw InputError("model.T: the sample period must be > 0, got " + T.str());
  const TransferFunction G = detail::model_tf(model, T);
  if (G.num().is_zero()) throw InputError("model.H: G = 0");
  if (G.num().degree() > G.den().degree()) throw InputError("model.H: G is not causal (deg N > deg D)");
  if (G.den().degree() > 1000) throw InputError("model.H: degree above this checker's limit of 1000");
  const SchurCohn stable = schur_cohn(G.den());
  if (!stable.stable) throw InputError("model.H: G is not Schur stable (" + stable.why + "): the level is not its frequency minimum");

  // ---- Re W = X/Q on the circle, c = cos(theta)
  const circle::OnCircle N = circle::at_circle(G.num()), D = circle::at_circle(G.den());
  const P s2 = circle::one_minus_c2();
  const P X = N.a * D.a + s2 * N.b * D.b;
  const P Q = osp ? N.a * N.a + s2 * N.b * N.b : D.a * D.a + s2 * D.b * D.b;
  const rational m1(-1), p1(1);
  const std::string name = osp ? "delta*" : "phi*";

  // ---- an upper bound (header): Re W(c0) <= hi at the witness with Q(c0) > 0; "" or what fails
  const auto upper_fails = [&](const rational& hi, const rational& c0) -> std::string {
    if (c0 < -1 || c0 > 1) return "evidence.witness_c = " + detail::shortened(c0) + " is outside [-1, 1]";
    if (Q(c0) == 0) return std::string("evidence.witness_c: ") + (osp ? "G" : "1/G") + " = 0 there (no bound from it)";
    const rational w0 = X(c0) / Q(c0);
    if (w0 > hi)
      return name + " <= " + hi.str() + " (" + detail::decimal(hi) + ") not shown: Re " + (osp ? "1/G" : "G") +
             " at the witness c0 = " + detail::shortened(c0) + " is " + detail::decimal(w0) + " > hi";
    return "";
  };
  const auto upper_shown = [&](const rational& hi, const rational& c0) {
    return name + " <= " + detail::decimal(hi) + " (Re " + (osp ? "1/G" : "G") + " = " + detail::decimal(X(c0) / Q(c0)) +
           " at c0 = " + detail::shortened(c0) + ", where the frequency inequality of every level above hi fails)";
  };
  if (status_written == "upper_bound") {
    const detail::ClaimRange range = detail::upper_bound_claim(claim);
    if (range.refuted) return {false, *range.refuted};
    const rational c0 = exact_field(evidence, "witness_c", "evidence");
    if (const std::string why = upper_fails(range.hi, c0); !why.empty()) return {false, why};
    return {true, upper_shown(range.hi, c0) + " (" + (osp ? "OSP" : "ISP") + ", an upper bound only; G Schur stable: " + stable.why + ")"};
  }

  // ---- a lower bound by Lemma 1 at the storage P of the realisation (A, B, C, D) written beside it
  if (lemma1) {
    bool has_hi = false;
    const detail::ClaimRange range = detail::lower_bound_claim(claim, has_hi);
    if (has_hi) detail::only_fields(evidence, {"A", "B", "C", "D", "P", "witness_c"}, "evidence");
    else detail::only_fields(evidence, {"A", "B", "C", "D", "P"}, "evidence");
    const Realisation r = read_realisation(evidence);
    const rational c0 = has_hi ? exact_field(evidence, "witness_c", "evidence") : rational(0);
    if (range.refuted) return {false, *range.refuted};
    if (const std::string why = realisation_fails(r, G); !why.empty()) return {false, why};
    if (const std::string why = rational_matrix::lemma1_level_fails(r.A, r.B, r.C, r.D, r.P, range.lo, osp); !why.empty())
      return {false, name + " >= " + range.lo.str() + " (" + detail::decimal(range.lo) + ") not shown: " + why};
    std::string shown = name + " >= " + detail::decimal(range.lo) + " (Lemma 1 at the storage P of the realisation written, " +
                        std::to_string(r.A.size()) + " states, which equals G at " + std::to_string(realisation_points(r, G)) +
                        " points: P > 0 and (2) < 0 at the level lo, exactly)";
    if (has_hi) {
      if (const std::string why = upper_fails(range.hi, c0); !why.empty()) return {false, why};
      shown += "; " + upper_shown(range.hi, c0);
    }
    return {true, shown + " (" + (osp ? "OSP" : "ISP") + "; G Schur stable: " + stable.why + ")"};
  }

  // ---- the claim
  const detail::ClaimRange range = detail::claim_range(claim);
  if (range.refuted) return {false, *range.refuted};
  const std::string& status = range.status;
  const rational &lo = range.lo, &hi = range.hi;
  if (osp) {
    if (auto why = max_positive_on(Q, Q, m1, p1))
      throw InputError("model.H: G has a zero on the unit circle (|N|^2 not > 0: " + *why + "): delta* is not Lemma 1's level there");
    if (lo <= 0)
      throw InputError("claim: an OSP value <= 0 (lo = " + detail::decimal(lo) + ") is an upper bound of Lemma 1's level only: no certificate");
  }
  if (auto why = nonnegative_on(X - lo * Q, m1, p1))
    return {false, name + " >= " + lo.str() + " (" + detail::decimal(lo) + ") fails: X(c) - lo Q(c) on [-1, 1]: " + *why};
  const rational c0 = exact_field(evidence, "witness_c", "evidence");
  if (c0 < -1 || c0 > 1) return {false, "evidence.witness_c = " + detail::shortened(c0) + " is outside [-1, 1]"};
  const rational w0 = X(c0) / Q(c0);  // Q > 0 on [-1, 1]
  if (w0 > hi)
    return {false, name + " <= " + hi.str() + " (" + detail::decimal(hi) + ") not shown: Re " + (osp ? "1/G" : "G") +
                       " at the witness c0 = " + detail::shortened(c0) + " is " + detail::decimal(w0) + " > hi"};
  const std::string what = status == "exact" ? name + " = " + lo.str() : name + " in [" + detail::decimal(lo) + ", " + detail::decimal(hi) + "]";
  return {true, what + " (" + (osp ? "OSP" : "ISP") + "; lower bound: X - lo " + (osp ? "|N|^2" : "|D|^2") +
                    " >= 0 on [-1, 1] by Sturm, degree " + std::to_string(std::max(X.degree(), Q.degree())) +
                    "; upper bound: Re " + (osp ? "1/G" : "G") + " at c0 = " + detail::shortened(c0) + "; G Schur stable: " +
                    stable.why + ")"};
}

}  // namespace hapstab::check
