// hapstab/check/operator_passivity_check.cpp -- see operator_passivity_check.hpp.
#include "hapstab/check/operator_passivity_check.hpp"

#include <optional>
#include <string>
#include <vector>

#include "hapstab/check/gaussian_rational.hpp"
#include "hapstab/check/interpolate.hpp"
#include "hapstab/check/rational_matrix.hpp"
#include "hapstab/check/scene_model.hpp"
#include "hapstab/numeric/error.hpp"

namespace hapstab::check {

namespace {

// p(jw), exactly (Horner in Q(j)).
Cq at_jw(const Polynomial<rational>& p, const rational& w) {
  Cq v(rational(0));
  for (int k = p.degree(); k >= 0; --k) v = v * Cq(rational(0), w) + Cq(p.coeff(k));
  return v;
}

// det M over Q(j) by Gaussian elimination with row swaps.
Cq det(std::vector<std::vector<Cq>> M) {
  const size_t n = M.size();
  Cq d(rational(1));
  for (size_t k = 0; k < n; ++k) {
    size_t p = k;
    while (p < n && M[p][k].is_zero()) ++p;
    if (p == n) return Cq(rational(0));
    if (p != k) std::swap(M[p], M[k]), d = Cq(rational(0)) - d;
    d = d * M[k][k];
    for (size_t i = k + 1; i < n; ++i) {
      if (M[i][k].is_zero()) continue;
      const Cq f = M[i][k] / M[k][k];
      for (size_t j = k; j < n; ++j) M[i][j] = M[i][j] - f * M[k][j];
    }
  }
  return d;
}

// Z(jw) of an ss operator as written, C (jwI - A)^-1 B + D, over Q(j) (Gauss-Jordan with row swaps);
// nullopt where jwI - A is singular (a pole of Z, or a hidden mode, at jw).
std::optional<std::vector<std::vector<Cq>>> ss_at_jw(const detail::SceneLoop::Impedance& op, const rational& w) {
  const size_t n = op.A.size(), m = op.D.size();
  std::vector<std::vector<Cq>> M(n, std::vector<Cq>(n)), Bq(n, std::vector<Cq>(m));
  for (size_t i = 0; i < n; ++i) {
    for (size_t j = 0; j < n; ++j) M[i][j] = Cq(-op.A[i][j], i == j ? w : rational(0));
    for (size_t j = 0; j < m; ++j) Bq[i][j] = Cq(op.B[i][j]);
  }
  const auto X = solve_exact(std::move(M), std::move(Bq));
  if (!X) return std::nullopt;
  std::vector<std::vector<Cq>> Z(m, std::vector<Cq>(m));
  for (size_t i = 0; i < m; ++i)
    for (size_t j = 0; j < m; ++j) {
      Cq v(op.D[i][j]);
      for (size_t k = 0; k < n; ++k) v = v + Cq(op.C[i][k]) * (*X)[k][j];
      Z[i][j] = v;
    }
  return Z;
}

// Z(s) = C (sI - A)^-1 B + D of an ss operator as written, entry by entry as rational functions: chi(s) =
// det(sI - A) by n + 1 exact determinants and interpolation; chi (Z - D) = C adj(sI - A) B, of degree < n,
// by n values at integers s_k where chi(s_k) != 0 ((s_k I - A) X = B solved exactly); entry = (D chi + N)/chi.
std::vector<std::vector<RationalFunction<rational>>> ss_transfer(const detail::SceneLoop::Impedance& op) {
  using namespace rational_matrix;
  const size_t n = op.A.size(), m = op.D.size();
  std::vector<rational> xs, chi_at;
  for (size_t k = 0; k <= n; ++k) {
    const rational s(static_cast<long>(k));
    xs.push_back(s);
    chi_at.push_back(rational_matrix::det(add(add(zeros(n, n), identity(n), s), op.A, -1)));
  }
  const Polynomial<rational> chi = interpolate(xs, chi_at);
  std::vector<rational> at;
  std::vector<std::vector<std::vector<rational>>> N(m, std::vector<std::vector<rational>>(m));
  for (long k = 0; at.size() < n; ++k) {  // chi has at most n roots among 0 .. 2n
    const rational s(k);
    const rational c = chi(s);
    if (c.is_zero()) continue;
    const auto X = solve_exact<rational>(add(add(zeros(n, n), identity(n), s), op.A, -1), op.B);
    if (!X) throw NumericalError("sI - A singular where det(sI - A) != 0 (a checker defect)");
    at.push_back(s);
    for (size_t i = 0; i < m; ++i)
      for (size_t j = 0; j < m; ++j) {
        rational v = 0;
        for (size_t l = 0; l < n; ++l) v += op.C[i][l] * (*X)[l][j];
        N[i][j].push_back(c * v);
      }
  }
  std::vector<std::vector<RationalFunction<rational>>> Z(m);
  for (size_t i = 0; i < m; ++i)
    for (size_t j = 0; j < m; ++j)
      Z[i].emplace_back(chi * Polynomial<rational>(op.D[i][j]) + (n ? interpolate(at, N[i][j]) : Polynomial<rational>()), chi);
  return Z;
}

// Z's residue at the axis pole s = j w0, w0 = sqrt(q) >= 0 (header; q rational, w0 rational or not): "" when
// no entry has a pole there of order >= 2 and R = lim (s - j w0) Z(s) is Hermitian positive semidefinite; else
// what fails. Each entry in lowest terms; f = s (q = 0) or s^2 + q, its multiplicity in the denominator d the
// pole's order. For a simple pole, with p(j w0) = E_p(-q) + j w0 O_p(-q) (p's even and odd parts, rational),
// n(j w0) = a + j w0 b and d'(j w0) = c + j w0 e give R_ij = X + j w0 Y, X = (a c + q b e)/(c^2 + q e^2), Y = (b c
// - a e)/(c^2 + q e^2), both rational. R Hermitian iff X symmetric and (q > 0) Y antisymmetric; PSD iff the real
// [[X, -w0 Y], [w0 Y, X]] is, iff (congruence by diag(I, I/w0), Sylvester's law of inertia) [[X, -Y], [Y, X/q]]
// is -- exactly, in rationals (q = 0: X alone).
std::string residue_fails(const std::vector<std::vector<RationalFunction<rational>>>& Z, const rational& q, const std::string& at) {
  const size_t m = Z.size();
  const Polynomial<rational> f = q.is_zero() ? Polynomial<rational>{rational(0), rational(1)} : Polynomial<rational>{q, rational(0), rational(1)};
  const auto parts = [&q](const Polynomial<rational>& p) {  // (E_p(-q), O_p(-q))
    rational even = 0, odd = 0, power = 1;                  // power = (-q)^k
    for (int k = 0; 2 * k <= p.degree(); ++k, power *= -q) {
      even += p.coeff(2 * k) * power;
      if (2 * k + 1 <= p.degree()) odd += p.coeff(2 * k + 1) * power;
    }
    return std::pair{even, odd};
  };
  rational_matrix::Mat X = rational_matrix::zeros(m, m), Y = X;
  for (size_t i = 0; i < m; ++i)
    for (size_t j = 0; j < m; ++j) {
      Polynomial<rational> n = Z[i][j].num(), d = Z[i][j].den();
      const Polynomial<rational> g = gcd(n, d);  // the entry in lowest terms
      if (g.degree() > 0) n = divmod(n, g).first, d = divmod(d, g).first;
      int order = 0;
      for (Polynomial<rational> e = d; e.degree() >= f.degree(); ++order) {
        auto [quot, rem] = divmod(e, f);
        if (!rem.is_zero()) break;
        e = quot;
      }
      if (order >= 2)
        return "entry (" + std::to_string(i + 1) + ", " + std::to_string(j + 1) + ") has a pole of order " + std::to_string(order) +
               " at " + at + " (a positive real Z has only simple poles on the imaginary axis)";
      if (order == 1) {
        const auto [a, b] = parts(n);
        const auto [c, e] = parts(d.derivative());
        const rational den = c * c + q * e * e;
        X[i][j] = (a * c + q * b * e) / den;
        Y[i][j] = (b * c - a * e) / den;
      }
    }
  for (size_t i = 0; i < m; ++i)
    for (size_t j = 0; j <= i; ++j)
      if (X[i][j] != X[j][i] || (!q.is_zero() && Y[i][j] != -Y[j][i]))
        return "the residue R = lim (s - j w0) Z(s) at " + at + " is not Hermitian";
  rational_matrix::Mat E = X;
  if (!q.is_zero()) {
    E = rational_matrix::zeros(2 * m, 2 * m);
    for (size_t i = 0; i < m; ++i)
      for (size_t j = 0; j < m; ++j) {
        E[i][j] = X[i][j];
        E[m + i][m + j] = X[i][j] / q;
        E[i][m + j] = -Y[i][j];
        E[m + i][j] = Y[i][j];
      }
  }
  if (!rational_matrix::positive_definite(E, false))
    return "the residue R = lim (s - j w0) Z(s) at " + at + " is not positive semidefinite (exact elimination)";
  return "";
}

}  // namespace

Verdict check_operator_passivity(const nlohmann::json& cert) {
  const auto [model, claim, evidence] = detail::certificate_parts(cert);
  detail::only_fields(claim, {"quantity", "status", "operator", "passive"}, "claim");
  const bool at_pole = evidence.contains("pole") || evidence.contains("pole_squared");
  if (at_pole) detail::only_fields(evidence, {evidence.contains("pole") ? "pole" : "pole_squared"}, "evidence");
  else detail::only_fields(evidence, {"w", "minor"}, "evidence");
  if (!claim.contains("status") || claim.at("status") != "exact") throw InputError("claim.status: missing or not \"exact\"");
  if (!claim.contains("passive") || !claim.at("passive").is_boolean()) throw InputError("claim.passive: missing or not true/false");
  if (claim.at("passive").get<bool>())
    throw InputError("claim.passive: true has no certificate form here (every principal minor >= 0 on the whole axis): only "
                     "false, with a witness");
  if (!claim.contains("operator") || !claim.at("operator").is_string()) throw InputError("claim.operator: missing or not a string");
  const std::string name = claim.at("operator").get<std::string>();
  const detail::SceneLoop L = detail::read_scene_loop(model);
  const detail::SceneLoop::Impedance* op = nullptr;
  for (const auto& o : L.operators)
    if (o.name == name) {
      if (op) throw InputError("claim.operator: two operators named '" + name + "' in the scene");
      op = &o;
    }
  if (!op) throw InputError("claim.operator: no operator given by tf or ss named '" + name + "' in the scene");
  if (at_pole) {  // the residue at the axis pole s = j w0 (header): w0 = pole, or sqrt(pole_squared)
    rational q;
    std::string at;
    if (evidence.contains("pole")) {
      const rational w0 = detail::exact_field(evidence, "pole", "evidence");
      if (w0 < 0) throw InputError("evidence.pole: w0 >= 0 (the pole s = j w0; its conjugate's residue is the conjugate)");
      q = w0 * w0, at = w0.is_zero() ? "s = 0" : "s = j" + w0.str();
    } else {
      q = detail::exact_field(evidence, "pole_squared", "evidence");
      if (q <= 0) throw InputError("evidence.pole_squared: w0^2 > 0 (the pole s = j sqrt(w0^2); s = 0 is pole = 0)");
      at = "s = j sqrt(" + q.str() + ")";
    }
    const std::string why = residue_fails(op->is_ss ? ss_transfer(*op) : op->Z, q, at);
    if (why.empty())
      return {false, "operator '" + name + "' not passive not shown: Z has at most a simple pole at " + at +
                         ", with a Hermitian positive semidefinite residue"};
    return {true, "operator '" + name + "' is not passive (positive real): " + why + ", exactly (Assumption 1(b) fails)"};
  }
  const rational w = detail::exact_field(evidence, "w", "evidence");
  const size_t q = op->is_ss ? op->D.size() : op->Z.size();
  if (!evidence.contains("minor") || !evidence.at("minor").is_array() || evidence.at("minor").empty())
    throw InputError("evidence.minor: missing, not an array or empty");
  std::vector<size_t> rows;
  for (const auto& r : evidence.at("minor")) {
    if (!r.is_number_integer() || r.get<long long>() < 0 || r.get<long long>() >= static_cast<long long>(q))
      throw InputError("evidence.minor: each row an integer in [0, " + std::to_string(q) + ")");
    const size_t i = static_cast<size_t>(r.get<long long>());
    if (!rows.empty() && i <= rows.back()) throw InputError("evidence.minor: rows not increasing");
    rows.push_back(i);
  }
  std::vector<std::vector<Cq>> Z(q, std::vector<Cq>(q));
  if (op->is_ss) {  // C (jwI - A)^-1 B + D as written
    const auto z = ss_at_jw(*op, w);
    if (!z) return {false, "Z(s) of '" + name + "' (ss) has jwI - A singular at w = " + w.str() + ": He Z(jw) is not defined there"};
    Z = *z;
  } else {
    for (size_t i = 0; i < q; ++i)
      for (size_t j = 0; j < q; ++j) {
        const Cq d = at_jw(op->Z[i][j].den(), w);
        if (d.is_zero())
          return {false, "Z(s) of '" + name + "' has a pole at s = jw, w = " + w.str() + ": He Z(jw) is not defined there"};
        Z[i][j] = at_jw(op->Z[i][j].num(), w) / d;
      }
  }
  std::vector<std::vector<Cq>> H(rows.size(), std::vector<Cq>(rows.size()));
  for (size_t a = 0; a < rows.size(); ++a)
    for (size_t b = 0; b < rows.size(); ++b) {
      const Cq h = Z[rows[a]][rows[b]] + conj(Z[rows[b]][rows[a]]);
      H[a][b] = Cq(h.re / 2, h.im / 2);
    }
  const Cq m = det(H);
  if (!m.im.is_zero()) throw NumericalError("a principal minor of a Hermitian matrix is not real (a checker defect)");
  std::string which;
  for (size_t i : rows) which += (which.empty() ? "" : ",") + std::to_string(i + 1);
  if (m.re >= 0)
    return {false, "operator '" + name + "' not passive not shown: the principal minor {" + which + "} of He Z(jw) at w = " + w.str() +
                       " is " + detail::decimal(m.re) + " >= 0"};
  return {true, "operator '" + name + "' is not passive (positive real): the principal minor {" + which + "} of He Z(jw) at w = " +
                    w.str() + " is " + detail::decimal(m.re) + " < 0, exactly (Assumption 1(b) fails)"};
}

}  // namespace hapstab::check
