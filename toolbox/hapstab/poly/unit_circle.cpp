#include "hapstab/poly/unit_circle.hpp"

namespace hapstab {

ComplexPolynomial operator+(const ComplexPolynomial& a, const ComplexPolynomial& b) {
  return {a.re + b.re, a.im + b.im};
}
ComplexPolynomial operator-(const ComplexPolynomial& a, const ComplexPolynomial& b) {
  return {a.re - b.re, a.im - b.im};
}
ComplexPolynomial operator*(const ComplexPolynomial& a, const ComplexPolynomial& b) {
  return {a.re * b.re - a.im * b.im, a.re * b.im + a.im * b.re};
}
ComplexPolynomial conj(const ComplexPolynomial& a) { return {a.re, -a.im}; }
ComplexPolynomial pow(const ComplexPolynomial& a, unsigned n) {
  ComplexPolynomial r{Polynomial<rational>(rational(1)), Polynomial<rational>()}, b = a;
  while (n) {
    if (n & 1u) r = r * b;
    n >>= 1u;
    if (n) b = b * b;
  }
  return r;
}
Polynomial<rational> norm(const ComplexPolynomial& a) { return a.re * a.re + a.im * a.im; }

ComplexPolynomial unit_circle_polynomial(const Polynomial<rational>& p, int n) {
  if (n < p.degree())
    throw InputError("unit_circle_polynomial: n = " + std::to_string(n) + " < degree " + std::to_string(p.degree()));
  const Polynomial<rational> t = Polynomial<rational>::monomial(1);
  const ComplexPolynomial plus{Polynomial<rational>(rational(1)), t};    // 1 + j t
  const ComplexPolynomial minus{Polynomial<rational>(rational(1)), -t};  // 1 - j t
  const int d = p.degree();
  if (d < 0) return {};
  // powers of (1 - jt), built once
  std::vector<ComplexPolynomial> pm(static_cast<size_t>(n) + 1);
  pm[0] = ComplexPolynomial{Polynomial<rational>(rational(1)), Polynomial<rational>()};
  for (int k = 1; k <= n; ++k) pm[k] = pm[k - 1] * minus;
  // Horner in (1 + jt): s = sum_k a_k (1 + jt)^k (1 - jt)^(d-k), then r = s (1 - jt)^(n-d);
  // products with the linear 1 + jt only, O(n^2) coefficient operations instead of O(n^3)
  const auto scaled = [](const ComplexPolynomial& c, const rational& a) { return ComplexPolynomial{c.re * a, c.im * a}; };
  ComplexPolynomial s = scaled(pm[0], p.coeffs()[d]);
  for (int k = d - 1; k >= 0; --k) {
    s = s * plus;
    const rational& a = p.coeffs()[k];
    if (a != 0) s = s + scaled(pm[d - k], a);
  }
  return n == d ? s : s * pm[n - d];
}

ReIm re_im(const ComplexPolynomial& N, const ComplexPolynomial& D) {
  Polynomial<rational> d = norm(D);
  if (d.is_zero()) throw InputError("re_im: zero denominator");
  ComplexPolynomial ncd = N * conj(D);
  return {RationalFunction<rational>(ncd.re, d), RationalFunction<rational>(ncd.im, d)};
}

ReIm on_unit_circle(const RationalFunction<rational>& H) {
  const int n = std::max(H.num().degree(), H.den().degree());
  return re_im(unit_circle_polynomial(H.num(), std::max(n, 0)), unit_circle_polynomial(H.den(), std::max(n, 0)));
}

}  // namespace hapstab
