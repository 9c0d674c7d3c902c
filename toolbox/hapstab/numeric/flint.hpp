// hapstab/numeric/flint.hpp -- the one door to FLINT (exact polynomials and matrices over Z
// and Q) and Arb (ball arithmetic). It hides the two layouts the libraries come in: FLINT 2.9
// with Arb as a separate library (Debian 12: arb.h in the include root) and FLINT 3 with Arb
// inside (flint/arb.h); HAPSTAB_FLINT3 is set by cmake/hapstabDependencies.cmake.
//
// Only the .cpp files of numeric/, poly/, lmi/, passivity/, stability/ and check/ include this header (and the
// internal numeric/ball.hpp, numeric/jet.hpp, which only .cpp files include): no other public header
// names a FLINT or Arb type, and Boost.Multiprecision (numeric/scalar.hpp) stays the scalar
// tower users see. The owners below are move-only RAII wrappers; the conversions are exact.
#pragma once

#include <cmath>
#include <utility>

#include <flint/fmpq.h>
#include <flint/fmpq_mat.h>
#include <flint/fmpq_poly.h>
#include <flint/fmpz.h>
#include <flint/fmpz_poly.h>
#if HAPSTAB_FLINT3
#include <flint/arb_mat.h>
#else
#include <arb_mat.h>
#endif

#include "hapstab/numeric/eigen_traits.hpp"
#include "hapstab/numeric/scalar.hpp"

namespace hapstab::flint {

/// An fmpz_t (integer) that clears itself.
class Fmpz {
 public:
  Fmpz() { fmpz_init(z_); }
  ~Fmpz() { fmpz_clear(z_); }
  Fmpz(const Fmpz&) = delete;
  Fmpz& operator=(const Fmpz&) = delete;
  fmpz* get() { return z_; }
  const fmpz* get() const { return z_; }

 private:
  fmpz_t z_;
};

/// An fmpz_poly_t (integer polynomial) that clears itself.
class FmpzPoly {
 public:
  FmpzPoly() { fmpz_poly_init(p_); }
  ~FmpzPoly() { fmpz_poly_clear(p_); }
  FmpzPoly(const FmpzPoly& o) {
    fmpz_poly_init(p_);
    fmpz_poly_set(p_, o.p_);
  }
  FmpzPoly& operator=(const FmpzPoly& o) {
    fmpz_poly_set(p_, o.p_);
    return *this;
  }
  FmpzPoly(FmpzPoly&& o) noexcept {
    fmpz_poly_init(p_);
    fmpz_poly_swap(p_, o.p_);
  }
  FmpzPoly& operator=(FmpzPoly&& o) noexcept {
    fmpz_poly_swap(p_, o.p_);
    return *this;
  }
  fmpz_poly_struct* get() { return p_; }
  const fmpz_poly_struct* get() const { return p_; }
  long length() const { return fmpz_poly_length(p_); }
  const fmpz* coeff(long i) const { return fmpz_poly_get_coeff_ptr(p_, i); }  ///< i < length()

 private:
  fmpz_poly_t p_;
};

/// An fmpq_poly_t that clears itself.
class FmpqPoly {
 public:
  FmpqPoly() { fmpq_poly_init(p_); }
  ~FmpqPoly() { fmpq_poly_clear(p_); }
  FmpqPoly(const FmpqPoly&) = delete;
  FmpqPoly& operator=(const FmpqPoly&) = delete;
  fmpq_poly_struct* get() { return p_; }
  const fmpq_poly_struct* get() const { return p_; }

 private:
  fmpq_poly_t p_;
};

/// An fmpq_mat_t that clears itself.
class QMat {
 public:
  QMat(long rows, long cols) { fmpq_mat_init(m_, rows, cols); }
  ~QMat() { fmpq_mat_clear(m_); }
  QMat(QMat&& o) noexcept {
    fmpq_mat_init(m_, 0, 0);
    fmpq_mat_swap(m_, o.m_);
  }
  QMat(const QMat&) = delete;
  QMat& operator=(const QMat&) = delete;
  fmpq_mat_struct* get() { return m_; }
  fmpq* at(long i, long j) { return fmpq_mat_entry(m_, i, j); }

 private:
  fmpq_mat_t m_;
};

/// An arb_mat_t (a matrix of real balls) that clears itself.
class BallMat {
 public:
  BallMat(long rows, long cols) { arb_mat_init(m_, rows, cols); }
  ~BallMat() { arb_mat_clear(m_); }
  BallMat(const BallMat&) = delete;
  BallMat& operator=(const BallMat&) = delete;
  arb_mat_struct* get() { return m_; }
  const arb_mat_struct* get() const { return m_; }
  arb_struct* at(long i, long j) { return arb_mat_entry(m_, i, j); }
  long rows() const { return arb_mat_nrows(m_); }
  long cols() const { return arb_mat_ncols(m_); }

 private:
  arb_mat_t m_;
};

/// Exact integer -> fmpz, rational -> fmpq and back.
inline void set(fmpq_t out, const rational& q) { fmpq_set_mpq(out, q.backend().data()); }
inline void set(fmpz_t out, const integer& z) { fmpz_set_mpz(out, z.backend().data()); }
inline integer to_integer(const fmpz_t z) {
  integer r;
  fmpz_get_mpz(r.backend().data(), z);
  return r;
}
inline rational to_rational(const fmpq_t q) {
  rational r;
  fmpq_get_mpq(r.backend().data(), q);
  return r;
}

/// An exact matrix as an fmpq_mat, and the block (r0, c0, rows x cols) of one back.
inline QMat to_qmat(const MatQ& M) {
  QMat q(static_cast<long>(M.rows()), static_cast<long>(M.cols()));
  for (long i = 0; i < M.rows(); ++i)
    for (long j = 0; j < M.cols(); ++j) set(q.at(i, j), M(i, j));
  return q;
}
inline MatQ from_qmat(QMat& q, long rows, long cols, long r0 = 0, long c0 = 0) {
  MatQ M(rows, cols);
  for (long i = 0; i < rows; ++i)
    for (long j = 0; j < cols; ++j) M(i, j) = to_rational(q.at(r0 + i, c0 + j));
  return M;
}

/// A rational as a real ball at `prec` bits (exact when it is a short dyadic).
inline void set(arb_t out, const rational& q, long prec) {
  fmpq_t f;
  fmpq_init(f);
  set(f, q);
  arb_set_fmpq(out, f, prec);
  fmpq_clear(f);
}
/// A finite arf m 2^e as the exact rational it is.
inline rational to_rational(const arf_t a) {
  Fmpz m, e;
  arf_get_fmpz_2exp(m.get(), e.get(), a);
  rational r(to_integer(m.get()));
  const long ex = fmpz_get_si(e.get());
  if (ex >= 0) return r * rational(integer(1) << static_cast<unsigned>(ex));
  return r / rational(integer(1) << static_cast<unsigned>(-ex));
}

/// A finite ball as a double midpoint (nearest) and a double radius that covers the ball's radius
/// and the rounding of the midpoint, rounded up; false when the ball is not finite.
inline bool to_double_ball(const arb_t x, double& mid, double& rad) {
  if (!arb_is_finite(x)) return false;
  mid = arf_get_d(arb_midref(x), ARF_RND_NEAR);
  arf_t d;
  arf_init(d);
  arf_set_d(d, mid);
  arf_sub(d, d, arb_midref(x), 64, ARF_RND_UP);
  const double rounding = std::fabs(arf_get_d(d, ARF_RND_UP));
  arf_clear(d);
  const double r = mag_get_d(arb_radref(x)) + rounding;  // mag_get_d rounds up
  rad = r > 0 ? std::nextafter(r, INFINITY) : 0.0;
  return true;
}

}  // namespace hapstab::flint
