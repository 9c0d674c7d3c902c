// hapstab/check/rational_matrix.cpp -- see rational_matrix.hpp.
#include "hapstab/check/rational_matrix.hpp"

#include <utility>

namespace hapstab::check::rational_matrix {

Mat zeros(size_t r, size_t c) { return Mat(r, std::vector<rational>(c)); }

Mat identity(size_t n) {
  Mat I = zeros(n, n);
  for (size_t i = 0; i < n; ++i) I[i][i] = 1;
  return I;
}

Mat transpose(const Mat& A) {
  Mat T = zeros(A.empty() ? 0 : A[0].size(), A.size());
  for (size_t i = 0; i < A.size(); ++i)
    for (size_t j = 0; j < A[i].size(); ++j) T[j][i] = A[i][j];
  return T;
}

Mat mul(const Mat& A, const Mat& B) {
  const size_t k = B.size(), c = B.empty() ? 0 : B[0].size();
  Mat R = zeros(A.size(), c);
  for (size_t i = 0; i < A.size(); ++i)
    for (size_t l = 0; l < k; ++l) {
      if (A[i][l].is_zero()) continue;
      for (size_t j = 0; j < c; ++j) R[i][j] += A[i][l] * B[l][j];
    }
  return R;
}

Mat add(const Mat& A, const Mat& B, const rational& s) {
  Mat R = A;
  for (size_t i = 0; i < A.size(); ++i)
    for (size_t j = 0; j < A[i].size(); ++j) R[i][j] += s * B[i][j];
  return R;
}

bool symmetric(const Mat& A) {
  for (const auto& row : A)
    if (row.size() != A.size()) return false;  // not square (a fuzzed [[]] once reached positive_definite)
  for (size_t i = 0; i < A.size(); ++i)
    for (size_t j = 0; j < i; ++j)
      if (A[i][j] != A[j][i]) return false;
  return true;
}

bool positive_definite(Mat M, bool strict) {
  const size_t n = M.size();
  for (const auto& row : M)
    if (row.size() != n) return false;  // not square: nothing to show
  for (size_t k = 0; k < n; ++k) {
    const rational p = M[k][k];
    if (p < 0 || (strict && p == 0)) return false;
    if (p == 0) {
      for (size_t j = k + 1; j < n; ++j)
        if (!M[k][j].is_zero()) return false;
      continue;
    }
    for (size_t i = k + 1; i < n; ++i) {
      if (M[i][k].is_zero()) continue;
      const rational f = M[i][k] / p;
      for (size_t j = k + 1; j < n; ++j) M[i][j] -= f * M[k][j];
    }
  }
  return true;
}

Mat lemma1_matrix(const Mat& A, const Mat& B, const Mat& C, const Mat& D, const Mat& P, const Mat& X, const Mat& Q) {
  const size_t n = A.size(), m = D.size();
  const Mat At = transpose(A), Ct = transpose(C), AtP = mul(At, P), CtQ = mul(Ct, Q);
  const Mat F11 = add(add(mul(AtP, A), P, -1), mul(CtQ, C));
  const Mat F12 = add(add(mul(AtP, B), mul(Ct, X), rational(-1, 2)), mul(CtQ, D));
  const Mat XD = mul(X, D);
  const Mat F22 = add(add(mul(mul(transpose(B), P), B), add(XD, transpose(XD)), rational(-1, 2)), mul(mul(transpose(D), Q), D));
  Mat F = zeros(n + m, n + m);
  for (size_t i = 0; i < n + m; ++i)
    for (size_t j = 0; j < n + m; ++j) F[i][j] = i < n ? (j < n ? F11[i][j] : F12[i][j - n]) : (j < n ? F12[j][i - n] : F22[i - n][j - n]);
  return F;
}

std::string lemma1_level_fails(const Mat& A, const Mat& B, const Mat& C, const Mat& D, const Mat& P, const rational& lo, bool osp) {
  const size_t n = A.size(), m = D.size();
  if (!symmetric(P)) return "evidence.P is not symmetric";
  if (!positive_definite(P, true)) return "P > 0 fails (exact elimination)";
  const Mat Q = osp ? add(zeros(m, m), identity(m), lo) : zeros(m, m);
  Mat negF = add(zeros(n + m, n + m), lemma1_matrix(A, B, C, D, P, identity(m), Q), -1);
  if (!osp)
    for (size_t i = 0; i < m; ++i) negF[n + i][n + i] -= lo;  // + Phi = lo I in (2)'s lower right block
  if (!positive_definite(negF, true)) return "(2) < 0 fails at the level lo with this P (exact elimination of -F)";
  return "";
}

rational det(Mat M) {
  const size_t n = M.size();
  rational d = 1;
  for (size_t k = 0; k < n; ++k) {
    size_t p = k;
    while (p < n && M[p][k].is_zero()) ++p;
    if (p == n) return 0;
    if (p != k) std::swap(M[p], M[k]), d = -d;
    d *= M[k][k];
    for (size_t i = k + 1; i < n; ++i) {
      if (M[i][k].is_zero()) continue;
      const rational f = M[i][k] / M[k][k];
      for (size_t j = k; j < n; ++j) M[i][j] -= f * M[k][j];
    }
  }
  return d;
}

}  // namespace hapstab::check::rational_matrix
