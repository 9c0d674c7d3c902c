// Paper 001, Section V: the forms (35), (36), (37), (38) and (44) of r(jw) are ONE function, proven
// exactly as an identity of rational functions of t = tan(wT/2) with T a polynomial variable
// (coefficients in Q(t)); Re r = -T/2 exactly; (40): k = (1 - e^{-sT}) r = T e^{-sT} on s = jw;
// Theorem 1's rhat of (9) = r/(T(e^{-jwT} - 1)) is real and positive (exact, via Sturm).
#include <sstream>

#include "hapstab/poly/sturm.hpp"
#include "hapstab/sampling/r_exact.hpp"
#include "proofs/proof.hpp"

namespace {

using namespace hapstab;
using namespace hapstab::sampling;
using RF = RationalFunction<rational>;
using P = Polynomial<rational>;
using PT = Polynomial<RF>;  // polynomials in the symbol T with coefficients in Q(t)

// A form of r as (Re, Im) polynomials in T over Q(t): the paper's scalar prefactor c T (c rational)
// times the t-part built from the blocks of r_exact.hpp.
struct FormT {
  PT re, im;
};
FormT with_T(const rational& c, const ComplexRF& tpart_over_c) {
  const PT Tc = PT::monomial(1, RF(P(c)));
  return {Tc * PT(tpart_over_c.re), Tc * PT(tpart_over_c.im)};
}

}  // namespace

HAPSTAB_PROOF(sampling_r_identities, "001", "(35)=(36)=(37)=(38)=(44) as rational functions of t = tan(wT/2)") {
  using namespace tform;
  const ComplexRF emj = conj(exp_j_theta());  // e^{-j wT}
  // each form exactly as printed, prefactor separated: c T * (t-part)
  const FormT f35 = with_T(rational(1, 2), (emj - constant(1)) / (constant(1) - cos_theta()));
  const FormT f36 = with_T(rational(1, 4), (emj - constant(1)) * csc2_half());
  const FormT f37 = with_T(rational(1, 2), csc_half_exp_minus_j_half() * (constant(0) - j()));
  const FormT f38 = with_T(rational(-1, 2), constant(1) + j() * cot_half());
  const FormT f44 = with_T(rational(1), constant(1) / (exp_j_theta() - constant(1)));
  struct Named {
    const char* name;
    const FormT* f;
  };
  bool all = true;
  std::ostringstream ev;
  for (Named n : {Named{"(35)", &f35}, Named{"(36)", &f36}, Named{"(37)", &f37}, Named{"(38)", &f38}}) {
    const bool eq = n.f->re == f44.re && n.f->im == f44.im;
    all = all && eq;
    ev << n.name << (eq ? "=(44) " : "!=(44) ");
  }
  // and the library's r_over_T_* agree with these (the code the rest of hapstab uses)
  const bool lib = r_over_T_eq35() == r_over_T_eq44() && r_over_T_eq36() == r_over_T_eq44() &&
                   r_over_T_eq37() == r_over_T_eq44() && r_over_T_eq38() == r_over_T_eq44();
  ev << "; coefficientwise in T over Q(t); library forms agree: " << (lib ? "yes" : "no")
     << "; r/T = " << to_string(f44.re.coeff(1)) << " + j " << to_string(f44.im.coeff(1));
  check.claim("001.eq35-44.identity", "(35) = (36) = (37) = (38) = (44)",
              "all five forms of r(jw) are the same rational function of t = tan(wT/2), for every T",
              hapstab::Status::exact, all && lib, ev.str());

  // Re r = -T/2 exactly; Im r = -(T/2) cot(wT/2) = -T/(2t)
  const bool re_ok = f44.re == PT::monomial(1, RF(P(rational(-1, 2))));
  const bool im_ok = f44.im == PT::monomial(1, RF(P(rational(-1, 2)), P::monomial(1)));
  check.no_certificate("001.eq38.re_minus_T_half", "the r kind certifies r(jw) at one (T, w); this is an identity for every T and w: no certificate kind yet (issue 47)");
  check.claim("001.eq38.re_minus_T_half", "(38), (44)", "Re r(jw) = -T/2 and Im r(jw) = -(T/2) cot(wT/2) exactly",
              hapstab::Status::exact, re_ok && im_ok,
              "Re = " + to_string(f44.re.coeff(1)) + " * T, Im = " + to_string(f44.im.coeff(1)) + " * T");

  // (40)-(44) on s = jw: k = (1 - e^{-jwT}) r = T e^{-jwT}
  const ComplexRF k_over_T = (constant(1) - emj) * r_over_T_eq44();
  check.claim("001.eq40.k_is_T_exp", "(40), (44)", "k(jw) = (1 - e^{-jwT}) r(jw) equals T e^{-jwT} exactly",
              hapstab::Status::exact, k_over_T == emj,
              "(1 - e^{-jwT}) / (e^{jwT} - 1) = e^{-jwT} in Q(t): " + to_string(k_over_T.re) + " + j " +
                  to_string(k_over_T.im));

  // Theorem 1: rhat = r/(T(e^{-jwT} - 1)) is real and positive for 0 < wT < 2 pi (t != 0 real)
  const ComplexRF rh = rhat_from_eq44();
  const bool real = rh.im.is_zero();
  const bool is_expected = rh.re == RF(P(std::vector<rational>{1, 0, 1}), P(std::vector<rational>{0, 0, 4}));
  // positivity on t real, t != 0: numerator has no real root and positive leading coefficient,
  // denominator's only real root is t = 0 (wT = 0, a pole) and its leading coefficient is positive
  const auto num_roots = isolate_real_roots(rh.re.num());
  const auto den_roots = isolate_real_roots(rh.re.den());
  const bool positive = num_roots.empty() && rh.re.num().leading() > 0 && rh.re.den() == P::monomial(2) &&
                        den_roots.size() == 1 && den_roots[0].lo <= 0 && 0 <= den_roots[0].hi;
  check.claim("001.eq9.rhat_real_positive", "(9), Theorem 1",
              "rhat(w) = r(jw)/(T(e^{-jwT}-1)) is real and > 0 for every wT not a multiple of 2 pi",
              hapstab::Status::exact, real && is_expected && positive,
              "rhat = " + to_string(rh.re) + " (= 1/(4 sin^2(wT/2))), Im rhat = 0 identically; Sturm: numerator " +
                  std::to_string(num_roots.size()) + " real roots, denominator = t^2 (> 0 for t != 0)");
}
