#include "hapstab/sampling/r_exact.hpp"

namespace hapstab::sampling {


ComplexRF operator+(const ComplexRF& a, const ComplexRF& b) { return {a.re + b.re, a.im + b.im}; }
ComplexRF operator-(const ComplexRF& a, const ComplexRF& b) { return {a.re - b.re, a.im - b.im}; }
ComplexRF operator*(const ComplexRF& a, const ComplexRF& b) {
  return {a.re * b.re - a.im * b.im, a.re * b.im + a.im * b.re};
}
ComplexRF operator/(const ComplexRF& a, const ComplexRF& b) {
  QRatFun d = b.re * b.re + b.im * b.im;
  if (d.is_zero()) throw InputError("ComplexRF: division by zero");
  return {(a.re * b.re + a.im * b.im) / d, (a.im * b.re - a.re * b.im) / d};
}
bool operator==(const ComplexRF& a, const ComplexRF& b) { return a.re == b.re && a.im == b.im; }
ComplexRF conj(const ComplexRF& a) { return {a.re, -a.im}; }

namespace tform {
ComplexRF t() { return {QRatFun(QPoly::monomial(1)), QRatFun(QPoly())}; }
ComplexRF j() { return {QRatFun(QPoly()), QRatFun(QPoly(rational(1)))}; }
ComplexRF constant(const rational& c) { return {QRatFun(QPoly(c)), QRatFun(QPoly())}; }
ComplexRF exp_j_theta() { return (constant(1) + j() * t()) / (constant(1) - j() * t()); }
ComplexRF cos_theta() { return (constant(1) - t() * t()) / (constant(1) + t() * t()); }
ComplexRF sin_theta() { return constant(2) * t() / (constant(1) + t() * t()); }
ComplexRF cot_half() { return constant(1) / t(); }
ComplexRF csc2_half() { return (constant(1) + t() * t()) / (t() * t()); }
ComplexRF csc_half_exp_minus_j_half() { return (constant(1) - j() * t()) / t(); }
}  // namespace tform

using namespace tform;

ComplexRF r_over_T_eq35() {
  ComplexRF emj = conj(exp_j_theta());  // e^{-j theta} (t real)
  return constant(rational(1, 2)) * (emj - constant(1)) / (constant(1) - cos_theta());
}
ComplexRF r_over_T_eq36() {
  ComplexRF emj = conj(exp_j_theta());
  return (emj - constant(1)) * constant(rational(1, 4)) * csc2_half();
}
ComplexRF r_over_T_eq37() {
  ComplexRF e_mj_pi_half = constant(0) - j();  // e^{-j pi/2}
  return constant(rational(1, 2)) * csc_half_exp_minus_j_half() * e_mj_pi_half;
}
ComplexRF r_over_T_eq38() { return constant(rational(-1, 2)) * (constant(1) + j() * cot_half()); }
ComplexRF r_over_T_eq44() { return constant(1) / (exp_j_theta() - constant(1)); }
ComplexRF rhat_from_eq44() { return r_over_T_eq44() / (conj(exp_j_theta()) - constant(1)); }

std::string to_string(const RationalFunction<rational>& f, const std::string& var) {
  if (f.den() == QPoly(rational(1))) return "(" + hapstab::to_string(f.num(), var) + ")";
  return "(" + hapstab::to_string(f.num(), var) + ")/(" + hapstab::to_string(f.den(), var) + ")";
}

}  // namespace hapstab::sampling
