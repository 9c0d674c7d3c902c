// hapstab/multidof/example.hpp -- the application example of paper 000, Sec. VI, as
// reconstructed in DESIGN.md (Fig. 5 is missing from the transcription):
//   E: one mass M = 0.3 tied to ground by k = 1000, B = 5, touched at two massless contact
//      points through k1 = 800, B1 = 1 and k2 = 500, B2 = 2; displacements -> contact forces;
//      backward Euler, T = 0.01; minimal realisation, 4 states.
//   perturbed E: C_E pre-multiplied by [[0, 1], [1, 0]], D_E unchanged (realisation-independent:
//      E_p(z) = Pi (E(z) - E(inf)) + E(inf)).
//   devices d_a, d_b: 1 DOF, OSP level 1.37; case i (25): one 2-DOF operator using both;
//      case ii (26): two 1-DOF operators with one device each.
//   operators: H(s) of Sec. VI (2x2, case i) and its diagonal (case ii).
//   the paper's controller (27) and the decentralised coupling structure N-bar = 2,
//   n-bar_i = m-bar_i = 1.
//
// The scaling scenes (issue 15) generalise Fig. 5 to N contact points on the one mass:
// contact_scene(N) is the scene TOML of bench/contact_scene.py (N mass-damper devices, N 1-DOF
// operators, case ii, one first-order SISO coupling block per device). `active`: every contact
// damper is -3 (ground damper 200 keeps E stable), so E lacks passivity and the least
// dissipative coupling needs Q_V = q I with q about 0.8 (the passive scene's q vanishes).
//
// Implements: paper 000 (25), (26), (27), Sec. VI.
#pragma once

#include <string>

#include "hapstab/multidof/analysis.hpp"

namespace hapstab::multidof::example {


MechanicalEnvironment fig5();
rational T();                               ///< 1/100
StateSpace<rational> environment(bool perturbed);
Structure structure(int which_case);        ///< 1 = case i (25), 2 = case ii (26)
TransferMatrix operator_H(int which_case);  ///< Sec. VI H(s) (case 1) or its diagonal (case 2)
StateSpace<rational> controller27();        ///< (27), decimals read exactly
Problem problem(int which_case, bool perturbed);
/// `objects` > 1: the N devices split into that many groups, each touching its own Fig. 5 mass
/// (E block diagonal: the scene decomposes, components.hpp; issue 39's multi-object scenes).
std::string contact_scene(int N, bool active = false, int objects = 1);
/// Issue 39 item 3: `pb` with dampers Bc between pairs of DOFs (i, j), each a force
/// Bc (1 - z^-1)/T (x_i - x_j) on i and its opposite on j (two states per link: x_i, x_j one sample
/// back). E(1) is unchanged, so objects linked only so keep one direction of X each in the facial
/// conditions (X is not pinned), while the scene no longer decomposes. Exact.
Problem linked_by_dampers(const Problem& pb, const std::vector<std::pair<int, int>>& links, const rational& Bc);

}  // namespace hapstab::multidof::example
