// hapstab/check/multidof_coupling_symmetric_check.cpp -- see multidof_coupling_symmetric_check.hpp.
#include "hapstab/check/multidof_coupling_symmetric_check.hpp"

#include <string>
#include <vector>

#include "hapstab/check/multidof_coupling_check.hpp"
#include "hapstab/check/multidof_feasible_check.hpp"
#include "hapstab/check/multidof_model.hpp"
#include "hapstab/check/multidof_symmetric_check.hpp"
#include "hapstab/check/rational_matrix.hpp"
#include "hapstab/numeric/error.hpp"

namespace hapstab::check {

namespace {

using namespace detail;
using namespace multidof_model;
using namespace rational_matrix;

// evidence[key]: one "p/q" per class
std::vector<rational> per_class(const nlohmann::json& ev, const char* key, size_t r) {
  if (!ev.contains(key) || !ev.at(key).is_array() || ev.at(key).size() != r)
    throw InputError(std::string("evidence.") + key + ": must be an array of " + std::to_string(r) + " \"p/q\" strings (one per class)");
  std::vector<rational> v;
  for (size_t c = 0; c < r; ++c) v.push_back(exact_string(ev.at(key).at(c), std::string("evidence.") + key + "[" + std::to_string(c) + "]"));
  return v;
}

Mat sized(const nlohmann::json& obj, const char* key, const std::string& where, size_t rows, size_t cols) {
  Mat M = exact_matrix(obj, key, where, 160);
  if (M.size() != rows || (rows > 0 && M[0].size() != cols))
    throw InputError(where + "." + key + ": must be " + std::to_string(rows) + " x " + std::to_string(cols));
  return M;
}

}  // namespace

Verdict check_multidof_coupling_symmetric(const nlohmann::json& cert) {
  const Parts p = certificate_parts(cert);
  if (!exact_boolean_claim(p, "theorem4", {"T", "delay", "environment", "set", "devices", "operators", "coupling_blocks"},
                           {"classes", "g", "q_E", "q_V", "fixed", "zero_sum", "P_V"}))
    return {false, "the claim is that V misses Theorem 4's conditions; points prove only that it meets them"};
  const SplitModel sm = read_split_model(p);
  const auto& classes = sm.classes;
  const auto& delta = sm.delta;
  const size_t m = sm.env.E.size(), r = classes.size();
  const SplitMultipliers w{per_class(p.evidence, "g", r), per_class(p.evidence, "q_E", r), per_class(p.evidence, "q_V", r)};
  for (size_t c = 0; c < r; ++c) {
    if (w.g[c] < 1) return {false, "g of class " + std::to_string(c) + " is " + decimal(w.g[c]) + " < 1 ((9))"};
    if (w.qv[c] <= 0) return {false, "q_V of class " + std::to_string(c) + " is " + decimal(w.qv[c]) + " <= 0 (Q_V > 0)"};
  }
  // the environment side: (16) of the whole at X = diag(g), Q_E = diag(q_E), Q_V = diag(q_V), by the split
  std::string said;
  size_t blocks = 0;
  if (const std::string why = split_16_fails(p, sm.env, delta, classes, &w, said, blocks); !why.empty())
    return {false, "(16) by the split: " + why};
  // the coupling side: Lemma 1 for each DOF's V-hat_i at (g, q_V) of its class
  std::vector<size_t> cls(m);
  for (size_t c = 0; c < r; ++c)
    for (size_t i : classes[c]) cls[i] = c;
  if (!p.model.contains("coupling_blocks") || !p.model.at("coupling_blocks").is_array() || p.model.at("coupling_blocks").size() != m)
    throw InputError("model.coupling_blocks: must be one {A, B, C, D} per DOF (" + std::to_string(m) + ")");
  if (!p.evidence.contains("P_V") || !p.evidence.at("P_V").is_array() || p.evidence.at("P_V").size() != m)
    throw InputError("evidence.P_V: must be one storage per DOF block (" + std::to_string(m) + ")");
  const nlohmann::json& Vb = p.model.at("coupling_blocks");
  size_t states = 0;
  for (size_t i = 0; i < m; ++i) {
    const std::string where = "model.coupling_blocks[" + std::to_string(i) + "]";
    const nlohmann::json& b = Vb.at(i);
    if (!b.is_object()) throw InputError(where + ": not an object");
    only_fields(b, {"A", "B", "C", "D"}, where);
    const Mat A = exact_matrix(b, "A", where, 159);
    const size_t n = A.size();
    if (n > 0 && A[0].size() != n) throw InputError(where + ".A: must be square");
    const Mat B = sized(b, "B", where, n, 1), C = sized(b, "C", where, 1, n), D = sized(b, "D", where, 1, 1);
    nlohmann::json holder = {{"P_V", p.evidence.at("P_V").at(i)}};
    const std::string pw = "evidence.P_V[" + std::to_string(i) + "]";
    const Mat PV = exact_matrix(holder, "P_V", "evidence.P_V[" + std::to_string(i) + "]", 160);
    const Mat X = {{w.g[cls[i]]}}, QV = {{w.qv[cls[i]]}};
    if (const std::string why = vhat_lemma1_fails(A, B, C, D, {delta[i]}, sm.pd.T, X, QV, PV, pw); !why.empty())
      return {false, "DOF " + std::to_string(i) + "'s block of V: " + why};
    states += n;
  }
  return {true, "V meets Theorem 4's conditions: (16) by the symmetry of " + std::to_string(r) + " classes (" +
                    std::to_string(m * m) + " entries of E compared exactly; " + said +
                    "; each block's X, Q_E, Q_V a positive multiple of the image of the whole's diagonal (g, q_E, q_V), g >= 1) "
                    "and Lemma 1 for V-hat block by block (" + std::to_string(m) + " blocks of V, " + std::to_string(states) +
                    " states, at (g, q_V) of each block's class: P_V,i > 0, F_i <= 0), exactly"};
}

}  // namespace hapstab::check
