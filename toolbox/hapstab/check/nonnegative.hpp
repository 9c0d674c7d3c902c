// hapstab/check/nonnegative.hpp -- the one algebraic test behind the checkers: is a polynomial
// with rational coefficients >= 0 on a closed interval [a, b]? Decided exactly, by code written
// for the checker alone (not poly/sturm.hpp, which the producers use):
//   0. above degree 64, p at 33 equally spaced points of [a, b]: a negative value refutes at once
//      (a false claim costs 33 evaluations, not the gcds and Sturm sequence of steps 2-3).
//   1. p = 0: yes.
//   2. Yun's square-free decomposition p = c * prod_i a_i^i (gcds over Q); the odd part
//      O = prod_{i odd} a_i holds exactly the roots where p changes sign.
//   3. O with its roots at a and b divided out has no root in [a, b]: first by Descartes' rule
//      of signs on R(y) = (1 + y)^d O(a + (b - a)/(1 + y)) (no sign variation: no root y > 0, i.e.
//      none in (a, b)); when R has variations, by Sturm's theorem on the square-free O
//      (V(a) - V(b) = number of distinct roots in (a, b], ends not roots).
//   4. Then p has one sign on (a, b) away from its roots: p(x) > 0 at the first of deg p + 1
//      distinct points x in (a, b) where p(x) != 0 (one of them is not a root).
// Theorem (Sturm, 1829): for a square-free p with p(a), p(b) != 0, the number of real roots in
// (a, b) is V(a) - V(b), V the sign variations of the sequence p, p', -rem(p, p'), ...
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "hapstab/numeric/scalar.hpp"
#include "hapstab/poly/polynomial.hpp"

namespace hapstab::check {

/// nullopt when p >= 0 on [a, b] (a < b), else a sentence saying why not (a point where p < 0,
/// or a sign change inside).
std::optional<std::string> nonnegative_on(const Polynomial<rational>& p, const rational& a, const rational& b);

/// True when Descartes' rule of signs proves that q has no root in the open interval (a, b), a < b:
/// R(y) = (1 + y)^d q(a + (b - a)/(1 + y)) has no sign variation (its roots y > 0 are q's in (a, b)).
/// False says nothing.
bool descartes_no_root(const Polynomial<rational>& q, const rational& a, const rational& b);

/// The number of distinct real roots of the square-free q in (a, b), when q(a), q(b) != 0 (Sturm).
int sturm_count(const Polynomial<rational>& q, const rational& a, const rational& b);

/// q's Sturm sequence, built once for a caller that counts on many intervals (a bisection):
/// sturm_count(seq, a, b) is then sturm_count(q, a, b) without the divisions.
std::vector<Polynomial<rational>> sturm_sequence(const Polynomial<rational>& q);
int sturm_count(const std::vector<Polynomial<rational>>& seq, const rational& a, const rational& b);

}  // namespace hapstab::check
