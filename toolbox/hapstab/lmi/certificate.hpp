// hapstab/lmi/certificate.hpp -- exact certificates for LMI verdicts.
//
//  * exact_definiteness(M): symmetric rational M, LDL^T without pivoting in exact mpq
//    arithmetic. PD iff every pivot > 0. PSD iff every pivot >= 0 and, whenever a pivot is 0,
//    the rest of its row in the current Schur complement is 0 too (a PSD matrix with a zero
//    diagonal entry has a zero row; then that row/column is dropped and elimination goes on).
//  * exact_pd_bareiss(M): the same PD verdict from the leading principal minors, computed by
//    fraction-free Bareiss elimination on the integer matrix L*M (L = common denominator):
//    integer arithmetic only, several times faster than mpq LDL^T (used for strict LMIs).
//  * round_dyadic(x, bits): x rounded to a dyadic rational with `bits` significant bits
//    (denominators are powers of two: the exact rebuild stays cheap and exact).
//  * Feasible verdicts (solve.cpp): the solution is rounded (20, 30, 40 bits, then the exact
//    double), every LMI, equality and inequality is rebuilt in exact arithmetic from the
//    doubles' exact values, and checked; only then the result is `certified`.
//  * Infeasible verdicts: the Farkas certificate of the standard form (backend.hpp):
//    Z_j >= 0, sum_j tr(F_jk Z_j) = 0 for every variable k, sum_j tr(F_j0 Z_j) < 0 proves that
//    F_j(x) >= 0 (a fortiori > 0) has no solution, since then
//    0 <= sum_j tr(F_j(x) Z_j) = sum_j tr(F_j0 Z_j) < 0. The rounded Z is projected exactly
//    onto {sum_j tr(F_jk Z_j) = 0} (least squares in the span of the F_jk, exact Gram system)
//    before the exact checks.
//  * facial_reduce(): for a non-strict LMI F(x) >= 0 with F(x) v = 0 for known v (paper 000,
//    Theorem 5's first LMI; DESIGN.md): imposes the equalities F(x) V = 0 (exact elimination
//    in solve.cpp), poses U^T F U with U an orthonormal basis of V's orthogonal complement to
//    the solver (strict: it has margin), and keeps F >= 0 for the exact check, where the
//    zero pivots along V are handled by exact_definiteness.
#pragma once

#include <Eigen/Core>
#include <string>

#include "hapstab/lmi/program.hpp"
#include "hapstab/numeric/eigen_traits.hpp"
#include "hapstab/numeric/scalar.hpp"

namespace hapstab::lmi {

struct Definiteness {
  bool psd = false;       ///< positive semidefinite (exact)
  bool pd = false;        ///< positive definite (exact)
  int rank = 0;           ///< number of positive pivots when psd
  int failed_at = -1;     ///< first pivot (0-based) that disproves psd, -1 if psd
  rational min_pivot;     ///< smallest pivot seen (the last one that failed, if not psd)
};

/// Exact LDL^T of the symmetric part (M + M^T)/2.
Definiteness exact_definiteness(MatQ M);

/// true iff M (symmetric part) is positive definite; fraction-free (Bareiss) integer elimination.
bool exact_pd_bareiss(const MatQ& M);

/// Does F(x) > 0 (strict) or F(x) >= 0 hold exactly (symmetric part)? The same verdict as
/// exact_pd_bareiss / exact_definiteness on exact_value(F, x), computed without a rational per
/// entry: with q the common denominator of x and 2^e the smallest binary exponent among F's
/// doubles, 2 q 2^-e F(x) is an integer matrix built by integer products and shifts only
/// (positive scaling keeps definiteness); strict: fraction-free Bareiss with exit at the first
/// non-positive leading minor; non-strict: exact LDL^T with zero-pivot handling on it.
bool exact_lmi_holds(const Expr& F, const std::vector<rational>& x, bool strict);

rational round_dyadic(double x, int bits);
MatQ to_rational(const Eigen::MatrixXd& M);

/// Exact rational F(x) for an expression and exact values of the program's scalars.
MatQ exact_value(const Expr& F, const std::vector<rational>& x);

/// See the header comment. Returns the index of the posed (reduced) LMI.
int facial_reduce(Program& prog, const std::string& lmi_name, const Eigen::MatrixXd& V);

}  // namespace hapstab::lmi
