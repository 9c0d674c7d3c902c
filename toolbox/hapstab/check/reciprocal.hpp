// hapstab/check/reciprocal.hpp -- where an affine family of real polynomials c(z; K) = c0 + K c1
// (deg c1 < deg c0 = d: the degree and the leading coefficient do not depend on K) can have a root
// on the unit circle: the roots in K of
//   D(K) = Res_{d,d}(c, c*),   c*(z) = z^d c(1/z)                (the stability-max checker)
// Theorem: with c of exact degree d, Res_{d,d}(c, g) = lc(c)^d prod_{c(a) = 0} g(a) for any g of
// formal degree d, so D(K) = 0 iff c and c* share a root b; b != 0 (c*(0) = lc(c) != 0), so
// c(b) = c(1/b) = 0: a pair b, 1/b of roots (b = +-1 alone counts), one of them with |.| >= 1. A
// root e^{j theta} on the circle is such a pair (real coefficients: e^{-j theta} = 1/e^{j theta}
// is a root too). So D(K) = 0 => c(.; K) NOT Schur stable, and D(K) != 0 => no root on the circle.
// D is a polynomial of degree <= 2d in K (the Sylvester determinant of order 2d, every entry
// affine in K): it is interpolated exactly (Newton) from its values at K = 0, 1, ..., 2d, each an
// exact resultant by Euclid's algorithm over Q: Res(f, g) = (-1)^(mn) lc(g)^(m - deg r) Res(g, r),
// r = f mod g (m = deg f, n = deg g); Res(f, g0) = g0^m; Res_{d,d} = lc(c)^(d - deg c*) Res(c, c*).
// Written for check/ alone (the producer computes its own D with FLINT's resultant).
#pragma once

#include <optional>

#include "hapstab/numeric/scalar.hpp"
#include "hapstab/poly/polynomial.hpp"

namespace hapstab::check::detail {

/// Res(f, g) of two non-zero polynomials, at their actual degrees (Euclid, exact).
rational resultant(const Polynomial<rational>& f, const Polynomial<rational>& g);

/// Res_{d,d}(c, c*) of c of degree d >= 1 (c* = z^d c(1/z)).
rational reciprocal_resultant(const Polynomial<rational>& c);

/// D(K) = Res_{d,d}(c0 + K c1, (c0 + K c1)*) as a polynomial in K; deg c1 < deg c0 = d >= 1.
Polynomial<rational> reciprocal_resultant(const Polynomial<rational>& c0, const Polynomial<rational>& c1);

/// The number of distinct real roots of p != 0 in the open interval (a, b), or in (a, b] when
/// `closed_b`; b = nullopt is +infinity. Exact: the square-free part, its roots at a and b divided
/// out, Descartes' rule on the interval (no sign variation: none) and else Sturm's theorem.
int roots_between(const Polynomial<rational>& p, const rational& a, const std::optional<rational>& b, bool closed_b);

}  // namespace hapstab::check::detail
