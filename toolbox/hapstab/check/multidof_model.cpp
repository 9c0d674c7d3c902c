// hapstab/check/multidof_model.cpp -- see multidof_model.hpp.
#include "hapstab/check/multidof_model.hpp"

#include <map>

#include "hapstab/check/certificate.hpp"
#include "hapstab/lti/parse.hpp"
#include "hapstab/lti/realization.hpp"
#include "hapstab/numeric/error.hpp"

namespace hapstab::check::multidof_model {

namespace {

using namespace detail;
using P = Polynomial<rational>;

Cq horner(const P& p, const Cq& x) {
  Cq r;
  for (int k = p.degree(); k >= 0; --k) r = r * x + Cq(p.coeff(k));
  return r;
}

// sum_k p_k sigma^k tau^(d - k)
Cq homogeneous(const P& p, const Cq& sigma, const Cq& tau, int d) {
  Cq r;
  std::vector<Cq> tau_pow(static_cast<size_t>(d) + 1);
  for (int k = 0; k <= d; ++k) tau_pow[static_cast<size_t>(k)] = k ? tau_pow[static_cast<size_t>(k) - 1] * tau : Cq(1);
  Cq sp(1);
  for (int k = 0; k <= d; ++k) {
    if (k <= p.degree()) r = r + Cq(p.coeff(k)) * sp * tau_pow[static_cast<size_t>(d - k)];
    sp = sp * sigma;
  }
  return r;
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

// model.environment.E, an m x m array of expression strings in the domain's variable (model.set's
// parameters), each entry parsed exactly.
std::vector<std::vector<TransferFunction>> written_entries(const nlohmann::json& model, const nlohmann::json& env, char var,
                                                           const rational& T) {
  if (!env.at("E").is_array() || env.at("E").empty() || env.at("E").size() > max_dofs)
    throw InputError("model.environment.E: must be an m x m array of expression strings, 1 <= m <= " +
                     std::to_string(max_dofs));
  const size_t m = env.at("E").size();
  std::vector<std::vector<TransferFunction>> E;
  std::map<std::string, TransferFunction> parsed;  // a compact scene written out repeats a few entries m^2 times
  ParseOptions po;
  po.variable = var;
  po.T = T;
  po.parameters = model_parameters(model);
  for (size_t i = 0; i < m; ++i) {
    const auto& row = env.at("E").at(i);
    if (!row.is_array() || row.size() != m)
      throw InputError("model.environment.E[" + std::to_string(i) + "]: a row of " + std::to_string(m) + " strings");
    E.emplace_back();
    for (size_t j = 0; j < m; ++j) {
      const std::string where = "model.environment.E[" + std::to_string(i) + "][" + std::to_string(j) + "]";
      if (!row.at(j).is_string()) throw InputError(where + ": not a string");
      try {
        const std::string& text = row.at(j).get_ref<const std::string&>();
        auto it = parsed.find(text);
        if (it == parsed.end()) it = parsed.emplace(text, parse_tf(text, po)).first;
        E.back().push_back(it->second);
      } catch (const InputError& err) {
        throw InputError(where + ": " + err.what());
      }
    }
  }
  return E;
}

// model.environment.ss {A, B, C, D} as written ("p/q" entries; m x m with m = D's rows), its
// transfer matrix C (xI - A)^-1 B + D exactly (lti/realization.hpp's ss2tf, Faddeev-LeVerrier), x the
// domain's variable: the entries as if written out.
std::vector<std::vector<TransferFunction>> ss_entries(const nlohmann::json& env, char var, const rational& T) {
  const nlohmann::json& ss = object_field(env, "ss", "model.environment");
  only_fields(ss, {"A", "B", "C", "D"}, "model.environment.ss");
  const std::string where = "model.environment.ss";
  const auto A = exact_matrix(ss, "A", where, max_ss_states), B = exact_matrix(ss, "B", where, max_dofs),
             C = exact_matrix(ss, "C", where, max_ss_states), D = exact_matrix(ss, "D", where, max_dofs);
  if (A.empty() || B.empty() || C.empty() || D.empty())
    throw InputError(where + ": A, B, C and D must be non-empty matrices (at least one state and one DOF)");
  const size_t N = A.size(), m = D.size();
  if (A[0].size() != N || B.size() != N || C[0].size() != N || B[0].size() != m || C.size() != m || D[0].size() != m)
    throw InputError(where + ": A must be N x N, B N x m, C m x N and D m x m (got A " + std::to_string(N) + " x " +
                     std::to_string(A[0].size()) + ", B " + std::to_string(B.size()) + " x " + std::to_string(B[0].size()) +
                     ", C " + std::to_string(C.size()) + " x " + std::to_string(C[0].size()) + ", D " + std::to_string(m) + " x " +
                     std::to_string(D[0].size()) + ")");
  const auto mat = [](const std::vector<std::vector<rational>>& M) {
    hapstab::Mat<rational> X(static_cast<Eigen::Index>(M.size()), static_cast<Eigen::Index>(M[0].size()));
    for (size_t i = 0; i < M.size(); ++i)
      for (size_t j = 0; j < M[0].size(); ++j) X(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(j)) = M[i][j];
    return X;
  };
  return ss2tf(StateSpace<rational>{mat(A), mat(B), mat(C), mat(D), var == 'z' ? T : rational(0)}).entries;
}

}  // namespace

Environment read_environment(const nlohmann::json& model, const rational& T, long n) {
  const nlohmann::json& env = object_field(model, "environment", "model");
  only_fields(env, {"domain", "method", "gain", "E", "ss", "perturb_C"}, "model.environment");
  Environment e;
  e.T = T;
  e.n = n;
  // (a JSON comparison, not env.value(...): a null or a number there is malformed, not a type error)
  if (!env.contains("domain") || (env.at("domain") != "z" && env.at("domain") != "s"))
    throw InputError("model.environment.domain: must be \"z\" or \"s\"");
  const std::string domain = env.at("domain").get<std::string>();
  e.var = domain[0];
  if (e.var == 's') {
    if (!env.contains("method") || (env.at("method") != "backward_euler" && env.at("method") != "tustin"))
      throw InputError("model.environment.method: must be \"backward_euler\" or \"tustin\" for domain \"s\"");
    e.tustin = env.at("method") == "tustin";
  } else if (env.contains("method")) {
    throw InputError("model.environment.method: only with domain \"s\"");
  }
  e.gain = exact_field(env, "gain", "model.environment");
  if (env.contains("E") == env.contains("ss"))
    throw InputError("model.environment: exactly one of E (the entries as written) and ss (the realisation as written)");
  if (env.contains("ss")) e.E = ss_entries(env, e.var, T);
  else e.E = written_entries(model, env, e.var, T);
  const size_t m = e.E.size();
  if (env.contains("perturb_C")) {  // C_E := Pi C_E, D_E unchanged: E' = Pi (E - E(inf)) + E(inf)
    e.perturb_C = exact_matrix(env, "perturb_C", "model.environment", max_dofs);
    if (e.perturb_C.size() != m || e.perturb_C[0].size() != m)
      throw InputError("model.environment.perturb_C: must be " + std::to_string(m) + " x " + std::to_string(m) + " (E's size)");
    // E(inf): z -> inf is s -> 1/T (backward Euler: s = (z - 1)/(T z)), s -> 2/T (Tustin), or the
    // ratio of the leading coefficients of an entry in z (0 when strictly proper)
    for (size_t i = 0; i < m; ++i) {
      e.D.emplace_back();
      for (size_t j = 0; j < m; ++j) {
        const TransferFunction& H = e.E[i][j];
        const std::string where = "model.environment.E[" + std::to_string(i) + "][" + std::to_string(j) + "]";
        if (e.var == 'z') {
          if (H.num().degree() > H.den().degree()) throw InputError(where + ": not proper (E(inf) is needed by perturb_C)");
          e.D.back().push_back(H.num().degree() == H.den().degree() ? rational(H.num().coeff(H.num().degree()) /
                                                                               H.den().coeff(H.den().degree()))
                                                                     : rational(0));
        } else {
          const int d = std::max(H.num().degree(), H.den().degree());
          const Cq sigma(e.tustin ? 2 : 1), tau(T);
          const Cq den = homogeneous(H.den(), sigma, tau, d);
          if (den.is_zero()) throw InputError(where + ": a pole at z = inf (E(inf) is needed by perturb_C)");
          e.D.back().push_back((homogeneous(H.num(), sigma, tau, d) / den).re);
        }
      }
    }
  }
  return e;
}

std::optional<std::vector<std::vector<Cq>>> environment_at(const Environment& e, const Cq& z) {
  const size_t m = e.E.size();
  std::vector<std::vector<Cq>> V(m, std::vector<Cq>(m));
  for (size_t i = 0; i < m; ++i)
    for (size_t j = 0; j < m; ++j) {
      const auto v = entry_at(e, e.E[i][j], z);
      if (!v) return std::nullopt;
      V[i][j] = *v;
    }
  if (e.perturb_C.empty()) return V;
  std::vector<std::vector<Cq>> W(m, std::vector<Cq>(m));
  for (size_t i = 0; i < m; ++i)
    for (size_t j = 0; j < m; ++j) {
      Cq s(e.D[i][j]);
      for (size_t k = 0; k < m; ++k)
        if (!e.perturb_C[i][k].is_zero()) s = s + Cq(e.perturb_C[i][k]) * (V[k][j] - Cq(e.D[k][j]));
      W[i][j] = s;
    }
  return W;
}

long environment_degree(const Environment& e) {
  long d = 0;
  for (const auto& row : e.E)
    for (const auto& H : row) d = std::max<long>(d, std::max(H.num().degree(), H.den().degree()));
  return e.perturb_C.empty() ? d : d * static_cast<long>(e.E.size());
}

std::optional<std::string> infeasibility_claim(const Parts& p, const std::string& by) {
  only_fields(p.model, {"T", "delay", "environment", "set", "devices", "operators"}, "model");
  only_fields(p.claim, {"status", "feasible"}, "claim");
  if (!p.claim.contains("status") || p.claim.at("status") != "exact") throw InputError("claim.status: must be \"exact\"");
  if (!p.claim.contains("feasible") || !p.claim.at("feasible").is_boolean())
    throw InputError("claim.feasible: missing or not a boolean");
  if (p.claim.at("feasible").get<bool>()) return "the claim is that (16) is feasible; " + by + " can only prove it infeasible";
  return std::nullopt;
}

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

Cq ehat_factor(const Environment& e, const Cq& z) {
  return Cq(e.T * e.gain) * z / (z - Cq(1)) * power(conj(z), e.n);
}

std::vector<rational> device_levels(const nlohmann::json& model, size_t m) {
  if (!model.contains("devices") || !model.at("devices").is_array() || model.at("devices").empty())
    throw InputError("model.devices: missing or not a non-empty array");
  std::vector<rational> delta;
  for (size_t d = 0; d < model.at("devices").size(); ++d) {
    const auto& dev = model.at("devices").at(d);
    const std::string where = "model.devices[" + std::to_string(d) + "]";
    if (!dev.is_object()) throw InputError(where + ": not an object");
    only_fields(dev, {"dofs", "m", "b", "osp"}, where);
    const long k = integer_field(dev, "dofs", where, 1, static_cast<long>(m));  // more would overrun E's m
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
      if (!v.is_number_integer() || (v.is_number_unsigned() ? v.get<unsigned long>() >= m : v.get<long>() < 0 || v.get<size_t>() >= m))
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

}  // namespace hapstab::check::multidof_model
