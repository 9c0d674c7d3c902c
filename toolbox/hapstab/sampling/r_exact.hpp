// hapstab/sampling/r_exact.hpp -- r(jw)/T of paper 001, forms (35)-(38) and (44), as EXACT
// complex rational functions of t = tan(wT/2) (polynomial arithmetic over Q; no sample points).
//
// Building blocks (theta = wT, c = cos(theta/2), s = sin(theta/2), t = s/c):
//   e^{j theta} = (1 + j t)/(1 - j t),  cos theta = (1 - t^2)/(1 + t^2),  sin theta = 2t/(1 + t^2),
//   cot(theta/2) = 1/t,  csc^2(theta/2) = (c^2 + s^2)/s^2 = (1 + t^2)/t^2,
//   csc(theta/2) e^{-j theta/2} = (c - j s)/s = (1 - j t)/t   (degree-0 homogeneous in c, s),
//   e^{-j pi/2} = -j.
// Each form is T times a function of theta alone (T enters as a scalar factor: T/2, T/4, -T/2, T),
// so the identity of the t-functions proves the identity for every T; proofs/sampling_identities.cpp
// also carries T as a polynomial variable over Q(t).
//
// Implements: paper 001 (35), (36), (37), (38), (44).
#pragma once

#include <string>

#include "hapstab/poly/rational_function.hpp"

namespace hapstab::sampling {

/// re + j im with re, im in Q(t) (t real).
struct ComplexRF {
  RationalFunction<rational> re, im;
};
ComplexRF operator+(const ComplexRF& a, const ComplexRF& b);
ComplexRF operator-(const ComplexRF& a, const ComplexRF& b);
ComplexRF operator*(const ComplexRF& a, const ComplexRF& b);
ComplexRF operator/(const ComplexRF& a, const ComplexRF& b);  ///< throws InputError if b = 0
bool operator==(const ComplexRF& a, const ComplexRF& b);
ComplexRF conj(const ComplexRF& a);

/// The building blocks above.
namespace tform {
ComplexRF t();             ///< t (real)
ComplexRF j();             ///< the imaginary unit
ComplexRF constant(const rational& c);
ComplexRF exp_j_theta();   ///< e^{j theta}
ComplexRF cos_theta();
ComplexRF sin_theta();
ComplexRF cot_half();      ///< cot(theta/2)
ComplexRF csc2_half();     ///< csc^2(theta/2)
ComplexRF csc_half_exp_minus_j_half();  ///< csc(theta/2) e^{-j theta/2}
}  // namespace tform

/// r/T for each form, built from the blocks exactly as the paper writes it.
ComplexRF r_over_T_eq35();  ///< 1/2 (e^{-j theta} - 1)/(1 - cos theta)
ComplexRF r_over_T_eq36();  ///< (e^{-j theta} - 1) 1/4 csc^2(theta/2)
ComplexRF r_over_T_eq37();  ///< 1/2 csc(theta/2) e^{-j theta/2} e^{-j pi/2}
ComplexRF r_over_T_eq38();  ///< -1/2 (1 + j cot(theta/2))
ComplexRF r_over_T_eq44();  ///< 1/(e^{j theta} - 1)
/// rhat of (9) as r/(T (e^{-j theta} - 1)), from (44): must be real, = (1 + t^2)/(4 t^2).
ComplexRF rhat_from_eq44();

std::string to_string(const RationalFunction<rational>& f, const std::string& var = "t");

}  // namespace hapstab::sampling
