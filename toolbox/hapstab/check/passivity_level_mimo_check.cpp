// hapstab/check/passivity_level_mimo_check.cpp -- see passivity_level_mimo_check.hpp.
#include "hapstab/check/passivity_level_mimo_check.hpp"

#include <algorithm>
#include <string>
#include <utility>
#include <vector>

#include "hapstab/check/bound_objective.hpp"
#include "hapstab/check/gaussian_rational.hpp"
#include "hapstab/check/interpolate.hpp"
#include "hapstab/check/nonnegative.hpp"
#include "hapstab/check/rational_matrix.hpp"
#include "hapstab/check/schur_cohn.hpp"
#include "hapstab/numeric/decimal.hpp"
#include "hapstab/numeric/error.hpp"

namespace hapstab::check {

namespace {

using P = Polynomial<rational>;

using Mat = std::vector<std::vector<rational>>;
using CMat = std::vector<std::vector<Cq>>;

constexpr long max_dim = 64, max_inputs = 16, max_mn = 64;

Mat read_matrix(const nlohmann::json& model, const char* key) {
  return detail::exact_matrix(model, key, "model", static_cast<size_t>(max_dim));
}

size_t cols(const Mat& M) { return M.empty() ? 0 : M[0].size(); }

struct MimoModel {
  Mat A, B, C, D;
  size_t n = 0, m = 0;
  bool osp = false;  ///< the pencil He G - nu G^H G (OSP) instead of He G - nu I (ISP)
};

MimoModel read_model(const nlohmann::json& model) {
  MimoModel s{read_matrix(model, "A"), read_matrix(model, "B"), read_matrix(model, "C"), read_matrix(model, "D")};
  s.n = s.A.size();
  s.m = cols(s.B);
  if (s.n == 0) throw InputError("model.A: empty (a static gain has no state and no certificate)");
  if (cols(s.A) != s.n) throw InputError("model.A: not square");
  if (s.B.size() != s.n) throw InputError("model.B: must have " + std::to_string(s.n) + " rows (the states)");
  if (s.m == 0) throw InputError("model.B: no columns (no input)");
  if (s.C.size() != s.m) throw InputError("model.C: must have " + std::to_string(s.m) + " rows (G square: outputs = inputs)");
  if (cols(s.C) != s.n) throw InputError("model.C: must have " + std::to_string(s.n) + " columns (the states)");
  if (s.D.size() != s.m || cols(s.D) != s.m) throw InputError("model.D: must be " + std::to_string(s.m) + "x" + std::to_string(s.m));
  if (static_cast<long>(s.m) > max_inputs || static_cast<long>(s.m * s.n) > max_mn)
    throw InputError("model: m = " + std::to_string(s.m) + " inputs, n = " + std::to_string(s.n) +
                     " states: above this checker's limit (m <= 16, m n <= 64)");
  return s;
}

// ---- exact linear algebra over a field F (rational or Cq)

template <class F>
F det(std::vector<std::vector<F>> M) {
  const size_t n = M.size();
  F d(rational(1));
  for (size_t k = 0; k < n; ++k) {
    size_t p = k;
    while (p < n && M[p][k].is_zero()) ++p;
    if (p == n) return F(rational(0));
    if (p != k) {
      std::swap(M[p], M[k]);
      d = F(rational(0)) - d;
    }
    d = d * M[k][k];
    for (size_t i = k + 1; i < n; ++i) {
      if (M[i][k].is_zero()) continue;
      const F f = M[i][k] / M[k][k];
      for (size_t j = k; j < n; ++j) M[i][j] = M[i][j] - f * M[k][j];
    }
  }
  return d;
}

/// X with M X = R (M regular: InputError otherwise, which A Schur stable excludes where it is used).
template <class F>
std::vector<std::vector<F>> solve(std::vector<std::vector<F>> M, std::vector<std::vector<F>> R) {
  auto X = solve_exact(std::move(M), std::move(R));
  if (!X) throw InputError("model.A: zI - A is singular at a point where A Schur stable excludes it");
  return *X;
}

/// G(z) = C (zI - A)^-1 B + D at z (F = rational for real z, Cq on the circle).
template <class F>
std::vector<std::vector<F>> G_at(const MimoModel& s, const F& z) {
  std::vector<std::vector<F>> M(s.n, std::vector<F>(s.n)), R(s.n, std::vector<F>(s.m));
  for (size_t i = 0; i < s.n; ++i)
    for (size_t j = 0; j < s.n; ++j) M[i][j] = (i == j ? z : F(rational(0))) - F(s.A[i][j]);
  for (size_t i = 0; i < s.n; ++i)
    for (size_t j = 0; j < s.m; ++j) R[i][j] = F(s.B[i][j]);
  const auto X = solve(std::move(M), std::move(R));
  std::vector<std::vector<F>> G(s.m, std::vector<F>(s.m));
  for (size_t i = 0; i < s.m; ++i)
    for (size_t j = 0; j < s.m; ++j) {
      F v(s.D[i][j]);
      for (size_t l = 0; l < s.n; ++l) v = v + F(s.C[i][l]) * X[l][j];
      G[i][j] = v;
    }
  return G;
}

rational charpoly_at(const MimoModel& s, const rational& z) {
  Mat M(s.n, std::vector<rational>(s.n));
  for (size_t i = 0; i < s.n; ++i)
    for (size_t j = 0; j < s.n; ++j) M[i][j] = (i == j ? z : rational(0)) - s.A[i][j];
  return det(std::move(M));
}

/// d(z) = det(zI - A), degree n, from its values at z = 0..n.
P charpoly(const MimoModel& s) {
  std::vector<rational> x, y;
  for (size_t k = 0; k <= s.n; ++k) {
    x.emplace_back(static_cast<long>(k));
    y.push_back(charpoly_at(s, x.back()));
  }
  return interpolate(x, y);
}

/// P_nu(c) of the header, from its values at c = (t + 1/t)/2, t = 2, 3, ... (d(1/t) != 0);
/// `singular`: instead Z(c) = (d(z) d(1/z))^m det G(z) det G(1/z), whose roots in [-1, 1] are the
/// zeros of det G on the circle (OSP's hypothesis; degree <= mn: det(d G) is a polynomial of degree
/// <= mn in z).
P level_polynomial(const MimoModel& s, const P& d, const rational& nu, bool singular = false) {
  const size_t N = s.m * s.n + 1;
  std::vector<rational> x, y;
  for (long t = 2; x.size() < N; ++t) {
    const rational z(t), iz(1, t);
    const rational dd = d(z) * d(iz);
    if (dd.is_zero()) continue;  // 1/t an eigenvalue of A
    const Mat Gz = G_at(s, z), Gi = G_at(s, iz);
    rational v;
    if (singular) {
      v = det(Gz) * det(Gi);
    } else {
      Mat M(s.m, std::vector<rational>(s.m));
      for (size_t i = 0; i < s.m; ++i)
        for (size_t j = 0; j < s.m; ++j) {
          M[i][j] = Gz[i][j] + Gi[j][i] - (i == j && !s.osp ? 2 * nu : rational(0));
          if (s.osp)  // - 2 nu (G(1/t)^T G(t))_ij
            for (size_t k = 0; k < s.m; ++k) M[i][j] -= 2 * nu * Gi[k][i] * Gz[k][j];
        }
      v = det(std::move(M));
    }
    for (size_t k = 0; k < s.m; ++k) v *= dd;
    x.push_back((z + iz) / 2);
    y.push_back(v);
  }
  return interpolate(x, y);
}

/// He G(z) - nu I (ISP) or He G(z) - nu G(z)^H G(z) (OSP) positive definite (Sylvester: Hermitian
/// elimination without pivoting, every pivot > 0).
bool positive_definite(const MimoModel& s, const Cq& z, const rational& nu) {
  const CMat G = G_at(s, z);
  CMat H(s.m, std::vector<Cq>(s.m));
  for (size_t i = 0; i < s.m; ++i)
    for (size_t j = 0; j < s.m; ++j) {
      const Cq h = G[i][j] + conj(G[j][i]);
      H[i][j] = Cq(h.re / 2 - (i == j && !s.osp ? nu : rational(0)), h.im / 2);
      if (s.osp)  // - nu (G^H G)_ij
        for (size_t k = 0; k < s.m; ++k) H[i][j] = H[i][j] - Cq(nu) * conj(G[k][i]) * G[k][j];
    }
  for (size_t k = 0; k < s.m; ++k) {
    if (!H[k][k].im.is_zero()) throw NumericalError("He G: a diagonal entry is not real (internal)");
    if (H[k][k].re <= 0) return false;
    for (size_t i = k + 1; i < s.m; ++i) {
      const Cq f = H[i][k] / H[k][k];
      for (size_t j = k; j < s.m; ++j) H[i][j] = H[i][j] - f * H[k][j];
    }
  }
  return true;
}

Cq circle_point(const rational& t) {  // (1 - t^2 + 2jt)/(1 + t^2)
  const rational w = 1 + t * t;
  return {(1 - t * t) / w, 2 * t / w};
}

/// A rational t >= 0 with c(t) = (1 - t^2)/(1 + t^2) in the open interval (x, y), -1 <= x < y <= 1.
rational t_inside(const rational& x, const rational& y) {
  const rational u1 = (1 - y) / (1 + y);  // t^2 > u1
  if (x == -1) return u1 + 1;             // (u1 + 1)^2 > u1
  const rational u2 = (1 - x) / (1 + x);  // t^2 < u2
  rational L(0), R = u2 + 1;
  for (;;) {
    const rational mid = (L + R) / 2, q = mid * mid;
    if (q <= u1) L = mid;
    else if (q >= u2) R = mid;
    else return mid;
  }
}

/// A root of the square-free S in [-1, 1]: exactly r (a = b) or inside the open (a, b), S(a), S(b) != 0.
struct Root {
  rational a, b;
};

std::vector<Root> isolate(P S) {
  std::vector<rational> exact;
  for (;;) {
    bool restart = false;
    for (const rational& e : {rational(-1), rational(1)})
      if (S.degree() > 0 && S(e) == 0) exact.push_back(e), S = divmod(S, P{-e, rational(1)}).first;
    std::vector<Root> found;
    std::vector<std::pair<rational, rational>> stack{{rational(-1), rational(1)}};
    while (!stack.empty() && !restart && S.degree() > 0) {
      const auto [a, b] = stack.back();
      stack.pop_back();
      const int k = sturm_count(S, a, b);
      if (k == 0) continue;
      if (k == 1) {
        found.push_back({a, b});
        continue;
      }
      const rational mid = (a + b) / 2;
      if (S(mid) == 0) {  // divided out, and the isolation restarted on the quotient
        exact.push_back(mid);
        S = divmod(S, P{-mid, rational(1)}).first;
        restart = true;
        break;
      }
      stack.push_back({a, mid});
      stack.push_back({mid, b});
    }
    if (restart) continue;
    // an interval holding an exact root too is split at it (S(r) != 0 for the quotient)
    for (Root& r : found)
      for (const rational& e : exact)
        if (r.a < e && e < r.b) {
          if (sturm_count(S, r.a, e) == 1) r.b = e;
          else r.a = e;
        }
    for (const rational& e : exact) found.push_back({e, e});
    // by (a, b): an exact root e before the interval (e, b) that starts at it
    std::sort(found.begin(), found.end(), [](const Root& x, const Root& y) { return x.a < y.a || (x.a == y.a && x.b < y.b); });
    // neighbours sharing an end point (not a root): shrink the one that is an interval until there is a gap
    for (size_t i = 0; i + 1 < found.size(); ++i)
      for (int step = 0; !(found[i].b < found[i + 1].a); ++step) {
        if (step > 100000) throw NumericalError("check: the roots of det(He G - lo I) were not separated (internal)");
        Root& r = found[i].a < found[i].b ? found[i] : found[i + 1];
        const rational mid = (r.a + r.b) / 2;
        if (S(mid) == 0) r.a = r.b = mid;  // the interval's one root, rational
        else if (sturm_count(S, r.a, mid) == 1) r.b = mid;
        else r.a = mid;
      }
    return found;
  }
}

/// "He G - nu I" (ISP) or "He G - nu G^H G" (OSP), for the messages.
std::string pencil(const MimoModel& s, const std::string& nu) { return "He G - " + nu + (s.osp ? " G^H G" : " I"); }

/// OSP's hypothesis: det G(e^{j theta}) != 0 for every theta (Z of level_polynomial has no root in
/// [-1, 1]); "" when it holds, else why not.
std::string zero_on_circle(const MimoModel& s, const P& d) {
  const P Z = level_polynomial(s, d, rational(0), true);
  if (Z.is_zero()) return "det G is 0 at every theta (G singular on the whole circle)";
  for (const rational& e : {rational(-1), rational(1)})
    if (Z(e) == 0) return e == 1 ? "det G(1) = 0 (a zero of G at z = 1)" : "det G(-1) = 0 (a zero of G at z = -1)";
  const P S = Z.degree() > 0 ? divmod(Z, gcd(Z, Z.derivative())).first : Z;
  if (S.degree() > 0 && sturm_count(S, rational(-1), rational(1)) > 0)
    return "det G vanishes on the unit circle (|det G|^2 |d|^{2m} has a root in (-1, 1) in cos theta, Sturm)";
  return "";
}

struct LowerTest {
  std::optional<std::string> fails;
  bool touches = false;  ///< P_lo has a root in [-1, 1]
  int degree = 0, samples = 0;
};

/// He G - lo I >= 0 on the whole circle (the header's (lower)).
LowerTest lower_test(const MimoModel& s, const P& d, const rational& lo) {
  LowerTest out;
  const P p = level_polynomial(s, d, lo);
  out.degree = p.degree();
  if (p.is_zero()) {
    out.fails = "det(" + pencil(s, "lo") + ") |d|^{2m} is identically 0 in cos theta (lo is an eigenvalue of the pencil "
                "at every theta): this theorem does not decide";
    return out;
  }
  const P S = p.degree() > 0 ? divmod(p, gcd(p, p.derivative())).first : p;
  const std::vector<Root> roots = S.degree() > 0 ? isolate(S) : std::vector<Root>{};
  out.touches = !roots.empty();
  auto test = [&](const Cq& z, const std::string& where) {
    ++out.samples;
    if (!out.fails && !positive_definite(s, z, lo))
      out.fails = pencil(s, "lo") + " is not positive definite at " + where + ", where it is regular (det != 0): the level < lo";
  };
  // the arc [-1, r_0) holds c = -1 unless -1 is a root, (r_last, 1] holds c = 1 unless 1 is one; with a
  // root at an end, its arc is the gap to the next root (or the other end's arc when it is alone)
  const bool root_at_minus1 = !roots.empty() && roots.front().b == -1, root_at_1 = !roots.empty() && roots.back().a == 1;
  if (!root_at_minus1) test(Cq(rational(-1)), "theta = pi");
  if (!root_at_1) test(Cq(rational(1)), "theta = 0");
  for (size_t i = 0; i + 1 < roots.size(); ++i) {
    const rational t = t_inside(roots[i].b, roots[i + 1].a);
    test(circle_point(t), "z = (1 - t^2 + 2jt)/(1 + t^2), t = " + t.str());
  }
  return out;
}

}  // namespace

Verdict check_passivity_level_mimo(const nlohmann::json& cert) {
  using detail::exact_field;
  const auto [model, claim, evidence] = detail::certificate_parts(cert);
  detail::only_fields(model, {"A", "B", "C", "D", "T", "kind"}, "model");
  detail::only_fields(claim, {"quantity", "status", "value", "lo", "hi", "printed", "printed_lo", "printed_hi"}, "claim");
  if (!model.contains("kind") || !model.at("kind").is_string() || (model.at("kind") != "isp" && model.at("kind") != "osp"))
    throw InputError("model.kind: missing or not \"isp\" or \"osp\"" +
                     (model.contains("kind") ? ", got " + model.at("kind").dump() : std::string()));
  const rational T = exact_field(model, "T", "model");
  if (T <= 0) throw InputError("model.T: the sample period must be > 0, got " + T.str());
  MimoModel s = read_model(model);
  s.osp = model.at("kind") == "osp";
  const std::string level = s.osp ? "delta*" : "phi*";
  const P d = charpoly(s);
  const SchurCohn stable = schur_cohn(d);
  if (!stable.stable)
    throw InputError("model.A: not Schur stable (" + stable.why + "): the level is not its frequency minimum");

  // ---- an upper bound only (header): the pencil at hi not > 0 at the witness, G(z0) regular (OSP);
  // ---- a lower bound by Lemma 1 at the storage P, with such an upper bound beside it or alone
  const std::string status = claim.contains("status") && claim.at("status").is_string() ? claim.at("status").get<std::string>() : "";
  if (status == "upper_bound" || status == "lower_bound" || status == "bounds") {
    bool has_hi = status == "upper_bound";
    const detail::ClaimRange range = status == "upper_bound" ? detail::upper_bound_claim(claim) : detail::lower_bound_claim(claim, has_hi);
    const bool has_lo = status != "upper_bound";
    if (!has_lo) detail::only_fields(evidence, {"witness_c", "witness_s"}, "evidence");
    else if (has_hi) detail::only_fields(evidence, {"witness_c", "witness_s", "P"}, "evidence");
    else detail::only_fields(evidence, {"P"}, "evidence");
    Mat Pm;
    if (has_lo) {
      Pm = detail::exact_matrix(evidence, "P", "evidence", static_cast<size_t>(max_dim));
      if (Pm.size() != s.n || cols(Pm) != s.n) throw InputError("evidence.P: must be " + std::to_string(s.n) + "x" + std::to_string(s.n) + " (the states)");
    }
    rational c0, s0;
    if (has_hi) c0 = exact_field(evidence, "witness_c", "evidence"), s0 = exact_field(evidence, "witness_s", "evidence");
    if (range.refuted) return {false, *range.refuted};
    std::string shown;
    if (has_lo) {
      const std::string why = rational_matrix::lemma1_level_fails(s.A, s.B, s.C, s.D, Pm, range.lo, s.osp);
      if (!why.empty()) return {false, level + " >= " + range.lo.str() + " (" + detail::decimal(range.lo) + ") not shown: " + why};
      shown = level + " >= " + detail::decimal(range.lo) + " (Lemma 1 at the storage P: P > 0 and (2) < 0 at the level lo, exactly)";
    }
    if (has_hi) {
      const rational& hi = range.hi;
      if (c0 * c0 + s0 * s0 != 1)
        return {false, "evidence: the witness (c0, s0) = (" + detail::shortened(c0) + ", " + detail::shortened(s0) +
                           ") is not on the unit circle (c0^2 + s0^2 != 1)"};
      const Cq z0(c0, s0);
      if (s.osp && det(G_at(s, z0)).is_zero())
        return {false, "evidence: det G = 0 at the witness z0 = " + detail::shortened(c0) + " + j " + detail::shortened(s0) +
                           " (no bound from it: the pencil is singular there for every nu)"};
      if (positive_definite(s, z0, hi))
        return {false, level + " <= " + hi.str() + " (" + detail::decimal(hi) + ") not shown: " + pencil(s, "hi") +
                           " is positive definite at the witness z0 = " + detail::shortened(c0) + " + j " + detail::shortened(s0)};
      shown += (shown.empty() ? "" : "; ") + level + " <= " + detail::decimal(hi) + " (" + pencil(s, "hi") +
               " not > 0 at the witness z0 = " + detail::shortened(c0) + " + j " + detail::shortened(s0) +
               (s.osp ? ", where det G != 0" : "") + ", so the frequency inequality of every level above hi fails there)";
    }
    return {true, shown + " (" + (s.osp ? "OSP" : "ISP") + ", " + std::to_string(s.m) + "x" + std::to_string(s.m) +
                      (has_lo ? "" : ", an upper bound only") + "; A Schur stable: " + stable.why + ")"};
  }
  std::string regular;
  if (s.osp) {  // G regular on the circle, so He G - nu G^H G = G^H (He G^-1 - nu I) G there
    const std::string why = zero_on_circle(s, d);
    if (!why.empty())
      throw InputError("model: " + why + ": the OSP pencil's minimum is not the level there (no certificate)");
    regular = "; det G != 0 on the circle (Sturm)";
  }

  const detail::ClaimRange range = detail::claim_range(claim);
  if (range.refuted) return {false, *range.refuted};
  const bool exact = range.status == "exact";
  if (exact) detail::only_fields(evidence, {}, "evidence");
  else detail::only_fields(evidence, {"witness_c", "witness_s"}, "evidence");
  const rational &lo = range.lo, &hi = range.hi;
  rational c0, s0;
  if (!exact) {
    c0 = exact_field(evidence, "witness_c", "evidence");
    s0 = exact_field(evidence, "witness_s", "evidence");
  }

  if (s.osp && lo <= 0)  // an OSP value <= 0 bounds Lemma 1's level only from above (as the SISO kind)
    return {false, "delta* >= " + lo.str() + ": an OSP claim needs lo > 0 (a value <= 0 is not the level of Lemma 1)"};
  const LowerTest low = lower_test(s, d, lo);
  if (low.fails) return {false, level + " >= " + lo.str() + " (" + detail::decimal(lo) + ") fails: " + *low.fails};
  std::string upper;
  if (exact) {
    if (!low.touches)
      return {false, level + " <= " + lo.str() + " not shown: det(" + pencil(s, "v") + ") has no root on the circle, so " +
                         pencil(s, "v") + " > 0 everywhere and the level > v"};
    upper = "det(" + pencil(s, "v") + ") has a root in [-1, 1], where " + pencil(s, "v") + " >= 0 is singular";
  } else {
    if (c0 * c0 + s0 * s0 != 1)
      return {false, "evidence: the witness (c0, s0) = (" + detail::shortened(c0) + ", " + detail::shortened(s0) +
                         ") is not on the unit circle (c0^2 + s0^2 != 1)"};
    if (positive_definite(s, Cq(c0, s0), hi))
      return {false, level + " <= " + hi.str() + " (" + detail::decimal(hi) + ") not shown: " + pencil(s, "hi") +
                         " is positive definite at the witness z0 = " + detail::shortened(c0) + " + j " + detail::shortened(s0)};
    upper = pencil(s, "hi") + " not > 0 at the witness z0 = " + detail::shortened(c0) + " + j " + detail::shortened(s0);
  }
  const std::string what = exact ? level + " = " + lo.str() : level + " in [" + detail::decimal(lo) + ", " + detail::decimal(hi) + "]";
  return {true, what + " (" + (s.osp ? "OSP" : "ISP") + ", " + std::to_string(s.m) + "x" + std::to_string(s.m) + ", " +
                    std::to_string(s.n) + " states; lower bound: " + pencil(s, "lo") + " > 0 at " + std::to_string(low.samples) +
                    " point(s), one per arc between the roots of det(" + pencil(s, "lo") + ")|d|^{2m} (Sturm, degree " +
                    std::to_string(low.degree) + "); upper bound: " + upper + "; A Schur stable: " + stable.why + regular + ")"};
}

}  // namespace hapstab::check
