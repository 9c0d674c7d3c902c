// hapstab/check/bound_check.cpp -- see bound_check.hpp.
#include "hapstab/check/bound_check.hpp"

#include <algorithm>
#include <map>
#include <utility>

#include "hapstab/check/nonnegative.hpp"
#include "hapstab/check/on_circle.hpp"
#include "hapstab/lti/parse.hpp"
#include "hapstab/numeric/decimal.hpp"
#include "hapstab/numeric/error.hpp"

namespace hapstab::check {

namespace {

using P = Polynomial<rational>;

using circle::OnCircle;
using circle::mul;
using circle::at_circle;
const P one_minus_c2 = circle::one_minus_c2();

OnCircle power(OnCircle x, long n) {
  OnCircle r{P(rational(1)), P()};
  while (n > 0) {
    if (n & 1) r = mul(r, x);
    n >>= 1;
    if (n) x = mul(x, x);
  }
  return r;
}

std::string decimal(const rational& x) { return to_decimal(x, 12); }

}  // namespace

Verdict check_bound(const nlohmann::json& cert) {
  constexpr long max_degree = 1000;
  using detail::exact_field;
  using detail::object_field;
  const nlohmann::json& model = object_field(cert, "model", "certificate");
  const nlohmann::json& claim = object_field(cert, "claim", "certificate");
  const nlohmann::json& evidence = object_field(cert, "evidence", "certificate");

  // ---- the model as written (a field this checker does not read would be a model it does not check)
  detail::only_fields(cert, {"certificate", "version", "kind", "model", "claim", "evidence", "produced_by"}, "certificate");
  detail::only_fields(model, {"H", "set", "T", "delay", "eta"}, "model");
  detail::only_fields(claim, {"quantity", "status", "value", "lo", "hi", "printed", "printed_lo", "printed_hi"}, "claim");
  detail::only_fields(evidence, {"witness_c"}, "evidence");
  if (!model.contains("H") || !model.at("H").is_string()) throw InputError("model.H: missing or not a string (the expression of H(z))");
  const std::string text = model.at("H").get<std::string>();
  const rational T = exact_field(model, "T", "model");
  if (T <= 0) throw InputError("model.T: the sample period must be > 0, got " + T.str());
  if (!model.contains("delay") || !model.at("delay").is_number_integer())
    throw InputError("model.delay: missing or not an integer (n in z^-n)");
  const long n = model.at("delay").get<long>();
  if (n < 0 || n > 100000) throw InputError("model.delay: " + std::to_string(n) + " is outside [0, 100000]");
  const rational eta = exact_field(model, "eta", "model");
  if (eta < 0) throw InputError("model.eta: must be >= 0, got " + eta.str());
  const TransferFunction H = detail::model_tf(model, text, T);
  // the checker expands z^-n: its polynomials have degree max(deg N, deg D + n) (twice that in c)
  const long degree = std::max<long>(H.num().degree(), H.den().degree() + n);
  if (degree > max_degree)
    throw InputError("model: H z^-n has degree " + std::to_string(degree) + ", beyond this checker's limit of " +
                     std::to_string(max_degree) + " (it expands the delay exactly)");

  // ---- the claim
  if (!claim.contains("status") || !claim.at("status").is_string())
    throw InputError("claim.status: missing or not a string (\"exact\" or \"certified\")");
  const std::string status = claim.at("status").get<std::string>();
  rational lo, hi;
  if (status == "exact") {
    lo = hi = exact_field(claim, "value", "claim");
  } else if (status == "certified") {
    lo = exact_field(claim, "lo", "claim");
    hi = exact_field(claim, "hi", "claim");
    if (lo > hi) return {false, "claim: lo = " + lo.str() + " > hi = " + hi.str()};
  } else {
    throw InputError("claim.status: \"" + status + "\" is neither \"exact\" nor \"certified\"");
  }
  // the printed decimals, when given, are the numbers claimed (what a reader sees is what is proven)
  for (const char* key : {"printed_lo", "printed_hi", "printed"}) {
    if (!claim.contains(key)) continue;
    const auto& v = claim.at(key);
    if (!v.is_string()) throw InputError(std::string("claim.") + key + ": not a string");
    const auto q = try_parse_rational(v.get<std::string>());
    if (!q) throw InputError(std::string("claim.") + key + ": '" + v.get<std::string>() + "' is not a number");
    const rational& want = std::string(key) == "printed_hi" ? hi : lo;
    if (*q != want)
      return {false, std::string("claim.") + key + " = " + v.get<std::string>() + " is not the claimed " + want.str()};
  }

  // ---- f(c) = A/B + eta, the checker's own derivation (header)
  OnCircle N = at_circle(H.num());
  if (n > 0) N = mul(N, power(OnCircle{P{rational(0), rational(1)}, P(rational(-1))}, n));  // conj(z)^n
  const OnCircle D = at_circle(H.den());
  const P X = N.a * D.a + one_minus_c2 * N.b * D.b, Y = N.b * D.a - N.a * D.b;
  const P A = T * (X - P{rational(1), rational(1)} * Y);
  const P B = rational(2) * (D.a * D.a + one_minus_c2 * D.b * D.b);

  // ---- upper: (hi - eta) B - A >= 0 on [-1, 1]
  if (auto why = nonnegative_on((hi - eta) * B - A, rational(-1), rational(1)))
    return {false, "b* <= " + hi.str() + " (" + decimal(hi) + ") fails: (hi - eta) B(c) - A(c) on [-1, 1]: " + *why};

  // ---- lower: the witness
  const rational c0 = exact_field(evidence, "witness_c", "evidence");
  if (c0 < -1 || c0 > 1) return {false, "evidence.witness_c = " + c0.str() + " is outside [-1, 1]"};
  // f on the reduced A/B: at a pole of H that cancels in A/B (a Tustin pole at z = -1, say) the
  // value is f's limit there, which the supremum reaches
  const P g = gcd(A, B);
  const P Ar = divmod(A, g).first, Br = divmod(B, g).first;
  const rational b0 = Br(c0);
  if (b0 == 0) return {false, "evidence.witness_c = " + c0.str() + " is a pole of the objective (a pole of H on the unit circle)"};
  const rational f0 = Ar(c0) / b0 + eta;
  if (f0 < lo)
    return {false, "b* >= " + lo.str() + " (" + decimal(lo) + ") not shown: the objective at the witness c0 = " + c0.str() +
                       " is " + decimal(f0) + " < lo"};

  std::string what = status == "exact" ? "b* = " + lo.str() : "b* in [" + decimal(lo) + ", " + decimal(hi) + "]";
  return {true, what + " (upper bound: (hi - eta) B - A >= 0 on [-1, 1] by Sturm, degree " + std::to_string(B.degree() > A.degree() ? B.degree() : A.degree()) +
                    "; lower bound: the objective at c0 = " + (c0.str().size() > 40 ? c0.str().substr(0, 40) + "..." : c0.str()) + ")"};
}

}  // namespace hapstab::check
