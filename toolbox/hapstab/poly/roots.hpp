// hapstab/poly/roots.hpp -- certified enclosures of the complex roots of a polynomial with
// rational coefficients: where a mode is, printed with a proof that it is there.
//
// p is factored over Z (FLINT, Zassenhaus): a linear factor is a rational root, given exactly
// (rounded outward to doubles: z = 2, s = 0 print as such); every other irreducible factor is
// handed to Arb's acb_poly_find_roots at 64, 128, ... bits until each of its roots is isolated in
// its own complex ball (Arb proves that each ball holds exactly one root); the multiplicity is the
// factor's exponent, exactly. Each enclosure is returned as outward-rounded double intervals for
// Re, Im and |z|, so that a caller can say "z in [0.4999999999, 0.5000000001]" and know it holds.
#pragma once

#include <string>
#include <vector>

#include "hapstab/poly/polynomial.hpp"

namespace hapstab {

struct RootEnclosure {
  double re_lo = 0, re_hi = 0, im_lo = 0, im_hi = 0;  ///< the root lies in [re_lo, re_hi] + j [im_lo, im_hi]
  double abs_lo = 0, abs_hi = 0;                      ///< |root| in [abs_lo, abs_hi]
  int multiplicity = 1;                               ///< exact
  /// "z = 2" when the interval is one double, else "z = [lo, hi]" (Re, then "+ j [...]" unless
  /// Im = 0 is certain), 10 digits rounded outward. `pair`: the root and its conjugate at once,
  /// "z = [..] +- j [..]" (the enclosure of the one with Im > 0).
  std::string text(const char* var = "z", bool pair = false) const;
};

/// Every distinct root of p (p != 0, degree >= 0), isolated and enclosed. NumericalError when
/// Arb has not isolated them at 4096 bits (never seen on the degrees hapstab meets).
std::vector<RootEnclosure> enclose_roots(const Polynomial<rational>& p);

/// p = c prod f_k^{e_k} over Q, each f_k irreducible (primitive, integer coefficients), exactly:
/// what a caller decides per distinct factor (a degree-126 hidden factor that is one quadratic
/// to the power 63 is decided as that quadratic).
struct IrreducibleFactor {
  Polynomial<rational> f;
  int multiplicity = 1;
};
std::vector<IrreducibleFactor> factor_over_q(const Polynomial<rational>& p);

}  // namespace hapstab
