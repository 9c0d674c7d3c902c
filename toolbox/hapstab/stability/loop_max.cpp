// The supremum of a parameter of the loop as written, any number of DOF (see loop_max.hpp).
#include "hapstab/stability/loop_max.hpp"

#include <Eigen/Eigenvalues>
#include <Eigen/QR>
#include <Eigen/SVD>
#if HAPSTAB_FLINT3
#include <flint/acb_mat.h>
#else
#include <acb_mat.h>
#endif
#include <algorithm>
#include <cmath>
#include <complex>
#include <functional>
#include <memory>
#include <sstream>
#include <vector>

#include "hapstab/numeric/ball.hpp"
#include "hapstab/numeric/decimal.hpp"
#include "hapstab/numeric/ball_matrix.hpp"
#include "hapstab/numeric/error.hpp"
#include "hapstab/numeric/exact_matrix.hpp"
#include "hapstab/numeric/lyapunov_ball.hpp"
#include "hapstab/lti/circle_crossing.hpp"
#include "hapstab/lti/realization.hpp"
#include "hapstab/numeric/numeric_decimal.hpp"
#include "hapstab/poly/stability.hpp"
#include "hapstab/poly/sturm.hpp"
#include "hapstab/sim/closed_loop.hpp"
#include "hapstab/stability/loop_as_written.hpp"

namespace hapstab::stability {

namespace {

using flint::Ball;
using flint::BallMat;

bool equal(const MatQ& a, const MatQ& b) {
  if (a.rows() != b.rows() || a.cols() != b.cols()) return false;
  for (Eigen::Index i = 0; i < a.rows(); ++i)
    for (Eigen::Index j = 0; j < a.cols(); ++j)
      if (a(i, j) != b(i, j)) return false;
  return true;
}

void load(BallMat& out, const MatQ& A, long prec) {
  flint::QMat q = flint::to_qmat(A);
  arb_mat_set_fmpq_mat(out.get(), q.get(), prec);
}

// dst[r0.., c0..] := src (or += when add)
void put(BallMat& dst, long r0, long c0, const BallMat& src, bool add, long prec) {
  for (long i = 0; i < src.rows(); ++i)
    for (long j = 0; j < src.cols(); ++j) {
      arb_struct* d = dst.at(r0 + i, c0 + j);
      const arb_struct* s = arb_mat_entry(src.get(), i, j);
      if (add) arb_add(d, d, s, prec);
      else arb_set(d, s);
    }
}

// The plant over the period at `prec` bits (sim/closed_loop.hpp): Phi_T, and the input matrices of
// u_{k-n} (Gn) and, with a fractional delay, of u_{k-n-1} (Go). Van Loan: exp([[A, B], [0, 0]] h).
struct ArbZoh {
  std::unique_ptr<BallMat> Phi, Gn, Go;
};
void van_loan(BallMat& Phi, BallMat& G, const MatQ& A, const MatQ& B, const rational& h, long prec) {
  const long ns = static_cast<long>(A.rows()), m = static_cast<long>(B.cols());
  MatQ V = MatQ::Zero(ns + m, ns + m);
  V.topLeftCorner(ns, ns) = A * h;
  V.topRightCorner(ns, m) = B * h;
  BallMat X(ns + m, ns + m), E(ns + m, ns + m);
  load(X, V, prec);
  arb_mat_exp(E.get(), X.get(), prec);
  for (long i = 0; i < ns; ++i) {
    for (long j = 0; j < ns; ++j) arb_set(Phi.at(i, j), E.at(i, j));
    for (long j = 0; j < m; ++j) arb_set(G.at(i, j), E.at(i, ns + j));
  }
}
ArbZoh plant_zoh(const LoopFamily& F, long prec) {
  const long ns = static_cast<long>(F.A.rows()), N = F.N;
  ArbZoh z{std::make_unique<BallMat>(ns, ns), std::make_unique<BallMat>(ns, N), std::make_unique<BallMat>(ns, N)};
  BallMat G(ns, N);
  van_loan(*z.Phi, G, F.A, F.Bu, F.T, prec);
  if (F.f > 0) {
    BallMat Pf(ns, ns), Gf(ns, N), Pr(ns, ns);
    van_loan(Pf, Gf, F.A, F.Bu, F.f, prec);
    van_loan(Pr, *z.Gn, F.A, F.Bu, F.T - F.f, prec);
    arb_mat_mul(z.Go->get(), Pr.get(), Gf.get(), prec);
  } else {
    arb_mat_set(z.Gn->get(), G.get());
  }
  return z;
}

long slots(const LoopFamily& F) { return F.n + (F.f > 0 ? 1 : 0); }
long order(const LoopFamily& F) { return static_cast<long>(F.A.rows() + F.Kx0.rows()) + slots(F) * F.N; }

// M of sim/closed_loop.cpp with the controller rows (Ku, Kx); `constant` false leaves out what does
// not depend on them (Phi, the delayed inputs' blocks, the buffer's shift): M1 from (dKu, dKx).
void assemble(BallMat& M, const LoopFamily& F, const ArbZoh& z, const MatQ& Ku, const MatQ& Kx, bool constant, long prec) {
  const long ns = static_cast<long>(F.A.rows()), nc = static_cast<long>(Kx.rows()), N = F.N, n = F.n;
  const long nb = slots(F) * N;
  arb_mat_zero(M.get());
  BallMat Kub(N, ns + nc), Kxb(nc, ns + nc);
  load(Kub, Ku, prec);
  load(Kxb, Kx, prec);
  if (constant) put(M, 0, 0, *z.Phi, false, prec);
  if (n == 0) {
    BallMat GK(ns, ns + nc);
    arb_mat_mul(GK.get(), z.Gn->get(), Kub.get(), prec);
    put(M, 0, 0, GK, true, prec);
  } else if (constant) {
    put(M, 0, ns + nc + (n - 1) * N, *z.Gn, false, prec);
  }
  if (F.f > 0 && constant) put(M, 0, ns + nc + n * N, *z.Go, false, prec);
  put(M, ns, 0, Kxb, false, prec);
  if (nb > 0) {
    put(M, ns + nc, 0, Kub, false, prec);
    if (constant)
      for (long j = N; j < nb; ++j) arb_one(M.at(ns + nc + j, ns + nc + j - N));
  }
}

// M0 and M1 at `prec` bits.
struct ArbFamily {
  std::unique_ptr<BallMat> M0, M1;
};
ArbFamily arb_family(const LoopFamily& F, long prec) {
  const long nx = order(F);
  ArbFamily a{std::make_unique<BallMat>(nx, nx), std::make_unique<BallMat>(nx, nx)};
  const ArbZoh z = plant_zoh(F, prec);
  assemble(*a.M0, F, z, F.Ku0, F.Kx0, true, prec);
  assemble(*a.M1, F, z, F.dKu, F.dKx, false, prec);
  return a;
}

Eigen::MatrixXd mid(const BallMat& B) {
  Eigen::MatrixXd m(B.rows(), B.cols());
  for (long i = 0; i < B.rows(); ++i)
    for (long j = 0; j < B.cols(); ++j) m(i, j) = arf_get_d(arb_midref(arb_mat_entry(B.get(), i, j)), ARF_RND_NEAR);
  return m;
}

// ---- step 2: the Krawczyk operator of the crossing system (loop_max.hpp) ----
struct CrossingSystem {
  const BallMat& M0;
  const BallMat& M1;
  bool complex;          // unknowns (a, b, p, theta); else (a, p) with z = sigma
  double sigma = 1;      // z = +-1 (real case)
  Eigen::VectorXd cr, ci;  // the normalising vector c
  long n() const { return M0.rows(); }
  long size() const { return complex ? 2 * n() + 2 : n() + 1; }
};

// F(x) and, when J != nullptr, its Jacobian, for every point of the ball vector x (m x 1).
void evaluate(const CrossingSystem& S, const BallMat& x, BallMat& Fv, BallMat* J, long prec) {
  const long n = S.n(), m = S.size();
  const long ip = S.complex ? 2 * n : n;
  BallMat Mp(n, n), a(n, 1), b(n, 1), Ma(n, 1), Mb(n, 1), M1a(n, 1), M1b(n, 1);
  arb_mat_scalar_mul_arb(Mp.get(), S.M1.get(), arb_mat_entry(x.get(), ip, 0), prec);
  arb_mat_add(Mp.get(), Mp.get(), S.M0.get(), prec);
  for (long i = 0; i < n; ++i) {
    arb_set(a.at(i, 0), arb_mat_entry(x.get(), i, 0));
    if (S.complex) arb_set(b.at(i, 0), arb_mat_entry(x.get(), n + i, 0));
  }
  arb_mat_mul(Ma.get(), Mp.get(), a.get(), prec);
  arb_mat_mul(M1a.get(), S.M1.get(), a.get(), prec);
  Ball c, s, t;
  if (S.complex) {
    arb_mat_mul(Mb.get(), Mp.get(), b.get(), prec);
    arb_mat_mul(M1b.get(), S.M1.get(), b.get(), prec);
    arb_sin_cos(s.get(), c.get(), arb_mat_entry(x.get(), ip + 1, 0), prec);
  } else {
    arb_set_d(c.get(), S.sigma);
  }
  arb_mat_zero(Fv.get());
  for (long i = 0; i < n; ++i) {
    arb_struct* f1 = Fv.at(i, 0);
    arb_mul(t.get(), c.get(), a.at(i, 0), prec);
    arb_sub(f1, Ma.at(i, 0), t.get(), prec);
    if (S.complex) {
      arb_addmul(f1, s.get(), b.at(i, 0), prec);
      arb_struct* f2 = Fv.at(n + i, 0);
      arb_mul(t.get(), c.get(), b.at(i, 0), prec);
      arb_sub(f2, Mb.at(i, 0), t.get(), prec);
      arb_submul(f2, s.get(), a.at(i, 0), prec);
    }
  }
  // the normalisation rows
  arb_struct* g1 = Fv.at(ip, 0);
  for (long i = 0; i < n; ++i) {
    arb_set_d(t.get(), S.cr(i));
    arb_addmul(g1, t.get(), a.at(i, 0), prec);
    if (S.complex) {
      arb_struct* g2 = Fv.at(ip + 1, 0);
      arb_set_d(t.get(), S.ci(i));
      arb_addmul(g1, t.get(), b.at(i, 0), prec);
      arb_submul(g2, t.get(), a.at(i, 0), prec);
      arb_set_d(t.get(), S.cr(i));
      arb_addmul(g2, t.get(), b.at(i, 0), prec);
    }
  }
  arb_sub_ui(g1, g1, 1, prec);
  if (!J) return;
  arb_mat_zero(J->get());
  for (long i = 0; i < n; ++i) {
    for (long j = 0; j < n; ++j) {
      arb_set(J->at(i, j), Mp.at(i, j));
      if (S.complex) arb_set(J->at(n + i, n + j), Mp.at(i, j));
    }
    arb_sub(J->at(i, i), J->at(i, i), c.get(), prec);
    arb_set(J->at(i, ip), M1a.at(i, 0));
    if (S.complex) {
      arb_sub(J->at(n + i, n + i), J->at(n + i, n + i), c.get(), prec);
      arb_set(J->at(i, n + i), s.get());
      arb_neg(J->at(n + i, i), s.get());
      arb_set(J->at(n + i, ip), M1b.at(i, 0));
      // d/dtheta: s a + c b and s b - c a
      arb_mul(J->at(i, ip + 1), s.get(), a.at(i, 0), prec);
      arb_addmul(J->at(i, ip + 1), c.get(), b.at(i, 0), prec);
      arb_mul(J->at(n + i, ip + 1), s.get(), b.at(i, 0), prec);
      arb_submul(J->at(n + i, ip + 1), c.get(), a.at(i, 0), prec);
    }
    arb_set_d(J->at(ip, i), S.cr(i));
    if (S.complex) {
      arb_set_d(J->at(ip, n + i), S.ci(i));
      arb_set_d(J->at(ip + 1, i), -S.ci(i));
      arb_set_d(J->at(ip + 1, n + i), S.cr(i));
    }
  }
  (void)m;
}

struct Enclosed {
  bool ok = false;
  Enclosure<rational> p{0, 0}, theta{0, 0};
  double rel_width = 0;
  std::string why;
};

// Newton at `prec` from x (midpoints), then the Krawczyk test on a box around the result.
Enclosed krawczyk(const CrossingSystem& S, BallMat& x, long prec) {
  const long m = S.size(), n = S.n();
  const long ip = S.complex ? 2 * n : n;
  BallMat Fv(m, 1), J(m, m), d(m, 1);
  for (int it = 0; it < 60; ++it) {
    arb_mat_get_mid(x.get(), x.get());
    evaluate(S, x, Fv, &J, prec);
    if (!arb_mat_approx_solve(d.get(), J.get(), Fv.get(), prec)) return {false, {0, 0}, {0, 0}, 0, "the crossing system is singular"};
    arb_mat_sub(x.get(), x.get(), d.get(), prec);
    arb_mat_get_mid(x.get(), x.get());
    // converged: the step is at the working precision's noise
    bool small = true;
    for (long i = 0; i < m && small; ++i) {
      const double di = std::fabs(arf_get_d(arb_midref(d.at(i, 0)), ARF_RND_UP));
      const double xi = std::fabs(arf_get_d(arb_midref(x.at(i, 0)), ARF_RND_UP));
      small = di <= std::ldexp(1.0 + xi, static_cast<int>(-prec + 24)) || di == 0;
    }
    if (small && it > 1) break;
  }
  // Y ~ J(x~)^-1 (exact midpoints), r from Y F(x~)
  evaluate(S, x, Fv, &J, prec);
  BallMat Y(m, m), YF(m, 1);
  if (!arb_mat_approx_inv(Y.get(), J.get(), prec)) return {false, {0, 0}, {0, 0}, 0, "the Jacobian of the crossing system is singular"};
  arb_mat_get_mid(Y.get(), Y.get());
  arb_mat_mul(YF.get(), Y.get(), Fv.get(), prec);
  std::vector<double> r(static_cast<size_t>(m));
  for (long i = 0; i < m; ++i) {
    const double yi = mag_get_d(arb_radref(YF.at(i, 0))) + std::fabs(arf_get_d(arb_midref(YF.at(i, 0)), ARF_RND_UP));
    const double xi = std::fabs(arf_get_d(arb_midref(x.at(i, 0)), ARF_RND_UP));
    r[static_cast<size_t>(i)] = 4 * yi + std::ldexp(1.0 + xi, static_cast<int>(-prec + 16));
  }
  BallMat X(m, 1), JX(m, m), I(m, m), D(m, 1), K(m, 1);
  for (int attempt = 0; attempt < 6; ++attempt) {
    for (long i = 0; i < m; ++i) {
      arb_set(X.at(i, 0), x.at(i, 0));
      mag_set_d(arb_radref(X.at(i, 0)), r[static_cast<size_t>(i)]);
    }
    // K(X) = x~ - Y F(x~) + (I - Y J(X)) (X - x~)
    evaluate(S, X, D, &JX, prec);
    arb_mat_mul(JX.get(), Y.get(), JX.get(), prec);
    arb_mat_one(I.get());
    arb_mat_sub(I.get(), I.get(), JX.get(), prec);
    arb_mat_sub(D.get(), X.get(), x.get(), prec);
    arb_mat_mul(K.get(), I.get(), D.get(), prec);
    arb_mat_add(K.get(), K.get(), x.get(), prec);
    arb_mat_sub(K.get(), K.get(), YF.get(), prec);
    bool inside = true;
    for (long i = 0; i < m && inside; ++i) inside = arb_contains_interior(X.at(i, 0), K.at(i, 0));
    if (inside) {
      Enclosed e;
      e.ok = true;
      e.p = Ball(K.at(ip, 0)).bounds();
      if (S.complex) e.theta = Ball(K.at(ip + 1, 0)).bounds();
      const double pm = std::fabs(arf_get_d(arb_midref(K.at(ip, 0)), ARF_RND_NEAR));
      e.rel_width = 2 * mag_get_d(arb_radref(K.at(ip, 0))) / pm;
      return e;
    }
    for (double& ri : r) ri *= 16;
  }
  return {false, {0, 0}, {0, 0}, 0, "the Krawczyk test did not contract at " + std::to_string(prec) + " bits"};
}

// S <- D^-1 S D for a diagonal D of powers of two (exact in balls: a similarity, the same
// eigenvalues), D balancing the midpoint's row and column norms (Parlett and Reinsch's iteration,
// as LAPACK's gebal). An environment realised with entries ~10^4 beside a device's ~10^-3 gives
// the Stein solve a P too ill-conditioned for double near a double eigenvalue; balanced, the
// same ball is certified (scene_max seed 58 case 100: the walk towards 0 stopped at g = 64.5).
// Not always better (on other scenes the unbalanced ball is certified and the balanced not), so
// stein() tries both.
void balance_by_powers_of_two(BallMat& S) {
  const long n = S.rows();
  Eigen::MatrixXd A(n, n);
  for (long i = 0; i < n; ++i)
    for (long j = 0; j < n; ++j) A(i, j) = arf_get_d(arb_midref(arb_mat_entry(S.get(), i, j)), ARF_RND_NEAR);
  const std::vector<long> e = balancing_exponents(A);
  for (long i = 0; i < n; ++i)
    for (long j = 0; j < n; ++j)
      if (i != j) {
        arb_struct* x = arb_mat_entry(S.get(), i, j);
        arb_mul_2exp_si(x, x, e[static_cast<size_t>(j)] - e[static_cast<size_t>(i)]);
      }
}

// An Arb ball matrix as numeric/ball_matrix.hpp's double BallMatrix: double midpoints, the rounding
// added to the radius (outward).
BallMatrix double_ball_matrix(const BallMat& S) {
  const long n = S.rows();
  BallMatrix Mb(n, S.cols());
  for (long i = 0; i < n; ++i)
    for (long j = 0; j < S.cols(); ++j) {
      const arb_struct* x = arb_mat_entry(S.get(), i, j);
      const double m = arf_get_d(arb_midref(x), ARF_RND_NEAR);
      Ball e;
      arb_set_d(e.get(), m);
      arb_sub(e.get(), e.get(), x, 128);
      mag_t t;
      mag_init(t);
      arb_get_mag(t, e.get());
      Mb.mid(i, j) = m;
      Mb.rad(i, j) = std::nextafter(mag_get_d(t), INFINITY);
      mag_clear(t);
    }
  return Mb;
}

// ---- step 3: eigenvalue enclosures over intervals of p (Rump's test in Arb) ----
struct AcbMat {
  acb_mat_t m;
  AcbMat(long r, long c) { acb_mat_init(m, r, c); }
  ~AcbMat() { acb_mat_clear(m); }
  AcbMat(const AcbMat&) = delete;
  AcbMat& operator=(const AcbMat&) = delete;
};
struct AcbVec {
  acb_ptr v;
  long n;
  explicit AcbVec(long k) : v(_acb_vec_init(k)), n(k) {}
  ~AcbVec() { _acb_vec_clear(v, n); }
  AcbVec(const AcbVec&) = delete;
  AcbVec& operator=(const AcbVec&) = delete;
};

// A := M0 + [lo, hi] M1 (complex balls holding every matrix of the family on [lo, hi])
void family_ball(AcbMat& A, const BallMat& M0, const BallMat& M1, const rational& lo, const rational& hi, long prec) {
  flint::BallPrecision bp(prec);
  const Ball k = Ball::hull(lo, hi);
  BallMat B(M0.rows(), M0.cols());
  arb_mat_scalar_mul_arb(B.get(), M1.get(), k.get(), prec);
  arb_mat_add(B.get(), B.get(), M0.get(), prec);
  acb_mat_set_arb_mat(A.m, B.get());
}

// Disjoint enclosures E of the n eigenvalues of every matrix in the ball A (each ball holds exactly
// one, simple; Arb's arithmetic is inclusion-isotone, so the test run on the ball proves it for each
// matrix the ball holds), and with L, R: L = R^-1, L A R = diag(E). false: not isolated.
bool spectrum(AcbVec& E, AcbMat* L, AcbMat* R, const AcbMat& A, long prec) {
  const long n = acb_mat_nrows(A.m);
  AcbMat Am(n, n), Ra(n, n);
  AcbVec Ea(n);
  acb_mat_get_mid(Am.m, A.m);
  if (prec <= 64) {  // the approximation in double (Rump's test proves what it encloses either way)
    Eigen::MatrixXd m(n, n);
    for (long i = 0; i < n; ++i)
      for (long j = 0; j < n; ++j) m(i, j) = arf_get_d(arb_midref(acb_realref(acb_mat_entry(Am.m, i, j))), ARF_RND_NEAR);
    Eigen::EigenSolver<Eigen::MatrixXd> es(m, true);
    if (es.info() != Eigen::Success) return false;
    for (long i = 0; i < n; ++i) {
      acb_set_d_d(Ea.v + i, es.eigenvalues()(i).real(), es.eigenvalues()(i).imag());
      for (long j = 0; j < n; ++j) acb_set_d_d(acb_mat_entry(Ra.m, j, i), es.eigenvectors()(j, i).real(), es.eigenvectors()(j, i).imag());
    }
  } else {
    acb_mat_approx_eig_qr(Ea.v, nullptr, Ra.m, Am.m, nullptr, 0, prec);
  }
  return acb_mat_eig_simple_rump(E.v, L ? L->m : nullptr, R ? R->m : nullptr, A.m, Ea.v, Ra.m, prec) != 0;
}

// |z| < 1 for every point of the ball z
bool inside_disk(const acb_t z, long prec) {
  Ball r;
  acb_abs(r.get(), z, prec);
  arb_sub_ui(r.get(), r.get(), 1, prec);
  return arb_is_negative(r.get());
}

// Gershgorin's discs of the first-order covers at p = 0 (Cover::near_zero): B = R^-1 M0 R (first k
// columns exactly [I; 0]) and C = R^-1 M1 R in the basis R = [V Q, R2], scaled by D = diag(I, t K),
// K = diag(kappa) (Cover::near_zero states the bounds). Row i of the first block: centre 1 + t c_i,
// c_i = C_ii, radius t rho_i + t^2 sigma_i. Row i of the second block: centre B_ii + t C_ii, radius
// sum_{j in 2, j != i} (|B_ij| + t |C_ij|) kappa_j / kappa_i + q_i / kappa_i, q_i = sum_{j in 1} |C_ij|.
struct ZeroDiscs {
  const AcbMat& B;
  const AcbMat& C;
  long k, n, pr;
  std::vector<Ball> kap, rho, sig;  // kappa (second block); rho_i, sigma_i (first block)

  ZeroDiscs(const AcbMat& B_, const AcbMat& C_, long k_, long pr_) : B(B_), C(C_), k(k_), n(acb_mat_nrows(B_.m)), pr(pr_) {}

  Ball abs_of(const AcbMat& M, long i, long j) const {
    Ball t;
    acb_abs(t.get(), acb_mat_entry(M.m, i, j), pr);
    return t;
  }
  Ball sum_abs(const AcbMat& M, long i, long j0, long j1, long skip) const {
    Ball s;
    for (long j = j0; j < j1; ++j)
      if (j != skip) arb_add(s.get(), s.get(), abs_of(M, i, j).get(), pr);
    return s;
  }
  static double upper(const Ball& x) { return arf_get_d(arb_midref(x.get()), ARF_RND_UP) + mag_get_d(arb_radref(x.get())); }
  Ball re_c(long i) const {
    Ball r;
    arb_set(r.get(), acb_realref(acb_mat_entry(C.m, i, i)));
    return r;
  }

  // kappa: W(e) kappa = 2 q + tiny over the second block, W(e) = diag(1 - max(|B_ii|, |B_ii + e C_ii|)) - (|B_off| +
  // e |C_off|) -- Perron's scaling for the discs at t = e (at e = 0 the smallest kappa with each second-block disc
  // inside; at the eps tried, every second-block disc then has the margin q_i / kappa_i there, where a kappa for t = 0
  // lets a row of small kappa beside a delay register's large ones fail at 1e-10: seed 7 case 163 of
  // indep_symmetric_max); upper bounds of the |.| in double, kappa only has to be positive (the discs are checked in
  // Arb). Then rho, sigma. False: no kappa > 0.
  bool scale(double e = 0) {
    const long d = n - k;
    Eigen::MatrixXd W(d, d);
    Eigen::VectorXd rhs(d);
    double qmax = 0;
    for (long i = 0; i < d; ++i) {
      for (long j = 0; j < d; ++j) {
        const double b = upper(abs_of(B, k + i, k + j)), c = e > 0 ? upper(abs_of(C, k + i, k + j)) : 0;
        if (i != j) {
          W(i, j) = -(b + e * c);
          continue;
        }
        double at_e = b;
        if (e > 0) {
          acb_t w;
          acb_init(w);
          acb_mul_arb(w, acb_mat_entry(C.m, k + i, k + i), Ball(e).get(), pr);
          acb_add(w, w, acb_mat_entry(B.m, k + i, k + i), pr);
          Ball a;
          acb_abs(a.get(), w, pr);
          acb_clear(w);
          at_e = std::max(b, upper(a));
        }
        W(i, j) = 1 - at_e;
      }
      rhs(i) = 2 * upper(sum_abs(C, k + i, 0, k, -1));
      qmax = std::max(qmax, rhs(i));
    }
    rhs.array() += std::max(qmax, 1e-280) * 1e-20;
    if (!W.allFinite() || !rhs.allFinite()) return false;
    const Eigen::VectorXd kd = W.partialPivLu().solve(rhs);
    if (!kd.allFinite() || !(kd.minCoeff() > 0)) return false;
    kap.clear(), rho.clear(), sig.clear();
    for (long i = 0; i < d; ++i) kap.emplace_back(kd(i));
    for (long i = 0; i < k; ++i) {
      Ball r = sum_abs(C, i, 0, k, i), s;
      for (long j = k; j < n; ++j) {
        arb_addmul(r.get(), kap[static_cast<size_t>(j - k)].get(), abs_of(B, i, j).get(), pr);
        arb_addmul(s.get(), kap[static_cast<size_t>(j - k)].get(), abs_of(C, i, j).get(), pr);
      }
      rho.push_back(r), sig.push_back(s);
    }
    return true;
  }
  // First-block row i inside the unit circle for every t in (0, e]: lin + e quad < 0 with lin = 2 (Re c + rho),
  // quad = |c|^2 + 2 sigma (lin < 0 makes the left side increasing in t: e is the worst).
  Ball inside_margin(long i, const Ball& e) const {
    Ball v = abs_of(C, i, i), lin = re_c(i);
    arb_sqr(v.get(), v.get(), pr);
    arb_addmul_si(v.get(), sig[static_cast<size_t>(i)].get(), 2, pr);
    arb_add(lin.get(), lin.get(), rho[static_cast<size_t>(i)].get(), pr);
    arb_mul_2exp_si(lin.get(), lin.get(), 1);
    arb_mul(v.get(), v.get(), e.get(), pr);
    arb_add(v.get(), v.get(), lin.get(), pr);
    return v;  // < 0: inside
  }
  // First-block row i outside the closed unit disk for every t in (0, e]: |1 + t c| >= 1 + t Re c, so the disc
  // lies in |z| > 1 when Re c - rho - t sigma > 0 (decreasing in t: e is the worst).
  Ball outside_margin(long i, const Ball& e) const {
    Ball v = re_c(i);
    arb_sub(v.get(), v.get(), rho[static_cast<size_t>(i)].get(), pr);
    arb_submul(v.get(), sig[static_cast<size_t>(i)].get(), e.get(), pr);
    return v;  // > 0: outside
  }
  // First-block discs i and j disjoint for every t in (0, e]: |t (c_i - c_j)| > t (rho_i + rho_j) + t^2 (sigma_i + sigma_j).
  bool apart(long i, long j, const Ball& e) const {
    acb_t w;
    acb_init(w);
    acb_sub(w, acb_mat_entry(C.m, i, i), acb_mat_entry(C.m, j, j), pr);
    Ball v, s;
    acb_abs(v.get(), w, pr);
    acb_clear(w);
    arb_sub(v.get(), v.get(), rho[static_cast<size_t>(i)].get(), pr);
    arb_sub(v.get(), v.get(), rho[static_cast<size_t>(j)].get(), pr);
    arb_add(s.get(), sig[static_cast<size_t>(i)].get(), sig[static_cast<size_t>(j)].get(), pr);
    arb_submul(v.get(), s.get(), e.get(), pr);
    return arb_is_positive(v.get());
  }
  // Every second-block disc inside the unit circle for t in [0, e]: max(|B_ii|, |B_ii + e C_ii|) (|B_ii + t C_ii|
  // is convex in t) + the radius at e (increasing in t) < 1.
  bool second_inside(const Ball& e) const {
    for (long i = k; i < n; ++i) {
      Ball z, a;
      for (long j = k; j < n; ++j) {
        if (j == i) continue;
        a = abs_of(B, i, j);
        arb_addmul(a.get(), abs_of(C, i, j).get(), e.get(), pr);
        arb_addmul(z.get(), a.get(), kap[static_cast<size_t>(j - k)].get(), pr);
      }
      arb_add(z.get(), z.get(), sum_abs(C, i, 0, k, -1).get(), pr);
      arb_div(z.get(), z.get(), kap[static_cast<size_t>(i - k)].get(), pr);
      acb_t w;
      acb_init(w);
      acb_mul_arb(w, acb_mat_entry(C.m, i, i), e.get(), pr);
      acb_add(w, w, acb_mat_entry(B.m, i, i), pr);
      acb_abs(a.get(), w, pr);
      acb_clear(w);
      arb_max(a.get(), a.get(), abs_of(B, i, i).get(), pr);
      arb_add(z.get(), z.get(), a.get(), pr);
      arb_sub_ui(z.get(), z.get(), 1, pr);
      if (!arb_is_negative(z.get())) return false;
    }
    return true;
  }
  // Where the second block's discs may stop being inside: min over its rows of margin / slope at t = 0 (margin
  // 1 - |B_ii| - radius at 0, slope |C_ii| + sum_{j != i} |C_ij| kappa_j / kappa_i), in double: a start only.
  double second_bound() const {
    auto kd = [&](long i) { return arf_get_d(arb_midref(kap[static_cast<size_t>(i - k)].get()), ARF_RND_NEAR); };
    double out = INFINITY;
    for (long i = k; i < n; ++i) {
      double r0 = upper(sum_abs(C, i, 0, k, -1)), r1 = upper(abs_of(C, i, i));
      for (long j = k; j < n; ++j)
        if (j != i) {
          const double ratio = kd(j) / kd(i);
          r0 += upper(abs_of(B, i, j)) * ratio, r1 += upper(abs_of(C, i, j)) * ratio;
        }
      const double margin = 1 - upper(abs_of(B, i, i)) - r0 / kd(i);
      if (margin > 0 && r1 > 0) out = std::min(out, margin / r1);
    }
    return out;
  }
  // kappa for the discs at t = e (scale(e)); the bounds that chose the start keep kappa's at t = 0.
  bool rescale(const Ball& e) { return scale(arf_get_d(arb_midref(e.get()), ARF_RND_NEAR)); }
  // The largest eps tried (from `start`, halved 60 times at most) where `holds(eps)`, 0 when none; after a halving,
  // refined by 6 bisections between the one that holds and the one that failed (a walk down towards 0 that stalls
  // just above the first-order eps meets it: fixed space of 3 DOFs, seed 7 case 11 of indep_symmetric_max).
  template <class F>
  static rational halving(double start, F holds) {
    if (!(start > 0) || !std::isfinite(start)) return 0;
    for (int tries = 0; tries < 60; ++tries, start *= 0.5)
      if (holds(Ball(start))) {
        double lo = start, hi = 2 * start;  // hi failed, unless start was the first tried
        for (int k = 0; tries > 0 && k < 6; ++k) {
          const double mid = 0.5 * (lo + hi);
          (holds(Ball(mid)) ? lo : hi) = mid;
        }
        return rational(lo);
      }
    return 0;
  }
  // Stable on (0, eps]: every disc inside (the first block's from lin < 0, eps <= -lin / quad / 2 to start).
  rational stable_to() {
    double start = INFINITY;
    for (long i = 0; i < k; ++i) {
      const Ball zero(0L), one(1L), lin = inside_margin(i, zero);
      if (!arb_is_negative(lin.get())) return 0;
      Ball quad = inside_margin(i, one);
      arb_sub(quad.get(), quad.get(), lin.get(), pr);
      arb_div(quad.get(), lin.get(), quad.get(), pr);
      const double e = -upper(quad);  // -lin / quad, rounded down
      if (std::isfinite(e) && e > 0) start = std::min(start, 0.5 * e);
    }
    return halving(start, [&](const Ball& e) {
      if (!rescale(e)) return false;
      for (long i = 0; i < k; ++i)
        if (!arb_is_negative(inside_margin(i, e).get())) return false;
      return second_inside(e);
    });
  }
  // NOT stable on (0, eps] (the mirror): O = the first-block rows whose discs lie outside the closed unit disk,
  // non-empty; every other first-block disc inside the circle or apart from each of O's, and every second-block
  // disc inside. Then O's union is disjoint from the others' and holds |O| eigenvalues (Gershgorin's theorem), each
  // of modulus > 1.
  rational unstable_to() {
    double start = INFINITY;
    for (long i = 0; i < k; ++i) {
      const Ball zero(0L), one(1L), out0 = outside_margin(i, zero);
      if (!arb_is_positive(out0.get())) continue;
      Ball slope = outside_margin(i, one);  // out0 - sigma
      arb_sub(slope.get(), out0.get(), slope.get(), pr);
      arb_div(slope.get(), out0.get(), slope.get(), pr);
      const double e = arf_get_d(arb_midref(slope.get()), ARF_RND_DOWN) - mag_get_d(arb_radref(slope.get()));
      if (std::isfinite(e) && e > 0) start = std::min(start, 0.5 * e);
    }
    if (!std::isfinite(start)) start = second_bound();  // sigma = 0: the second block's bound (kappa at t = 0) to start
    return halving(start, [&](const Ball& e) {
      if (!rescale(e)) return false;
      std::vector<long> out;
      for (long i = 0; i < k; ++i)
        if (arb_is_positive(outside_margin(i, e).get())) out.push_back(i);
      if (out.empty()) return false;
      for (long j = 0; j < k; ++j) {
        if (std::find(out.begin(), out.end(), j) != out.end() || arb_is_negative(inside_margin(j, e).get())) continue;
        for (const long i : out)
          if (!apart(i, j, e)) return false;
      }
      return second_inside(e);
    });
  }
};

struct Cover {
  const BallMat& M0;
  const BallMat& M1;
  long prec = 128;
  long checks = 0;
  MatQ integrators{};  // integrator_kernel: exact eigenvectors of M0 for the eigenvalue 1 (columns)
  // Eigenvalues of M(c) closer to each other than a quarter of their distance to the unit circle
  // (or than 1e-7) form a cluster (grouped transitively): the 8 operators' modes s^2 + s + 1 of the
  // 8-DOF contact scene, within 1e-5 of each other and 5e-3 inside. Their eigenvectors are nearly
  // parallel where two of them collide, and R^-1 then amplifies rounding into B0. A cluster's
  // columns are replaced by a basis of its invariant subspace (two steps of subspace inverse
  // iteration at the cluster's centre from its eigenvectors, orthonormalised), turned so that the
  // cluster's block of R^-1 M1 R is diagonal when that turn is well conditioned. A choice of R
  // only: the proof (Gershgorin on B0 + t C, B0 = L M(c) R) holds for any invertible R.
  void cluster_bases(Eigen::MatrixXcd& Rd, const Eigen::VectorXcd& ev, const Eigen::MatrixXd& Mc) const {
    const long n = Rd.cols();
    std::vector<long> group(static_cast<size_t>(n));
    for (long i = 0; i < n; ++i) group[static_cast<size_t>(i)] = i;
    std::function<long(long)> root = [&](long i) { return group[static_cast<size_t>(i)] == i ? i : root(group[static_cast<size_t>(i)]); };
    for (long i = 0; i < n; ++i)
      for (long j = i + 1; j < n; ++j) {
        const double gap = std::abs(ev(j) - ev(i)), margin = std::min(1 - std::abs(ev(i)), 1 - std::abs(ev(j)));
        if (gap <= std::max(1e-7 * (1 + std::abs(ev(i))), 0.25 * margin)) group[static_cast<size_t>(root(j))] = root(i);
      }
    Eigen::MatrixXcd Cd;  // R^-1 M1 R in double, once a cluster needs it
    const Eigen::MatrixXcd Mcc = Mc.cast<std::complex<double>>();
    for (long g = 0; g < n; ++g) {
      std::vector<long> k;
      for (long i = 0; i < n; ++i)
        if (root(i) == g) k.push_back(i);
      const long q = static_cast<long>(k.size());
      if (q < 2) continue;
      std::complex<double> centre = 0;
      Eigen::MatrixXcd X(n, q);
      for (long a = 0; a < q; ++a) {
        centre += ev(k[static_cast<size_t>(a)]) / static_cast<double>(q);
        X.col(a) = Rd.col(k[static_cast<size_t>(a)]);
      }
      Eigen::PartialPivLU<Eigen::MatrixXcd> lu(Mcc - centre * Eigen::MatrixXcd::Identity(n, n));
      for (int it = 0; it < 2; ++it) {
        Eigen::HouseholderQR<Eigen::MatrixXcd> qr(X);
        X = qr.householderQ() * Eigen::MatrixXcd::Identity(n, q);
        X = lu.solve(X);
      }
      Eigen::HouseholderQR<Eigen::MatrixXcd> qr(X);
      X = qr.householderQ() * Eigen::MatrixXcd::Identity(n, q);
      if (!X.allFinite()) continue;
      for (long a = 0; a < q; ++a) Rd.col(k[static_cast<size_t>(a)]) = X.col(a);
      // turn the cluster so that its block of R^-1 M1 R is diagonal (when well conditioned)
      Cd = Rd.partialPivLu().solve(mid(M1).cast<std::complex<double>>() * Rd);
      Eigen::MatrixXcd blk(q, q);
      for (long a = 0; a < q; ++a)
        for (long b = 0; b < q; ++b) blk(a, b) = Cd(k[static_cast<size_t>(a)], k[static_cast<size_t>(b)]);
      Eigen::ComplexEigenSolver<Eigen::MatrixXcd> ce(blk, true);
      if (ce.info() != Eigen::Success) continue;
      Eigen::JacobiSVD<Eigen::MatrixXcd> sv(ce.eigenvectors());
      if (!(sv.singularValues()(q - 1) > 1e-3 * sv.singularValues()(0))) continue;
      const Eigen::MatrixXcd turned = X * ce.eigenvectors();
      for (long a = 0; a < q; ++a) Rd.col(k[static_cast<size_t>(a)]) = turned.col(a);
    }
  }
  // h >= 0 such that every M0 + p M1, p between c and c + dir h (dir = +-1), is Schur stable
  // (certified; 0: none found). R: approximate eigenvectors of M(c) in double, exact as they are;
  // L: a ball enclosure of R^-1 (at `prec` bits, as everything below). Then for every p, with t = p - c,
  //   R^-1 M(p) R  in  B0 + t C,   B0 = L M(c) R (nearly diagonal),  C = L M1 R,
  // a similarity: Gershgorin's discs of D^-1 (B0 + t C) D, D = diag(d) > 0 (any d), hold every
  // eigenvalue of M(p). Row i: centre B0_ii + t C_ii (|.| convex in t: the larger of its ends),
  // radius sum_{j != i} (|B0_ij| + h |C_ij|) d_j / d_i. d: the Perron vector of
  // diag(1/(1 - |B0_ii|)) |C_off| (double; a choice, not part of the proof), which balances the
  // radii against the margins. All discs inside the unit circle for t in [0, dir h]: h is proven.
  rational radius(const rational& c, int dir) {
    ++checks;
    const long n = M0.rows();
    AcbMat A(n, n), R(n, n), L(n, n), B0(n, n), C(n, n), M1c(n, n);
    family_ball(A, M0, M1, c, c, prec);
    {  // the approximation in double, whatever `prec` (near the crossing the scaling d below makes its
       // ~1e-16 off-diagonal residue in the crossing rows as small as their margins need)
      Eigen::MatrixXd m(n, n);
      for (long i = 0; i < n; ++i)
        for (long j = 0; j < n; ++j) m(i, j) = arf_get_d(arb_midref(acb_realref(acb_mat_entry(A.m, i, j))), ARF_RND_NEAR);
      Eigen::EigenSolver<Eigen::MatrixXd> es(m, true);
      if (es.info() != Eigen::Success) return 0;
      Eigen::MatrixXcd Rd = es.eigenvectors();
      cluster_bases(Rd, es.eigenvalues(), m);
      for (long i = 0; i < n; ++i)
        for (long j = 0; j < n; ++j) acb_set_d_d(acb_mat_entry(R.m, i, j), Rd(i, j).real(), Rd(i, j).imag());
    }
    if (!acb_mat_inv(L.m, R.m, prec)) return 0;
    acb_mat_mul(B0.m, L.m, A.m, prec);
    acb_mat_mul(B0.m, B0.m, R.m, prec);
    acb_mat_set_arb_mat(M1c.m, M1.get());
    acb_mat_mul(C.m, L.m, M1c.m, prec);
    acb_mat_mul(C.m, C.m, R.m, prec);
    auto upper = [&](const acb_struct* z) {  // |z|, rounded up, as a double
      mag_t t;
      mag_init(t);
      acb_get_mag(t, z);
      const double v = mag_get_d(t);
      mag_clear(t);
      return v;
    };
    auto margin = [&](long i, const Ball& minus) {  // 1 - |B0_ii| - minus, its lower end as a double
      Ball m;
      acb_abs(m.get(), acb_mat_entry(B0.m, i, i), prec);
      arb_add(m.get(), m.get(), minus.get(), prec);
      arb_sub_ui(m.get(), m.get(), 1, prec);
      arb_neg(m.get(), m.get());
      arf_t lo;
      arf_init(lo);
      arb_get_lbound_arf(lo, m.get(), prec);
      const double v = arf_get_d(lo, ARF_RND_DOWN);
      arf_clear(lo);
      return v;
    };
    Eigen::MatrixXd Bd = Eigen::MatrixXd::Zero(n, n);
    for (long i = 0; i < n; ++i) {
      const double mi = margin(i, Ball(0L));
      if (!(mi > 0)) return 0;
      for (long j = 0; j < n; ++j)
        if (j != i) Bd(i, j) = upper(acb_mat_entry(C.m, i, j)) / mi;
    }
    auto perron = [&](const Eigen::MatrixXd& P) {
      Eigen::VectorXd v = Eigen::VectorXd::Ones(n);
      double rho = 0;
      for (int it = 0; it < 60; ++it) {
        Eigen::VectorXd nv = P * v + 1e-12 * v.sum() * Eigen::VectorXd::Ones(n);
        const double mx = nv.maxCoeff();
        if (!(mx > 0) || !std::isfinite(mx)) break;
        rho = mx / v.maxCoeff();
        v = nv / mx;
      }
      if (!(v.minCoeff() > 0) || !v.allFinite()) v = Eigen::VectorXd::Ones(n);
      return std::make_pair(v, rho);
    };
    // first |C_off| alone (h_est = 1/rho: the step it allows), then with B0's own off-diagonal
    // part (a near-defective cluster's coupling, which a scaling shrinks) at that step
    const double rho1 = perron(Bd).second;
    Eigen::MatrixXd Bt = Eigen::MatrixXd::Zero(n, n);
    const double h_est = rho1 > 0 ? 0.5 / rho1 : 0.0;
    for (long i = 0; i < n; ++i) {
      const double mi = margin(i, Ball(0L));
      for (long j = 0; j < n; ++j)
        if (j != i) Bt(i, j) = upper(acb_mat_entry(B0.m, i, j)) / mi + h_est * Bd(i, j);
    }
    const Eigen::VectorXd d = perron(Bt).first;
    // per row: the scaled radii of B0 and of C (upper bounds, balls)
    std::vector<Ball> off0(static_cast<size_t>(n)), offC(static_cast<size_t>(n));
    double h0 = INFINITY;  // the zeroth-order guess: (1 - |B0_ii| - r0_i) / (|C_ii| + rC_i)
    for (long i = 0; i < n; ++i) {
      Ball t, dj;
      for (long j = 0; j < n; ++j) {
        if (j == i) continue;
        arb_set_d(dj.get(), d(j));
        acb_abs(t.get(), acb_mat_entry(B0.m, i, j), prec);
        arb_addmul(off0[static_cast<size_t>(i)].get(), t.get(), dj.get(), prec);
        acb_abs(t.get(), acb_mat_entry(C.m, i, j), prec);
        arb_addmul(offC[static_cast<size_t>(i)].get(), t.get(), dj.get(), prec);
      }
      arb_set_d(dj.get(), d(i));
      arb_div(off0[static_cast<size_t>(i)].get(), off0[static_cast<size_t>(i)].get(), dj.get(), prec);
      arb_div(offC[static_cast<size_t>(i)].get(), offC[static_cast<size_t>(i)].get(), dj.get(), prec);
      const double m = margin(i, off0[static_cast<size_t>(i)]);
      const double r = upper(acb_mat_entry(C.m, i, i)) + arf_get_d(arb_midref(offC[static_cast<size_t>(i)].get()), ARF_RND_UP);
      if (!(m > 0)) return 0;
      if (r > 0) h0 = std::min(h0, m / r);
    }
    if (!std::isfinite(h0)) return 0;  // the family does not move: not a question for this cover
    auto holds = [&](double h) {       // every disc inside for t in [0, dir h] (proven in balls)
      Ball hb(h * dir), ha(h), z, e0;
      acb_t w;
      acb_init(w);
      bool ok = true;
      for (long i = 0; i < n && ok; ++i) {
        acb_mul_arb(w, acb_mat_entry(C.m, i, i), hb.get(), prec);
        acb_add(w, w, acb_mat_entry(B0.m, i, i), prec);
        acb_abs(z.get(), w, prec);
        acb_abs(e0.get(), acb_mat_entry(B0.m, i, i), prec);
        arb_max(z.get(), z.get(), e0.get(), prec);
        arb_add(z.get(), z.get(), off0[static_cast<size_t>(i)].get(), prec);
        arb_addmul(z.get(), ha.get(), offC[static_cast<size_t>(i)].get(), prec);
        arb_sub_ui(z.get(), z.get(), 1, prec);
        ok = arb_is_negative(z.get());
      }
      acb_clear(w);
      return ok;
    };
    double h = 0.5 * h0;
    if (!holds(h)) return 0;
    while (holds(2 * h)) h *= 2;
    for (double f : {1.5, 1.25, 1.125})
      if (holds(f * h)) {
        h *= f;
        break;
      }
    return rational(h);
  }
  // Every M(p), p in [a, b], Schur stable by one Lyapunov P (numeric/lyapunov_ball.hpp: the Stein
  // inequality is convex in M, and M(p) is affine in p, so its two ends suffice). The walk towards 0
  // takes it where M(0) is Schur stable: the steps above shrink near 0 where a delay register's
  // defective eigenvalue 0 splits like sqrt(p) (their eigenbasis is ill-conditioned there), while one
  // P serves a whole interval [0, b].
  bool segment(const rational& a, const rational& b) {
    ++checks;
    const long n = M0.rows();
    flint::BallPrecision bp(128);
    BallMat A(n, n), B(n, n);
    for (const auto& [end, out] : {std::pair<const rational*, BallMat*>{&a, &A}, {&b, &B}}) {
      const Ball k_(*end);
      arb_mat_scalar_mul_arb(out->get(), M1.get(), k_.get(), 128);
      arb_mat_add(out->get(), out->get(), M0.get(), 128);
    }
    return lyapunov_proves_segment_stable(A, B);
  }
  // Where the eigenbasis fails (two eigenvalues colliding: R near singular), a Stein certificate
  // on the ball matrix M0 + [a, b] M1 (numeric/ball_matrix.hpp's schur_decide: P - M^T P M > 0
  // for every matrix of the ball): the largest of the widths tried, 0 when none is certified.
  rational stein(const rational& c, int dir, const rational& scale) {
    const long n = M0.rows();
    rational w = scale / 10;
    for (int k = 2; k <= 6; ++k) {
      ++checks;
      w /= 10;  // scale 10^-k
      const rational a = dir > 0 ? c : c - w, b = dir > 0 ? c + w : c;
      if (a < 0) continue;
      flint::BallPrecision bp(128);
      const Ball k_ = Ball::hull(a, b);
      BallMat S(n, n);
      arb_mat_scalar_mul_arb(S.get(), M1.get(), k_.get(), 128);
      arb_mat_add(S.get(), S.get(), M0.get(), 128);
      const SchurDecision d = schur_decide(double_ball_matrix(S));
      if (d.stable && *d.stable) return w;
      balance_by_powers_of_two(S);  // the same ball, balanced: certifies some where the first fails
      const SchurDecision db = schur_decide(double_ball_matrix(S));
      if (db.stable && *db.stable) return w;
    }
    return 0;
  }
  // The first-order cover at p = 0, where M(0) has the eigenvalue 1 on position integrators (a
  // device's position that nothing scaled by p holds; an environment's state that remembers it
  // follows). Returns eps > 0 such that every M(p), p in (0, eps], is Schur stable (certified; 0:
  // not proven). V = `integrators` (integrator_kernel: exact, rational), so M0 V = V exactly and
  // M0 V Q = V Q for any Q. R = [V Q, R2]: Q (double) turns V so that the block C11 of
  // C = R^-1 M1 R is diagonal, R2 (double, exact as stored) a basis completing it; R as a ball
  // (V Q in Arb), L a ball enclosure of R^-1 (of every matrix of the ball, the true R among them).
  // The exact R^-1 M0 R has the columns [I; 0] in the first block, whatever R2, so
  //   R^-1 M(t) R = [[I + t C11, B12 + t C12], [t C21, B22 + t C22]]      (B = R^-1 M0 R)
  // and, for each t > 0, Gershgorin's discs of D^-1 (.) D with D = diag(I, t K), K = diag(kappa_j)
  // > 0 (a similarity):
  //  - row i of the first block: centre 1 + t c (c = C_ii), radius <= t rho_i + t^2 sigma_i with
  //    rho_i = sum_{j in 1, j != i} |C_ij| + sum_{j in 2} kappa_j |B_ij|, sigma_i = sum_{j in 2} kappa_j |C_ij|;
  //    inside the unit circle when 2 (Re c + rho_i) + t (|c|^2 + 2 sigma_i) < 0, since then
  //    |1 + t c|^2 = 1 + 2t Re c + t^2 |c|^2 < 1 - 2t rho_i - 2t^2 sigma_i <= (1 - t rho_i - t^2 sigma_i)^2
  //    (and t rho_i + t^2 sigma_i < 1/2); the left side is increasing in t: checked at t = eps;
  //  - row i of the second block: centre B_ii + t C_ii, radius sum_{j in 2, j != i} (|B_ij| + t |C_ij|)
  //    kappa_j / kappa_i + sum_{j in 1} |C_ij| / kappa_i; |B_ii + t C_ii| is convex in t: checked at
  //    t = 0 and t = eps.
  // kappa (double; a choice, not part of the proof) solves (diag(1 - |B_ii|) - |B_off|) kappa = 2 q + tiny
  // over the second block, q_i = sum_{j in 1} |C_ij| (Perron's scaling: the smallest kappa with each
  // second-block disc inside at t = 0, where the comparison matrix is an M-matrix; one kappa for all
  // rows, as before stop 59, needed every row diagonally dominant). R2: first approximate
  // eigenvectors of M(0)'s other eigenvalues (B12 ~ 0, B22 ~ diagonal); where that fails (a delay
  // register's or an environment memory's defective eigenvalue 0 makes them ill-conditioned), an
  // orthonormal basis of range(M(0) - I) -- the complementary invariant subspace when the eigenvalue
  // 1 is semisimple, so B12 ~ 0 still -- turned by the Schur vectors of its B22, which is then
  // triangular: its comparison matrix is an M-matrix whenever its eigenvalues are inside the disk.
  // A first-block eigenvalue that p does not move into the disk (Re c >= 0: a conserved quantity, an
  // unstable direction), or an eigenvalue of M(0) at 1 that V does not hold (a pure mass's Jordan
  // block: B is block upper triangular, so B22 then has the eigenvalue 1 and its discs cannot all
  // be inside), leaves the cover unproven.
  //
  // The mirror (outward = true): eps > 0 such that every M(p), p in (0, eps], has an eigenvalue outside the unit
  // circle, so sup = 0 -- where p moves a slow mode out at first order (Re c > 0: a negative stiffness on a
  // position that nothing holds at p = 0). ZeroDiscs::unstable_to: the first-block discs with Re c - rho - t sigma
  // > 0 lie in |z| > 1 (|1 + t c| >= 1 + t Re c), apart from every other disc, so they hold as many eigenvalues.
  rational near_zero(bool outward = false) const {
    const long n = M0.rows();
    const MatQ& V = integrators;
    const long k = V.cols();
    if (k == 0 || k == n || V.rows() != n) return 0;
    rational best(0);  // the largest of the three bases' (an ill-conditioned eigenbasis can give eps ~ 1e-15)
    for (const int basis : {0, 1, 2}) {
      Eigen::MatrixXcd R2;
      if (!(basis == 1 ? complement_by_schur(R2, k) : complement_by_eigenvectors(R2, k, basis == 2))) continue;
      const rational eps = near_zero_on(R2, V, outward);
      if (eps > best) best = eps;
    }
    return best;
  }
  // eps of near_zero for the basis R = [V Q, R2]: B, C in Arb, the first k columns of B exact.
  rational near_zero_on(const Eigen::MatrixXcd& R2, const MatQ& V, bool outward) const {
    const long n = M0.rows(), k = V.cols(), pr = 128;
    AcbMat R(n, n);
    if (!near_zero_basis(R, V, R2, pr)) return 0;
    AcbMat L(n, n), M(n, n), B(n, n), C(n, n);
    if (!acb_mat_inv(L.m, R.m, pr)) return 0;
    acb_mat_set_arb_mat(M.m, M0.get());
    acb_mat_mul(B.m, L.m, M.m, pr);
    acb_mat_mul(B.m, B.m, R.m, pr);
    acb_mat_set_arb_mat(M.m, M1.get());
    acb_mat_mul(C.m, L.m, M.m, pr);
    acb_mat_mul(C.m, C.m, R.m, pr);
    for (long j = 0; j < k; ++j)  // R^-1 M0 R e_j = R^-1 R e_j = e_j exactly (M0 R e_j = R e_j)
      for (long i = 0; i < n; ++i) {
        if (i == j) acb_one(acb_mat_entry(B.m, i, j));
        else acb_zero(acb_mat_entry(B.m, i, j));
      }
    ZeroDiscs discs(B, C, k, pr);
    if (!discs.scale()) return 0;
    return outward ? discs.unstable_to() : discs.stable_to();
  }
  // R2: approximate eigenvectors of M(0) for its eigenvalues other than 1; false when M(0) has more
  // eigenvalues near 1 than V's k columns, or the eigensolver fails. `clusters`: each cluster of close eigenvalues
  // (a delay register's defective 0) given an orthonormal basis of its invariant subspace instead (cluster_bases, as
  // the walk's steps), where its eigenvectors are too nearly parallel for R's inverse.
  bool complement_by_eigenvectors(Eigen::MatrixXcd& R2, long k, bool clusters = false) const {
    const long n = M0.rows();
    Eigen::EigenSolver<Eigen::MatrixXd> es(mid(M0), true);
    if (es.info() != Eigen::Success) return false;
    std::vector<long> rest;
    for (long i = 0; i < n; ++i)
      if (std::abs(es.eigenvalues()(i) - 1.0) > 1e-9) rest.push_back(i);
    if (static_cast<long>(rest.size()) != n - k) return false;
    R2.resize(n, n - k);
    for (long a = 0; a < n - k; ++a) R2.col(a) = es.eigenvectors().col(rest[static_cast<size_t>(a)]);
    if (clusters) {  // [V, R2] with V's eigenvalues set apart (far from the disk: no cluster joins them)
      Eigen::MatrixXcd Rd(n, n);
      Eigen::VectorXcd ev(n);
      for (long i = 0; i < n; ++i)
        for (long a = 0; a < k; ++a) Rd(i, a) = to_real<double>(integrators(i, a));
      Rd.rightCols(n - k) = R2;
      for (long a = 0; a < k; ++a) ev(a) = 100.0 + static_cast<double>(a);
      for (long a = 0; a < n - k; ++a) ev(k + a) = es.eigenvalues()(rest[static_cast<size_t>(a)]);
      cluster_bases(Rd, ev, mid(M0));
      R2 = Rd.rightCols(n - k);
    }
    return R2.allFinite();
  }
  // R2: an orthonormal basis of range(M(0) - I) (QR with column pivoting, rank n - k) times the Schur
  // vectors of M(0) compressed to it, so that B22 is (nearly) upper triangular.
  bool complement_by_schur(Eigen::MatrixXcd& R2, long k) const {
    const long n = M0.rows();
    const Eigen::MatrixXd A = mid(M0) - Eigen::MatrixXd::Identity(n, n);
    Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(A);
    const Eigen::MatrixXd Q = qr.householderQ() * Eigen::MatrixXd::Identity(n, n - k);
    if (!Q.allFinite()) return false;
    const Eigen::MatrixXd S = Q.transpose() * mid(M0) * Q;  // M(0) on the range, in its basis
    if (!S.allFinite()) return false;
    Eigen::ComplexSchur<Eigen::MatrixXcd> cs(S.cast<std::complex<double>>(), true);
    if (cs.info() != Eigen::Success) return false;
    R2 = Q.cast<std::complex<double>>() * cs.matrixU();
    return R2.allFinite();
  }
  // R = [V Q, R2] of near_zero, V Q in Arb (a ball holding it), R2 exact as stored (doubles); Q the
  // eigenvectors of C11 in double (false when that eigensolver fails).
  bool near_zero_basis(AcbMat& R, const MatQ& V, const Eigen::MatrixXcd& R2, long pr) const {
    const long n = M0.rows(), k = V.cols();
    Eigen::MatrixXcd Rd(n, n);
    for (long i = 0; i < n; ++i)
      for (long a = 0; a < k; ++a) Rd(i, a) = to_real<double>(V(i, a));
    Rd.rightCols(n - k) = R2;
    // R singular in double (R2 meeting V's span) gives a Cd of inf/NaN, on which Eigen's complex
    // Schur reads outside its matrix (ASan, LoopMax.TwoDofAgreesWithExactSchurBisection): refused first
    if (!Rd.allFinite()) return false;
    const Eigen::PartialPivLU<Eigen::MatrixXcd> lu(Rd);
    if (!(lu.rcond() > 1e-13)) return false;
    const Eigen::MatrixXcd Cd = lu.solve(mid(M1).cast<std::complex<double>>() * Rd);
    if (!Cd.allFinite()) return false;
    Eigen::ComplexEigenSolver<Eigen::MatrixXcd> ce(Cd.topLeftCorner(k, k), true);
    if (ce.info() != Eigen::Success || !ce.eigenvectors().allFinite()) return false;
    AcbMat Vb(n, k), Qb(k, k), VQ(n, k);
    for (long i = 0; i < n; ++i)
      for (long a = 0; a < k; ++a) {
        flint::set(acb_realref(acb_mat_entry(Vb.m, i, a)), V(i, a), pr);
        arb_zero(acb_imagref(acb_mat_entry(Vb.m, i, a)));
      }
    for (long a = 0; a < k; ++a)
      for (long b = 0; b < k; ++b)
        acb_set_d_d(acb_mat_entry(Qb.m, a, b), ce.eigenvectors()(a, b).real(), ce.eigenvectors()(a, b).imag());
    acb_mat_mul(VQ.m, Vb.m, Qb.m, pr);
    for (long i = 0; i < n; ++i) {
      for (long a = 0; a < k; ++a) acb_set(acb_mat_entry(R.m, i, a), acb_mat_entry(VQ.m, i, a));
      for (long a = k; a < n; ++a) acb_set_d_d(acb_mat_entry(R.m, i, a), Rd(i, a).real(), Rd(i, a).imag());
    }
    return true;
  }
  // The last step, from `to` (stable) to the crossing's enclosure [lo, hi] (certified): on each
  // piece [a, b] of [to, hi] every eigenvalue (Rump's enclosures on the ball M0 + [a, b] M1) is
  // either inside the disk or has d|lambda|^2/dp > 0 (dlambda/dp = (L M1 R)_ii), and at p = q (just
  // below the crossing's enclosure) every eigenvalue is inside: then every |lambda_i(p)| < 1 on
  // [to, q] (a branch with |lambda| >= 1 at some p only grows, piece after piece, up to q), so the
  // supremum lies in [q, hi]. Pieces: [to, hi] halved where Rump's test or a sign is not decided
  // on the whole (the ball's width times R's condition number: a stiff wall's M1 ~ 10^4 over a
  // gap of 10^-10 relative), at most 6 halvings deep (64 pieces).
  bool monotone_on(const rational& a, const rational& b, int depth) {
    ++checks;
    const long n = M0.rows();
    AcbMat A(n, n), L(n, n), R(n, n), D(n, n), M1c(n, n);
    family_ball(A, M0, M1, a, b, 128);
    acb_mat_set_arb_mat(M1c.m, M1.get());
    // D^-1 (.) D by powers of two (exact; the same eigenvalues and d lambda/dp): a stiff
    // environment's states beside a device's make Rump's eigenvector enclosures, and so
    // (L M1 R)_ii, 10^6 times wider unbalanced (scene_max seed 58 case 14)
    const std::vector<long> e = balancing_exponents(mid(M0) + to_real<double>(a) * mid(M1));
    for (long i = 0; i < n; ++i)
      for (long j = 0; j < n; ++j)
        if (i != j)
          for (AcbMat* X : {&A, &M1c}) {
            acb_ptr x = acb_mat_entry(X->m, i, j);
            acb_mul_2exp_si(x, x, e[static_cast<size_t>(j)] - e[static_cast<size_t>(i)]);
          }
    AcbVec E(n);
    bool ok = spectrum(E, &L, &R, A, 128);
    if (ok) {
      acb_mat_mul(D.m, L.m, M1c.m, 128);
      acb_mat_mul(D.m, D.m, R.m, 128);
      for (long i = 0; i < n && ok; ++i) {
        if (inside_disk(E.v + i, 128)) continue;
        acb_t g;
        acb_init(g);
        acb_conj(g, E.v + i);
        acb_mul(g, g, acb_mat_entry(D.m, i, i), 128);
        ok = arb_is_positive(acb_realref(g));
        acb_clear(g);
      }
    }
    if (ok) return true;
    if (depth >= 6) return false;
    const rational m = (a + b) / 2;
    return monotone_on(a, m, depth + 1) && monotone_on(m, b, depth + 1);
  }
  bool close(const rational& to, const rational& q, const rational& hi, const BallMat& M0p, const BallMat& M1p, long precp) {
    const long n = M0.rows();
    if (!monotone_on(to, hi, 0)) return false;
    // at p = lo, at the enclosure's precision (the moving eigenvalue is within ~ (p* - lo) of the circle)
    for (long bits = precp; bits <= 4 * precp; bits *= 2) {
      AcbMat B(n, n);
      family_ball(B, M0p, M1p, q, q, bits);
      AcbVec F(n);
      if (!spectrum(F, nullptr, nullptr, B, bits)) continue;
      bool all = true;
      for (long i = 0; i < n && all; ++i) all = inside_disk(F.v + i, bits);
      if (all) return true;
    }
    return false;
  }
};

// ---- the modes no p moves, deflated exactly ----
// A basis (columns) of the kernel of A, exact (reduced row echelon form).
MatQ kernel(const MatQ& A) {
  MatQ R = A;
  const long rows = R.rows(), cols = R.cols();
  std::vector<long> pivot_col;
  long r = 0;
  for (long c = 0; c < cols && r < rows; ++c) {
    long piv = -1;
    for (long i = r; i < rows; ++i)
      if (R(i, c) != 0) {
        piv = i;
        break;
      }
    if (piv < 0) continue;
    R.row(r).swap(R.row(piv));
    const rational inv = 1 / R(r, c);
    for (long j = 0; j < cols; ++j) R(r, j) *= inv;
    for (long i = 0; i < rows; ++i)
      if (i != r && R(i, c) != 0) {
        const rational f = R(i, c);
        for (long j = 0; j < cols; ++j) R(i, j) -= f * R(r, j);
      }
    pivot_col.push_back(c);
    ++r;
  }
  std::vector<bool> is_pivot(static_cast<size_t>(cols), false);
  for (long c : pivot_col) is_pivot[static_cast<size_t>(c)] = true;
  MatQ K = MatQ::Zero(cols, cols - r);
  long k = 0;
  for (long f = 0; f < cols; ++f) {
    if (is_pivot[static_cast<size_t>(f)]) continue;
    K(f, k) = 1;
    for (long i = 0; i < r; ++i) K(pivot_col[static_cast<size_t>(i)], k) = -R(i, f);
    ++k;
  }
  return K;
}

// M0 and M1 exactly (sim/closed_loop.cpp's assembly) where every component of the plant is nilpotent (pure masses:
// e^{AT} a finite sum, sim::exact_plant_zoh), else nullopt.
std::optional<std::pair<MatQ, MatQ>> exact_matrices(const LoopFamily& F) {
  const auto w = sim::exact_plant_zoh(F.A, F.Bu, F.T);
  if (!w) return std::nullopt;
  MatQ Gn = w->second, Go;
  if (F.f > 0) {
    const auto a = sim::exact_plant_zoh(F.A, F.Bu, F.f), b = sim::exact_plant_zoh(F.A, F.Bu, F.T - F.f);
    Go = exact_product(b->first, a->second);
    Gn = b->second;
  }
  const long ns = static_cast<long>(F.A.rows()), nc = static_cast<long>(F.Kx0.rows()), N = F.N, n = F.n, nb = slots(F) * N;
  const auto build = [&](const MatQ& Ku, const MatQ& Kx, bool constant) {
    MatQ M = MatQ::Zero(order(F), order(F));
    if (constant) M.topLeftCorner(ns, ns) = w->first;
    if (n == 0) M.topLeftCorner(ns, ns + nc) += exact_product(Gn, Ku);
    else if (constant) M.block(0, ns + nc + (n - 1) * N, ns, N) = Gn;
    if (F.f > 0 && constant) M.block(0, ns + nc + n * N, ns, N) = Go;
    M.block(ns, 0, nc, ns + nc) = Kx;
    if (nb > 0) {
      M.block(ns + nc, 0, N, ns + nc) = Ku;
      if (constant)
        for (long j = 1; j < nb / N; ++j) M.block(ns + nc + j * N, ns + nc + (j - 1) * N, N, N) = MatQ::Identity(N, N);
    }
    return M;
  };
  return std::make_pair(build(F.Ku0, F.Kx0, true), build(F.dKu, F.dKx, false));
}

// R(p) / p^m of lti/circle_crossing.hpp for the family, where M is rational and within its limits (nullopt otherwise,
// and where R vanishes for every p).
std::optional<Polynomial<rational>> exact_crossing_polynomial(const LoopFamily& F) {
  const auto ex = exact_matrices(F);
  if (!ex || static_cast<long>(ex->first.rows()) > kCircleCrossingOrder) return std::nullopt;
  try {
    const CircleCrossing cc = circle_crossing(ex->first, ex->second);
    if (cc.identically_zero) return std::nullopt;
    return cc.R;
  } catch (const InputError&) {
    return std::nullopt;  // 2 n rank M1 beyond its degree limit
  }
}

// The controller-state subspace V with Ku(p) V = 0 and Kx(p) V in V for every p (Ku, Kx restricted
// to the controller's states): the largest such, by V_{j+1} = {v in V_j : X0 v, dX v in V_j}.
// A mode in V is an eigenvalue of every M(p) (the hidden modes of a block: an environment's
// unobservable states); the rest of the spectrum is that of M on the quotient.
// The vectors v = [vp; vc; 0] of M(0)'s state (plant, controller, delay buffer: assemble's order)
// with A vp = 0, Ku0 [vp; vc] = 0 and Kx0 [vp; vc] = vc, a basis (columns, exact): for each,
// M0 v = v exactly, whatever M0's balls hold -- e^{AT} vp = vp (A vp = 0), the force Ku0 v it
// produces is 0 (so are the buffer's slots and the input integrals' share), the controller state
// holds. A device's position (x' = v, read by nothing that p does not scale) is one; an
// environment's state that remembers the position comes with it.
MatQ integrator_kernel(const LoopFamily& F) {
  const long ns = static_cast<long>(F.A.rows()), nc = static_cast<long>(F.Kx0.rows()), N = static_cast<long>(F.Ku0.rows());
  MatQ S = MatQ::Zero(ns + N + nc, ns + nc);
  S.topLeftCorner(ns, ns) = F.A;
  S.middleRows(ns, N) = F.Ku0;
  S.bottomRows(nc) = F.Kx0;
  for (long i = 0; i < nc; ++i) S(ns + N + i, ns + i) -= 1;
  const MatQ K = kernel(S);
  MatQ V = MatQ::Zero(order(F), K.cols());
  V.topRows(ns + nc) = K;
  return V;
}

MatQ fixed_subspace(const MatQ& Kc0, const MatQ& dKc, const MatQ& X0, const MatQ& dX) {
  MatQ S(Kc0.rows() + dKc.rows(), Kc0.cols());
  S << Kc0, dKc;
  MatQ V = kernel(S);
  while (V.cols() > 0) {
    const MatQ P = kernel(MatQ(V.transpose())).transpose();  // rows annihilate span(V)
    if (P.rows() == 0) break;                                // V is everything
    MatQ Cn(2 * P.rows(), V.cols());
    Cn << exact_product(P, exact_product(X0, V)), exact_product(P, exact_product(dX, V));
    const MatQ a = kernel(Cn);
    if (a.cols() == V.cols()) break;
    V = exact_product(V, a);
  }
  return V;
}

}  // namespace

// Removes the controller's fixed modes (fixed_subspace) from F, exactly: with T = [W V]
// invertible, T^-1 Kx T is block lower triangular and Ku T = [Ku W, 0]; F keeps the W block. The
// V block must not move with p (else F is left as it is) and is recorded in F.fixed.
void deflate(LoopFamily& F) {
  const long ns = F.A.rows(), nc = F.Kx0.rows();
  if (nc == 0) return;
  const MatQ X0 = F.Kx0.rightCols(nc), dX = F.dKx.rightCols(nc);
  const MatQ V = fixed_subspace(F.Ku0.rightCols(nc), F.dKu.rightCols(nc), X0, dX);
  const long nv = V.cols();
  if (nv == 0) return;
  MatQ T(nc, nc);  // [W V]: W the unit vectors that complete V
  long nw = 0;
  MatQ basis = V;
  for (long i = 0; i < nc && nw < nc - nv; ++i) {
    MatQ trial(nc, basis.cols() + 1);
    trial << basis, MatQ::Identity(nc, nc).col(i);
    if (exact_rank(trial) == trial.cols()) {
      basis = trial;
      T.col(nw++) = MatQ::Identity(nc, nc).col(i);
    }
  }
  T.rightCols(nv) = V;
  const MatQ Ti = exact_solve(T, MatQ(MatQ::Identity(nc, nc)), "the fixed-mode basis");
  const MatQ dXT = exact_product(Ti, exact_product(dX, T));
  if (!dXT.bottomRightCorner(nv, nv).isZero(0)) return;  // V's own dynamics move with p: keep all
  F.fixed = exact_product(Ti, exact_product(X0, T)).bottomRightCorner(nv, nv);
  const long nw0 = nc - nv;
  const MatQ W = T.leftCols(nw0), TiW = Ti.topRows(nw0);
  auto rows_u = [&](const MatQ& Ku) {  // [Ku_s, Ku_c W]
    MatQ r(Ku.rows(), ns + nw0);
    r << Ku.leftCols(ns), exact_product(MatQ(Ku.rightCols(nc)), W);
    return r;
  };
  auto rows_x = [&](const MatQ& Kx) {  // W rows of T^-1 [Kx_s, Kx_c W]
    MatQ r(nw0, ns + nw0);
    r << exact_product(TiW, MatQ(Kx.leftCols(ns))), exact_product(TiW, exact_product(MatQ(Kx.rightCols(nc)), W));
    return r;
  };
  F.Ku0 = rows_u(F.Ku0);
  F.dKu = rows_u(F.dKu);
  F.Kx0 = rows_x(F.Kx0);
  F.dKx = rows_x(F.dKx);
  MatQ pos(F.positions.rows(), F.positions.cols() - nv);
  pos << F.positions.leftCols(ns), exact_product(MatQ(F.positions.middleCols(ns, nc)), W), F.positions.rightCols(F.positions.cols() - ns - nc);
  F.positions = pos;
}

LoopFamily loop_family(const LoopAt& at, const rational& p1, const std::string& name, long points) {
  if (p1 <= 0) throw InputError("--max " + name + ": the reference value must be > 0");
  auto cl = [&](const rational& p) {
    const sim::LoopSpec s = at(p);
    const std::string nl = sim::nonlinear_parts(s);
    if (!nl.empty())
      throw InputError("--max " + name + ": the loop has " + nl +
                       ", which the closed-loop matrix does not model (`hapstab simulate` runs it)");
    return sim::sampled_closed_loop(s);
  };
  const rational p2 = p1 * 2;
  const sim::SampledClosedLoop c1 = cl(p1), c2 = cl(p2);
  auto same_plant = [&](const sim::SampledClosedLoop& c) {
    return equal(c.A, c1.A) && equal(c.Bu, c1.Bu) && c.n == c1.n && c.f == c1.f && c.T == c1.T && c.Kx.rows() == c1.Kx.rows() &&
           c.removed == c1.removed;
  };
  const std::string only = "--max " + name + ": only a parameter of [environment] or [coupling] that leaves the controller's order "
                           "unchanged and enters the closed loop affinely (M(p) = M0 + p M1: a gain, `gain = \"" + name +
                           "\"`, or a stiffness written linearly) can be maximised beyond one DOF";
  if (!same_plant(c2)) throw InputError(only + "; " + name + " changes the device, the operator, the delay or the controller's order");
  LoopFamily F;
  F.A = c1.A;
  F.Bu = c1.Bu;
  F.n = c1.n;
  F.f = c1.f;
  F.T = c1.T;
  F.N = c1.Ku.rows();
  F.positions = c1.positions;
  F.dKu = (c2.Ku - c1.Ku) / p1;
  F.dKx = (c2.Kx - c1.Kx) / p1;
  F.Ku0 = c1.Ku - F.dKu * p1;
  F.Kx0 = c1.Kx - F.dKx * p1;
  if (F.dKu.isZero(0) && F.dKx.isZero(0)) throw ParameterAbsent("--max " + name + ": the loop does not depend on " + name);
  // the degree bound's values (loop_max.hpp): distinct, none of them p1 or 2 p1
  const long extra = std::max<long>(points, 4) - 2;
  if (extra > 1000) throw InputError(only + "; proving it would take " + std::to_string(extra) + " more loops");
  for (long j = 0; j < extra; ++j) {
    const rational p = j == 0 ? p1 / 3 : j == 1 ? p1 * 7 / 2 : p1 * rational(2 * j + 1, 2 * j + 7);  // increasing in (0, 1): 5/11, 7/13, ...
    const sim::SampledClosedLoop c = cl(p);
    if (!same_plant(c) || !equal(c.Ku, MatQ(F.Ku0 + F.dKu * p)) || !equal(c.Kx, MatQ(F.Kx0 + F.dKx * p)))
      throw InputError(only + "; the closed loop is not affine in " + name + " (checked exactly at " + name + " = " + p.str() + ")");
  }
  deflate(F);
  return F;
}

// ---- max_parameter's steps (loop_max.hpp) ----
namespace {

/// Step 1's findings: the first crossing, located in double.
struct Isolated {
  double pstar = 0;
  std::complex<double> lambda;  // the eigenvalue crossing the circle (Im >= 0)
  Eigen::VectorXcd v;           // its eigenvector
  bool complex = false;
  double stable_grid = 0, below = 0;  // a grid point of the first stable run; the last one below the crossing
};

/// The spectral radius of M0 + p M1 in double (numeric: step 1 only locates).
struct Spectrum {
  Eigen::MatrixXd M0, M1;
  double rho(double p) const {
    Eigen::EigenSolver<Eigen::MatrixXd> es(M0 + p * M1, false);
    return es.eigenvalues().cwiseAbs().maxCoeff();
  }
};

/// Step 1: the spectral radius on a geometric grid reference 10^-6 .. 10^6, the first stable run
/// and the first point past it where it is >= 1, bisection between them. nullopt (note set): no
/// stable run, or no crossing.
std::optional<Isolated> isolate(const Spectrum& sp, double ref, const std::string& name, LoopMax& out) {
  const int G = 300;
  auto grid = [&](int k) { return ref * std::pow(10.0, -6.0 + 12.0 * k / G); };
  int ks = -1, ku = -1;
  for (int k = 0; k <= G; ++k) {
    const double r = sp.rho(grid(k));
    if (ks < 0 && r < 1 - 1e-12) ks = k;
    if (ks >= 0 && r >= 1) {
      ku = k;
      break;
    }
  }
  if (ks < 0) {
    out.note = "no " + name + " in [" + numeric_decimal(grid(0)) + ", " + numeric_decimal(grid(G)) + "] with every eigenvalue of M inside the unit disk "
               "(numeric scan of the spectral radius): no stable interval to maximise over";
    return std::nullopt;
  }
  if (ku < 0) {
    out.note = "the spectral radius stays below 1 from " + name + " = " + numeric_decimal(grid(ks)) + " up to " + numeric_decimal(grid(G)) +
               " (numeric scan): no crossing found, so no supremum is certified";
    return std::nullopt;
  }
  double lo = grid(ku - 1), hi = grid(ku);
  for (int it = 0; it < 200 && hi - lo > 1e-15 * hi; ++it) {
    const double c = 0.5 * (lo + hi);
    (sp.rho(c) < 1 ? lo : hi) = c;
  }
  Isolated is;
  is.pstar = 0.5 * (lo + hi);
  is.stable_grid = grid(ks);
  is.below = grid(ku - 1);
  Eigen::EigenSolver<Eigen::MatrixXd> es(sp.M0 + is.pstar * sp.M1, true);
  Eigen::Index imax = 0;
  es.eigenvalues().cwiseAbs().maxCoeff(&imax);
  is.lambda = es.eigenvalues()(imax);
  is.v = es.eigenvectors().col(imax);
  if (is.lambda.imag() < 0) {
    is.lambda = std::conj(is.lambda);
    is.v = is.v.conjugate();
  }
  is.complex = std::fabs(is.lambda.imag()) > 1e-7 * std::abs(is.lambda);
  return is;
}

/// The crossing mode's |position| per DOF, largest = 1.
std::vector<double> mode_shape(const LoopFamily& F, const Eigen::VectorXcd& v) {
  Eigen::MatrixXd P(F.positions.rows(), F.positions.cols());
  for (Eigen::Index i = 0; i < P.rows(); ++i)
    for (Eigen::Index j = 0; j < P.cols(); ++j) P(i, j) = static_cast<double>(F.positions(i, j));
  const Eigen::VectorXd amp = (P * v).cwiseAbs();
  const double mx = amp.maxCoeff();
  std::vector<double> mode;
  for (Eigen::Index i = 0; i < amp.size(); ++i) mode.push_back(mx > 0 ? amp(i) / mx : 0.0);
  return mode;
}

/// Step 2: the crossing enclosed by the Krawczyk test, the precision raised until it is 10^-digits
/// relative. `fine` keeps M0, M1 at the enclosure's precision when it is above 128 bits.
Enclosed enclose_crossing(const LoopFamily& F, const ArbFamily& base, ArbFamily& fine, const Isolated& is, int digits,
                          LoopMax& out) {
  Enclosed e;
  const double target = std::pow(10.0, -digits);
  const Eigen::VectorXcd c = is.v / is.v.squaredNorm();  // c^H v = 1
  for (long prec = 128; prec <= 4096; prec *= 2) {
    fine = prec == 128 ? ArbFamily{} : arb_family(F, prec);
    const BallMat& M0 = prec == 128 ? *base.M0 : *fine.M0;
    const BallMat& M1 = prec == 128 ? *base.M1 : *fine.M1;
    CrossingSystem S{M0, M1, is.complex, is.complex ? 1.0 : (is.lambda.real() > 0 ? 1.0 : -1.0), c.real(), c.imag()};
    const long n = S.n(), m = S.size();
    BallMat x(m, 1);
    for (long i = 0; i < n; ++i) {
      arb_set_d(x.at(i, 0), is.v(i).real());
      if (is.complex) arb_set_d(x.at(n + i, 0), is.v(i).imag());
    }
    arb_set_d(x.at(is.complex ? 2 * n : n, 0), is.pstar);
    if (is.complex) arb_set_d(x.at(2 * n + 1, 0), std::arg(is.lambda));
    e = krawczyk(S, x, prec);
    out.precision_bits = prec;
    if (e.ok && e.rel_width <= target) break;
  }
  return e;
}

/// Step 3: the cover. Up from p0 to within `enough` of the crossing's lower end `top` (closing by
/// monotonicity where the walk stalls), down from p0 towards 0. Sets stable_from, stable_to;
/// returns whether the last step closed on the crossing.
bool cover_below(Cover& cov, const rational& p0, const rational& top, const Enclosed& e, const BallMat& M0p,
                 const BallMat& M1p, int digits, LoopMax& out) {
  rational up = p0, down = p0;
  bool closed = false;
  // up: from p0 each step covers [up - h, up + h] and moves to up + h; near the crossing h is a
  // fixed fraction of what is left, so the walk approaches it geometrically
  rational tried = top;  // the distance left at the last attempt to close (each retry after it shrank 4x)
  const rational enough = top * rational(std::pow(10.0, -digits - 1));  // sup enclosed as narrowly as the crossing
  while (cov.checks < 2000 && top - up > enough) {
    cov.prec = top - up > top / 100000000 ? 64 : 128;
    if ((top - up) <= top / 1000000000 && (top - up) * 4 <= tried) {
      tried = top - up;
      if (cov.close(up, top - enough, e.p.hi, M0p, M1p, out.precision_bits)) {
        closed = true;
        break;
      }
    }
    rational h = cov.radius(up, 1);
    if (h <= 0) h = cov.stein(up, 1, top - up);
    // stalled or crawling (the Stein step's 0.1 % of what is left) short of the 10^-9 zone (an
    // eigenbasis too ill-conditioned for double near the crossing): the monotonicity step from here,
    // again each time what is left has shrunk 4x
    if ((h <= 0 && (top - up) < tried) || (h * 100 < top - up && (top - up) * 4 <= tried)) {
      tried = top - up;
      if (cov.close(up, top - enough, e.p.hi, M0p, M1p, out.precision_bits)) {
        closed = true;
        break;
      }
    }
    if (h <= 0 || up + h >= top) break;
    up += h;
  }
  // down: to 0 where M(0) is Schur stable (a step of the walk, or one Lyapunov P for all of [0, down],
  // reaches it); where an eigenvalue of M(0) is on the circle (a device's position integrator under a
  // spring scaled by p) the steps shrink geometrically towards 0 and the walk stops at 10^-6 of the crossing
  const rational floor = top / 1000000;
  cov.prec = 64;
  rational tried_segment = 2 * down;  // [0, down] by one P, tried again each time down halves
  // steps of O(n^3): 4000 of them up to order 20, as many as cost the same beyond, at least 400
  const double order = static_cast<double>(cov.M0.rows());
  const long steps_down = std::clamp(static_cast<long>(4000.0 * std::pow(20.0 / std::max(order, 1.0), 3)), 400L, 4000L);
  for (const long budget = cov.checks + steps_down; cov.checks < budget && down > 0;) {
    if (down * 2 <= tried_segment) {
      tried_segment = down;
      if (cov.segment(0, down)) {
        down = 0;
        break;
      }
    }
    rational h = cov.radius(down, -1);
    if (h <= 0) h = cov.stein(down, -1, down);
    if (h <= 0) break;
    down = h >= down ? rational(0) : down - h;
    if (down < floor && down > 0) break;
  }
  if (down > 0) {
    // M(0) with the eigenvalue 1 on position integrators: (0, eps] by the first-order cover at 0,
    // and the walk on down to eps (the floor lifted)
    const rational eps = cov.near_zero();
    if (eps > 0) {
      for (const long budget = cov.checks + 400; cov.checks < budget && down > eps;) {
        rational h = cov.radius(down, -1);
        if (h <= 0) h = cov.stein(down, -1, down);
        if (h <= 0) break;
        down = h >= down ? rational(0) : down - h;
      }
      if (down <= eps) {
        down = 0;
        out.open_at_zero = true;
        out.first_order_to = eps;
      }
    }
  }
  out.cover_intervals = cov.checks;
  out.stable_from = down;
  out.stable_to = closed ? top - enough : up;
  if (up > p0 || closed) {
    out.sup = {out.stable_to, e.p.hi};
    out.gap = static_cast<double>((top - out.stable_to) / top);
  }
  return closed;
}

bool rump_outside(const ArbFamily& base, const rational& p, std::string& why);

/// Step 4: decide_loop, independently, stable just below the crossing and NOT stable just above
/// it. Where decide_loop is undecided at every point tried (its Stein certificate too
/// ill-conditioned near a crossing: light devices on a stiff wall, an eigenvalue leaving through
/// z = -1), the point below is one the walk certified, and the point above is proven NOT stable by
/// Rump's enclosure of an eigenvalue of M(p) outside the disk (rump_outside). False (note set) when
/// decide_loop disagrees, or neither decides.
bool confirm(const LoopAt& at, const Enclosed& e, const std::string& name, const ArbFamily& base, LoopMax& out) {
  const rational top = e.p.lo;
  for (const rational& eps : {rational(1, 10000), rational(1, 1000), rational(1, 100)}) {
    const rational pb = top * (1 - eps);
    if (pb < out.stable_from) break;
    const LoopVerdict below = decide_loop(at(pb));
    if (below.stable && *below.stable) {
      out.stable_at = pb;
      break;
    }
    if (below.stable && !*below.stable) {
      out.note = "decide_loop finds the loop NOT stable at " + name + " = " + numeric_decimal(static_cast<double>(pb), 17) +
                 ", inside the interval the cover certified stable: " + below.why;
      return false;
    }
  }
  if (!out.stable_at && top * (1 - rational(1, 10000)) <= out.stable_to && top * (1 - rational(1, 10000)) >= out.stable_from) {
    out.stable_at = top * (1 - rational(1, 10000));  // inside the walk's certified cover
    out.confirmed_by = "the walk's certified cover (decide_loop undecided there)";
  }
  if (!out.stable_at) {
    out.note = "decide_loop could not confirm stability just below the crossing";
    return false;
  }
  for (const rational& eps : {rational(1, 1000000), rational(1, 10000), rational(1, 100)}) {
    const rational pa = e.p.hi * (1 + eps);
    const LoopVerdict above = decide_loop(at(pa));
    if (above.stable && !*above.stable) {
      out.unstable_at = pa;
      break;
    }
    if (above.stable && *above.stable) {
      out.note = "decide_loop finds the loop stable just above the crossing (" + name + " = " + numeric_decimal(static_cast<double>(pa), 17) +
                 "): the crossing is a touch, not an exit";
      return false;
    }
  }
  for (const rational& eps : {rational(1, 1000000), rational(1, 10000), rational(1, 100)}) {
    std::string why;
    if (out.unstable_at || !rump_outside(base, e.p.hi * (1 + eps), why)) continue;
    out.unstable_at = e.p.hi * (1 + eps);
    out.confirmed_by += (out.confirmed_by.empty() ? "" : "; ") + why + " (decide_loop undecided there)";
  }
  if (!out.unstable_at) {
    out.note = "decide_loop could not decide the loop just above the crossing";
    return false;
  }
  return true;
}

/// An eigenvalue of M(p) strictly outside the unit circle, proven by Rump's enclosure of it
/// (acb_mat_eig_enclosure_rump: a ball proven to hold an eigenvalue of every matrix in the ball
/// M0 + p M1) lying outside the circle. False when the enclosure fails or touches the circle.
bool rump_outside(const ArbFamily& base, const rational& p, std::string& why) {
  const long n = base.M0->rows(), prec = 128;
  const Eigen::MatrixXd M = mid(*base.M0) + static_cast<double>(p) * mid(*base.M1);
  Eigen::EigenSolver<Eigen::MatrixXd> es(M, true);
  if (es.info() != Eigen::Success) return false;
  Eigen::Index k = 0;
  if (!(es.eigenvalues().cwiseAbs().maxCoeff(&k) > 1 + 1e-12)) return false;
  AcbMat A(n, n), Rapprox(n, 1), J(1, 1), R(n, 1);
  family_ball(A, *base.M0, *base.M1, p, p, prec);
  acb_t lambda, approx;
  acb_init(lambda);
  acb_init(approx);
  acb_set_d_d(approx, es.eigenvalues()(k).real(), es.eigenvalues()(k).imag());
  for (long i = 0; i < n; ++i)
    acb_set_d_d(acb_mat_entry(Rapprox.m, i, 0), es.eigenvectors()(i, k).real(), es.eigenvectors()(i, k).imag());
  acb_mat_eig_enclosure_rump(lambda, J.m, R.m, A.m, approx, Rapprox.m, prec);
  arb_t modulus;
  arb_init(modulus);
  acb_abs(modulus, lambda, prec);
  const bool outside = acb_is_finite(lambda) && arb_gt(modulus, Ball(1).get());
  if (outside) {
    std::ostringstream o;
    o.precision(17);
    o << "an eigenvalue of M(" << (p == 0 ? std::string("0") : numeric_decimal(static_cast<double>(p), 17))
      << ") enclosed by Rump's test in Arb balls (" << prec << " bits) with |z| >= "
      << std::nextafter(arf_get_d(arb_midref(modulus), ARF_RND_DOWN) - mag_get_d(arb_radref(modulus)), 0.0);
    why = o.str();
  }
  arb_clear(modulus);
  acb_clear(lambda);
  acb_clear(approx);
  return outside;
}

// M rational (pure masses) and NOT Schur stable at a (exactly) with no eigenvalue meeting the circle on (0, a] (the
// resultant R): NOT stable for every p in (0, a], sup = 0 -- a Jordan block at z = 1 pushed out, which neither Stein
// inertia at 0 nor the first-order mirror shows. a: half of R's first positive root, or the reference below it. True
// (out set: outcome fails, exact) when shown.
bool unstable_by_resultant(const LoopFamily& F, const Polynomial<rational>& R, const rational& reference, const std::string& name,
                           LoopMax& out) {
  rational a = reference;
  for (const RootInterval& r : isolate_real_roots(R, rational(0), reference))
    if (r.hi > 0) {
      a = (r.lo > 0 ? r.lo : r.hi) / 2;
      break;
    }
  for (int k = 0; k < 64 && a > 0 && count_real_roots(R, rational(0), a) != 0; ++k) a /= 2;
  const auto ex = exact_matrices(F);
  if (!ex || a <= 0 || count_real_roots(R, rational(0), a) != 0 || schur_stable(charpoly(MatQ(ex->first + ex->second * a)))) return false;
  out.outcome = Outcome::fails;
  out.status = Status::exact;
  out.no_crossing_to = a;
  out.note = "NOT stable for every " + name + " in (0, " + decimal_outward(a, 6, -1) + "] [exact]: the closed-loop matrix M(" + name +
             ") is rational (pure masses), not Schur stable at " + a.str() + " (Schur-Cohn on det(zI - M), exact), and no eigenvalue "
             "meets the unit circle on (0, " + decimal_outward(a, 6, -1) + "] (the resultant of det(zI - M(" + name +
             ")) and its reciprocal polynomial has no root there): the supremum of (0, sup) is 0";
  return true;
}

// Where M is rational (pure masses), the resultant R joins what the walk leaves: (0, stable_from] below it (a Jordan
// block at z = 1 whose eigenvalues leave like sqrt(p)), and (stable_to, top] above it (a walk stalled short of the
// crossing, top = crossing.lo): no root of R there, so no eigenvalue meets the circle, and M stable at the interval's
// other end (the walk) makes every M(p) in it stable.
void close_by_resultant(const Polynomial<rational>& R, const rational& top, const rational& crossing_hi, bool& closed, LoopMax& out) {
  if (out.stable_to <= out.stable_from) return;
  if (out.stable_from > 0 && count_real_roots(R, rational(0), out.stable_from) == 0) {
    out.no_crossing_to = out.stable_from;
    out.stable_from = 0;
    out.open_at_zero = true;
  }
  if (!closed && out.stable_to < top && count_real_roots(R, out.stable_to, top) == 0) {
    out.no_crossing_above = out.stable_to;
    out.stable_to = top;
    out.sup = {top, crossing_hi};
    out.gap = 0;
    closed = true;
  }
}

/// M(0) with an eigenvalue strictly outside the unit circle: then so has M(p) for every p in some
/// (0, eps), by continuity of the eigenvalues, and the supremum of (0, sup) is 0. Proven by a Stein
/// inertia certificate on the ball M0 (numeric/ball_matrix.hpp), or -- where M(0) also has
/// eigenvalues ON the circle (the devices' position integrators at p = 0), which the Stein equation
/// cannot take -- by Rump's enclosure of that one eigenvalue lying outside the circle (rump_outside).
bool unstable_at_zero(const ArbFamily& base, std::string& why) {
  const SchurDecision d = schur_decide(double_ball_matrix(*base.M0));
  if (d.stable && !*d.stable) {
    why = d.why;
    return true;
  }
  return rump_outside(base, rational(0), why);
}

}  // namespace

LoopMax max_parameter(const LoopAt& at, const rational& reference, const std::string& name, long points, int digits) {
  if (digits < 1 || digits > 60) throw InputError("--digits must be in [1, 60] for a multi-DOF --max, got " + std::to_string(digits));
  const LoopFamily F = loop_family(at, reference, name, points);
  LoopMax out;
  out.T = F.T;
  out.states = order(F);
  out.fixed_modes = F.fixed.rows();
  if (F.fixed.rows() > 0 && !schur_stable(charpoly(F.fixed))) {
    // at z = 1 exactly (an environment's memory of positions) and inside the circle otherwise: such a
    // mode is not unstable by itself (it settles as the loop decays, unless a constant reaches it:
    // sim/hidden_modes.hpp), so nothing is stated, never "NOT stable"
    Polynomial<rational> rest = charpoly(F.fixed);
    const Polynomial<rational> at_one{rational(-1), rational(1)};
    while (rest.degree() >= 1 && rest(rational(1)) == 0) rest = divmod(rest, at_one).first;
    if (rest.degree() < charpoly(F.fixed).degree() && (rest.degree() < 1 || schur_stable(rest))) {
      out.outcome = Outcome::undecided;
      out.status = Status::failed;
      out.note = "undecided: " + std::to_string(F.fixed.rows()) + " mode(s) of the controller that no " + name +
                 " moves (a block's hidden modes) lie at z = 1 or inside the unit circle: whether those at 1 settle (a "
                 "conserved quantity) or grow (a constant fed to them) is not decided here";
      return out;
    }
    out.outcome = Outcome::fails;
    out.status = Status::exact;
    out.note = "NOT stable for any " + name + " [exact]: " + std::to_string(F.fixed.rows()) +
               " mode(s) of the controller that no " + name + " moves (a block's hidden modes) are not all inside the unit circle";
    return out;
  }
  const ArbFamily base = arb_family(F, 128);
  std::string why_zero;
  if (unstable_at_zero(base, why_zero)) {  // (0, sup) is empty: sup = 0, whatever happens further up
    out.outcome = Outcome::fails;
    out.status = Status::certified;
    out.note = "NOT stable for every small " + name + " > 0 [certified]: at " + name + " = 0 the closed-loop matrix has an "
               "eigenvalue outside the unit circle (" + why_zero + "), and so has M(" + name + ") for every " + name +
               " in some (0, eps) (the eigenvalues move continuously): the supremum of (0, sup) is 0";
    return out;
  }
  const MatQ slow = integrator_kernel(F);
  if (slow.cols() > 0) {  // M(0) marginal on position integrators: does p move one of them outward at first order?
    Cover c0{*base.M0, *base.M1};
    c0.integrators = slow;
    if (const rational eps = c0.near_zero(true); eps > 0) {
      out.outcome = Outcome::fails;
      out.status = Status::certified;
      out.first_order_to = eps;
      out.note = "NOT stable for every " + name + " in (0, " + decimal_outward(eps, 6, -1) + "] [certified]: at " + name +
                 " = 0 the closed-loop matrix has the eigenvalue 1 on position integrators (M(0) only marginally stable), and " + name +
                 " moves one of them outward at first order (Gershgorin's discs of the first-order cover at 0 lie outside the unit "
                 "circle, apart from the others): the supremum of (0, sup) is 0";
      return out;
    }
  }
  const std::optional<Polynomial<rational>> R = exact_crossing_polynomial(F);
  if (R && unstable_by_resultant(F, *R, reference, name, out)) return out;
  const Spectrum sp{mid(*base.M0), mid(*base.M1)};
  const std::optional<Isolated> is = isolate(sp, static_cast<double>(reference), name, out);
  if (!is) return out;
  out.mode = mode_shape(F, is->v);
  out.where = is->complex ? "complex pair" : (is->lambda.real() > 0 ? "z = 1" : "z = -1");
  ArbFamily fine;
  const Enclosed e = enclose_crossing(F, base, fine, *is, digits, out);
  if (!e.ok || e.rel_width > std::pow(10.0, -digits)) {
    out.note = "the crossing near " + name + " = " + numeric_decimal(is->pstar, 17) + " (numeric) could not be enclosed to 10^-" +
               std::to_string(digits) + " relative: " + (e.ok ? "relative width " + numeric_decimal(e.rel_width, 3) : e.why);
    return out;
  }
  out.crossing = e.p;
  if (is->complex) out.theta = e.theta;
  else if (is->lambda.real() < 0) {  // theta = pi, enclosed
    flint::BallPrecision bp(out.precision_bits);
    out.theta = Ball::pi().bounds();
  }
  const BallMat& M0p = out.precision_bits == 128 ? *base.M0 : *fine.M0;
  const BallMat& M1p = out.precision_bits == 128 ? *base.M1 : *fine.M1;
  const rational top = e.p.lo;
  double p0d = 0.5 * static_cast<double>(top);
  if (sp.rho(p0d) >= 1) p0d = is->below < static_cast<double>(top) ? is->below : is->stable_grid;
  const rational p0 = rational(p0d);
  Cover cov{*base.M0, *base.M1};
  cov.integrators = slow;
  bool closed = cover_below(cov, p0, top, e, M0p, M1p, digits, out);
  if (R) close_by_resultant(*R, top, e.p.hi, closed, out);
  if (out.stable_to <= p0 && !closed) {
    out.note = "the crossing at " + name + " in [" + numeric_decimal(static_cast<double>(e.p.lo), 17) + ", " +
               numeric_decimal(static_cast<double>(e.p.hi), 17) +
               "] is certified, but no interval below it could be certified stable (an earlier crossing, or eigenvalues too close "
               "to each other for Rump's test)";
    return out;
  }
  const std::string on = "every " + name + " in " + (out.open_at_zero ? "(" : "[") + decimal_outward(out.stable_from, 17, +1) + ", " +
                         decimal_outward(out.stable_to, 17, -1) + "] is proven stable (" +
                         std::to_string(cov.checks) + " steps)";
  const std::string crossing = "the crossing at " + name + " in [" + numeric_decimal(static_cast<double>(e.p.lo), 17) + ", " +
                               numeric_decimal(static_cast<double>(e.p.hi), 17) + "] is certified";
  // The walk stopped short: sup is still in [stable_to, unstable_at] (stable on (0, stable_to], NOT stable just above
  // the crossing), so within 10^-6 (relative) of it the supremum is stated with the digits its two ends share (fewer
  // than --digits, and said so); beyond, undecided.
  const bool short_of = !closed && top - out.stable_to > top * rational(std::pow(10.0, -digits - 1));
  if (short_of && out.gap > 1e-6) {
    out.note = crossing + " and " + on + ", but the walk stopped " + numeric_decimal(out.gap, 6) +
               " (relative) short of the crossing: the supremum is not enclosed to 10^-" + std::to_string(digits);
    return out;
  }
  if (out.stable_from > 0) {
    // (0, stable_from) is not covered: the loop may be unstable there (an open-loop unstable
    // device stabilised only by larger gains), so no supremum of (0, sup) is stated
    out.status = Status::certified;  // of stable_on only; outcome stays undecided
    out.note = crossing + " and " + on + ", but stability on (0, " + decimal_outward(out.stable_from, 17, +1) +
               ") is not proven (the walk towards 0 stopped there" +
               std::string(sp.rho(0) >= 1 - 1e-12 ? ": M(0) has an eigenvalue on the unit circle (numeric)" : "") +
               "), so the supremum of (0, sup) is undecided";
    return out;
  }
  if (!confirm(at, e, name, base, out)) return out;
  out.outcome = Outcome::holds;
  out.status = Status::certified;
  std::ostringstream o;
  o.precision(6);
  o << "certified: an eigenvalue of the closed-loop matrix M (order " << out.states << ") is on the unit circle at " << name
    << " in the crossing enclosure (" << out.where << ", Krawczyk test at " << out.precision_bits << " bits); every " << name
    << " in " << (out.open_at_zero ? "(" : "[") << "0, " << decimal_outward(out.stable_to, 6, -1) << "] is stable (" << cov.checks
    << " steps of the walk: Gershgorin discs in an eigenbasis of M, or a Stein certificate, over intervals of " << name << "";
  if (closed && out.no_crossing_above > 0)
    o << ", up to " << decimal_outward(out.no_crossing_above, 6, -1) << ", then to the crossing no eigenvalue of M meets the unit "
      << "circle (the exact resultant of det(zI - M(" << name << ")) and its reciprocal polynomial has no root there; M rational)";
  else if (closed) o << ", the last one up to the crossing: there the eigenvalues that move out only grow in modulus";
  if (out.open_at_zero && out.no_crossing_to > 0)
    o << "; on (0, " << decimal_outward(out.no_crossing_to, 6, -1) << "] no eigenvalue of M meets the unit circle (the exact "
      << "resultant of det(zI - M(" << name << ")) and its reciprocal polynomial has no root there; M rational: pure masses), "
      << "where M(0) has the eigenvalue 1 in a Jordan block (M(0) itself is only marginally stable)";
  else if (out.open_at_zero)
    o << "; on (0, " << decimal_outward(out.first_order_to, 6, -1) << "] the first-order cover at " << name
      << " = 0, where M(0) has the eigenvalue 1 on position integrators (M(0) itself is only marginally stable)";
  o << "); " << (out.confirmed_by.empty() ? "decide_loop: " : "") << "stable at " << static_cast<double>(*out.stable_at)
    << ", NOT stable at " << static_cast<double>(*out.unstable_at)
    << (out.confirmed_by.empty() ? std::string() : " (by " + out.confirmed_by + ")") << ". ";
  if (closed) o << "So the supremum of the stable interval is the crossing, enclosed";
  else
    o << "The supremum lies in [" << decimal_outward(out.stable_to, 6, -1) << ", crossing]: the crossing is it unless an eigenvalue "
      << "leaves and re-enters the disk within the last " << out.gap << " (relative) below it, which no certificate covered"
      << (short_of ? " (so fewer digits than --digits " + std::to_string(digits) + ": those the two ends share)" : std::string());
  out.note = o.str();
  return out;
}

}  // namespace hapstab::stability
