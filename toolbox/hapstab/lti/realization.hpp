// hapstab/lti/realization.hpp -- exact conversions between transfer functions and state
// space (python-control's tf2ss / ss2tf), in rational arithmetic.
//
//   tf2ss: controllable canonical form of a proper SISO H = D + C (xI - A)^{-1} B, and for a
//          transfer matrix one controllable form per column (common column denominator);
//   ss2tf: C (xI - A)^{-1} B + D entry by entry, (xI - A)^{-1} = adj/det computed by the
//          Faddeev-LeVerrier recursion (exact over Q);
//   minreal: removes uncontrollable and unobservable states by exact Kalman decompositions.
// Used to check realisations such as (15) and (17) of paper 000 against transfer functions.
#pragma once

#include <optional>
#include <utility>
#include <vector>

#include "hapstab/lti/state_space.hpp"
#include "hapstab/lti/tf.hpp"

namespace hapstab {

/// A p x m matrix of transfer functions sharing a domain and sample period.
struct TransferMatrix {
  std::vector<std::vector<TransferFunction>> entries;  ///< entries[i][j]: input j -> output i
  Domain domain = Domain::z;
  rational T = 0;
  size_t outputs() const { return entries.size(); }
  size_t inputs() const { return entries.empty() ? 0 : entries[0].size(); }
  const TransferFunction& operator()(size_t i, size_t j) const { return entries.at(i).at(j); }
};

/// Proper SISO H -> controllable canonical form (deg den states). InputError if improper.
StateSpace<rational> tf2ss(const TransferFunction& G);
/// Proper transfer matrix -> a realisation (not minimal in general; see minreal).
StateSpace<rational> tf2ss(const TransferMatrix& G);
/// The same for a p x m matrix given by its distinct entries: entry (i, j) is
/// distinct[index[i m + j]] (a compact scene's N x N matrix: N^2 entries, a few distinct). The
/// realisation is the one tf2ss gives the matrix written out; its cost is that of the distinct
/// columns and entries, plus copying.
StateSpace<rational> tf2ss(const std::vector<TransferFunction>& distinct, const std::vector<int>& index, size_t p,
                           size_t m, const rational& T);
/// Transfer matrix of a state-space model, exact; entries reduced.
TransferMatrix ss2tf(const StateSpace<rational>& sys);
/// Characteristic polynomial det(xI - A), exact (FLINT's fraction-free fmpq_mat_charpoly).
Polynomial<rational> charpoly(const Mat<rational>& A);
/// Minimal realisation: keeps the controllable and observable part (exact rank decisions).
StateSpace<rational> minreal(const StateSpace<rational>& sys);

/// The Kalman split of (A, B): in coordinates x = V xi with V = [controllable basis, completion],
/// A = [[A_c, A_12], [0, A_u]]. `controllable` is (A_c, B_c, C V_c, D) (what minreal keeps first),
/// `uncontrollable_A` the block A_u (0 x 0 when (A, B) is controllable): its eigenvalues are the
/// modes no input reaches.
struct KalmanSplit {
  StateSpace<rational> controllable;
  Mat<rational> uncontrollable_A;
};
KalmanSplit controllable_split(const StateSpace<rational>& sys);

/// A product of polynomials, each to a power, kept unexpanded: a symmetric scene's hidden modes
/// repeat a block's k - 1 times (stability/symmetry.hpp), and the product written out would have a
/// degree in the thousands and coefficients to match. The empty product is 1.
struct PolynomialProduct {
  std::vector<std::pair<Polynomial<rational>, int>> factors;  ///< (p, power): deg p >= 1, power >= 1
  PolynomialProduct() = default;
  explicit PolynomialProduct(const Polynomial<rational>& p) { multiply(p); }
  /// *this times p^power (nothing when p is a constant or power is 0).
  void multiply(const Polynomial<rational>& p, int power = 1);
  /// *this times q^power.
  void multiply(const PolynomialProduct& q, int power = 1);
  int degree() const;
  bool vanishes_at(const rational& x) const;
  Polynomial<rational> expanded() const;  ///< written out (for tests and small products)
};

/// The modes a realisation hides from its input or its output, exactly (the Kalman
/// decompositions minreal makes): with A_c the controllable part and A_min the minimal one,
///   det(xI - A) = uncontrollable(x) * det(xI - A_c),   det(xI - A_c) = unobservable(x) * det(xI - A_min).
/// A mode both uncontrollable and unobservable is counted as uncontrollable. Both factors are
/// monic (1 when nothing is hidden). Every hidden mode stays an eigenvalue of any loop the block
/// is connected into (no input reaches it, or no output shows it): a verdict about the loop as
/// written must check them before it works on `minimal` (DESIGN.md, Theorem 5 and realisations).
struct HiddenModes {
  PolynomialProduct uncontrollable, unobservable;
  StateSpace<rational> minimal;  ///< minreal(sys)
  /// Whether z = 1 (s = 0), when an eigenvalue of A, is semisimple (algebraic multiplicity =
  /// geometric), where the producer knew it without A's characteristic polynomial (a symmetric
  /// environment: the blocks' answers, stability/symmetry.hpp); unset: sim::hidden_modes decides.
  std::optional<bool> marginal_semisimple;
  bool any() const { return uncontrollable.degree() > 0 || unobservable.degree() > 0; }
};
HiddenModes hidden_modes(const StateSpace<rational>& sys);
/// lambda is not an eigenvalue of A, or it is semisimple: its algebraic multiplicity (in
/// det(xI - A)) equals its geometric one (the nullity of A - lambda I), exactly.
bool semisimple_eigenvalue(const Mat<rational>& A, const rational& lambda);
/// Whether z = 1 (s = 0 for a continuous sys) is semisimple in the two parts of A that no loop
/// moves: the uncontrollable quotient and the restriction to the unobservable subspace (each a
/// diagonal block of a Kalman form that a feedback leaves as it is, so a Jordan block there is one
/// of every loop). A chain through the controllable and observable part -- a hidden constant into a
/// PI wall's integrator, gravity on a device with its own position -- is the loop's to break: the
/// reduced loop decides that part, and a hidden constant that reaches a hidden sum through the loop
/// is sim::hidden_modes' chain test. (Before stop 88 the whole A was tested, and such blocks were
/// "NOT stable [exact]" in loops whose state settles.)
bool hidden_marginal_semisimple(const StateSpace<rational>& sys);

}  // namespace hapstab
