// hapstab/stability/max_evidence.hpp -- what the producer of a `stability-max` certificate
// (cli/certificate.hpp; check/stability_max_check.hpp) needs beyond max_gain: the exact family
// c(z; K) = c0(z) + K c1(z) of sampled_loop.hpp (H = H0 + K H1, L = lcm of their denominators)
// and the polynomial D(K) = Res_{d,d}(c, c*), c*(z) = z^d c(1/z), whose roots are the K where c has
// a pair of roots b, 1/b (every root on the unit circle is one): the certificate's evidence must
// avoid them (a stable probe below the first, an unstable one for sup = 0). D comes from FLINT's
// fmpq_poly_resultant at 2d + 1 values of K, interpolated (D has degree <= 2d: a Sylvester
// determinant of order 2d with entries affine in K) -- not the checkers' own Euclid.
#pragma once

#include <optional>
#include <utility>

#include "hapstab/stability/sampled_loop.hpp"

namespace hapstab::stability {

/// (c0, c1) of max_gain's characteristic polynomial when every device pole is at s = 0 (exact
/// data), else nullopt. loop.H_gain must be set.
std::optional<std::pair<Polynomial<rational>, Polynomial<rational>>> exact_family(const Loop& loop);

/// D(K) = Res_{d,d}(c0 + K c1, its reciprocal) as a polynomial in K; deg c1 < deg c0 = d >= 1.
Polynomial<rational> reciprocal_resultant(const Polynomial<rational>& c0, const Polynomial<rational>& c1);

}  // namespace hapstab::stability
