// hapstab/multidof/components.hpp -- Theorem 5's problem split into independent components
// before anything is solved (issue 39; DESIGN.md "Structure to exploit, cheapest first").
//
// The graph: one node per DOF and one per state of E's realisation; an edge wherever a nonzero
// entry of A_E, B_E, C_E or D_E connects two of them, and between the DOFs of one operator (its
// X block is g I, one multiplier). Its connected components are independent Theorem 5 problems:
// after a permutation of states and DOFs the realisation is the direct sum of the components'
// realisations, EXACTLY (the cross entries are zero by construction), and the operators do not
// straddle components. Then
//   (16) holds for the whole  <=>  it holds for every component:
//   <= the block-diagonal assembly of the components' points (P, X, Q_E, Q_V) is a point of the
//      whole: E-hat of (15) and its split coordinates are built per state and per DOF from
//      (A, B, C, D), so they are the direct sum of the components' as well, and every term of
//      (16) is then block diagonal;
//   => every term of (16) restricted to a component's rows and columns (its states and DOFs) is
//      that component's (16) at the principal blocks of P, X, Q_E, Q_V (A block diagonal:
//      (A^T P A)_kk = A_k^T P_kk A_k, and so on), and principal blocks of a (semi)definite
//      matrix are (semi)definite.
// So the whole is certified feasible when each component's point passed the exact re-check,
// and certified infeasible when one component is. The least dissipative ||Q_V||_2 of the whole
// is the largest of the components' (the block-diagonal assembly attains it; a restriction
// needs at least it).
//
// Implements: paper 000 (16), Theorem 5.
#pragma once

#include <string>
#include <vector>

#include "hapstab/multidof/analysis.hpp"

namespace hapstab::multidof {

struct Component {
  std::vector<int> operators;  ///< indices into the whole's structure.operators, in order
  std::vector<int> dofs;       ///< the whole's DOF indices, increasing
  std::vector<int> states;     ///< the whole's state indices of E, increasing
  Problem problem;             ///< the component's Theorem 5 problem (exact sub-blocks of E)
};

/// The connected components of pb's graph (above), ordered by their first DOF. One component
/// (the whole, with the whole's problem) when the scene does not split.
std::vector<Component> components(const Problem& pb);

/// The whole's exact point from one exact point per component (points[k] on comps[k].problem): the
/// components' E-hat realisations side by side, B's columns and C's rows at each component's DOFs,
/// P = blockdiag(P_k), X, Q_E, Q_V placed at the DOFs -- a realisation of pb's E-hat (block diagonal
/// over the components) and a point of its (16), which the checkers verify as any other.
StoredPoint assemble_components(const Problem& pb, const std::vector<Component>& comps, const std::vector<ExactPoint>& points);

/// The inverse of the split: E = blockdiag(E_a, E_b) in the realisation (states, inputs and outputs
/// of a, then of b; exact), the operators of a then of b (same sample period: InputError otherwise).
Problem direct_sum(const Problem& a, const Problem& b);

/// "{H1, H2} (2 DOF, 5 states)": a component named by its operators, for verdicts and output.
std::string component_name(const Problem& whole, const Component& c);

}  // namespace hapstab::multidof
