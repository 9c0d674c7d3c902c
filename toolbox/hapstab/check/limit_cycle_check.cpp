// hapstab/check/limit_cycle_check.cpp -- see limit_cycle_check.hpp.
#include "hapstab/check/limit_cycle_check.hpp"

#include <optional>
#include <string>
#include <vector>

#include "hapstab/check/interpolate.hpp"
#include "hapstab/check/schur_cohn.hpp"
#include "hapstab/numeric/eigen_traits.hpp"
#include "hapstab/numeric/error.hpp"
#include "hapstab/numeric/exact_matrix.hpp"

namespace hapstab::check {

namespace {

using P = Polynomial<rational>;
using Seq = std::vector<rational>;

constexpr long max_period = 100000;
constexpr int max_order = 200;

// The loop of the model as written: H = N/D reduced (D monic, degree n), the gain k, rho.
struct Loop {
  P N, D;
  rational k, rho, beta;  // beta = k n_n = k H(inf)
  int n = 0;
};

Loop parse_model(const nlohmann::json& model) {
  detail::only_fields(model, {"H", "set", "num", "den", "T", "gain", "rho"}, "model");
  const rational T = detail::exact_field(model, "T", "model");
  if (T <= 0) throw InputError("model.T: the sample period must be > 0, got " + T.str());
  const TransferFunction H = detail::model_tf(model, T);
  Loop L;
  L.N = H.num();
  L.D = H.den();
  if (L.N.degree() > L.D.degree()) throw InputError("model.H: not causal (deg num > deg den)");
  L.n = L.D.degree();
  if (L.n < 1) throw InputError("model.H: H is a constant: the loop has no state, so no orbit to certify");
  if (L.n > max_order) throw InputError("model.H: order " + std::to_string(L.n) + " above this checker's limit (200)");
  const rational lead = L.D.coeff(L.n);  // made monic here whatever the parser keeps
  L.N = L.N * P(rational(1) / lead);
  L.D = L.D * P(rational(1) / lead);
  L.k = detail::exact_field(model, "gain", "model");
  if (L.k < 0) throw InputError("model.gain: the gain must be >= 0, got " + L.k.str());
  L.rho = detail::exact_field(model, "rho", "model");
  if (L.rho <= 0) throw InputError("model.rho: rho must be > 0, got " + L.rho.str());
  L.beta = L.k * L.N.coeff(L.n);
  if (1 + L.beta <= 0)
    throw InputError("model: 1 + k H(inf) = " + rational(1 + L.beta).str() + " <= 0: the algebraic loop has no unique solution");
  return L;
}

// y_0..y_{P+n-1} from the window y_0..y_{n-1}: each y_{j+n} the unique solution of the step.
Seq run(const Loop& L, Seq y, long P) {
  const rational minus_rho = -L.rho;
  for (long j = 0; j < P; ++j) {
    rational a = 0;
    for (int i = 0; i < L.n; ++i) {
      const rational& v = y[j + i];
      a -= L.D.coeff(i) * v + L.k * L.N.coeff(i) * (v < minus_rho ? minus_rho : v);
    }
    const rational contact = a / (1 + L.beta);
    y.push_back(contact >= minus_rho ? contact : rational(a + L.beta * L.rho));
  }
  return y;
}

// The least period of y_0..y_{P-1} (y P-periodic, P >= 1): some y_{i+P/p} != y_i for each prime p | P.
std::optional<long> smaller_period(const Seq& y, long P) {
  long m = P;
  for (long p = 2; p <= m; ++p) {
    if (m % p != 0) continue;
    while (m % p == 0) m /= p;
    const long d = P / p;
    bool repeats = true;
    for (long i = 0; i + d < P && repeats; ++i) repeats = y[i + d] == y[i];
    if (repeats) return d;
  }
  return std::nullopt;
}

// J of the header: column c is the linearised recursion run P steps from the unit window e_c.
MatQ monodromy(const Loop& L, const Seq& y, long P) {
  const rational minus_rho = -L.rho;
  MatQ J(L.n, L.n);
  for (int c = 0; c < L.n; ++c) {
    Seq d(L.n, rational(0));
    d[c] = 1;
    for (long j = 0; j < P; ++j) {
      rational a = 0;
      for (int i = 0; i < L.n; ++i)
        a -= (L.D.coeff(i) + (y[j + i] > minus_rho ? L.k * L.N.coeff(i) : rational(0))) * d[j + i];
      d.push_back(a / (y[j + L.n] > minus_rho ? rational(1 + L.beta) : rational(1)));
    }
    for (int r = 0; r < L.n; ++r) J(r, c) = d[P + r];
  }
  return J;
}

// Schur-Cohn on det(tI - J), interpolated from its values at t = 0..n.
SchurCohn attraction(const MatQ& J) {
  const long n = J.rows();
  std::vector<rational> x, v;
  for (long t = 0; t <= n; ++t) {
    MatQ M = -J;
    for (long i = 0; i < n; ++i) M(i, i) += rational(t);
    x.emplace_back(t);
    v.push_back(exact_determinant(M));
  }
  return schur_cohn(interpolate(x, v));
}


}  // namespace

Verdict check_limit_cycle(const nlohmann::json& cert) {
  const auto [model, claim, evidence] = detail::certificate_parts(cert);
  detail::only_fields(evidence, {"y"}, "evidence");
  detail::only_fields(claim, {"quantity", "status", "period", "amplitude", "printed_amplitude", "free_steps", "attracting"}, "claim");
  if (!claim.contains("status") || claim.at("status") != "exact") throw InputError("claim.status: missing or not \"exact\"");
  const Loop L = parse_model(model);
  const long P = detail::integer_field(claim, "period", "claim", 1, max_period);
  const long free_claimed = detail::integer_field(claim, "free_steps", "claim", 0, max_period);
  const rational amplitude = detail::exact_field(claim, "amplitude", "claim");
  if (!claim.contains("printed_amplitude") || !claim.at("printed_amplitude").is_string())
    throw InputError("claim.printed_amplitude: missing or not a string");
  const std::string printed = claim.at("printed_amplitude").get<std::string>();
  std::optional<bool> attracting;
  if (claim.contains("attracting")) {
    if (!claim.at("attracting").is_boolean()) throw InputError("claim.attracting: not true/false");
    attracting = claim.at("attracting").get<bool>();
  }
  if (!evidence.contains("y") || !evidence.at("y").is_array()) throw InputError("evidence.y: missing or not an array");
  const auto& ys = evidence.at("y");
  if (static_cast<long>(ys.size()) != L.n)
    throw InputError("evidence.y: " + std::to_string(ys.size()) + " outputs, expected n = " + std::to_string(L.n) +
                     " (the order of H reduced)");
  Seq y;
  for (size_t i = 0; i < ys.size(); ++i) y.push_back(detail::exact_string(ys[i], "evidence.y[" + std::to_string(i) + "]"));
  const auto rounded = detail::rounds_to(printed, amplitude);
  if (!rounded) throw InputError("claim.printed_amplitude: '" + printed.substr(0, 60) + "' is not a decimal");

  y = run(L, std::move(y), P);
  for (int i = 0; i < L.n; ++i)
    if (y[P + i] != y[i])
      return {false, "the state does not repeat: y_" + std::to_string(P + i) + " = " + detail::decimal(y[P + i]) + " != y_" +
                         std::to_string(i) + " = " + detail::decimal(y[i]) + " (the recursion of (4) from evidence.y)"};
  if (const auto d = smaller_period(y, P))
    return {false, "claim.period = " + std::to_string(P) + " is not the least period: y repeats after " + std::to_string(*d)};
  rational lo = y[0], hi = y[0];
  long free = 0;
  bool on_boundary = false;
  for (long i = 0; i < P; ++i) {
    lo = y[i] < lo ? y[i] : lo;
    hi = y[i] > hi ? y[i] : hi;
    free += y[i] < -L.rho ? 1 : 0;
    on_boundary = on_boundary || y[i] == -L.rho;
  }
  const rational amp = (hi - lo) / 2;
  if (amplitude != amp)
    return {false, "claim.amplitude = " + detail::decimal(amplitude) + " is not (max - min)/2 of y over the orbit, " +
                       detail::decimal(amp) + " (max " + detail::decimal(hi) + ", min " + detail::decimal(lo) + ")"};
  if (!*rounded)
    return {false, "claim.printed_amplitude = " + printed + " is not the amplitude " + detail::decimal(amp) + " rounded"};
  if (free != free_claimed)
    return {false, "claim.free_steps = " + std::to_string(free_claimed) + ", but " + std::to_string(free) +
                       " samples per period have y < -rho"};
  std::string shown = "periodic orbit of least period " + std::to_string(P) + " (the state y_0..y_" + std::to_string(L.n - 1) +
                      " repeats exactly after " + std::to_string(P) + " steps of (4)); amplitude " + detail::decimal(amp) + "; " +
                      std::to_string(free) + " samples out of contact";
  if (attracting) {
    if (on_boundary)
      throw InputError("claim.attracting: a sample of the orbit lies on y = -rho (the map is only piecewise affine there): "
                       "beyond this checker");
    const SchurCohn sc = attraction(monodromy(L, y, P));
    if (sc.stable != *attracting)
      return {false, std::string("claim.attracting = ") + (*attracting ? "true" : "false") + ", but the monodromy matrix: " + sc.why};
    shown += std::string("; ") + (sc.stable ? "attracting" : "not attracting") + " (monodromy matrix: " + sc.why + ")";
  }
  return {true, shown};
}

}  // namespace hapstab::check
