// hapstab/check/multidof_feasible_check.cpp -- see multidof_feasible_check.hpp.
#include "hapstab/check/multidof_feasible_check.hpp"

#include "hapstab/check/gaussian_rational.hpp"

#include <algorithm>
#include <string>
#include <vector>

#include "hapstab/check/multidof_model.hpp"
#include "hapstab/check/rational_matrix.hpp"
#include "hapstab/numeric/error.hpp"

namespace hapstab::check {

namespace {

using namespace detail;
using namespace multidof_model;
using namespace rational_matrix;

constexpr size_t max_order = 160;  // N + m

// (zI - A)^-1 B, exactly (z rational); nullopt when singular
std::optional<Mat> resolvent_times(const Mat& A, const Mat& B, const rational& z) {
  const size_t n = A.size();
  Mat M = zeros(n, n);
  for (size_t i = 0; i < n; ++i)
    for (size_t j = 0; j < n; ++j) M[i][j] = (i == j ? z : rational(0)) - A[i][j];
  return solve_exact(std::move(M), B);
}

Mat sized(const nlohmann::json& ev, const std::string& where, const char* key, size_t rows, size_t cols) {
  Mat M = exact_matrix(ev, key, where, max_order);
  if (M.size() != rows || (rows > 0 && M[0].size() != cols))
    throw InputError(where + "." + key + ": must be " + std::to_string(rows) + " x " + std::to_string(cols));
  return M;
}

// (r): C (zI - A)^-1 B + D = T z/(z - 1) z^-n g E(z) as rational functions, "" or what differs
std::string realises(const Environment& env, const Mat& A, const Mat& B, const Mat& C, const Mat& D, long& need) {
  const size_t N = A.size(), m = env.E.size();
  need = static_cast<long>(N) + env.n + environment_degree(env) + 2;
  long agreed = 0;
  for (long k = 2; agreed < need && k < 2 + 4 * need + 64; ++k) {
    const rational z(k);
    const auto Y = resolvent_times(A, B, z);
    if (!Y) continue;
    const Mat G = add(mul(C, *Y), D);
    rational zn = 1;
    for (long i = 0; i < env.n; ++i) zn *= z;
    const rational factor = env.T * env.gain * z / (z - 1) / zn;
    const auto e = environment_at(env, Cq(z));
    if (!e) continue;
    for (size_t i = 0; i < m; ++i)
      for (size_t j = 0; j < m; ++j)
        if (G[i][j] != factor * (*e)[i][j].re)
          return "at z = " + std::to_string(k) + " entry (" + std::to_string(i) + ", " + std::to_string(j) + ") of C (zI - A)^-1 B + D is " +
                 decimal(G[i][j]) + ", the model's E-hat " + decimal(factor * (*e)[i][j].re);
    agreed += 1;
  }
  return agreed >= need ? "" : "too few points where both sides are defined";
}

}  // namespace

namespace detail {

FeasiblePoint read_feasible_point(const nlohmann::json& ev, const std::string& where, size_t m) {
  only_fields(ev, {"A", "B", "C", "D", "P", "X", "Q_E", "Q_V"}, where);
  FeasiblePoint pt;
  pt.A = exact_matrix(ev, "A", where, max_order);
  const size_t N = pt.A.size();
  if (N + m > max_order)
    throw InputError(where + ".A: order " + std::to_string(N) + " with m = " + std::to_string(m) + " is beyond this checker's limit");
  if (N > 0 && pt.A[0].size() != N) throw InputError(where + ".A: must be square");
  pt.B = sized(ev, where, "B", N, m);
  pt.C = sized(ev, where, "C", m, N);
  pt.D = sized(ev, where, "D", m, m);
  pt.P = sized(ev, where, "P", N, N);
  pt.X = sized(ev, where, "X", m, m);
  pt.QE = sized(ev, where, "Q_E", m, m);
  pt.QV = sized(ev, where, "Q_V", m, m);
  return pt;
}

std::string feasible_point_fails(const Environment& env, const std::vector<rational>& delta, const std::vector<size_t>& owner,
                                 const FeasiblePoint& pt, bool g_at_least_one, long& points) {
  const size_t m = env.E.size(), N = pt.A.size();
  const Mat &A = pt.A, &B = pt.B, &C = pt.C, &D = pt.D, &P = pt.P, &X = pt.X, &QE = pt.QE, &QV = pt.QV;
  if (const std::string why = realises(env, A, B, C, D, points); !why.empty())
    return "(A, B, C, D) does not realise the model's E-hat = T z/(z - 1) z^-n g E(z): " + why;
  // X in G: diagonal, one g per operator, g >= 1 (9) (or g > 0: a block of the split, which the lift scales)
  for (size_t i = 0; i < m; ++i)
    for (size_t j = 0; j < m; ++j) {
      if (i != j && !X[i][j].is_zero()) return "X is not diagonal";
      if (owner[i] == owner[j] && X[i][i] != X[j][j]) return "X is not g I on the DOFs of one operator";
    }
  for (size_t i = 0; i < m; ++i) {
    if (g_at_least_one && X[i][i] < 1) return "g_" + std::to_string(i) + " = " + decimal(X[i][i]) + " < 1 ((9))";
    if (X[i][i] <= 0) return "g_" + std::to_string(i) + " = " + decimal(X[i][i]) + " <= 0";
  }
  if (!symmetric(P) || !symmetric(QE) || !symmetric(QV)) return "P, Q_E or Q_V is not symmetric";
  if (!positive_definite(P, true)) return "P > 0 fails";
  // -M1 >= 0
  const Mat At = transpose(A), AtP = mul(At, P);
  const Mat M11 = add(mul(AtP, A), P, -1);
  const Mat M12 = add(mul(AtP, B), mul(transpose(C), X), rational(-1, 2));
  const Mat XD = mul(X, D);
  Mat M22 = add(mul(mul(transpose(B), P), B), QE, -1);
  M22 = add(M22, add(XD, transpose(XD)), rational(-1, 2));
  Mat negM1 = zeros(N + m, N + m);
  for (size_t i = 0; i < N + m; ++i)
    for (size_t j = 0; j < N + m; ++j)
      negM1[i][j] = -(i < N ? (j < N ? M11[i][j] : M12[i][j - N]) : (j < N ? M12[j][i - N] : M22[i - N][j - N]));
  if (!positive_definite(negM1, false)) return "(16)'s first LMI M1 <= 0 fails";
  // (14): [[Delta_D X - Q_E, -Q_E], [-Q_E, Q_V - Q_E]] > 0
  Mat S = zeros(2 * m, 2 * m);
  for (size_t i = 0; i < m; ++i)
    for (size_t j = 0; j < m; ++j) {
      S[i][j] = (i == j ? delta[i] * X[i][i] : rational(0)) - QE[i][j];
      S[i][m + j] = S[m + i][j] = -QE[i][j];
      S[m + i][m + j] = QV[i][j] - QE[i][j];
    }
  if (!positive_definite(S, true)) return "(14) > 0 fails";
  if (!positive_definite(QV, true)) return "Q_V > 0 fails";
  return "";
}

WholeModel read_whole_model(const Parts& p) {
  WholeModel w;
  w.pd = read_period_delay(p.model);
  w.env = read_environment(p.model, w.pd.T, w.pd.n);
  w.delta = device_levels(p.model, w.env.E.size());
  w.owner = operator_of(p.model, w.env.E.size());
  return w;
}

bool exact_boolean_claim(const Parts& p, const std::string& key, std::initializer_list<const char*> model_fields,
                         std::initializer_list<const char*> evidence_fields) {
  only_fields(p.model, model_fields, "model");
  only_fields(p.claim, {"status", key.c_str()}, "claim");
  only_fields(p.evidence, evidence_fields, "evidence");
  if (!p.claim.contains("status") || p.claim.at("status") != "exact") throw InputError("claim.status: must be \"exact\"");
  if (!p.claim.contains(key) || !p.claim.at(key).is_boolean()) throw InputError("claim." + key + ": missing or not a boolean");
  return p.claim.at(key).get<bool>();
}

}  // namespace detail

Verdict check_multidof_feasible(const nlohmann::json& cert) {
  const Parts p = certificate_parts(cert);
  if (!exact_boolean_claim(p, "feasible", {"T", "delay", "environment", "set", "devices", "operators"},
                           {"A", "B", "C", "D", "P", "X", "Q_E", "Q_V"}))
    return {false, "the claim is that (16) is infeasible; a point proves only feasibility"};
  const WholeModel w = read_whole_model(p);
  const FeasiblePoint pt = read_feasible_point(p.evidence, "evidence", w.env.E.size());
  long points = 0;
  if (const std::string why = feasible_point_fails(w.env, w.delta, w.owner, pt, true, points); !why.empty()) return {false, why};
  return {true, "(16) feasible: (A, B, C, D) realises the model's E-hat (" + std::to_string(pt.A.size()) +
                    " states; equal at " + std::to_string(points) +
                    " points, more than the degree of their difference), P > 0, M1 <= 0, (14) > 0, "
                    "Q_V > 0 and X = diag(g) in G with g >= 1, exactly"};
}

}  // namespace hapstab::check
