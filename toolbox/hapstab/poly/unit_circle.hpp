// hapstab/poly/unit_circle.hpp -- the substitution t = tan(theta/2) on the unit circle.
//
//   z = e^{j theta} = (1 + j t)/(1 - j t) = (1 - t^2 + 2 j t)/(1 + t^2),
//   cos theta = (1 - t^2)/(1 + t^2),  sin theta = 2t/(1 + t^2),  cot(theta/2) = 1/t.
// For a rational function H(z) = N(z)/D(z) with rational coefficients, with n = max(deg N, deg D),
//   N~(t) = (1 - j t)^n N(z(t)) = sum_k a_k (1 + j t)^k (1 - j t)^{n-k}   (a complex polynomial
// in t with rational real and imaginary parts), likewise D~, and H = N~/D~, so
//   Re H = Re(N~ conj D~)/|D~|^2,  Im H = Im(N~ conj D~)/|D~|^2,
// exact rational functions of the real t (reduced). Paper 001 uses this with wT = theta: it
// turns (35)-(38), (44) and the bound (45) into rational functions of t = tan(wT/2).
// theta in [0, pi) <-> t in [0, inf); theta = pi is t -> inf (the caller uses degrees and
// leading coefficients there).
#pragma once

#include "hapstab/poly/rational_function.hpp"

namespace hapstab {

/// re(t) + j im(t) with rational coefficients, t real.
struct ComplexPolynomial {
  Polynomial<rational> re, im;
};
ComplexPolynomial operator+(const ComplexPolynomial& a, const ComplexPolynomial& b);
ComplexPolynomial operator-(const ComplexPolynomial& a, const ComplexPolynomial& b);
ComplexPolynomial operator*(const ComplexPolynomial& a, const ComplexPolynomial& b);
ComplexPolynomial conj(const ComplexPolynomial& a);
ComplexPolynomial pow(const ComplexPolynomial& a, unsigned n);
/// |a|^2 = re^2 + im^2 (t real).
Polynomial<rational> norm(const ComplexPolynomial& a);

/// (1 - j t)^n p(z(t)) for z = (1 + j t)/(1 - j t); n must be >= deg p.
ComplexPolynomial unit_circle_polynomial(const Polynomial<rational>& p, int n);

/// Exact real and imaginary parts of a rational function of t.
struct ReIm {
  RationalFunction<rational> re, im;
};

/// Re/Im of H(z) at z = (1 + j t)/(1 - j t), t real, as reduced rational functions of t.
ReIm on_unit_circle(const RationalFunction<rational>& H);

/// Re/Im of N(t)/D(t) for complex polynomials N, D (D not zero).
ReIm re_im(const ComplexPolynomial& N, const ComplexPolynomial& D);

}  // namespace hapstab
