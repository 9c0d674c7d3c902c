// hapstab/check/multidof_symmetric_check.cpp -- see multidof_symmetric_check.hpp.
#include "hapstab/check/multidof_symmetric_check.hpp"

#include <string>
#include <utility>
#include <vector>

#include "hapstab/check/multidof_feasible_check.hpp"
#include "hapstab/check/multidof_model.hpp"
#include "hapstab/numeric/error.hpp"

namespace hapstab::check {

namespace {

using namespace detail;
using namespace multidof_model;

// evidence.classes: a partition of 0..m-1 into non-empty arrays; InputError naming the field.
std::vector<std::vector<size_t>> read_classes(const nlohmann::json& ev, size_t m) {
  if (!ev.contains("classes") || !ev.at("classes").is_array() || ev.at("classes").empty())
    throw InputError("evidence.classes: missing or not a non-empty array");
  std::vector<bool> seen(m, false);
  std::vector<std::vector<size_t>> classes;
  for (size_t a = 0; a < ev.at("classes").size(); ++a) {
    const auto& c = ev.at("classes").at(a);
    const std::string where = "evidence.classes[" + std::to_string(a) + "]";
    if (!c.is_array() || c.empty()) throw InputError(where + ": a non-empty array of DOF indices");
    classes.emplace_back();
    for (const auto& v : c) {
      if (!v.is_number_integer() || (v.is_number_unsigned() ? v.get<unsigned long>() >= m : v.get<long>() < 0 || v.get<size_t>() >= m))
        throw InputError(where + ": a DOF index outside [0, " + std::to_string(m - 1) + "]");
      if (seen[v.get<size_t>()]) throw InputError(where + ": DOF " + std::to_string(v.get<long>()) + " is in two classes");
      seen[v.get<size_t>()] = true;
      classes.back().push_back(v.get<size_t>());
    }
  }
  for (size_t i = 0; i < m; ++i)
    if (!seen[i]) throw InputError("evidence.classes: DOF " + std::to_string(i) + " is in no class");
  return classes;
}

std::string entry(size_t i, size_t k) { return "E(" + std::to_string(i) + ", " + std::to_string(k) + ")"; }

// (h3): "" when E is invariant under the permutations within the classes, else the first entry that is not
std::string not_invariant(const Environment& env, const std::vector<std::vector<size_t>>& classes) {
  const size_t m = env.E.size();
  std::vector<size_t> cls(m);
  for (size_t a = 0; a < classes.size(); ++a)
    for (size_t i : classes[a]) cls[i] = a;
  for (size_t i = 0; i < m; ++i)
    for (size_t k = 0; k < m; ++k) {
      const auto &a = classes[cls[i]], &c = classes[cls[k]];
      const size_t ri = a[0], rk = i == k ? a[0] : cls[i] == cls[k] ? a[1] : c[0];
      if (!(env.E[i][k].H == env.E[ri][rk].H))
        return entry(i, k) + " is not " + entry(ri, rk) + " (" + env.E[i][k].to_string() + " against " +
               env.E[ri][rk].to_string() + ")";
    }
  return "";
}

// One block's point: "" when it holds, else why not. With `image` (the whole's invariant X, Q_E, Q_V
// on the block's DOFs, diagonal), the point's X, Q_E, Q_V must be one positive multiple of it.
std::string block_fails(const Environment& block, const std::vector<rational>& delta, const nlohmann::json& ev,
                        const std::string& where, const std::vector<std::vector<rational>>* image, std::string& said) {
  const size_t mb = block.E.size();
  std::vector<size_t> owner(mb);
  for (size_t i = 0; i < mb; ++i) owner[i] = i;  // (h1): one g per DOF of the block
  const FeasiblePoint pt = read_feasible_point(ev, where, mb);
  if (image) {  // (*image)[0..2][i]: the image's X, Q_E, Q_V at the block's DOF i
    const rational tau = pt.X[0][0] / (*image)[0][0];
    for (size_t i = 0; i < mb; ++i)
      for (size_t j = 0; j < mb; ++j) {
        const bool d = i == j;
        if (pt.X[i][j] != (d ? tau * (*image)[0][i] : rational(0)) || pt.QE[i][j] != (d ? tau * (*image)[1][i] : rational(0)) ||
            pt.QV[i][j] != (d ? tau * (*image)[2][i] : rational(0)) || tau <= 0)
          return "its X, Q_E, Q_V are not one positive multiple of the image of the whole's (g, q_E, q_V)";
      }
  }
  long points = 0;
  const std::string why = feasible_point_fails(block, delta, owner, pt, false, points);
  said += std::to_string(pt.A.size()) + " states, " + std::to_string(points) + " points";
  return why;
}

}  // namespace

namespace detail {

SplitModel read_split_model(const Parts& p) {
  WholeModel w = read_whole_model(p);  // every DOF in one operator
  const size_t m = w.env.E.size();
  return {w.pd, std::move(w.env), std::move(w.delta), read_classes(p.evidence, m)};
}

std::string split_16_fails(const Parts& p, const Environment& env, const std::vector<rational>& delta,
                           const std::vector<std::vector<size_t>>& classes, const SplitMultipliers* invariant,
                           std::string& said, size_t& blocks) {
  const size_t m = env.E.size();
  if (!env.perturb_C.empty())
    throw InputError("model.environment.perturb_C: outside this kind (the split needs E itself invariant; use multidof-feasible)");
  if (p.model.at("operators").size() != m)  // (h1)
    throw InputError("model.operators: an operator has two DOFs or more; this kind needs one-DOF operators (X = diag(g))");
  for (size_t a = 0; a < classes.size(); ++a)  // (h2)
    for (size_t i : classes[a])
      if (delta[i] != delta[classes[a][0]])
        return "class " + std::to_string(a) + " is not of alike DOFs: the OSP level of DOF " + std::to_string(i) + " is " +
               decimal(delta[i]) + ", DOF " + std::to_string(classes[a][0]) + "'s " + decimal(delta[classes[a][0]]);
  if (const std::string why = not_invariant(env, classes); !why.empty())  // (h3)
    return "E is not invariant under the permutations within the classes: " + why;
  // the fixed space's block: E_f(a, c) = sum over class c's DOFs j of E(a0, j), one DOF per class
  const size_t r = classes.size();
  Environment fixed = env;
  fixed.E.assign(r, {});
  std::vector<rational> delta_f(r);
  std::vector<std::vector<rational>> image_f(3, std::vector<rational>(r));  // S^T diag S on the indicators: k_c times
  for (size_t a = 0; a < r; ++a) {
    delta_f[a] = delta[classes[a][0]];
    if (invariant) {
      const rational k(static_cast<long>(classes[a].size()));
      image_f[0][a] = k * invariant->g[a], image_f[1][a] = k * invariant->qe[a], image_f[2][a] = k * invariant->qv[a];
    }
    for (size_t c = 0; c < r; ++c) {
      TransferFunction s = env.E[classes[a][0]][classes[c][0]];
      for (size_t j = 1; j < classes[c].size(); ++j) s = parallel(s, env.E[classes[a][0]][classes[c][j]]);
      fixed.E[a].push_back(s);
    }
  }
  said = "the fixed space (" + std::to_string(r) + " DOF: ";
  if (!p.evidence.contains("fixed") || !p.evidence.at("fixed").is_object())
    throw InputError("evidence.fixed: missing or not an object");
  if (const std::string why = block_fails(fixed, delta_f, p.evidence.at("fixed"), "evidence.fixed", invariant ? &image_f : nullptr, said);
      !why.empty())
    return "the fixed space's block: " + why;
  said += ")";
  // one zero-sum block per class of two DOFs or more: e_a = E(a0, a0) - E(a0, a1)
  if (!p.evidence.contains("zero_sum") || !p.evidence.at("zero_sum").is_array())
    throw InputError("evidence.zero_sum: missing or not an array");
  const auto& zs = p.evidence.at("zero_sum");
  size_t next = 0, copies = 0;
  for (size_t a = 0; a < r; ++a) {
    if (classes[a].size() < 2) continue;
    const std::string where = "evidence.zero_sum[" + std::to_string(next) + "]";
    if (next >= zs.size()) throw InputError("evidence.zero_sum: no block for class " + std::to_string(a) + " (" +
                                            std::to_string(classes[a].size()) + " DOFs)");
    const auto& b = zs.at(next++);
    if (!b.is_object()) throw InputError(where + ": not an object");
    only_fields(b, {"class", "point"}, where);
    if (integer_field(b, "class", where, 0, static_cast<long>(r) - 1) != static_cast<long>(a))
      throw InputError(where + ".class: must be " + std::to_string(a) + " (the classes of two DOFs or more, in order)");
    const size_t a0 = classes[a][0], a1 = classes[a][1];
    TransferFunction minus = env.E[a0][a1];
    minus.H = -minus.H;
    Environment e = env;
    e.E = {{parallel(env.E[a0][a0], minus)}};
    std::vector<std::vector<rational>> image_a;  // the Helmert vectors' image: j (j + 1) times, any multiple
    if (invariant) image_a = {{invariant->g[a]}, {invariant->qe[a]}, {invariant->qv[a]}};
    said += "; class " + std::to_string(a) + "'s zero-sum space (" + std::to_string(classes[a].size() - 1) + " copies: ";
    if (const std::string why = block_fails(e, {delta[a0]}, object_field(b, "point", where), where + ".point",
                                            invariant ? &image_a : nullptr, said);
        !why.empty())
      return "class " + std::to_string(a) + "'s zero-sum block: " + why;
    said += ")";
    copies += classes[a].size() - 1;
  }
  if (next != zs.size()) throw InputError("evidence.zero_sum: " + std::to_string(zs.size() - next) + " block(s) beyond the classes of two DOFs or more");
  blocks = r + copies;
  return "";
}

}  // namespace detail

Verdict check_multidof_feasible_symmetric(const nlohmann::json& cert) {
  const Parts p = certificate_parts(cert);
  if (!exact_boolean_claim(p, "feasible", {"T", "delay", "environment", "set", "devices", "operators"}, {"classes", "fixed", "zero_sum"}))
    return {false, "the claim is that (16) is infeasible; points prove only feasibility"};
  const SplitModel sm = read_split_model(p);
  const auto& classes = sm.classes;
  const size_t m = sm.env.E.size();
  std::string said;
  size_t blocks = 0;
  if (const std::string why = split_16_fails(p, sm.env, sm.delta, classes, nullptr, said, blocks); !why.empty()) return {false, why};
  return {true, "(16) feasible by the symmetry of " + std::to_string(classes.size()) + " classes of alike DOFs (E invariant under the "
                "permutations within them: " + std::to_string(m * m) + " entries compared exactly; the levels equal and the "
                "operators one-DOF): " + said + "; each block's realisation is its E-hat and its point holds (16) with g > 0, "
                "exactly, so the lifted point holds the whole's (16) with g >= 1 (" + std::to_string(blocks) + " blocks)"};
}

}  // namespace hapstab::check
