#include "hapstab/multidof/witness_json.hpp"

#include "hapstab/numeric/scalar.hpp"

namespace hapstab::multidof {

namespace {

using nlohmann::json;

json strings(const std::vector<rational>& v) {
  json a = json::array();
  for (const auto& x : v) a.push_back(x.str());
  return a;
}

json complex_vector(const ComplexVectorQ& v) { return {{"re", strings(v.re)}, {"im", strings(v.im)}}; }

json directions(const std::vector<std::vector<rational>>& d) {
  json a = json::array();
  for (const auto& x : d) a.push_back(strings(x));
  return a;
}

json doubles(const std::vector<rational>& v) {
  json a = json::array();
  for (const auto& x : v) a.push_back(to_real<double>(x));
  return a;
}

bool all_nonpositive(const std::vector<rational>& v) {
  for (const auto& x : v)
    if (x > 0) return false;
  return !v.empty();
}

}  // namespace

json frequency_witness_json(const std::optional<FrequencyWitness>& w) {
  if (!w) return nullptr;
  return {{"theta", w->theta}, {"z", {w->z_re.str(), w->z_im.str()}}, {"u", strings(w->u)},
          {"phi", to_real<double>(w->phi)}, {"phi_negative", w->phi < 0},
          {"form", "phi = Re(u^T X E-hat(z) u) + u^T Delta_D X u <= 0, X the facial direction X_1 (exact)"}};
}

json coupling_witness_json(const std::optional<CouplingWitness>& w) {
  if (!w) return nullptr;
  return {{"theta1", w->theta1},
          {"theta2", w->theta2},
          {"z1", {w->z1_re.str(), w->z1_im.str()}},
          {"z2", {w->z2_re.str(), w->z2_im.str()}},
          {"p", complex_vector(w->p)},
          {"u", complex_vector(w->u)},
          {"directions", directions(w->directions)},
          {"phi", strings(w->phi)},
          {"phi_numeric", doubles(w->phi)},
          {"phi_nonpositive", all_nonpositive(w->phi)},
          {"form", "phi_k = p^* Delta_D X_k p + Re(u^* X_k V-hat(z2) u) + Re(w^* X_k E-hat(z1) w) <= 0, "
                   "w = p + V-hat(z2) u, [p; V-hat(z2) u] != 0, for each facial direction X_k = diag(directions[k]) (exact)"}};
}

json weighted_witness_json(const std::optional<WeightedWitness>& w) {
  if (!w) return nullptr;
  json pts = json::array();
  for (const auto& p : w->points)
    pts.push_back({{"theta", p.theta}, {"z", {p.z_re.str(), p.z_im.str()}}, {"u", complex_vector(p.u)}, {"weight", p.weight.str()}});
  return {{"points", pts},
          {"directions", directions(w->directions)},
          {"sums", strings(w->sums)},
          {"sums_numeric", doubles(w->sums)},
          {"sums_nonpositive", all_nonpositive(w->sums)},
          {"form", "sum_j weight_j (Re(u_j^* X_k E-hat(z_j) u_j) + u_j^* Delta_D X_k u_j) <= 0 for each facial direction "
                   "X_k = diag(directions[k]), weights >= 0 not all 0, u_j != 0 (exact)"}};
}

}  // namespace hapstab::multidof
