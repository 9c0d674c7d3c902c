// hapstab/poly/polynomial.hpp -- univariate polynomials over a field F (rational, double,
// mpfloat<D>, ...), the algebra under every exact proof of paper 001 (the unit-circle
// substitution t = tan(wT/2) turns (35)-(38), (44), (45) into rational functions of t).
//
// Coefficients are stored ASCENDING (c[0] + c[1] x + ...); the zero polynomial has no
// coefficients and degree -1. Over `rational` everything is exact; over floating types the
// arithmetic is the naive one (no error analysis here; trailing coefficients are dropped only
// when exactly zero). Evaluation (Horner) works at any X constructible from F through
// scalar_cast: complex<double>, mpfloat<D>, interval<D> (outward-rounded, so evaluating an
// exact rational polynomial at an interval encloses the true value), rational.
//
// Over `rational`, products beyond a few terms, powers, division and gcd run on FLINT's
// fmpq_poly (polynomial.cpp): Kronecker/Schönhage-Strassen products and a modular gcd instead
// of schoolbook loops and coefficient-exploding Euclid (a degree-26 gcd with a common factor:
// 45 ms -> 32 us). Small and sparse products (delays z^-n) stay on the loop below, which skips
// zero coefficients. Over floating types gcd is Euclid's algorithm with monic normalisation at
// every step. gcd is monic; gcd(0, 0) = 0.
#pragma once

#include <algorithm>
#include <complex>
#include <initializer_list>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "hapstab/numeric/error.hpp"
#include "hapstab/numeric/scalar.hpp"

namespace hapstab {

namespace detail {
template <class T> struct is_std_complex : std::false_type {};
template <class T> struct is_std_complex<std::complex<T>> : std::true_type {};
template <class T> struct is_interval : std::false_type {};
template <unsigned D> struct is_interval<interval<D>> : std::true_type {};
/// c == 0 without building a zero: for an exact rational, F(0) is an mpq_init and an mpq_clear,
/// and the polynomial loops ask this of every coefficient.
template <class F>
bool is_zero_coefficient(const F& c) {
  if constexpr (std::is_same_v<F, rational>) return c.is_zero();
  else return c == F(0);
}
}  // namespace detail

/// Converts a coefficient to the evaluation scalar X. rational -> interval is an outward-rounded
/// enclosure (mpfi_set_q); rational -> double is correctly rounded; rational -> mpfloat<D> is
/// correctly rounded (mpfr_set_q).
template <class X, class F>
X scalar_cast(const F& c) {
  if constexpr (std::is_same_v<X, F>) {
    return c;
  } else if constexpr (detail::is_std_complex<X>::value) {
    using R = typename X::value_type;
    return X(scalar_cast<R>(c), R(0));
  } else if constexpr (detail::is_interval<X>::value && std::is_same_v<F, rational>) {
    X x;
    mpfi_set_q(x.backend().data(), c.backend().data());
    return x;
  } else if constexpr (std::is_same_v<F, rational>) {
    return to_real<X>(c);
  } else if constexpr (std::is_arithmetic_v<X>) {
    return static_cast<X>(c);
  } else {
    return X(c);
  }
}

template <class F>
class Polynomial;

namespace detail {
// The exact operations on FLINT (polynomial.cpp). A product goes there when it has at least
// flint_min_products nonzero coefficient products (below that the conversion costs more).
inline constexpr size_t flint_min_products = 64;
Polynomial<rational> flint_mul(const Polynomial<rational>& a, const Polynomial<rational>& b);
Polynomial<rational> flint_pow(const Polynomial<rational>& a, unsigned n);
std::pair<Polynomial<rational>, Polynomial<rational>> flint_divrem(const Polynomial<rational>& a,
                                                                   const Polynomial<rational>& b);
}  // namespace detail

template <class F>
class Polynomial {
 public:
  using value_type = F;

  Polynomial() = default;
  Polynomial(F c) {  // NOLINT: a constant is a polynomial
    if (!detail::is_zero_coefficient(c)) c_.push_back(std::move(c));
  }
  template <class A, std::enable_if_t<std::is_arithmetic_v<A> && !std::is_same_v<A, F>, int> = 0>
  Polynomial(A c) : Polynomial(F(c)) {}  // NOLINT: Polynomial<rational> p = 1;
  explicit Polynomial(std::vector<F> ascending) : c_(std::move(ascending)) { trim(); }
  /// Polynomial<rational>({a0, a1, ...}) (ascending). Without it the braced list would be
  /// ambiguous for F = rational, which is itself constructible from two numbers (num, den).
  Polynomial(std::initializer_list<F> ascending) : c_(ascending) { trim(); }

  /// c x^k
  static Polynomial monomial(int k, F c = F(1)) {
    if (k < 0) throw InputError("Polynomial::monomial: negative exponent " + std::to_string(k));
    std::vector<F> v(static_cast<size_t>(k) + 1, F(0));
    v[k] = std::move(c);
    return Polynomial(std::move(v));
  }

  int degree() const { return static_cast<int>(c_.size()) - 1; }
  size_t nonzero_terms() const {
    size_t n = 0;
    for (const auto& x : c_) n += !detail::is_zero_coefficient(x);
    return n;
  }
  F coeff(int i) const { return (i >= 0 && i < static_cast<int>(c_.size())) ? c_[i] : F(0); }
  const std::vector<F>& coeffs() const { return c_; }
  const F& leading() const {
    if (c_.empty()) throw InputError("Polynomial::leading: the zero polynomial has no leading coefficient");
    return c_.back();
  }
  bool is_zero() const { return c_.empty(); }

  Polynomial operator-() const {
    Polynomial r = *this;
    for (auto& x : r.c_) x = -x;
    return r;
  }
  Polynomial& operator+=(const Polynomial& o) {
    if (o.c_.size() > c_.size()) c_.resize(o.c_.size(), F(0));
    for (size_t i = 0; i < o.c_.size(); ++i) c_[i] += o.c_[i];
    trim();
    return *this;
  }
  Polynomial& operator-=(const Polynomial& o) {
    if (o.c_.size() > c_.size()) c_.resize(o.c_.size(), F(0));
    for (size_t i = 0; i < o.c_.size(); ++i) c_[i] -= o.c_[i];
    trim();
    return *this;
  }
  Polynomial& operator*=(const Polynomial& o) {
    *this = *this * o;
    return *this;
  }
  friend Polynomial operator+(Polynomial a, const Polynomial& b) { return a += b; }
  friend Polynomial operator-(Polynomial a, const Polynomial& b) { return a -= b; }
  friend Polynomial operator*(const Polynomial& a, const Polynomial& b) {
    if (a.is_zero() || b.is_zero()) return Polynomial();
    // Zero coefficients are skipped: delays z^-n and powers of them are sparse, and z^9999
    // costs 14 products this way instead of ~10^8.
    std::vector<size_t> nz;
    for (size_t j = 0; j < b.c_.size(); ++j)
      if (!detail::is_zero_coefficient(b.c_[j])) nz.push_back(j);
    if constexpr (std::is_same_v<F, rational>) {
      if (nz.size() * a.nonzero_terms() >= detail::flint_min_products) return detail::flint_mul(a, b);
    }
    std::vector<F> r(a.c_.size() + b.c_.size() - 1, F(0));
    for (size_t i = 0; i < a.c_.size(); ++i) {
      if (detail::is_zero_coefficient(a.c_[i])) continue;
      for (size_t j : nz) r[i + j] += a.c_[i] * b.c_[j];
    }
    return Polynomial(std::move(r));
  }
  friend bool operator==(const Polynomial& a, const Polynomial& b) { return a.c_ == b.c_; }
  friend bool operator!=(const Polynomial& a, const Polynomial& b) { return !(a == b); }

  Polynomial pow(unsigned n) const {
    if constexpr (std::is_same_v<F, rational>) {
      if (n >= 2 && nonzero_terms() >= 2) return detail::flint_pow(*this, n);
    }
    Polynomial r(F(1)), b = *this;
    while (n) {
      if (n & 1u) r = r * b;
      n >>= 1u;
      if (n) b = b * b;
    }
    return r;
  }
  Polynomial derivative() const {
    if (c_.size() <= 1) return Polynomial();
    std::vector<F> r(c_.size() - 1);
    for (size_t i = 1; i < c_.size(); ++i) r[i - 1] = c_[i] * F(static_cast<long>(i));
    return Polynomial(std::move(r));
  }
  /// p(inner(x)), by Horner in polynomials.
  Polynomial compose(const Polynomial& inner) const {
    Polynomial r;
    for (auto it = c_.rbegin(); it != c_.rend(); ++it) r = r * inner + Polynomial(*it);
    return r;
  }
  /// p / leading(p); the zero polynomial stays zero.
  Polynomial monic() const {
    if (is_zero()) return *this;
    Polynomial r = *this;
    const F l = c_.back();
    for (auto& x : r.c_) x /= l;
    return r;
  }
  /// Horner's rule at x in the scalar X (coefficients converted by scalar_cast<X>).
  template <class X>
  X operator()(const X& x) const {
    if (c_.empty()) return scalar_cast<X>(F(0));
    X r = scalar_cast<X>(c_.back());
    for (size_t i = c_.size() - 1; i-- > 0;) r = r * x + scalar_cast<X>(c_[i]);
    return r;
  }
  template <class G>
  Polynomial<G> cast() const {
    std::vector<G> v;
    v.reserve(c_.size());
    for (const auto& x : c_) v.push_back(scalar_cast<G>(x));
    return Polynomial<G>(std::move(v));
  }

 private:
  std::vector<F> c_;
  void trim() {
    while (!c_.empty() && detail::is_zero_coefficient(c_.back())) c_.pop_back();
  }
};

// Mixed polynomial/scalar arithmetic (the scalar converts to a constant polynomial).
template <class F> Polynomial<F> operator+(const Polynomial<F>& a, const F& b) { return a + Polynomial<F>(b); }
template <class F> Polynomial<F> operator+(const F& a, const Polynomial<F>& b) { return Polynomial<F>(a) + b; }
template <class F> Polynomial<F> operator-(const Polynomial<F>& a, const F& b) { return a - Polynomial<F>(b); }
template <class F> Polynomial<F> operator-(const F& a, const Polynomial<F>& b) { return Polynomial<F>(a) - b; }
template <class F> Polynomial<F> operator*(const Polynomial<F>& a, const F& b) { return a * Polynomial<F>(b); }
template <class F> Polynomial<F> operator*(const F& a, const Polynomial<F>& b) { return Polynomial<F>(a) * b; }

/// (quotient, remainder) with a = q b + r, deg r < deg b. Throws InputError if b is zero.
template <class F>
std::pair<Polynomial<F>, Polynomial<F>> divmod(const Polynomial<F>& a, const Polynomial<F>& b) {
  if (b.is_zero()) throw InputError("divmod: division by the zero polynomial");
  const int db = b.degree();
  if (a.degree() < db) return {Polynomial<F>(), a};
  if constexpr (std::is_same_v<F, rational>) {
    if (size_t(a.degree() - db + 1) * b.nonzero_terms() >= detail::flint_min_products) return detail::flint_divrem(a, b);
  }
  std::vector<F> r = a.coeffs();
  std::vector<F> q(static_cast<size_t>(a.degree() - db) + 1, F(0));
  const F& lb = b.leading();
  const auto& bc = b.coeffs();
  for (int k = a.degree() - db; k >= 0; --k) {
    F f = r[k + db] / lb;
    if (f != F(0)) {
      for (int i = 0; i <= db; ++i) r[k + i] -= f * bc[i];
    }
    r[k + db] = F(0);  // exact zero by construction (also over floating types)
    q[k] = std::move(f);
  }
  r.resize(static_cast<size_t>(db));
  return {Polynomial<F>(std::move(q)), Polynomial<F>(std::move(r))};
}

namespace detail {
template <class F>
Polynomial<F> euclid_gcd(Polynomial<F> a, Polynomial<F> b) {
  a = a.monic();
  b = b.monic();
  while (!b.is_zero()) {
    Polynomial<F> r = divmod(a, b).second.monic();
    a = std::move(b);
    b = std::move(r);
  }
  return a;
}
}  // namespace detail

/// Monic greatest common divisor; gcd(0,0) = 0. Over `rational` FLINT's fmpq_poly_gcd, over
/// floating types Euclid with monic normalisation at each step.
template <class F>
Polynomial<F> gcd(Polynomial<F> a, Polynomial<F> b) {
  return detail::euclid_gcd(std::move(a), std::move(b));
}

/// The reciprocal polynomial x^deg p p(1/x): the coefficients in reverse order. A root r != 0 of
/// p is a root 1/r of it, so gcd(p, reversed(p)) holds p's roots on |x| = 1 and its reciprocal pairs.
template <class F>
Polynomial<F> reversed(const Polynomial<F>& p) {
  std::vector<F> c = p.coeffs();
  std::reverse(c.begin(), c.end());
  return Polynomial<F>(std::move(c));
}

/// "3*x^2 - 1/2*x + 1" (descending powers; "0" for the zero polynomial).
std::string to_string(const Polynomial<rational>& p, const std::string& var = "x");

extern template class Polynomial<rational>;

/// The exact polynomial over Q: the one name for it in every module.
using QPoly = Polynomial<rational>;
extern template std::pair<Polynomial<rational>, Polynomial<rational>> divmod(const Polynomial<rational>&,
                                                                             const Polynomial<rational>&);
template <> Polynomial<rational> gcd(Polynomial<rational>, Polynomial<rational>);

}  // namespace hapstab
