// hapstab/check/multidof_witness_check.cpp -- see multidof_witness_check.hpp.
#include "hapstab/check/multidof_witness_check.hpp"

#include <algorithm>
#include <optional>
#include <string>
#include <vector>

#include "hapstab/check/multidof_model.hpp"
#include "hapstab/numeric/error.hpp"

namespace hapstab::check {

namespace {

using namespace detail;
using namespace multidof_model;

struct WitnessPoint {
  Cq z;
  std::vector<Cq> u;
  rational w = 1;
};

std::vector<Cq> direction(const nlohmann::json& pt, size_t m, const std::string& where) {
  if (!pt.contains("u") || !pt.at("u").is_array() || pt.at("u").size() != m)
    throw InputError(where + ".u: must be an array of " + std::to_string(m) + " \"p/q\" strings (one per DOF)");
  const bool im = pt.contains("u_im");
  if (im && (!pt.at("u_im").is_array() || pt.at("u_im").size() != m))
    throw InputError(where + ".u_im: must be an array of " + std::to_string(m) + " \"p/q\" strings");
  std::vector<Cq> u;
  for (size_t i = 0; i < m; ++i)
    u.emplace_back(exact_string(pt.at("u").at(i), where + ".u[" + std::to_string(i) + "]"),
                   im ? exact_string(pt.at("u_im").at(i), where + ".u_im[" + std::to_string(i) + "]") : rational(0));
  return u;
}

// evidence {z_re, z_im, u[, u_im]} or {points: [{z_re, z_im, u[, u_im], weight}, ...]}
std::vector<WitnessPoint> witness_points(const nlohmann::json& ev, size_t m) {
  if (!ev.contains("points")) {
    only_fields(ev, {"z_re", "z_im", "u", "u_im"}, "evidence");
    return {{Cq(exact_field(ev, "z_re", "evidence"), exact_field(ev, "z_im", "evidence")), direction(ev, m, "evidence")}};
  }
  only_fields(ev, {"points"}, "evidence");
  const auto& pts = ev.at("points");
  if (!pts.is_array() || pts.empty() || pts.size() > 4096)
    throw InputError("evidence.points: must be an array of 1 to 4096 points");
  std::vector<WitnessPoint> out;
  for (size_t k = 0; k < pts.size(); ++k) {
    const std::string where = "evidence.points[" + std::to_string(k) + "]";
    if (!pts.at(k).is_object()) throw InputError(where + ": not an object");
    only_fields(pts.at(k), {"z_re", "z_im", "u", "u_im", "weight"}, where);
    out.push_back({Cq(exact_field(pts.at(k), "z_re", where), exact_field(pts.at(k), "z_im", where)),
                   direction(pts.at(k), m, where), exact_field(pts.at(k), "weight", where)});
  }
  return out;
}

}  // namespace

Verdict check_multidof_witness(const nlohmann::json& cert) {
  const Parts p = certificate_parts(cert);
  if (auto refuted = infeasibility_claim(p, "a witness")) return {false, *refuted};
  const PeriodDelay pd = read_period_delay(p.model);
  const Environment env = read_environment(p.model, pd.T, pd.n);
  const size_t m = env.E.size();
  const std::vector<rational> delta = device_levels(p.model, m);
  const std::vector<size_t> owner = operator_of(p.model, m);
  // (a): E(1) finite; the admissible X: g_o E(1)_ij = g_o' E(1)_ji (i in operator o, j in o'), so
  // along each entry coupling two operators g_o' = g_o E(1)_ij / E(1)_ji, a positive ratio; each
  // connected group of operators has one direction X_c (ratio r_o on operator o's DOFs, relative
  // to the group's first operator), found by a search along the entries and checked consistent
  const auto at1 = environment_at(env, Cq(1));
  if (!at1)
    throw InputError("model.environment.E: an entry has a pole at z = 1 (E-hat would have a double pole there; this kind "
                     "needs E(1) finite)");
  const std::vector<std::vector<Cq>>& E1 = *at1;
  const size_t nops = 1 + *std::max_element(owner.begin(), owner.end());
  std::vector<std::optional<rational>> ratio(nops);
  std::vector<size_t> root(nops);
  const auto no_x = [](size_t i, size_t j, const std::string& why) {
    return InputError("model.environment.E: no X > 0 makes X E(1) symmetric (entries " + std::to_string(i) + "," +
                      std::to_string(j) + ": " + why + "): the facial conditions decide, not a witness");
  };
  for (size_t s0 = 0; s0 < nops; ++s0) {
    if (ratio[s0]) continue;
    ratio[s0] = rational(1);
    root[s0] = s0;
    std::vector<size_t> stack{s0};
    while (!stack.empty()) {
      const size_t o = stack.back();
      stack.pop_back();
      for (size_t i = 0; i < m; ++i) {
        if (owner[i] != o) continue;
        for (size_t j = 0; j < m; ++j) {
          const rational& a = E1[i][j].re;
          const rational& b = E1[j][i].re;
          if (a.is_zero() && b.is_zero()) continue;
          if (a.is_zero() || b.is_zero()) throw no_x(i, j, "one of the pair is 0");
          const size_t o2 = owner[j];
          const rational r = *ratio[o] * a / b;  // g_o2 = g_o a / b
          if (!(r > 0)) throw no_x(i, j, "opposite signs");
          if (!ratio[o2]) {
            ratio[o2] = r;
            root[o2] = s0;
            stack.push_back(o2);
          } else if (*ratio[o2] != r) {
            throw no_x(i, j, o2 == o ? "one operator's DOFs share g" : "the ratios around a cycle disagree");
          }
        }
      }
    }
  }
  // (b): the evidence, one point or several weighted ones; S_c = sum_j w_j phi_c(z_j, u_j)
  std::vector<rational> S(m);  // per group root
  std::vector<bool> is_root(m, false);
  const std::vector<WitnessPoint> points = witness_points(p.evidence, m);
  for (size_t k = 0; k < points.size(); ++k) {
    const WitnessPoint& pt = points[k];
    const std::string at = points.size() > 1 ? "point " + std::to_string(k) + ": " : "";
    const Cq& z = pt.z;
    if (z.re * z.re + z.im * z.im != 1) return {false, at + "z = " + decimal(z.re) + " + j " + decimal(z.im) + " is not on the unit circle"};
    if (z.re == 1) return {false, at + "z = 1: E-hat has its pole there"};
    if (std::all_of(pt.u.begin(), pt.u.end(), [](const Cq& x) { return x.is_zero(); }))
      return {false, at + "u = 0: the witness needs a direction u != 0"};
    if (pt.w < 0) return {false, at + "the weight " + decimal(pt.w) + " is negative"};
    // E-hat(z) u, row by row: T z/(z - 1) z^-n g sum_j E_ij(z) u_j  (z^-n = conj(z)^n on the circle)
    const Cq factor = ehat_factor(env, z);
    const auto Ez = environment_at(env, z);
    if (!Ez) return {false, at + "z = " + decimal(z.re) + " + j " + decimal(z.im) + " is a pole of an entry of E"};
    for (size_t i = 0; i < m; ++i) {
      Cq w;
      for (size_t j = 0; j < m; ++j)
        if (!pt.u[j].is_zero()) w = w + (*Ez)[i][j] * pt.u[j];
      const size_t c = root[owner[i]];
      is_root[c] = true;  // r_o (Re(conj(u_i) (E-hat u)_i) + delta_i |u_i|^2)
      const Cq& ui = pt.u[i];
      S[c] += pt.w * *ratio[owner[i]] * ((conj(ui) * factor * w).re + delta[i] * (ui.re * ui.re + ui.im * ui.im));
    }
  }
  size_t groups = 0, negative = 0;
  std::string worst;
  for (size_t c = 0; c < m; ++c) {
    if (!is_root[c]) continue;
    ++groups;
    if (S[c] > 0)
      return {false, "phi = " + decimal(S[c]) + " > 0 on the group of operator " + std::to_string(c) +
                         ": the witness does not hold for every admissible X"};
    if (S[c] < 0) {
      ++negative;
      worst = decimal(S[c]);
    }
  }
  if (negative == 0) return {false, "phi = 0 on every group of operators: no strict witness"};
  return {true, "(16) infeasible for every admissible X (" + std::to_string(groups) +
                    " direction(s): the groups of operators coupled through E(1)): " +
                    (points.size() > 1 ? "sum_j w_j phi(z_j, u_j)" : std::string("phi")) +
                    " = Re(u^H X E-hat(z) u) + u^H Delta_D X u <= 0 on each, < 0 on " + std::to_string(negative) + " (" +
                    worst + "), " +
                    (points.size() > 1 ? "at " + std::to_string(points.size()) + " points z_j of the unit circle, weights w_j >= 0"
                                       : "at z = " + decimal(points[0].z.re) + " + j " + decimal(points[0].z.im)) +
                    ", u != 0, exactly"};
}

}  // namespace hapstab::check
