// hapstab/check/multidof_witness_check.cpp -- see multidof_witness_check.hpp.
#include "hapstab/check/multidof_witness_check.hpp"

#include <numeric>
#include <string>
#include <vector>

#include "hapstab/check/gaussian_rational.hpp"
#include "hapstab/lti/parse.hpp"
#include "hapstab/numeric/error.hpp"

namespace hapstab::check {

namespace {

using namespace detail;
using P = Polynomial<rational>;

constexpr size_t max_dofs = 512;

struct Environment {
  char var = 'z';
  bool tustin = false;
  rational T, gain;
  long n = 0;
  std::vector<std::vector<TransferFunction>> E;  // m x m, as written
};

Environment read_environment(const nlohmann::json& model, const rational& T, long n) {
  const nlohmann::json& env = object_field(model, "environment", "model");
  only_fields(env, {"domain", "method", "gain", "E"}, "model.environment");
  Environment e;
  e.T = T;
  e.n = n;
  const std::string domain = env.value("domain", std::string());
  if (domain != "z" && domain != "s") throw InputError("model.environment.domain: must be \"z\" or \"s\"");
  e.var = domain[0];
  if (e.var == 's') {
    const std::string method = env.value("method", std::string());
    if (method != "backward_euler" && method != "tustin")
      throw InputError("model.environment.method: must be \"backward_euler\" or \"tustin\" for domain \"s\"");
    e.tustin = method == "tustin";
  } else if (env.contains("method")) {
    throw InputError("model.environment.method: only with domain \"s\"");
  }
  e.gain = exact_field(env, "gain", "model.environment");
  if (!env.contains("E") || !env.at("E").is_array() || env.at("E").empty() || env.at("E").size() > max_dofs)
    throw InputError("model.environment.E: must be an m x m array of expression strings, 1 <= m <= " +
                     std::to_string(max_dofs));
  const size_t m = env.at("E").size();
  ParseOptions po;
  po.variable = e.var;
  po.T = T;
  po.parameters = model_parameters(model);
  for (size_t i = 0; i < m; ++i) {
    const auto& row = env.at("E").at(i);
    if (!row.is_array() || row.size() != m)
      throw InputError("model.environment.E[" + std::to_string(i) + "]: a row of " + std::to_string(m) + " strings");
    e.E.emplace_back();
    for (size_t j = 0; j < m; ++j) {
      const std::string where = "model.environment.E[" + std::to_string(i) + "][" + std::to_string(j) + "]";
      if (!row.at(j).is_string()) throw InputError(where + ": not a string");
      try {
        e.E.back().push_back(parse_tf(row.at(j).get<std::string>(), po));
      } catch (const InputError& err) {
        throw InputError(where + ": " + err.what());
      }
    }
  }
  return e;
}

Cq horner(const P& p, const Cq& x) {
  Cq r;
  for (int k = p.degree(); k >= 0; --k) r = r * x + Cq(p.coeff(k));
  return r;
}

// sum_k p_k sigma^k tau^(d - k)
Cq homogeneous(const P& p, const Cq& sigma, const Cq& tau, int d) {
  Cq r, tp(1);
  std::vector<Cq> tau_pow(static_cast<size_t>(d) + 1);
  for (int k = 0; k <= d; ++k) tau_pow[static_cast<size_t>(k)] = k ? tau_pow[static_cast<size_t>(k) - 1] * tau : Cq(1);
  Cq sp(1);
  for (int k = 0; k <= d; ++k) {
    if (k <= p.degree()) r = r + Cq(p.coeff(k)) * sp * tau_pow[static_cast<size_t>(d - k)];
    sp = sp * sigma;
  }
  return r;
}

/// E_ij(z) exactly, or nullopt at a pole (the denominator as parsed vanishes there).
std::optional<Cq> entry_at(const Environment& e, const TransferFunction& H, const Cq& z) {
  if (e.var == 'z') {
    const Cq d = horner(H.den(), z);
    if (d.is_zero()) return std::nullopt;
    return horner(H.num(), z) / d;
  }
  const Cq sigma = e.tustin ? Cq(2) * (z - Cq(1)) : z - Cq(1);
  const Cq tau = e.tustin ? Cq(e.T) * (z + Cq(1)) : Cq(e.T) * z;
  const int d = std::max(H.num().degree(), H.den().degree());
  const Cq den = homogeneous(H.den(), sigma, tau, d);
  if (den.is_zero()) return std::nullopt;
  return homogeneous(H.num(), sigma, tau, d) / den;
}

Cq power(Cq x, long n) {
  Cq r(1);
  while (n > 0) {
    if (n & 1) r = r * x;
    x = x * x;
    n >>= 1;
  }
  return r;
}

struct UnionFind {
  std::vector<size_t> parent;
  explicit UnionFind(size_t n) : parent(n) { std::iota(parent.begin(), parent.end(), size_t(0)); }
  size_t find(size_t a) {
    while (parent[a] != a) a = parent[a] = parent[parent[a]];
    return a;
  }
};

// delta_i per DOF from model.devices, in DOF order
std::vector<rational> device_levels(const nlohmann::json& model, size_t m) {
  if (!model.contains("devices") || !model.at("devices").is_array() || model.at("devices").empty())
    throw InputError("model.devices: missing or not a non-empty array");
  std::vector<rational> delta;
  for (size_t d = 0; d < model.at("devices").size(); ++d) {
    const auto& dev = model.at("devices").at(d);
    const std::string where = "model.devices[" + std::to_string(d) + "]";
    if (!dev.is_object()) throw InputError(where + ": not an object");
    only_fields(dev, {"dofs", "m", "b", "osp"}, where);
    if (!dev.contains("dofs") || !dev.at("dofs").is_number_integer() || dev.at("dofs").get<long>() < 1)
      throw InputError(where + ".dofs: missing or not a positive integer");
    const long k = dev.at("dofs").get<long>();
    rational level;
    if (dev.contains("osp")) {
      if (dev.contains("m") || dev.contains("b")) throw InputError(where + ": osp beside m, b (give one)");
      level = exact_field(dev, "osp", where);
    } else {
      if (k != 1) throw InputError(where + ": a mass-damper (m, b) has one DOF");
      if (exact_field(dev, "m", where) <= 0) throw InputError(where + ".m: the mass must be > 0");
      level = exact_field(dev, "b", where);  // the OSP level of 1/(m s + b)
    }
    for (long i = 0; i < k; ++i) delta.push_back(level);
    if (delta.size() > m) break;
  }
  if (delta.size() != m)
    throw InputError("model.devices: their DOFs add up to " + std::to_string(delta.size()) + ", E has " + std::to_string(m));
  return delta;
}

// the operator of every DOF (each DOF in exactly one operator)
std::vector<size_t> operator_of(const nlohmann::json& model, size_t m) {
  if (!model.contains("operators") || !model.at("operators").is_array() || model.at("operators").empty())
    throw InputError("model.operators: missing or not a non-empty array");
  const size_t none = model.at("operators").size();
  std::vector<size_t> owner(m, none);
  for (size_t o = 0; o < model.at("operators").size(); ++o) {
    const auto& dofs = model.at("operators").at(o);
    const std::string where = "model.operators[" + std::to_string(o) + "]";
    if (!dofs.is_array() || dofs.empty()) throw InputError(where + ": a non-empty array of DOF indices");
    for (const auto& v : dofs) {
      if (!v.is_number_integer() || v.get<long>() < 0 || v.get<size_t>() >= m)
        throw InputError(where + ": a DOF index outside [0, " + std::to_string(m - 1) + "]");
      if (owner[v.get<size_t>()] != none)
        throw InputError(where + ": DOF " + std::to_string(v.get<long>()) + " belongs to two operators");
      owner[v.get<size_t>()] = o;
    }
  }
  for (size_t i = 0; i < m; ++i)
    if (owner[i] == none) throw InputError("model.operators: DOF " + std::to_string(i) + " has no operator");
  return owner;
}

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
  only_fields(p.model, {"T", "delay", "environment", "set", "devices", "operators"}, "model");
  only_fields(p.claim, {"status", "feasible"}, "claim");
  if (p.claim.value("status", std::string()) != "exact") throw InputError("claim.status: must be \"exact\"");
  if (!p.claim.contains("feasible") || !p.claim.at("feasible").is_boolean())
    throw InputError("claim.feasible: missing or not a boolean");
  if (p.claim.at("feasible").get<bool>())
    return {false, "the claim is that (16) is feasible; a witness can only prove it infeasible"};
  const PeriodDelay pd = read_period_delay(p.model);
  const Environment env = read_environment(p.model, pd.T, pd.n);
  const size_t m = env.E.size();
  const std::vector<rational> delta = device_levels(p.model, m);
  const std::vector<size_t> owner = operator_of(p.model, m);
  // (a): E(1) finite and symmetric; the components of the operators coupled through E(1)
  std::vector<std::vector<Cq>> E1(m, std::vector<Cq>(m));
  for (size_t i = 0; i < m; ++i)
    for (size_t j = 0; j < m; ++j) {
      const auto v = entry_at(env, env.E[i][j], Cq(1));
      if (!v)
        throw InputError("model.environment.E[" + std::to_string(i) + "][" + std::to_string(j) +
                         "]: a pole at z = 1 (E-hat would have a double pole there; this kind needs E(1) finite)");
      E1[i][j] = *v;
    }
  UnionFind uf(m);
  for (size_t i = 0; i < m; ++i)
    for (size_t j = 0; j < m; ++j) {
      if (E1[i][j].re != E1[j][i].re)
        throw InputError("model.environment.E: E(1) is not symmetric (entries " + std::to_string(i) + "," +
                         std::to_string(j) + "); this kind covers a symmetric E(1) only");
      if (!E1[i][j].re.is_zero()) uf.parent[uf.find(owner[i])] = uf.find(owner[j]);
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
    const Cq factor = Cq(env.T * env.gain) * z / (z - Cq(1)) * power(conj(z), env.n);
    for (size_t i = 0; i < m; ++i) {
      Cq w;
      for (size_t j = 0; j < m; ++j) {
        if (pt.u[j].is_zero()) continue;
        const auto v = entry_at(env, env.E[i][j], z);
        if (!v)
          return {false, at + "z = " + decimal(z.re) + " + j " + decimal(z.im) + " is a pole of E[" + std::to_string(i) + "][" +
                             std::to_string(j) + "]"};
        w = w + *v * pt.u[j];
      }
      const size_t c = uf.find(owner[i]);
      is_root[c] = true;  // Re(conj(u_i) (E-hat u)_i) + delta_i |u_i|^2
      const Cq& ui = pt.u[i];
      S[c] += pt.w * ((conj(ui) * factor * w).re + delta[i] * (ui.re * ui.re + ui.im * ui.im));
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
                    " direction(s): the operators coupled through the symmetric E(1)): " +
                    (points.size() > 1 ? "sum_j w_j phi(z_j, u_j)" : std::string("phi")) +
                    " = Re(u^H X E-hat(z) u) + u^H Delta_D X u <= 0 on each, < 0 on " + std::to_string(negative) + " (" +
                    worst + "), " +
                    (points.size() > 1 ? "at " + std::to_string(points.size()) + " points z_j of the unit circle, weights w_j >= 0"
                                       : "at z = " + decimal(points[0].z.re) + " + j " + decimal(points[0].z.im)) +
                    ", u != 0, exactly"};
}

}  // namespace hapstab::check
