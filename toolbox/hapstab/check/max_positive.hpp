// hapstab/check/max_positive.hpp -- the decision behind the `wedge` checker: is max(p1, p2) > 0
// at every point of a closed interval [a, b] (p1, p2 polynomials over Q)? Exact:
//   1. the ends a and b are tested directly;
//   2. the distinct roots of R = squarefree(p1 p2) inside (a, b) are isolated by bisection with
//      Sturm counts (check/nonnegative.hpp: sturm_count) into intervals (lo, hi), one root each,
//      R(lo), R(hi) != 0; p1 and p2 keep their signs between consecutive roots of R, so testing
//      every lo and hi (rational points) tests every open cell between roots;
//   3. at the root r in (lo, hi): when gcd(p1, p2) vanishes in (lo, hi), p1(r) = p2(r) = 0 (fails);
//      otherwise one of them, say p1, vanishes at r and the other has no root in [lo, hi], so
//      sign p2(r) = sign p2(lo): max(p1, p2)(r) > 0 iff p2(lo) > 0.
// With p2 = p1 it decides p1 > 0 on [a, b]. Non-strict (max >= 0): step 3 is not needed.
#pragma once

#include <optional>
#include <string>

#include "hapstab/numeric/scalar.hpp"
#include "hapstab/poly/polynomial.hpp"

namespace hapstab::check {

/// nullopt when max(p1, p2) > 0 on [a, b] (a < b), else where it is not (a point or an interval
/// holding a root where both are <= 0). With strict = false: max(p1, p2) >= 0 on [a, b] -- at a
/// root of p1 p2 the max is >= 0 by itself, so only the open cells between roots are tested, each
/// at a point inside it (an end of [a, b] that is a root stands for no cell).
std::optional<std::string> max_positive_on(const Polynomial<rational>& p1, const Polynomial<rational>& p2,
                                           const rational& a, const rational& b, bool strict = true);

}  // namespace hapstab::check
