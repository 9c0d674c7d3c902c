// hapstab/lti/circle_crossing.hpp -- where an eigenvalue of an affine family of rational matrices
// M(p) = M0 + p M1 can meet the unit circle: the real roots of
//   R(p) = Res_z( c(z, p), z^n c(1/z, p) ),   c(z, p) = det(zI - M(p)),  n the order.
//
// Theorem. c(., p) is monic of degree n for every p, and the resultant of a monic f with any g is
// prod over the roots mu of f of g(mu), whatever g's degree; so R(p) = prod_mu mu^n c(1/mu, p), which vanishes
// iff two roots of c(., p) satisfy mu mu' = 1 -- in particular (not only) whenever a root lies on |z| = 1,
// since then 1/mu = conj(mu) is a root too (real coefficients). The roots of c(., p) depend continuously on p,
// so on an interval of p where R has no root no root crosses the circle: the number of eigenvalues in the
// open unit disk is constant there, and M(p) Schur stable at one point of it is Schur stable on all of it.
// This decides stability near p = 0 where no enclosure of eigenvalues can: M(0) with a Jordan block at z = 1
// (a pure mass that nothing holds at p = 0), whose eigenvalues leave 1 like sqrt(p).
// Degrees: c has degree <= r = rank M1 in p (det(A - p U V^T) = det(A) det(I - p V^T A^-1 U) for every z
// where A = zI - M0 is invertible: a polynomial identity in z), and R, the determinant of the Sylvester matrix
// of c and z^n c(1/z) (2n rows, each entry of degree <= r in p), has degree <= 2 n r. So c is interpolated
// from r + 1 exact characteristic polynomials (realization.hpp) and R from its values at 2 n r + 1 integers,
// each the exact resultant of two polynomials with rational coefficients (FLINT).
// Used by stability/loop_max.hpp (stable on (0, a] where the walk towards 0 stops) and by the certificate
// checker of stability-loop-max (evidence no_crossing).
#pragma once

#include <string>

#include "hapstab/lti/state_space.hpp"
#include "hapstab/poly/polynomial.hpp"

namespace hapstab {

struct CircleCrossing {
  Polynomial<rational> R;   ///< R(p) / p^m, exact (zero when R vanishes identically)
  long zero_order = 0;      ///< m, the multiplicity of p = 0 as a root of R
  bool identically_zero = false;  ///< R = 0 for every p: some pair mu mu' = 1 at every p (nothing shown)
};

/// Res_{d,d}(c, z^d c(1/z)), d = deg c, exactly: FLINT's resultant at the actual degrees, times lc(c)^(d - deg c*)
/// (c* loses degree where c(0) = 0). Zero iff c has a root on |z| = 1 or a pair mu, 1/mu. Also the one-DOF
/// supremum's D(K) (stability/max_evidence.hpp).
rational reciprocal_resultant(const Polynomial<rational>& c);

/// R of the header for M(p) = M0 + p M1 (square, the same order, at most kCircleCrossingOrder, and
/// 2 n rank(M1) at most kCircleCrossingDegree: InputError beyond).
CircleCrossing circle_crossing(const Mat<rational>& M0, const Mat<rational>& M1);
constexpr long kCircleCrossingOrder = 64, kCircleCrossingDegree = 2048;

/// "" when no p in (0, a] gives M0 + p M1 an eigenvalue on the unit circle (R not identically 0 and R / p^m
/// without a real root in (0, a], by Sturm's theorem, poly/sturm.hpp); else why not.
std::string no_circle_crossing(const Mat<rational>& M0, const Mat<rational>& M1, const rational& a);

}  // namespace hapstab
