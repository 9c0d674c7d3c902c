#include "hapstab/lti/tf.hpp"

#include "hapstab/numeric/decimal.hpp"
#include "hapstab/numeric/error.hpp"
#include "hapstab/poly/stability.hpp"

namespace hapstab {

TransferFunction tf(Polynomial<rational> num, Polynomial<rational> den, const rational& T) {
  if (den.is_zero()) throw InputError("tf: the denominator is zero");
  if (T < 0) throw InputError("tf: sample period T must be > 0 (or 0 for continuous time)");
  TransferFunction G;
  G.H = RationalFunction<rational>(std::move(num), std::move(den));
  G.domain = T > 0 ? Domain::z : Domain::s;
  G.T = T;
  return G;
}

Polynomial<rational> unstable_cancelled_factor(const Polynomial<rational>& written, const Polynomial<rational>& reduced,
                                               Domain domain) {
  if (reduced.degree() >= written.degree()) return {};
  auto [lost, rest] = divmod(written, reduced);
  if (!rest.is_zero()) throw std::logic_error("unstable_cancelled_factor: the reduced denominator does not divide the written one");
  const bool stable = domain == Domain::z ? schur_stable(lost) : hurwitz_stable(lost);
  return stable ? Polynomial<rational>() : lost.monic();
}

std::string TransferFunction::to_string() const {
  return "(" + hapstab::to_string(num(), variable()) + ")/(" + hapstab::to_string(den(), variable()) + ")";
}

namespace {
void same_kind(const TransferFunction& a, const TransferFunction& b, const char* op) {
  if (a.domain != b.domain || a.T != b.T)
    throw InputError(std::string(op) + ": operands differ in domain or sample period (" + a.variable() + ", T=" +
                     to_decimal(a.T, 17) + " vs " + b.variable() + ", T=" + to_decimal(b.T, 17) + ")");
}
}  // namespace

TransferFunction series(const TransferFunction& a, const TransferFunction& b) {
  same_kind(a, b, "series");
  return {a.H * b.H, a.domain, a.T};
}

TransferFunction parallel(const TransferFunction& a, const TransferFunction& b) {
  same_kind(a, b, "parallel");
  return {a.H + b.H, a.domain, a.T};
}

TransferFunction feedback(const TransferFunction& a, const TransferFunction& b, int sign) {
  same_kind(a, b, "feedback");
  if (sign != 1 && sign != -1) throw InputError("feedback: sign must be -1 (negative) or +1 (positive)");
  // a/(1 - sign*a*b) = na*db / (da*db - sign*na*nb)
  const auto& na = a.num();
  const auto& da = a.den();
  const auto& nb = b.num();
  const auto& db = b.den();
  Polynomial<rational> den = da * db - (sign == 1 ? na * nb : -(na * nb));
  if (den.is_zero()) throw InputError("feedback: the loop 1 + a*b is identically zero (algebraic loop is singular)");
  return {RationalFunction<rational>(na * db, den), a.domain, a.T};
}

}  // namespace hapstab
