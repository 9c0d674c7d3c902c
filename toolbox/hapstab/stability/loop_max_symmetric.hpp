// hapstab/stability/loop_max_symmetric.hpp -- the supremum of stability/loop_max.hpp for a loop of
// identical DOFs (`hapstab stability --scene S --max NAME`, where split_pays), on the small loops of
// the split by the permutations of identical DOFs (stability/symmetry.hpp) instead of the whole
// closed-loop matrix. Two reasons: size (96 held devices: the whole ran for more than 11 minutes;
// the split's three loops of 2 and 1 DOFs take 0.3 s), and multiplicity (a class of k >= 3 DOFs
// makes each of its zero-sum loop's eigenvalues an eigenvalue of the whole k - 1 times, so a
// crossing there is a repeated eigenvalue, which the whole's Krawczyk enclosure of one simple
// eigenvalue cannot contract: 8 held devices in two classes of 4 were undecided at 4096 bits).
//
// Why the split holds for every p, not only where it was computed: the scene's text makes every
// matrix of every block a polynomial of degree <= 1 in p (scene/parameter_degree.hpp), and the
// invariance under a permutation sigma within the classes is a set of equalities between those
// entries, so of polynomials of degree <= 1: shown at two distinct values it holds at every p.
// Each block's loop is built from the whole's matrices by a linear map fixed by the classes (the
// sums of E's entries over a class, symmetry.hpp's header), so its matrices are of degree <= 1 in
// p too and `points` values prove its controller rows affine exactly as they prove the whole's
// (a block has fewer DOFs: points_needed's 2N + 3 only shrinks). Every evaluation of a block's loop
// re-splits the whole loop at that p and requires the same classes (loop_family evaluates it at
// max(points, 4) values), and states of the environment that no input reaches (symmetry.hpp's
// `isolated`, whose dynamics p could move) are refused.
// det(zI - M(p)) = det(zI - M_F(p)) prod_a det(zI - M_a(p))^(k_a - 1) at every p, so the loop is
// stable at p iff every block is, and
//   sup p = min over the blocks of sup_b p:
// each block's supremum by max_parameter (certified crossing and cover); the whole's enclosure is
// [min_b lo_b, min_b hi_b] (every block stable on [0, min lo_b], the block of the least hi_b NOT
// stable at its hi_b). sup = 0 when one block's is (that block's status); undecided when a block's is
// and none fails -- an undecided block is never counted as either answer.
// Implements: paper 000 Sec. VI, Theorem 5.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "hapstab/stability/loop_max.hpp"

namespace hapstab::stability {

/// Beyond this many DOFs `stability --scene --max` splits a loop of identical DOFs (the whole's
/// supremum costs 5 s at 8 DOFs, 32 s at 16, more than 11 min at 96; `--no-symmetry` keeps the whole).
constexpr long kSplitMaxDofs = 8;
/// Whether --max splits the loop: it splits and has more than kSplitMaxDofs DOFs or a class of three or
/// more (a repeated crossing eigenvalue, header). Two identical DOFs of a small scene keep the whole.
bool split_pays(const sim::LoopSpec& loop);
/// Without a split, the whole closed-loop matrix is refused beyond this many DOFs (by name).
constexpr long kWholeMaxDofs = 64;

struct LoopMaxBlock {
  std::string label;  ///< "the fixed space (r DOFs)" or "the zero-sum space of class a (k DOFs, multiplicity k - 1)"
  int cls = -1;       ///< -1: the fixed space; else the class (0-based) of this zero-sum block
  LoopMax max;        ///< its supremum (stability/loop_max.hpp)
};

struct LoopMaxSplit {
  std::vector<std::vector<int>> classes;  ///< the DOFs of each class (0-based)
  std::string group;                      ///< "S_48^2 (2 classes of 48 identical DOFs)"
  std::vector<LoopMaxBlock> blocks;       ///< the fixed space first, then one per class of two DOFs or more
  int deciding = -1;                      ///< the block that fails, is undecided, or has the least hi (holds)
  LoopMax whole;                          ///< the combination of the header (mode on the whole's DOFs)
};

/// The split's affinity check (loop_family on every block, `points` values; the whole's, of order ~4N, is not
/// built: at 256 DOFs it took 20 s and 1 GB): nullopt when the loop does not split, or a block does not depend on p
/// (the caller checks the whole), "" when every block is affine in p, else why not.
std::optional<std::string> split_not_affine(const LoopAt& at, const rational& reference, const std::string& name, long points);

/// The split supremum, or nullopt with `why_not` when the loop does not split (no two DOFs alike, a
/// state no input reaches, classes that differ at 2 reference).
std::optional<LoopMaxSplit> max_parameter_by_symmetry(const LoopAt& at, const rational& reference, const std::string& name, long points,
                                                      int digits, std::string& why_not);

}  // namespace hapstab::stability
