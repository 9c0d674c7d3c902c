// hapstab/check/bound_objective.hpp -- the objective of paper 001 (45)/(54) as the checkers of
// check/ derive it (not passivity::objective, nor the fractional-delay path's H(w^q)/S(w)):
//
//   b* = sup_{0 <= w <= pi/T} Re{ T H(z) z^-n e^{-j w t_d} / (1 - z) } + eta,   z = e^{jwT}.
//
// With tau = n + t_d/T = P/q in lowest terms (q = 1 for an integer delay), put phi = wT/q,
// v = e^{j phi}: z = v^q and z^-n e^{-j w t_d} = e^{-j tau wT} = conj(v)^P, so the objective is
//   Re{ T N(v^q) conj(v)^P / (D(v^q) (1 - v^q)) },   H = N/D,   phi in [0, pi/q].
// Put c = cos(phi), s = sin(phi) (v = c + js, s^2 = 1 - c^2), every polynomial in v as
// a(c) + js b(c) (check/on_circle.hpp): N(v^q) conj(v)^P conj(D(v^q)) = X + jsY and
// 1 - v^q = Ea + js Eb, so multiplying by conj(D (1 - v^q)) / |D (1 - v^q)|^2,
//   f(c) = A(c)/B(c) + eta,   A = T (X Ea + (1 - c^2) Y Eb),
//                             B = (Da^2 + (1 - c^2) Db^2)(Ea^2 + (1 - c^2) Eb^2) >= 0 on [-1, 1],
// with every common factor (1 - c) of A and B divided out (1 - c > 0 inside the domain, so the
// quotient is the same function and B stays >= 0). phi in [0, pi/q] <-> c in [cos(pi/q), 1] one to
// one; B = 0 only at the finitely many poles of H on the unit circle (and at c = 1 before the
// division, where the limit is finite when H(1) is). For q = 1 this is the integer-delay
// derivation: Ea = 1 - c, Eb = -1 give A = T (1 - c)(X - (1 + c) Y), B = 2 (1 - c)|D|^2.
//
// The domain's end cos(pi/q) is irrational for q >= 4. The checkers never need it: an upper bound
// is shown on a rational [c_lo, 1] that contains the domain, a witness is shown to lie inside it:
//   c_lo <= cos(pi/q)          iff  c_lo = -1, or U_{k-1}(c_lo) <= 0 for some k = 1 .. q
//                              (phi < pi/q iff sin(k phi) > 0 for every k <= q: if phi >= pi/q,
//                              the first k with k phi >= pi has k phi in [pi, 2 pi), sin <= 0);
//   c0 in [cos(pi/q), 1]       iff  U_{k-1}(c0) > 0 for k = 1 .. q-1 and U_{q-1}(c0) >= 0, c0 in [-1, 1]
//                              (phi0 <= pi/q: sin(k phi0) > 0 for k < q, >= 0 for k = q; phi0 > pi/q:
//                              the first k with k phi0 > pi has k phi0 in (pi, 2 pi), sin < 0),
// U_k the Chebyshev polynomials of the second kind (U_0 = 1, U_1 = 2c, U_k = 2c U_{k-1} - U_{k-2}).
// The same fact lets an upper bound cross the irrational end: U_{q-1} > 0 on (cos(pi/q), 1] with a
// simple root at cos(pi/q), so P >= 0 on the domain if P U_{q-1} >= 0 on [c_lo, 1]. That is the
// test where H has a pole at z = -1 and f -> -inf at wT = pi (issue 46 item 1 with t_d = 1.25 T):
// there A has a simple and B a double zero at cos(pi/q), so P = (hi - eta) B - A changes sign AT
// the end and is negative just beyond it; P U_{q-1} is not.
#pragma once

#include <optional>
#include <string>

#include <nlohmann/json.hpp>

#include "hapstab/numeric/scalar.hpp"
#include "hapstab/poly/polynomial.hpp"
#include "hapstab/poly/rational_function.hpp"

namespace hapstab::check::detail {

/// The model fields of (45)/(54) besides H: T > 0, the delay n (an integer in [0, 100000]),
/// t_d = model.frac_delay (seconds, >= 0; 0 when absent), eta >= 0; tau = n + t_d/T = P/q.
struct DelayModel {
  rational T, td, eta;
  long n = 0;
  long P = 0, q = 1;
};
/// Reads them (InputError naming the field); refuses (InputError) a model whose polynomials in c
/// would exceed `max_size` = q (max(deg N, deg D) + 1) + P, checked before anything is expanded.
DelayModel read_delay_model(const nlohmann::json& model);
void check_size(const DelayModel& m, int deg_num, int deg_den, long max_size);

struct ObjectivePolys {
  Polynomial<rational> A, B;  ///< f = A/B + eta in c = cos(wT/q), B >= 0 on [-1, 1]
};
/// A and B of the header for H = N/D (exact), T, tau = P/q.
ObjectivePolys bound_objective(const RationalFunction<rational>& H, const rational& T, long P, long q);

/// c <= cos(pi/q), decided exactly: c = -1, or some U_{k-1}(c) <= 0, k = 1 .. q (the header).
bool at_or_below_domain_end(const rational& c, long q);
/// c in [cos(pi/q), 1] (the header).
bool in_domain(const rational& c, long q);
/// U_k(c), the Chebyshev polynomial of the second kind.
Polynomial<rational> chebyshev_u(long k);

/// nullopt when A/B <= bound on the band [cos(pi/q), 1]: c_lo shown <= cos(pi/q), and
/// P = bound B - A >= 0 on [c_lo, 1], or P U_{q-1} >= 0 there; else what failed. `how` gets the
/// test that showed it, in words; `bound_name` is how both name the bound ("(hi - eta)").
std::optional<std::string> upper_bound_fails(const ObjectivePolys& f, const rational& bound, const std::string& bound_name,
                                             const rational& c_lo, long q, std::string& how);
/// nullopt when the witness c0 lies in the band and A/B reduced by gcd(A, B) (f's value or limit
/// at c0, which the sup reaches) is >= target there; else what failed.
std::optional<std::string> lower_bound_fails(const ObjectivePolys& f, const rational& target, const rational& c0, long q);

/// nullopt when the objective is unbounded above on the band (b* = +inf), shown at a pole c_p:
/// with A/B reduced by gcd(A, B) to Ar/Br, Br(c_p) = 0 (so Ar(c_p) != 0) and Br = (c - c_p)^m R,
/// R(c_p) != 0, the objective near c_p is Ar(c_p)/((c - c_p)^m R(c_p)) to first order, so it tends
/// to +inf as c -> c_p from the side sigma = +1 (c > c_p) or -1 (c < c_p) iff
/// sign Ar(c_p) * sigma^m * sign R(c_p) > 0. The side must lie in the band: c_p in [cos(pi/q), 1],
/// and c_p < 1 for sigma = +1, c_p > cos(pi/q) strictly for sigma = -1 (c_p > -1 for q = 1; for
/// q >= 2, U_{k-1}(c_p) > 0 for every k = 1 .. q, i.e. phi_p < pi/q). Else what failed.
std::optional<std::string> unbounded_above_fails(const ObjectivePolys& f, const rational& c_p, long side, long q);

/// nullopt when the objective is unbounded above at the band's irrational end c_e = cos(pi/q), q >= 2
/// (H's pole at z = -1 with a fractional delay), shown on the rational interval (s, b] the evidence
/// gives, everything decided exactly: U_{q-1} (square-free, roots cos(k pi/q)) has exactly one root
/// in (s, 1) and one in (s, b), so s < c_e < b and c_e is U's only root in (s, 1); the reduced
/// denominator R = B/gcd(A, B) vanishes at c_e: gcd(R, U_{q-1}) has a root in (s, 1) (its roots are
/// U's); R has no other root in (s, b] (its square-free part, Sturm: one root there) and Ar = A/gcd
/// none (Sturm: none). So f = Ar/R keeps the sign of Ar(b) R(b) on (c_e, b], where |f| -> inf as
/// c -> c_e from above (inside the band): +inf iff Ar(b) R(b) > 0. Else what failed.
std::optional<std::string> unbounded_at_end_fails(const ObjectivePolys& f, const rational& s, const rational& b, long q);

/// nullopt when the objective is unbounded above at a pole c_p inside the band that the rational
/// interval (s, b) isolates (an irrational one: H's pole on the circle seen through t_d/T = p/q,
/// cos(theta_p/q)), everything decided exactly: s and b in the band [cos(pi/q), 1], s < b; the reduced
/// denominator R = B/gcd(A, B) has exactly one root in (s, b) and none at s or b (its square-free
/// part, Sturm), Ar = A/gcd none in [s, b]. So f = Ar/R keeps the sign of Ar(b) R(b) on (c_p, b] and of
/// Ar(s) R(s) on [s, c_p), and |f| -> inf as c -> c_p (R -> 0, |Ar| bounded below on [s, b]): +inf from
/// the side sigma = +1 iff Ar(b) R(b) > 0, from sigma = -1 iff Ar(s) R(s) > 0. Else what failed.
std::optional<std::string> unbounded_inside_fails(const ObjectivePolys& f, const rational& s, const rational& b, long side, long q);

/// A rational in a message: "p/q", cut at 40 characters.
std::string shortened(const rational& x);

}  // namespace hapstab::check::detail
