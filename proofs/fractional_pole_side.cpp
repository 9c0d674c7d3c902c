// proofs/fractional_pole_side.cpp -- issue 46: b* with a fractional delay when H has a pole
// at z = -1 (a Tustin wall). Near wT = pi, with eps = pi - wT and tau = t_d/T, the objective of
// (45)/(54) is (T/2)[A(c) cos(tau wT) + E(c) sin(tau wT) cot(wT/2)]/B(c) (claim 001.eq45.delay_form);
// for the Tustin wall K + (2B/T)(z - 1)/(z + 1), B(c) = 1 + c ~ eps^2/2, A = (1 + c)(K - 2B/T),
// E(-1) = 4B/T, and cot(wT/2) = tan(eps/2) ~ eps/2, so
//   f ~ (T/2) (4B/T) sin(pi tau) (eps/2) / (eps^2/2) = 2B sin(pi tau) / eps:
// +inf as wT -> pi when sin(pi tau) > 0 (0 < tau < 1 mod 2: paper 001's Example 3), -inf when
// sin(pi tau) < 0 -- then b* is finite, an interior maximum. The exact path maps t_d = (p/q) T to
// w = e^{j wT/q}, where this pole sits at the END of the domain, c = cos(pi/q): only the side inside
// the domain may decide (before, both sides of a rational end were read, and tau = 3/2 gave
// "+inf [exact]" for b* = 7.32).
//   001.fracdelay.pole_side  b* = +inf exactly when sin(pi tau) > 0; otherwise b* is finite and its
//                            certified enclosure agrees with the objective evaluated ON THE UNIT CIRCLE
//                            (Horner in 50-digit MPFR, objective_at: another evaluation than the exact
//                            c-form the path maximises): no sample of an 800-point grid exceeds the
//                            enclosure's upper end, and the objective at the reported maximiser reaches
//                            its lower end
#include <cmath>
#include <sstream>

#include "hapstab/numeric/decimal.hpp"
#include "hapstab/passivity/bound.hpp"
#include "proofs/certify.hpp"
#include "proofs/proof.hpp"

namespace {

using namespace hapstab;
using namespace hapstab::passivity;
using hapstab::proofs::Instances;
using P = Polynomial<rational>;
using RF = RationalFunction<rational>;

HAPSTAB_PROOF(fractional_pole_side, "001", "t_d with a pole at z = -1: +inf only when sin(pi t_d/T) > 0") {
  const rational T(1, 1000);
  const RF tustin_dz = RF(P{rational(-1), rational(1)}) / RF(P{rational(1), rational(1)});  // (z - 1)/(z + 1)
  bool ok = true;
  Instances infinite{"t_d/T with sin(pi t_d/T) > 0: b* = +inf", 6}, finite{"t_d/T with sin(pi t_d/T) < 0: b* finite", 12};
  std::ostringstream worst;
  double max_excess = 0;
  for (const rational& K : {rational(20), rational(1000)})
    for (const rational& B : {rational(1, 2), rational(5)})
      for (const rational& tau : {rational(1, 100), rational(1, 2), rational(99, 100), rational(9, 4), rational(3, 2), rational(7, 2),
                                 rational(4, 3), rational(5, 3), rational(5, 4), rational(7, 4), rational(11, 2)}) {
        BoundProblem p;
        p.H = RF(K) + RF(2 * B / T) * tustin_dz;
        p.T = T;
        p.frac_delay = tau * T;
        // sin(pi tau) > 0 iff tau mod 2 lies in (0, 1)
        const rational m = tau - 2 * rational(static_cast<long>(std::floor(to_real<double>(tau) / 2)));
        const bool plus = m > 0 && m < 1;
        const Bound b = bound_certified(p, 20);
        if (plus) {
          infinite.count(true);
          ok = ok && b.infinite && b.status == Status::exact;
          {  // b* = +inf's certificate: the pole z = -1 at the band's end c = cos(pi/q), rational for q <= 3,
             // isolated by an interval for q >= 4 (check/bound_objective.hpp)
            proofs::BoundInstance inst{"K + 2*B*(z-1)/(T*(z+1))", T, {{"K", K}, {"B", B}}};
            inst.frac_delay = tau * T;
            proofs::CertificateRequest r;
            r.args = proofs::bound_args(inst);
            r.flags = {{"infinite", true}};
            check.certify("001.fracdelay.pole_side", r);
          }
          continue;
        }
        finite.count(true);
        {  // its certificate: b* finite, in the enclosure that `bound` prints (no expected value: the claim names none)
          proofs::BoundInstance inst{"K + 2*B*(z-1)/(T*(z+1))", T, {{"K", K}, {"B", B}}};
          inst.frac_delay = tau * T;
          proofs::CertificateRequest r;
          r.args = proofs::bound_args(inst);
          check.certify("001.fracdelay.pole_side", r);
        }
        if (b.infinite || !b.enclosure) {
          ok = false;
          continue;
        }
        const double lo = to_real<double>(b.enclosure->lo), hi = to_real<double>(b.enclosure->hi);
        const double wmax = 3.14159265358979323846 / to_real<double>(T);
        double grid = -INFINITY;
        for (int k = 0; k < 800; ++k) grid = std::max(grid, objective_at(p, wmax * (k + 0.5) / 800));
        const double at = b.omega_enclosure ? objective_at(p, to_real<double>((b.omega_enclosure->lo + b.omega_enclosure->hi) / 2)) : -INFINITY;
        const double tol = 1e-12 * std::max(1.0, std::abs(hi));  // the double image of 50-digit values
        max_excess = std::max(max_excess, (grid - hi) / std::max(1.0, std::abs(hi)));
        const bool this_ok = grid <= hi + tol && at >= lo - tol;
        if (!this_ok) worst << " K = " << K << ", B = " << B << ", tau = " << tau << ": grid " << grid << ", at " << at << ", [" << lo << ", " << hi << "];";
        ok = ok && this_ok;
      }
  check.claim("001.fracdelay.pole_side", "(45), (54), Example 3",
              "Tustin wall with t_d = tau T: b* = +inf exactly when sin(pi tau) > 0; for sin(pi tau) < 0 b* is a finite interior "
              "maximum, its enclosure agreeing with the objective evaluated on the unit circle -- at T = 1/1000, K in {20, 1000}, "
              "B in {1/2, 5}, tau in {1/100, 1/2, 99/100, 9/4, 3/2, 7/2, 4/3, 5/3, 5/4, 7/4, 11/2}",
              Status::certified, ok,
              "+inf [exact] exactly where sin(pi tau) > 0; elsewhere no sample of an 800-point grid on the unit circle (50-digit "
              "Horner) exceeds the upper end (largest relative excess " + to_decimal(exact_rational(max_excess), 3) +
                  ", tolerance 1e-12: the double image) and the objective at the maximiser reaches the lower end" + worst.str(),
              {infinite, finite});
}

}  // namespace
