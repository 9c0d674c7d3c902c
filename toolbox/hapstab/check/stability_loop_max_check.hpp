// hapstab/check/stability_loop_max_check.hpp -- the checker of a `stability-loop-max` certificate:
// the largest value of a gain p for which a scene's loop as written is stable, beyond one DOF
// (`hapstab stability --scene S --max p --certificate FILE`, stability/loop_max.hpp; docs/stability.md):
//   sup p = sup{ p0 > 0 : the loop is stable for every p in (0, p0) }   (0 when no p0 > 0 qualifies)
// claimed in [lo, hi] (claim.status "certified", lo <= hi, the printed enclosure), sup = 0 with lo =
// hi = 0. The loop is the `stability-loop` kind's (check/stability_loop_check.hpp: the closed-loop
// matrix M built from the scene's text, on the quotient by its conserved quantities, claim.conserved).
//
// Model: {scene, set, name}: p = name is a parameter of the scene, not in set, the whole value of
// exactly one `gain` key, of [environment] or of [coupling], and named in no other string of the scene
// (every identifier of every string is compared; [parameters].p's own definition is skipped, the
// `--set` value never used). So the scene at p is the scene at 1 with that block's transfer matrix
// times p and nothing else changed.
// Or p inside the tf: p named only in the `tf` entries of one of those blocks (its gain not p), e.g. a wall
// K + B (z - 1)/(T z) with K maximised. Then (a) each entry naming p is proven affine in it, E = E0 + p E1
// (check/affine.hpp: the parser's degree bound D, then D + 1 values); (b) with L_j the monic lcm of the
// denominators of E0 and E1 down column j, every p's own column lcm divides L_j, so the realisation read at p
// (column by column over that lcm) has order <= sum_j deg L_j, with equality exactly where its lcm is L_j --
// and there it IS the realisation over L_j with numerators (E0 + p E1) L_j: A, B fixed, C, D affine in p. The
// checker requires that order at p = 1, 2 and hi (else beyond: a pole cancelled there), so R(p) := (A, B,
// (2 - p) C(1) + (p - 1) C(2), ...) realises E(p) for every p, and is the loop's own realisation at 1, 2, hi.
// Where a pole of E cancels at some p, the loop as written drops the cancelled modes; its eigenvalues are
// then a subset of R(p)'s (the modes of a controllable realisation: the minimal ones and its unobservable
// ones, roots of the lcm, which divides L_j), so R(p) Schur stable still proves the loop as written stable.
// D_E D_V = D_V D_E = 0 is checked at p = 1 and 2 (so at every p). Conserved quantities (since stop 78): the
// rows l with l^T M = l^T are the plant's (l^T [A B] = 0, no p in it) and a block's uncontrollable z = 1
// (l^T (A - I) = 0, l^T B = 0: A, B, fixed in p), so the rows and the quotient's embedding x = E y are the
// same at every p -- checked equal at 1 and 2 -- and M_q(p), a fixed linear map of M(p), is affine as M(p) is.
// A block's unobservable z = 1 (r with (A - I) r = 0, C r = 0: with C(p) it could move) is refused by name.
// Affine in p, the gain case (verified, not assumed): the block realised column by column over the monic lcm of each
// column's denominators (the same for every p != 0) has A, B independent of p and C, D proportional
// to it -- checked exactly on the realisations read at p = 1 and p = 2 (A, B equal; C, D doubled; the
// other block and the conserved quantities the same). The loop solves x_e = y + C_V eta + D_V u, u =
// -(C_E xi + D_E x_e) through W = (I + D_E D_V)^-1; with D_E D_V = 0 and D_V D_E = 0 (checked exactly)
// W = I and u, x_e and every row of M are affine in p. So M(p) = (2 - p) M(1) + (p - 1) M(2) for every
// p > 0, and as p -> 0 M(p) -> M(0) := 2 M(1) - M(2) (in balls, from the two matrices built here).
// Theorem (convexity of Stein's inequality along a segment): for P = P^T > 0 and M(p) affine, p ->
// v^T (M(p)^T P M(p) - P) v = |P^{1/2} M(p) v|^2 - v^T P v is convex; < 0 at both ends of [a, b] for
// every v != 0 gives < 0 on [a, b]: Q(p) = P - M(p)^T P M(p) > 0 there, and with P > 0 every M(p),
// a <= p <= b, is Schur stable (Stein). Evidence:
//   cover: [{to, P}, ...], t_0 = 0 < t_1 < ... < t_m = lo: on [t_{k-1}, t_k] P_k symmetric, P_k > 0
//          (exactly up to order 24, else by the congruence test), Q > 0 at both ends (the test of
//          stability_loop_check.hpp at 128, 256, 512 bits) => stable on [0, lo], so sup >= lo;
//          Or {to, P, P_to} (P linear, since stop 74; P left out after an interval with P_to: that P_to): P at
//          t_{k-1}, P_to at t_k, P(p) affine between; with
//          t = (p - t_{k-1})/(t_k - t_{k-1}), P(t) and M(t) affine in t, so S(t) = P(t) - M(t)^T P(t) M(t) is a cubic,
//          sum_s C_s B_s(t) in the Bernstein basis (B_s >= 0, sum 1): C_0..C_3 > 0 (balls; the formula in
//          stability_loop_check.hpp's bernstein_stein_holds) and P, P_to > 0 give P(p) > 0 and S > 0 on the
//          interval, so M(p) Schur stable there. Near a crossing P must follow M: one P per interval needs widths
//          ~ the distance to the crossing times a small ratio, a linear one ~ that times its square root.
//   unstable_at: {at = hi, P, w}: Q > 0 at M(hi) and w^T P w < 0 => M(hi) has an eigenvalue outside
//          the unit circle (Stein inertia): NOT stable at hi, so sup <= hi. With hi = 0 (no cover):
//          M(0) has an eigenvalue |z| > 1, and so has M(p) for every small p > 0 (eigenvalues are
//          continuous in p): sup = 0.
// The first-order start (evidence.first_order {to = eps, P0, S}): where M(0) is only marginally stable --
// a device's position that nothing holds at p = 0 -- no cover can start at 0. The rows L of the slow modes
// (check/stability_loop_check.hpp's slow_rows: a basis of {l : l^T (M~(0) - I) = 0, l_p^T A = 0}, M~ the
// exact slow matrix, each hold e^{Ah} -> I and Gamma_h -> h B; for l_p^T A = 0, l_p^T e^{Ah} = l_p^T and
// l_p^T Gamma_h = h l_p^T B exactly, so l^T M(p) = l^T M~(p)) satisfy L M(0) = L exactly, so L M(p) = L + p K,
// K = L (M(2) - M(1)). With P(p) = P0 + L^T S L / p (P0 > 0, S >= 0 exactly: P(p) > 0 for p > 0),
//   P(p) - M(p)^T P(p) M(p) = P0 - M(p)^T P0 M(p) - (K^T S L + L^T S K) - p K^T S K =: Q(p)   (exactly),
// and v^T Q(p) v = v^T P0 v - |P0^{1/2} M(p) v|^2 - 2 v^T L^T S K v - p |S^{1/2} K v|^2 is concave in p:
// Q > 0 at 0 and at eps (balls) gives Q > 0 on [0, eps], so M(p) is Schur stable for 0 < p <= eps (Stein).
// The cover then starts at eps. Any block, p a gain or inside a tf (a wall K + B (z - 1)/(T z) whose K is 0
// leaves a damper: the slow row is then m v + b x + B x_{k-1}, exactly). On the quotient by conserved
// quantities (rows c with c^T M = c^T, the subspace {c^T x = 0} invariant, x = E y) the rows are l^T E:
// (l^T E) M_q = l^T M E = l^T E since E P M E = M E on the invariant subspace; the conserved rows' own
// images vanish and are dropped. A quotient by right eigenvectors too (a block's unobservable z = 1) is beyond.
// The mirror (evidence.first_order_unstable {to = eps, P0, S, w}, with claim lo = hi = 0 in place of unstable_at): where
// p moves a slow mode OUT at first order (a negative stiffness on a position nothing holds), the same P(p) = P0 +
// L^T S L / p with S of any sign: Q > 0 at 0 and eps (P0 > 0: concave, so on [0, eps]) and, exactly,
// s = (L w)^T S (L w) < 0 and w^T P0 w + s / eps < 0, so w^T P(p) w = w^T P0 w + s / p < 0 for every p in (0, eps]. Then
// P(p) - M(p)^T P(p) M(p) > 0 with P(p) not positive definite: M(p) is not Schur stable (were it, the Stein equation's
// solution sum (M^T)^i Q M^i would be P(p), > 0) and has no eigenvalue on the circle (v^* Q v = (1 - |z|^2) v^* P v
// would vanish), so one outside: NOT stable on (0, eps], sup = 0. (S must be indefinite: Q's slow block is
// -(G^T S + S G), G = K V the first-order matrix, and G has an eigenvalue with Re > 0.)
// A hidden mode for every p (evidence.hidden, since stop 90; claim "exact", value 0): the stability-loop kind's
// evidence.hidden (check/stability_loop_check.hpp: an ss block's unobservable or uncontrollable subspace whose A_h has
// an eigenvalue |lambda| >= 1, lambda != 1, or a Jordan block at 1), verified on the loop read at p = 1 and at 2. Its
// conditions are linear in the block's (A, B, C), and p enters only the environment's or coupling's gain (C, D times
// p) or tf entries (not an ss block), nothing else (the model rule above): so the subspace is the loop's at every
// p > 0, NOT stable on (0, inf), sup = 0. (`stability --scene S --max p` printed this sup = 0 [exact] with no
// certificate before stop 90.)
// No crossing of the circle (evidence.no_crossing {to = a}, since stop 78; lti/circle_crossing.hpp): where M(p) is
// rational -- every plant component nilpotent (pure masses: e^{Ah} and Gamma_h finite sums), no conserved quantity --
// the checker builds M(1), M(2) exactly (stability_loop_check.hpp's exact_loop_matrix), c(z, p) = det(zI - M(p)) and
// R(p) = Res_z(c, z^n c(1/z)), and requires R / p^m without a real root in (0, a] (Sturm): no eigenvalue meets the
// circle there, so M(p) keeps one inertia on (0, a]. In place of first_order the cover then starts at min(a, lo) (a >=
// lo: one interval [lo, lo], M(lo) stable by one P): stable on (0, max(a, lo)] -- a pure mass's Jordan block at z = 1,
// whose eigenvalues leave like sqrt(p), defeats the first-order start. With claim hi = 0, beside unstable_at at a
// (Stein inertia there): NOT stable on (0, a], sup = 0.
// Limits: the loop's order <= 160, at most 4096 intervals, and intervals x n^3 <= 5e7 (one with P linear counted 5
// times; beyond: malformed, by name); no_crossing: order <= 64 and 2 n rank(M1) <= 2048.
// Implements: paper 000 Sec. VI.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "hapstab/check/certificate.hpp"
#include "hapstab/check/scene_model.hpp"
#include "hapstab/check/stability_loop_check.hpp"

namespace hapstab::check {

namespace detail {
/// InputError when the loop's order is beyond this kind's 160 (a cover of Stein tests at that order; the stability-loop
/// kind takes 1024): the producer asks before it solves anything.
void require_loop_max_order(size_t order);
/// The model read at p = value (model.set with p added, model.name dropped): the scene's, or the one-DOF --plant/--H
/// loop's (check/scene_model.hpp).
nlohmann::json model_at(const nlohmann::json& model, const std::string& p, const rational& value);
/// A supremum kind's maximised parameter (model.name, given no value in model.set) and its claim [lo, hi] (status
/// "certified", or `status`: "exact" for the hidden form; lo >= 0); InputError when malformed; c.refuted when the
/// printed ends are not lo and hi.
struct SupModel {
  std::string p;
  ClaimRange c;
};
SupModel sup_model(const nlohmann::json& model, const nlohmann::json& claim, const std::string& status = "certified");
/// The header's reading of p: the block ("environment" or "coupling") whose `gain` is exactly p, p named in no
/// other string of the scene; or (`inside`) p named only in the `tf` entries of one of them, its gain not p.
/// InputError naming what is not so.
struct MaxReading {
  std::string block;
  bool inside = false;
};
MaxReading read_max_parameter(const std::string& scene, const std::string& p);
/// p inside the block's tf (header): each entry naming p proven affine in it (check/affine.hpp), H = H0 + p H1; per
/// column j, deg L_j, L_j the monic lcm over column j of den H0 and den H1 (of the entry where it does not name p):
/// the largest order the checker's realisation of that column reaches at any p. `degree`: the largest degree bound
/// proven. InputError (beyond) when an entry is not proven affine.
std::vector<size_t> affine_column_orders(const nlohmann::json& model, const MaxReading& r, const std::string& p, const SceneLoop& L1,
                                         long& degree);
/// One loop's supremum evidence ({cover, first_order, unstable_at} of `ev`, named `at` in messages) on the loop
/// read at p = 1 and 2, checked as the header says: verified (true), refuted (false, why), or not shown at 512
/// bits (nullopt, why). `conserved` < 0: not compared. `order`, `at_hi`: p inside the tf (else 0, nullopt).
/// unstable_at may be absent only where `need_unstable` is false (a block of stability-loop-max-symmetric whose
/// supremum another block bounds). InputError when malformed.
struct MaxPart {
  std::optional<bool> verified;
  std::string why;
  long bits = 0;
  size_t order = 0;      ///< the loop's order (M before the quotient)
  size_t conserved = 0;  ///< the loop's conserved quantities
};
MaxPart check_max_part(const SceneLoop& L1, const SceneLoop& L2, const MaxReading& r, const std::string& p, const nlohmann::json& ev,
                       const ClaimRange& c, long conserved, size_t order, const std::optional<LoopMatrix>& at_hi, const std::string& at,
                       bool need_unstable = true);
/// M(p) = (2 - p) M(1) + (p - 1) M(2) in balls: the loop's matrix at p, the family affine (header).
BallRows affine_loop_at(const BallRows& M1, const BallRows& M2, const rational& p);
/// evidence.first_order {to = eps, P0, S} (header): "" when it shows every M(p), 0 < p <= eps, Schur stable
/// (`from` := eps), else what fails; InputError when malformed or beyond (no slow mode). L: slow_rows of the
/// loops read at p = 1 and 2, on M's coordinates.
std::string first_order_start(const nlohmann::json& first_order, const LoopMatrix& m1, const LoopMatrix& m2, const rational_matrix::Mat& L,
                              const rational& lo, rational& from);
/// evidence.first_order_unstable {to = eps, P0, S, w} (header): "" when it shows every M(p), 0 < p <= eps, NOT Schur
/// stable, else what fails (`refuted`: an exact test on w failed; else a ball test, another precision may pass).
std::string first_order_unstable(const nlohmann::json& first_order_unstable, const LoopMatrix& m1, const LoopMatrix& m2,
                                 const rational_matrix::Mat& L, const std::string& at, bool& refuted);
}  // namespace detail

Verdict check_stability_loop_max(const nlohmann::json& certificate);

}  // namespace hapstab::check
