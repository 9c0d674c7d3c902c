// hapstab/check/rational_matrix.hpp -- the multi-DOF checkers' exact matrices: dense rows of
// rationals, their products and sums, and definiteness by symmetric elimination (written for
// check/ alone; not numeric/exact_matrix.hpp or lmi/, which the producers use).
//   positive_definite(M, strict): symmetric elimination without pivoting. Strict: every pivot > 0
//   (Sylvester). Not strict: no pivot < 0, and a zero pivot has its remaining row 0 (a PSD matrix
//   with a zero diagonal entry has that row 0; Schur complements of PSD matrices are PSD).
//   lemma1_matrix: the matrix of paper 000's Lemma 1 (2) with the supply y'Xu - y'Qy (X = I, Q = Delta:
//   (2) itself), for the checkers that verify a storage P.
#pragma once

#include <string>
#include <vector>

#include "hapstab/numeric/scalar.hpp"

namespace hapstab::check::rational_matrix {

using Mat = std::vector<std::vector<rational>>;

Mat zeros(size_t rows, size_t cols);
Mat identity(size_t n);
Mat transpose(const Mat& A);
Mat mul(const Mat& A, const Mat& B);
/// A + s B
Mat add(const Mat& A, const Mat& B, const rational& s = 1);
bool symmetric(const Mat& A);
/// M > 0 (strict) or M >= 0, M symmetric (see above).
bool positive_definite(Mat M, bool strict);
/// F = [[A'PA - P + C'QC, A'PB - C'X/2 + C'QD], [., B'PB - (XD + D'X')/2 + D'QD]], (n + m) x (n + m):
/// for [x; u], x+'Px+ - x'Px - (y'Xu + u'X'y)/2 + y'Qy with y = Cx + Du, x+ = Ax + Bu (X = I, Q = Delta
/// I: paper 000 (2) without Phi). F <= 0 (< 0) with P > 0 is the dissipation inequality (1).
Mat lemma1_matrix(const Mat& A, const Mat& B, const Mat& C, const Mat& D, const Mat& P, const Mat& X, const Mat& Q);
/// Paper 000's Lemma 1 at the level lo with the storage P (its "if": then (1) holds at Delta = lo I, OSP,
/// or Phi = lo I, ISP): "" when P = P' > 0 and (2) < 0, both by strict elimination; else what fails.
std::string lemma1_level_fails(const Mat& A, const Mat& B, const Mat& C, const Mat& D, const Mat& P, const rational& lo, bool osp);
/// det M (square), by elimination with row exchanges.
rational det(Mat M);

}  // namespace hapstab::check::rational_matrix
