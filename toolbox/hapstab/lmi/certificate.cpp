// hapstab/lmi/certificate.cpp -- exact definiteness tests, dyadic rounding, facial reduction.
#include "hapstab/lmi/certificate.hpp"

#include <Eigen/QR>
#include <algorithm>
#include <cmath>

#include "hapstab/numeric/decimal.hpp"
#include "hapstab/numeric/flint.hpp"
#include "hapstab/numeric/error.hpp"

namespace hapstab::lmi {

Definiteness exact_definiteness(MatQ M) {
  Definiteness d;
  const auto n = M.rows();
  if (M.cols() != n) throw InputError("exact_definiteness: matrix is not square");
  for (Eigen::Index i = 0; i < n; ++i)
    for (Eigen::Index j = 0; j < i; ++j) {
      rational s = (M(i, j) + M(j, i)) / 2;
      M(i, j) = s;  // only the lower triangle is used below
    }
  bool first = true;
  for (Eigen::Index k = 0; k < n; ++k) {
    const rational p = M(k, k);
    if (first || p < d.min_pivot) d.min_pivot = p;
    first = false;
    if (p < 0) {
      d.failed_at = static_cast<int>(k);
      return d;
    }
    if (p == 0) {
      for (Eigen::Index i = k + 1; i < n; ++i)
        if (M(i, k) != 0) {  // zero pivot with a non-zero rest of its row: indefinite
          d.failed_at = static_cast<int>(k);
          return d;
        }
      continue;
    }
    ++d.rank;
    for (Eigen::Index i = k + 1; i < n; ++i) {
      if (M(i, k) == 0) continue;
      const rational f = M(i, k) / p;
      for (Eigen::Index j = k + 1; j <= i; ++j)
        if (M(j, k) != 0) M(i, j) -= f * M(j, k);
    }
  }
  d.psd = true;
  d.pd = d.rank == n;
  return d;
}

namespace {
// A proof of positive definiteness by Arb's ball Cholesky (arb_mat_cho: nonzero only when the
// matrix is certainly positive definite) at 128 bits on the integer matrix, exactly loaded up
// to the ball's own radius. A false is no verdict: the caller then decides exactly.
bool ball_cholesky_pd_lower(const std::vector<integer>& A, Eigen::Index n) {
  const long prec = 128;
  flint::BallMat M(static_cast<long>(n), static_cast<long>(n)), L(static_cast<long>(n), static_cast<long>(n));
  fmpz_t f;
  fmpz_init(f);
  for (Eigen::Index i = 0; i < n; ++i)
    for (Eigen::Index j = 0; j <= i; ++j) {
      fmpz_set_mpz(f, A[static_cast<size_t>(i * n + j)].backend().data());
      arb_set_round_fmpz(M.at(static_cast<long>(i), static_cast<long>(j)), f, prec);
      arb_set(M.at(static_cast<long>(j), static_cast<long>(i)), M.at(static_cast<long>(i), static_cast<long>(j)));
    }
  fmpz_clear(f);
  return arb_mat_cho(L.get(), M.get(), prec) != 0;
}

// Leading principal minors of the symmetric integer matrix whose lower triangle is A (row-major
// n x n, upper part unused), fraction-free (Bareiss): true iff all are positive. Destroys A.
// Ball Cholesky first (microseconds where Bareiss's integers grow to thousands of digits: the
// 32-device Theorem 5 certificate); it can only say "yes", so a "no" is always Bareiss's.
bool bareiss_pd_lower(std::vector<integer>& A, Eigen::Index n) {
  if (n >= 8 && ball_cholesky_pd_lower(A, n)) return true;
  auto at = [&](Eigen::Index i, Eigen::Index j) -> integer& { return A[static_cast<size_t>(i * n + j)]; };
  integer prev = 1, t;
  for (Eigen::Index k = 0; k < n; ++k) {
    if (at(k, k) <= 0) return false;  // leading principal minor k+1 (times a positive factor) not positive
    for (Eigen::Index i = k + 1; i < n; ++i)
      for (Eigen::Index j = k + 1; j <= i; ++j) {
        t = at(i, j) * at(k, k);
        t -= at(i, k) * at(j, k);
        at(i, j) = t / prev;  // exact division (Sylvester's identity)
      }
    prev = at(k, k);
  }
  return true;
}

// v = mant * 2^exp exactly (mant odd or 0, |mant| < 2^53).
void split_double(double v, long long& mant, long& exp) {
  if (v == 0.0) {
    mant = 0;
    exp = 0;
    return;
  }
  int e = 0;
  const double f = std::frexp(v, &e);
  mant = static_cast<long long>(std::ldexp(f, 53));
  exp = e - 53;
  const int tz = __builtin_ctzll(static_cast<unsigned long long>(mant < 0 ? -mant : mant));
  mant >>= tz;
  exp += tz;
}
}  // namespace

bool exact_lmi_holds(const Expr& F, const std::vector<rational>& x, bool strict) {
  const Eigen::Index n = F.rows();
  if (F.cols() != n) throw InputError("exact_lmi_holds: matrix is not square");
  if (n == 0) return true;
  // common denominator q of the x_k used, integer numerators P_k = x_k q
  integer q = 1;
  for (const auto& [k, m] : F.terms()) {
    const rational& xk = x.at(static_cast<size_t>(k));
    if (xk != 0 && m.nonZeros() > 0) {
      const integer d = den(xk);
      if (d != 1) q = boost::multiprecision::lcm(q, d);
    }
  }
  struct Contrib {
    Eigen::Index i, j;
    long long mant;
    long exp;
    const integer* a;  // multiplier (q for the constant, P_k for term k)
  };
  std::vector<Contrib> cs;
  std::vector<integer> P;
  P.reserve(F.terms().size());
  long emin = 0;
  bool first = true;
  auto add = [&](Eigen::Index i, Eigen::Index j, double v, const integer* a) {
    long long mt;
    long ex;
    split_double(v, mt, ex);
    if (mt == 0) return;
    if (first || ex < emin) emin = ex;
    first = false;
    cs.push_back({i, j, mt, ex, a});
  };
  const MatrixXd& C0 = F.constant();
  for (Eigen::Index j = 0; j < n; ++j)
    for (Eigen::Index i = 0; i < n; ++i)
      if (C0(i, j) != 0.0) add(i, j, C0(i, j), &q);
  for (const auto& [k, m] : F.terms()) {
    const rational& xk = x.at(static_cast<size_t>(k));
    if (xk == 0) continue;
    P.push_back(num(xk) * (q / den(xk)));
    const integer* a = &P.back();
    for (int o = 0; o < m.outerSize(); ++o)
      for (SpMat::InnerIterator it(m, o); it; ++it) add(it.row(), it.col(), it.value(), a);
  }
  // integer matrix G = q 2^-emin F(x), then S = G + G^T (lower triangle)
  std::vector<integer> G(static_cast<size_t>(n * n));
  integer t;
  for (const auto& c : cs) {
    t = *c.a;
    t *= c.mant;
    t <<= static_cast<unsigned>(c.exp - emin);
    const Eigen::Index i = std::max(c.i, c.j), j = std::min(c.i, c.j);
    G[static_cast<size_t>(i * n + j)] += t;  // (i,j) and (j,i) both land in the lower triangle: G + G^T
  }
  for (Eigen::Index i = 0; i < n; ++i) G[static_cast<size_t>(i * n + i)] *= 2;
  if (strict) return bareiss_pd_lower(G, n);
  MatQ S(n, n);
  for (Eigen::Index i = 0; i < n; ++i)
    for (Eigen::Index j = 0; j <= i; ++j) S(i, j) = S(j, i) = rational(G[static_cast<size_t>(i * n + j)]);
  return exact_definiteness(std::move(S)).psd;
}

bool exact_pd_bareiss(const MatQ& Min) {
  const auto n = Min.rows();
  if (Min.cols() != n) throw InputError("exact_pd_bareiss: matrix is not square");
  if (n == 0) return true;
  // Symmetric part, then a common denominator (lcm) to get an integer matrix.
  MatQ S(n, n);
  integer L = 1;
  for (Eigen::Index i = 0; i < n; ++i)
    for (Eigen::Index j = 0; j <= i; ++j) {
      S(i, j) = (i == j) ? Min(i, i) : (Min(i, j) + Min(j, i)) / 2;
      const integer dd = den(S(i, j));
      if (dd != 1) L = boost::multiprecision::lcm(L, dd);
    }
  std::vector<integer> A(static_cast<size_t>(n * n));
  for (Eigen::Index i = 0; i < n; ++i)
    for (Eigen::Index j = 0; j <= i; ++j) A[static_cast<size_t>(i * n + j)] = num(S(i, j)) * (L / den(S(i, j)));
  return bareiss_pd_lower(A, n);
}

rational round_dyadic(double x, int bits) {
  if (!std::isfinite(x)) throw NumericalError("round_dyadic: value is not finite");
  if (x == 0.0 || bits >= 53) return exact_rational(x);
  int e = 0;
  const double m = std::frexp(x, &e);  // x = m 2^e, 0.5 <= |m| < 1
  const double r = std::nearbyint(std::ldexp(m, bits));
  return exact_rational(std::ldexp(r, e - bits));  // exact: r has <= bits+1 significant bits
}

MatQ to_rational(const Eigen::MatrixXd& M) {
  MatQ Q(M.rows(), M.cols());
  for (Eigen::Index j = 0; j < M.cols(); ++j)
    for (Eigen::Index i = 0; i < M.rows(); ++i) Q(i, j) = exact_rational(M(i, j));
  return Q;
}

MatQ exact_value(const Expr& F, const std::vector<rational>& x) {
  MatQ V = to_rational(F.constant());
  for (const auto& [k, m] : F.terms()) {
    const rational& xk = x.at(static_cast<size_t>(k));
    if (xk == 0) continue;
    for (int o = 0; o < m.outerSize(); ++o)
      for (SpMat::InnerIterator it(m, o); it; ++it) V(it.row(), it.col()) += xk * exact_rational(it.value());
  }
  return V;
}

int facial_reduce(Program& prog, const std::string& lmi_name, const Eigen::MatrixXd& V) {
  int idx = -1;
  for (size_t i = 0; i < prog.lmis().size(); ++i)
    if (prog.lmis()[i].name == lmi_name) idx = static_cast<int>(i);
  if (idx < 0) throw InputError("facial_reduce: no constraint named '" + lmi_name + "'");
  LmiConstraint c = prog.lmis()[static_cast<size_t>(idx)];
  const int n = c.F.rows();
  const std::string where = "facial_reduce on constraint '" + lmi_name + "'";
  if (V.rows() != n || V.cols() < 1 || V.cols() >= n)
    throw InputError(where + ": kernel vectors must be " + std::to_string(n) + "xr with 1 <= r < " + std::to_string(n));
  Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(V);
  if (qr.rank() != V.cols()) throw InputError(where + ": the kernel vectors are linearly dependent");
  const Eigen::MatrixXd Q = qr.householderQ();
  const Eigen::MatrixXd U = Q.rightCols(n - V.cols());
  // 1) the equalities F(x) V = 0 (imposed exactly by the elimination in solve.cpp);
  prog.add_linear_equality(lmi_name + " [F*V = 0]", c.F * V, Eigen::MatrixXd::Zero(n, V.cols()));
  // 2) the original constraint, non-strict, checked exactly but not posed;
  c.strictness = Strictness::nonstrict;
  c.posed = false;
  prog.replace_lmi(idx, c);
  // 3) the reduced constraint U^T F U > 0, posed to the solver (it has an interior).
  Expr R = U.transpose() * c.F * U;
  Expr Rs = 0.5 * (R + R.transpose());
  int r = prog.add_lmi(lmi_name + " [reduced]", Rs, Strictness::strict);
  LmiConstraint rc = prog.lmis()[static_cast<size_t>(r)];
  rc.auxiliary = true;
  prog.replace_lmi(r, rc);
  return r;
}

}  // namespace hapstab::lmi
