// hapstab/poly/rational_function.hpp -- rational functions num(x)/den(x) over a field F.
//
// Over `rational` they are kept canonical: reduced by the gcd and with a monic denominator,
// so two equal rational functions have equal num() and den() (this is what makes the exact
// identity proofs of (35)-(38) = (44) in paper 001 a comparison of coefficients). Over
// floating types no reduction is done (a numerical gcd is not trustworthy).
#pragma once

#include <algorithm>
#include <utility>
#include <vector>

#include "hapstab/poly/polynomial.hpp"

namespace hapstab {

template <class F>
class RationalFunction {
 public:
  using value_type = F;

  RationalFunction(Polynomial<F> num, Polynomial<F> den = Polynomial<F>(F(1)))
      : num_(std::move(num)), den_(std::move(den)) {
    if (den_.is_zero()) throw InputError("RationalFunction: zero denominator");
    normalise();
  }
  template <class A, std::enable_if_t<std::is_arithmetic_v<A> || std::is_same_v<A, F>, int> = 0>
  RationalFunction(A c) : RationalFunction(Polynomial<F>(F(c))) {}  // NOLINT: constants

  const Polynomial<F>& num() const { return num_; }
  const Polynomial<F>& den() const { return den_; }
  bool is_zero() const { return num_.is_zero(); }

  RationalFunction operator-() const { return RationalFunction(-num_, den_, raw{}); }
  // With a constant c on one side the result is canonical without a gcd: gcd(n + c d, d) =
  // gcd(c n, d) = gcd(n, d) = 1 and d stays monic. The parser meets a constant at every number
  // and parameter, and the gcd was most of the cost of parsing H.
  friend RationalFunction operator+(const RationalFunction& a, const RationalFunction& b) {
    if (b.is_exact_constant()) return a.plus_constant(b.num_);
    if (a.is_exact_constant()) return b.plus_constant(a.num_);
    if (a.den_ == b.den_) return RationalFunction(a.num_ + b.num_, a.den_);
    return RationalFunction(a.num_ * b.den_ + b.num_ * a.den_, a.den_ * b.den_);
  }
  friend RationalFunction operator-(const RationalFunction& a, const RationalFunction& b) { return a + (-b); }
  friend RationalFunction operator*(const RationalFunction& a, const RationalFunction& b) {
    if (b.is_exact_constant()) return a.times_constant(b.num_);
    if (a.is_exact_constant()) return b.times_constant(a.num_);
    return RationalFunction(a.num_ * b.num_, a.den_ * b.den_);
  }
  friend RationalFunction operator/(const RationalFunction& a, const RationalFunction& b) {
    if (b.num_.is_zero()) throw InputError("RationalFunction: division by the zero rational function");
    if (b.is_exact_constant()) return a.times_constant(Polynomial<F>(F(1) / b.num_.leading()));
    return RationalFunction(a.num_ * b.den_, a.den_ * b.num_);
  }
  RationalFunction& operator+=(const RationalFunction& o) { return *this = *this + o; }
  RationalFunction& operator-=(const RationalFunction& o) { return *this = *this - o; }
  RationalFunction& operator*=(const RationalFunction& o) { return *this = *this * o; }
  RationalFunction& operator/=(const RationalFunction& o) { return *this = *this / o; }
  /// Equal as functions: a.num*b.den == b.num*a.den (exact over rational).
  friend bool operator==(const RationalFunction& a, const RationalFunction& b) {
    return a.num_ * b.den_ == b.num_ * a.den_;
  }
  friend bool operator!=(const RationalFunction& a, const RationalFunction& b) { return !(a == b); }

  /// f^n, n may be negative (then f must not be zero).
  RationalFunction pow(int n) const {
    if (n < 0) {
      if (num_.is_zero()) throw InputError("RationalFunction::pow: zero to a negative power");
      return RationalFunction(den_.pow(static_cast<unsigned>(-n)), num_.pow(static_cast<unsigned>(-n)));
    }
    return RationalFunction(num_.pow(static_cast<unsigned>(n)), den_.pow(static_cast<unsigned>(n)));
  }
  /// (num' den - num den') / den^2
  RationalFunction derivative() const {
    return RationalFunction(num_.derivative() * den_ - num_ * den_.derivative(), den_ * den_);
  }
  /// num(x)/den(x) in the scalar X.
  template <class X>
  X operator()(const X& x) const {
    return num_(x) / den_(x);
  }

 private:
  struct raw {};
  RationalFunction(Polynomial<F> n, Polynomial<F> d, raw) : num_(std::move(n)), den_(std::move(d)) {}
  /// Canonical (exact) and constant: num = c (or 0), den = 1.
  bool is_exact_constant() const { return std::is_same_v<F, rational> && den_.degree() == 0 && num_.degree() <= 0; }
  /// this + c and this * c for a constant polynomial c, canonical as the comment above says.
  RationalFunction plus_constant(const Polynomial<F>& c) const {
    Polynomial<F> n = num_ + den_ * c;
    if (n.is_zero()) return RationalFunction(std::move(n));
    return RationalFunction(std::move(n), den_, raw{});
  }
  RationalFunction times_constant(const Polynomial<F>& c) const {
    if (c.is_zero()) return RationalFunction(Polynomial<F>());
    return RationalFunction(num_ * c, den_, raw{});
  }
  // When one side is a monomial c z^k (a constant, or the T z of a backward difference), the
  // gcd is the power of z both share: returns it. -1 when neither side is a monomial. (The
  // parser builds most haptic H this way; a polynomial gcd there cost 60% of parsing H.)
  int common_power_of_z() const {
    const auto low = [](const Polynomial<F>& p) {
      int k = 0;
      while (detail::is_zero_coefficient(p.coeffs()[k])) ++k;
      return k;
    };
    const int num_low = low(num_), den_low = low(den_);
    if (num_low != num_.degree() && den_low != den_.degree()) return -1;
    return std::min(num_low, den_low);
  }
  static Polynomial<F> drop_low_powers(const Polynomial<F>& p, int k) {
    return Polynomial<F>(std::vector<F>(p.coeffs().begin() + k, p.coeffs().end()));
  }
  void normalise() {
    if constexpr (std::is_same_v<F, rational>) {
      if (num_.is_zero()) {
        den_ = Polynomial<F>(F(1));
        return;
      }
      const int shared_z = common_power_of_z();
      if (shared_z >= 0) {  // the gcd is z^shared_z: no polynomial gcd needed
        if (shared_z > 0) num_ = drop_low_powers(num_, shared_z), den_ = drop_low_powers(den_, shared_z);
      } else {
        Polynomial<F> g = gcd(num_, den_);
        if (g.degree() > 0) {
          num_ = divmod(num_, g).first;
          den_ = divmod(den_, g).first;
        }
      }
      const F& l = den_.leading();
      if (l != 1) {
        num_ = num_ * Polynomial<F>(F(1) / l);
        den_ = den_.monic();
      }
    }
  }
  Polynomial<F> num_, den_;
};

extern template class RationalFunction<rational>;

/// The exact rational function (every transfer function of the toolbox): the one name for it.
using QRatFun = RationalFunction<rational>;

}  // namespace hapstab
