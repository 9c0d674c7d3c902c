// proofs/symbolic.hpp -- polynomials in many variables over Q, and matrices of them, for the claims
// that must hold for EVERY value of their symbols: a matrix identity whose two sides are equal
// entry by entry as polynomials in the matrices' entries holds for all values of those entries,
// not only at sample points (issue 40). Small and sparse: a monomial is the sorted list of its
// variables (with repetition), a polynomial a map from monomials to non-zero rational coefficients.
// Used by proofs/lmi_lemmas.cpp (Lemma 1's Schur identity and Lemma 2's block matrix).
#pragma once

#include <algorithm>
#include <map>
#include <vector>

#include "hapstab/numeric/scalar.hpp"

namespace hapstab::proofs {

class MPoly {
 public:
  MPoly() = default;
  MPoly(const rational& c) {  // NOLINT: a constant is a polynomial
    if (c != 0) terms_[{}] = c;
  }
  static MPoly variable(int id) {
    MPoly p;
    p.terms_[{id}] = 1;
    return p;
  }
  bool is_zero() const { return terms_.empty(); }
  friend bool operator==(const MPoly& a, const MPoly& b) { return a.terms_ == b.terms_; }
  friend bool operator!=(const MPoly& a, const MPoly& b) { return !(a == b); }
  MPoly& operator+=(const MPoly& b) {
    for (const auto& [m, c] : b.terms_) add(m, c);
    return *this;
  }
  MPoly& operator-=(const MPoly& b) {
    for (const auto& [m, c] : b.terms_) add(m, -c);
    return *this;
  }
  friend MPoly operator+(MPoly a, const MPoly& b) { return a += b; }
  friend MPoly operator-(MPoly a, const MPoly& b) { return a -= b; }
  friend MPoly operator*(const MPoly& a, const MPoly& b) {
    MPoly r;
    for (const auto& [ma, ca] : a.terms_)
      for (const auto& [mb, cb] : b.terms_) {
        std::vector<int> m(ma.size() + mb.size());
        std::merge(ma.begin(), ma.end(), mb.begin(), mb.end(), m.begin());
        r.add(m, ca * cb);
      }
    return r;
  }
  /// The number of monomials (for evidence: how large the compared polynomials were).
  size_t size() const { return terms_.size(); }

 private:
  std::map<std::vector<int>, rational> terms_;
  void add(const std::vector<int>& m, const rational& c) {
    auto [it, fresh] = terms_.emplace(m, c);
    if (!fresh) it->second += c;
    if (it->second == 0) terms_.erase(it);
  }
};

/// A matrix of polynomials, row-major.
using SymMat = std::vector<std::vector<MPoly>>;

inline SymMat zeros(size_t r, size_t c) { return SymMat(r, std::vector<MPoly>(c)); }
inline SymMat identity(size_t n) {
  SymMat I = zeros(n, n);
  for (size_t i = 0; i < n; ++i) I[i][i] = rational(1);
  return I;
}
inline size_t rows(const SymMat& A) { return A.size(); }
inline size_t cols(const SymMat& A) { return A.empty() ? 0 : A[0].size(); }

inline SymMat operator*(const SymMat& A, const SymMat& B) {
  SymMat C = zeros(rows(A), cols(B));
  for (size_t i = 0; i < rows(A); ++i)
    for (size_t k = 0; k < cols(A); ++k)
      if (!A[i][k].is_zero())
        for (size_t j = 0; j < cols(B); ++j) C[i][j] += A[i][k] * B[k][j];
  return C;
}
inline SymMat operator*(const rational& s, SymMat A) {
  for (auto& row : A)
    for (auto& x : row) x = MPoly(s) * x;
  return A;
}
inline SymMat operator+(SymMat A, const SymMat& B) {
  for (size_t i = 0; i < rows(A); ++i)
    for (size_t j = 0; j < cols(A); ++j) A[i][j] += B[i][j];
  return A;
}
inline SymMat operator-(SymMat A, const SymMat& B) {
  for (size_t i = 0; i < rows(A); ++i)
    for (size_t j = 0; j < cols(A); ++j) A[i][j] -= B[i][j];
  return A;
}
inline SymMat operator-(const SymMat& A) { return zeros(rows(A), cols(A)) - A; }
inline SymMat transpose(const SymMat& A) {
  SymMat T = zeros(cols(A), rows(A));
  for (size_t i = 0; i < rows(A); ++i)
    for (size_t j = 0; j < cols(A); ++j) T[j][i] = A[i][j];
  return T;
}
/// The block matrix of `b` (rows of blocks; the blocks of a row have equal heights).
inline SymMat blocks(const std::vector<std::vector<SymMat>>& b) {
  SymMat M;
  for (const auto& brow : b)
    for (size_t i = 0; i < rows(brow[0]); ++i) {
      std::vector<MPoly> row;
      for (const auto& blk : brow) row.insert(row.end(), blk[i].begin(), blk[i].end());
      M.push_back(row);
    }
  return M;
}

/// Fresh variables: a general r x c matrix, or a symmetric n x n one (x_ij = x_ji).
class Symbols {
 public:
  SymMat matrix(size_t r, size_t c) {
    SymMat M = zeros(r, c);
    for (auto& row : M)
      for (auto& x : row) x = MPoly::variable(next_++);
    return M;
  }
  SymMat symmetric(size_t n) {
    SymMat M = zeros(n, n);
    for (size_t i = 0; i < n; ++i)
      for (size_t j = i; j < n; ++j) M[i][j] = M[j][i] = MPoly::variable(next_++);
    return M;
  }
  int count() const { return next_; }

 private:
  int next_ = 0;
};

}  // namespace hapstab::proofs
