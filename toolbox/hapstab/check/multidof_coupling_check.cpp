// hapstab/check/multidof_coupling_check.cpp -- see multidof_coupling_check.hpp.
#include "hapstab/check/multidof_coupling_check.hpp"

#include <string>
#include <vector>

#include "hapstab/check/multidof_feasible_check.hpp"
#include "hapstab/check/multidof_model.hpp"
#include "hapstab/check/rational_matrix.hpp"
#include "hapstab/numeric/error.hpp"

namespace hapstab::check {

namespace {

using namespace detail;
using namespace multidof_model;
using namespace rational_matrix;

constexpr size_t max_vhat_order = 160;

Mat coupling_matrix(const nlohmann::json& V, const char* key, size_t rows, size_t cols) {
  Mat M = exact_matrix(V, key, "model.coupling", max_vhat_order);
  if (M.size() != rows || (rows > 0 && M[0].size() != cols))
    throw InputError(std::string("model.coupling.") + key + ": must be " + std::to_string(rows) + " x " + std::to_string(cols));
  return M;
}

}  // namespace

namespace detail {

std::string vhat_lemma1_fails(const Mat& AV, const Mat& BV, const Mat& CV, const Mat& DV, const std::vector<rational>& delta,
                              const rational& T, const Mat& X, const Mat& QV, const Mat& PV, const std::string& where) {
  const size_t nv = AV.size(), m = DV.size();
  // V-hat (17) with Gamma = I, K = (T/2) Delta_D^-1 (12)
  for (size_t i = 0; i < m; ++i)
    if (delta[i] <= 0)
      throw InputError("model.devices: DOF " + std::to_string(i) + "'s level is " + decimal(delta[i]) +
                       " <= 0: K = (T/2) Delta_D^-1 (12) is not defined");
  const size_t n = nv + m;
  Mat A = zeros(n, n), B = zeros(n, m), C = zeros(m, n), D = zeros(m, m);
  for (size_t i = 0; i < nv; ++i) {
    for (size_t j = 0; j < nv; ++j) A[i][j] = AV[i][j];
    for (size_t j = 0; j < m; ++j) {
      A[i][nv + j] = -BV[i][j] / T;
      B[i][j] = BV[i][j] / T;
    }
  }
  for (size_t i = 0; i < m; ++i) {
    B[nv + i][i] = 1;
    for (size_t j = 0; j < nv; ++j) C[i][j] = CV[i][j];
    for (size_t j = 0; j < m; ++j) {
      const rational K = i == j ? T / (2 * delta[i]) : rational(0);
      C[i][nv + j] = (K - DV[i][j]) / T;
      D[i][j] = (DV[i][j] - K) / T;
    }
  }
  if (PV.size() != n || PV[0].size() != n)
    throw InputError(where + ": must be " + std::to_string(n) + " x " + std::to_string(n) + " (V-hat's order nV + m)");
  if (!symmetric(PV)) return "P_V is not symmetric";
  if (!positive_definite(PV, true)) return "P_V > 0 fails";
  // Lemma 1 at X and Q_V: F <= 0
  const Mat negF = add(zeros(n + m, n + m), lemma1_matrix(A, B, C, D, PV, X, QV), -1);
  if (!positive_definite(negF, false)) return "Lemma 1 for V-hat at X and Q_V: F <= 0 fails";
  return "";
}

}  // namespace detail

Verdict check_multidof_coupling(const nlohmann::json& cert) {
  const Parts p = certificate_parts(cert);
  if (!exact_boolean_claim(p, "theorem4", {"T", "delay", "environment", "set", "devices", "operators", "coupling"},
                           {"A", "B", "C", "D", "P", "X", "Q_E", "Q_V", "P_V"}))
    return {false, "the claim is that V misses Theorem 4's conditions; a point proves only that it meets them"};
  const WholeModel w = read_whole_model(p);
  const size_t m = w.env.E.size();
  // V as written in the model
  const nlohmann::json& V = object_field(p.model, "coupling", "model");
  only_fields(V, {"A", "B", "C", "D"}, "model.coupling");
  const Mat AV = exact_matrix(V, "A", "model.coupling", max_vhat_order);
  const size_t nv = AV.size();
  if (nv > 0 && AV[0].size() != nv) throw InputError("model.coupling.A: must be square");
  if (nv + m > max_vhat_order) throw InputError("model.coupling.A: V-hat's order " + std::to_string(nv + m) + " is beyond this checker's limit");
  const Mat BV = coupling_matrix(V, "B", nv, m), CV = coupling_matrix(V, "C", m, nv), DV = coupling_matrix(V, "D", m, m);
  // the environment side: (16) at the point
  nlohmann::json ev = p.evidence;
  ev.erase("P_V");
  const FeasiblePoint pt = read_feasible_point(ev, "evidence", m);
  long points = 0;
  if (const std::string why = feasible_point_fails(w.env, w.delta, w.owner, pt, true, points); !why.empty())
    return {false, "(16) at the evidence's point: " + why};
  const Mat PV = exact_matrix(p.evidence, "P_V", "evidence", max_vhat_order);
  if (const std::string why = vhat_lemma1_fails(AV, BV, CV, DV, w.delta, w.pd.T, pt.X, pt.QV, PV, "evidence.P_V"); !why.empty())
    return {false, why};
  return {true, "V meets Theorem 4's conditions: (16) holds at the point ((A, B, C, D) realises the model's E-hat, " +
                    std::to_string(pt.A.size()) + " states, equal at " + std::to_string(points) +
                    " points; P > 0, M1 <= 0, (14) > 0, Q_V > 0, X = diag(g) in G with g >= 1) and V-hat (17), built from the "
                    "model's V (" + std::to_string(nv) + " states) with K = (T/2) Delta_D^-1, is Gamma^-1 Q_V Gamma^-1-OSP by "
                    "Lemma 1 (P_V > 0, F <= 0), exactly"};
}

}  // namespace hapstab::check
