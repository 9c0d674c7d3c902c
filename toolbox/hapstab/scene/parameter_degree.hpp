// hapstab/scene/parameter_degree.hpp -- how a scene parameter enters the loop, PROVEN from the
// scene's text (issue 46 item 5): the ground for "M(p) = M0 + p M1" in `stability --scene --max
// NAME` (stability/loop_max.hpp) and "H = H0 + p H1" on the one-DOF scene path.
//
// Every string of the scene that names NAME (the parser's own lexer, lti/parse.hpp `names_in`) is
// classified by its key; the rule, each part checked exactly:
//  - NAME may appear only in [environment] and [coupling] (and in [[input]]/[simulate], which are
//    not the loop); a [parameters] entry defined from NAME, or NAME in T, a device, an operator,
//    a delay or a contact key, rules the proof out (the key is named);
//  - in a block, as its `gain` (an expression whose numerator has degree <= 1 in NAME and whose
//    denominator has degree 0, by the parse's degree bound: a polynomial a + b NAME), in entries of
//    a z-domain `ss` (each a polynomial of degree <= 1 in NAME, the same way), in D of an s-domain
//    `ss`, or in a `tf` entry proven H0 + NAME H1 (lti/parse.hpp `split_affine`: proven from a
//    degree bound). For the loop's matrix H1 must be a constant c: tf2ss realises the constant in
//    D and the rest from the strictly proper part, so A, B and C do not move (a tf whose dynamics
//    move is kept in `tf_dynamics`: the one-DOF loop, on transfer functions, takes it);
//  - the gain and an entry of C or D naming NAME in one block would be of degree 2: ruled out.
// So every matrix of both blocks is a polynomial of degree <= 1 in NAME. What that gives the
// composed controller (sim/loop.cpp, coupled_controller) is stated by points_needed below.
#pragma once

#include <string>

#include "hapstab/scene/scene.hpp"

namespace hapstab::scene {

struct ParameterDegree {
  bool environment = false, coupling = false;  ///< NAME enters this block
  bool feedthrough_moves = false;              ///< NAME enters D_E or D_V (the algebraic loop I + D_E D_V)
  bool dynamics_move = false;                  ///< NAME enters A or B of a block
  long environment_states = 0;                 ///< the environment's order (the one-DOF bound)
  bool has_coupling = false;                   ///< the scene has a [coupling] (whether or not NAME enters it)
  long dofs = 0;
  std::string where;                           ///< the keys NAME appears in, for messages
  std::string tf_dynamics;                     ///< a tf entry whose H1 is not a constant (why), or ""
  std::string name;
};

/// The classification above, or an InputError naming the key that rules the proof out (the
/// caller then treats the loop as not proven affine). `sc` is the scene loaded at any value.
ParameterDegree parameter_degree(const Scene& sc, const std::string& name);

/// How many distinct values of NAME (where the loop is built) prove the closed loop's controller
/// rows Ku, Kx (sim/closed_loop.hpp) affine, given the classification (InputError when a tf's
/// dynamics move: its realisation is not proven affine). Every block matrix is a
/// polynomial of degree <= 1 in p. Without a coupling the controller is (A_E, B_E, -C_E, -D_E):
/// affine outright (2 values fix it). With one, coupled_controller's entries are P(p)/det S(p),
/// S = I + D_E D_V: when neither D moves, S is constant and each entry a polynomial of degree <= 4
/// (Cu <= 2, Du <= 1, Xs = D_V Cu + C_V <= 3, Xm <= 2, A_E + B_E Xs <= 4): 5 values; otherwise
/// deg det S <= 2N, the adjugate's entries <= 2N - 2, and P has degree <= 2N + 2: 2N + 3 values.
/// (A polynomial of degree <= D that vanishes at D + 1 points is 0: Ku(p) - Ku0 - p Ku1, times
/// det S, is one.)
long points_needed(const ParameterDegree& d);

/// The same for the one-DOF loop's H(p) = C (zI - A)^{-1} B + D of the environment: affine
/// outright when A and B do not move (2 values; a tf entry is proven H0 + p H1 on its own); otherwise (C adj(zI - A) B + D det(zI - A)) -
/// (H0 + p H1) det(zI - A), cleared of H0's and H1's denominators, has degree <= n + 2 in p:
/// n + 3 values.
long points_needed_one_dof(const ParameterDegree& d);

}  // namespace hapstab::scene
