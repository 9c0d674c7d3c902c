// hapstab/lmi/passivity_level.hpp -- OSP level Delta and ISP level Phi of a discrete-time LTI
// system (A, B, C, D), MIMO with square G (paper 000, Definition 2, Lemmas 1 and 2), scalar
// levels Delta = delta I, Phi = phi I:
//
//  Lemma 1 (KYP, (2)): sup delta (resp. phi) s.t. P > 0 and
//     [[A'PA - P + C'DeltaC,  A'PB - C'/2 + C'DeltaD], [.., B'PB - (D+D')/2 + D'DeltaD + Phi]] < 0.
//  Lemma 2: Schur complement of (2) with Q = P^{-1}. The correct S has (D+D')/2 - Phi in its
//     top-left block; the transcription's "+Phi" is a typo (proofs/lmi_lemmas.cpp: with +Phi
//     a non-ISP system passes as ISP). Posed as an LMI in (Q, mu = 1/delta) through a second
//     Schur complement: Q > 0, S(Q, mu) - R Q R' > 0, R = [C/2; A; C]; needs Delta > 0, so the
//     OSP level by Lemma 2 exists only when it is positive. The ISP form (Delta = 0) drops
//     the third block row and column.
//  Frequency domain (independent of any SDP solver), A Schur:
//     ISP: phi* = min_{theta in [0, pi]} lambda_min((G(e^{j theta}) + G^*)/2);
//     OSP: delta* = min_theta lambda_min of the pencil ((G + G^*)/2, G^* G) (= ISP level of
//          G^{-1} where G is invertible).
//     Method: a uniform grid of `grid` points on [0, pi] (both ends included), then golden-
//     section refinement on the bracket of each of the 8 smallest grid minima to |dtheta| <
//     1e-12. lambda_min(theta) is continuous and piecewise analytic, so this finds the global
//     minimum unless a narrower dip than the grid spacing exists (stated as the caveat).
//
//     The frequency levels are also certified: SISO by passivity_level_certified, square MIMO
//     by passivity_level_certified_mimo (below).
//  Lemma 1 = frequency: for ISP always (A'PA - P < 0 forces P > 0); for OSP only when
//     delta* > 0 and G has no zero on the unit circle. A zero on the circle makes the
//     frequency inequality tight there for every delta (the strict LMI has no solution; the
//     grid notes the degenerate pencil only when a sample hits the zero, e.g. at theta = 0 for
//     paper 000's V-hat with V(1) = 0); delta* <= 0 is an upper bound on Lemma 1's level only.
//
// Comparison with python-control (solve_passivity_LMI: one non-strict cvxopt SDP that
// maximises the index, discrete time from the system's dt, since 0.9.3) and MATLAB
// (getPassiveIndex: frequency-domain indices, documented as invalid with zeros on the
// stability boundary): docs/passivity-levels.md.
//
// LMI results, when the exact check passes (`lower_bound` set): the rounded (P, level_q)
// satisfies the LMIs of the lemma used, exactly (LDL^T), proving that the system IS
// level_q-OSP/ISP (a certified lower bound level_q <= sup). The reported `level` itself is
// numeric. The statuses are hapstab::Status (numeric/result.hpp).
//
// Implements: paper 000 Definition 2, Lemma 1, Lemma 2, (2).
#pragma once

#include <optional>
#include <string>

#include "hapstab/lmi/backend.hpp"
#include "hapstab/lti/state_space.hpp"
#include "hapstab/numeric/result.hpp"
#include "hapstab/numeric/scalar.hpp"
#include "hapstab/poly/rational_function.hpp"

namespace hapstab::lmi {

enum class PassivityKind { osp, isp };
const char* to_string(PassivityKind k);

struct PassivityLevel {
  double level = 0;             ///< numeric value of the level (sup)
  std::string method;           ///< "Lemma 1 LMI (DSDP)", "frequency grid+golden", ...
  /// numeric (LMI, frequency grid); exact | certified (certified frequency method: the
  /// enclosure, or the level -inf); failed (reason in `note`)
  Status status = Status::numeric;
  /// Proven exactly: LMI, the system is lower_bound-OSP/ISP; certified frequency method, the
  /// enclosure's lower end.
  std::optional<rational> lower_bound;
  /// Lemma 1 LMI: the rounded P with which (2) holds strictly at lower_bound (exactly checked);
  /// the evidence of a lower-bound certificate. Not set for Lemma 2 (its Q = P^-1).
  std::optional<MatQ> lemma1_P;
  std::optional<Enclosure<rational>> enclosure;  ///< certified frequency method: the level is in [lo, hi]
  std::string value;            ///< certified frequency method: the level to `digits` digits ("-inf")
  double theta_min = -1;        ///< frequency methods: the minimising theta in [0, pi]
  /// certified MIMO path: cos(theta_min) as the exact rational the path worked with (where its upper
  /// end was found; exact status: next to a root of det(He G - level I)); the witness of a certificate
  std::optional<rational> c_min;
  std::string note;             ///< caveats, failure reasons

  /// Something is proven: a lower bound, or the certified frequency method's level.
  bool proven() const { return lower_bound || status == Status::exact || status == Status::certified; }
};

/// Lemma 1 (lemma = 1) or Lemma 2 (lemma = 2) LMI. Requires a discrete, square system.
PassivityLevel passivity_level_lmi(const StateSpace<double>& sys, PassivityKind kind, int lemma = 1,
                                   Backend backend = Backend::automatic);

/// Lemma 1 exactly, for a model as written (not the doubles the SDP saw): P > 0 and (2) < 0 at
/// Delta = level I (osp) or Phi = level I (isp), both by exact fraction-free elimination. (2) is
/// non-decreasing in the level (it adds level times a PSD matrix), so it then holds at every lower level too.
bool lemma1_holds(const StateSpace<rational>& s, const MatQ& P, const rational& level, PassivityKind kind);

/// Frequency-domain level (see header comment).
PassivityLevel passivity_level_freq(const StateSpace<double>& sys, PassivityKind kind, int grid = 4096);

/// Feasibility of Lemma 1 / Lemma 2 (with the transcribed "+Phi" when typo = true) at fixed
/// Delta = delta I, Phi = phi I; returns the margin (> 0: feasible). Used by proofs/.
double lemma_margin(const StateSpace<double>& sys, int lemma, double delta, double phi, bool typo = false,
                    Backend backend = Backend::automatic);

/// SISO, certified: phi* = min_theta Re G(e^{j theta}) (isp) or delta* = min_theta Re(1/G) (osp,
/// where G != 0) as an exact enclosure. With W = G (isp) or 1/G (osp), -min Re W is the
/// passivity bound (45) of H = (z - 1) W at T = 1, no delay: T H/(1 - z) = -W. So the certified
/// path of passivity/bound.hpp applies unchanged -- the exact objective as a rational function
/// of c = cos theta (the t = tan(theta/2) substitution without 1/t), Descartes isolation of its
/// critical points, MPFI enclosure -- with `digits` correct digits. G must be Schur stable;
/// osp needs 1/G without poles outside the unit circle (zeros of G in |z| <= 1, simple on it),
/// otherwise status "failed" with the reason. A zero of G on the circle where Re G < 0 nearby
/// gives delta* = -inf. The ISP value is Lemma 1's level (A^T P A - P < 0 forces P > 0). The OSP
/// value is Lemma 1's level only when delta* > 0 and G has no zero on the circle: with a zero
/// on it, delta* is the supremum of non-strict levels only; with delta* <= 0 it is an upper
/// bound only (G = 1/(z - 1/2): delta* = -3/2, but (2) has no solution) -- `note` says which.
PassivityLevel passivity_level_certified(const RationalFunction<rational>& G, PassivityKind kind, int digits = 30);
/// The same for a SISO state-space model, through its exact transfer function (the doubles'
/// exact values, ss2tf).
PassivityLevel passivity_level_certified(const StateSpace<double>& sys, PassivityKind kind, int digits = 30);

/// Square MIMO (any size; also SISO), certified: phi* = min_theta lambda_min(He G(e^{j theta}))
/// (isp) or delta* = sup {delta : He G - delta G^* G >= 0 on the circle} (osp) for the exact
/// realisation `sys`, as an exact enclosure [lo, hi] with hi - lo <= 10^-(digits+3) max(1, |level|),
/// or exactly (status exact) when the level is rational. det(He G - nu W) is an exact polynomial
/// in (cos theta, nu); each candidate nu is decided exactly by root isolation in cos theta and
/// inertia counts between the roots (passivity_level_mimo.cpp). `theta_hint` (e.g. the grid's
/// minimiser; < 0: none) starts the search; the result does not depend on it being right. G
/// must be Schur stable (checked exactly); the same notes as the SISO path for OSP (a zero of G
/// on the circle, delta* <= 0). Not attempted (status failed, `note`) when inputs x states > 64.
PassivityLevel passivity_level_certified_mimo(const StateSpace<rational>& sys, PassivityKind kind, int digits = 17,
                                              double theta_hint = -1);

/// lambda_min((G + G^*)/2) at theta (numeric, double).
double isp_index_at(const StateSpace<double>& sys, double theta);

}  // namespace hapstab::lmi
