// hapstab/check/bound_cells.hpp -- b* of paper 001 (45)/(54) bounded cell by cell, without
// expanding the delay: the `bound` certificate's evidence form for long delays (evidence.cells;
// check/bound_check.hpp), where the expanded polynomials in cos(wT/q) would have degree ~n.
//
// Derivation (the checker's own; check/on_circle.hpp): on z = e^{j theta}, c = cos theta,
// s = sin theta, with H = N/D and N(z) conj(D(z)) = X(c) + j s Y(c), |D|^2 = B(c), and
// T/(1 - z) = (T/2)(1 + j cot(theta/2)), e^{-j nu theta} (nu = n + t_d/T, any rational >= 0):
//   Re{T H z^-n e^{-j w t_d}/(1 - z)} = (T/2) [(X cos nu theta + s Y sin nu theta)
//                                              - (s Y cos nu theta - X sin nu theta) cot(theta/2)] / B
// and s cot(theta/2) = 1 + c, s sin(nu theta) = (1 - c) S_nu(theta), so
//   f(theta) = eta + (T/2) [A(c) cos(nu theta) + E(c) S_nu(theta)] / B(c),
//   A = X - (1 + c) Y,  E = X + (1 - c) Y,  S_nu(theta) = sin(nu theta) cot(theta/2)
//                                                       = 2 nu cos(theta/2) sinc(nu theta) / sinc(theta/2),
// the sinc form regular on [0, 2 pi) (numeric/jet.hpp: sinc near 0 by its Taylor polynomial with the
// remainder bounded). b* = sup f over theta = wT in [0, pi].
//
// Theorem checked (claim "b* in [lo, hi]"; check/bound_max_check.hpp uses the same two tests on
// H0 + K H1 at K = 0, lo and hi):
//   (upper) f < hi on [0, pi] if the cells [theta_{i-1}, theta_i] (theta_0 = 0 < theta_1 < ... <
//           theta_k, rationals, theta_k > pi shown with a ball of pi) each have
//           f(m) + f'([theta_{i-1}, theta_i]) [-r, r] < hi, m the midpoint, r the half-width (the
//           mean value theorem), every quantity an Arb ball (numeric/jet.hpp's order-2 jets);
//           f on the part of the last cell beyond pi is f's formula there (the identities above
//           hold for every theta in (0, 2 pi)), so the cell bounds its part inside too;
//   (lower) b* >= lo if f(theta0) > lo at the witness theta0 in [0, pi] (a ball of f at the point).
// B's ball containing 0 (a pole of H on the circle) makes the cell's bound infinite: it fails -- except a
// simple pole at z = -1 with nu = n an integer (the Tustin wall with a delay, since stop 81): H = H~ + rho/(z + 1),
// rho = N(-1)/D'(-1), A, E, B are H~'s (no pole at -1: B(-1) != 0), and the pole's part is
//   T Re{rho e^{-j n theta}/((1 + z)(1 - z))} = T rho sin((n + 1) theta)/(2 sin theta)
// ((1 + z)(1 - z) = 1 - z^2 = -2j sin(theta) e^{j theta}), so f gains (T/2) rho K_{n+1}(theta),
// K_m = sin(m theta)/sin(theta), finite on [0, pi] for an integer m (m sinc(m theta)/sinc(theta) near 0, its
// mirror in pi - theta near pi: numeric/jet.hpp's kernel_K).  With a fractional nu (since stop 82) the same part,
// written sin((nu + 1) theta)/sin(theta) = cos(nu theta) + sin(nu theta) cot(theta) and cot(theta) =
// (cot(theta/2) - tan(theta/2))/2, is (T/2) rho [cos(nu theta) + S_nu/2 - sin(nu theta) tan(theta/2)/2]: finite
// below pi, and at pi it tends to -(T/4) rho sin(nu pi) (+inf). +inf when rho sin(nu pi) < 0 (b* = +inf, the
// local form of bound_check.hpp): no cell bounds it. -inf when rho sin(nu pi) > 0: the cell holding pi, [a, b]
// with a < pi < b, is shown by its own test (a tail): with g = f minus that last term, bounded on [a, pi],
//   f <= g(a) + g'([a, pi]) [0, pi - a] - (T/4) inf_{[a, pi]}(rho sin(nu theta)) tan(a/2) < hi,
// valid when rho sin(nu theta) > 0 on all of [a, pi] (tan(theta/2) >= tan(a/2) > 0 there); f(pi) = -inf.
// Size limit: 400000 cells (a delay of 10^5 samples needs ~2 10^5; checked in ~3 s).
//
// Implements: paper 001 (45), (53), (54).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "hapstab/numeric/scalar.hpp"
#include "hapstab/poly/polynomial.hpp"
#include "hapstab/poly/rational_function.hpp"

namespace hapstab::check::detail {

constexpr size_t max_bound_cells = 400000;  ///< ~2 per period 2 pi/nu: delays to ~2 10^5 samples

/// f = eta + (T/2) (A cos(nu theta) + E S_nu) / B of the header, for H = N/D exact.
struct KernelForm {
  Polynomial<rational> A, E, B;
  rational T, nu, eta;
  rational rho = 0;  ///< H's simple pole at z = -1 set apart: f gains (T/2) rho K_m, m = nu + 1 (integer nu),
  long m = 0;        ///< or, m = 0 (nu not whole), (T/2) rho [cos(nu theta) + S_nu/2 - sin(nu theta) tan(theta/2)/2]
};
KernelForm kernel_form(const RationalFunction<rational>& H, const rational& T, const rational& nu, const rational& eta);

/// f(m) + f'([a, b]) [-r, r] < hi shown in balls (0 <= a < b < 2 pi); for the cell holding pi of a
/// pole at z = -1 met by a fractional delay, the tail test of the header instead.
bool cell_below(const KernelForm& f, const rational& a, const rational& b, const rational& hi);
/// f(theta0) > lo shown in balls.
bool point_above(const KernelForm& f, const rational& theta0, const rational& lo);
/// f, f', f'' at theta, the midpoints of their balls as doubles (for producers' searches, never a result).
struct PointJet {
  double v = 0, d = 0, dd = 0;
};
PointJet objective_at(const KernelForm& f, const rational& theta);
/// theta > pi, shown with a ball of pi (false when not shown).
bool beyond_pi(const rational& theta);

/// nullopt when the cells (their right ends theta_1 < ... < theta_k, theta_k > pi) show f < hi on
/// [0, pi]; else what failed.
std::optional<std::string> cells_below_fail(const KernelForm& f, const std::vector<rational>& ends, const rational& hi);
/// nullopt when theta0 lies in [0, pi] and f(theta0) > lo is shown; else what failed.
std::optional<std::string> witness_fails(const KernelForm& f, const rational& theta0, const rational& lo);
/// The cells' right ends at evidence[key]: a non-empty array of at most max_bound_cells "p/q"
/// strings (InputError naming the field).
std::vector<rational> read_cells(const nlohmann::json& evidence, const std::string& key);

}  // namespace hapstab::check::detail
