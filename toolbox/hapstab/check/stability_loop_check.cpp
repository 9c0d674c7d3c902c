// hapstab/check/stability_loop_check.cpp -- see stability_loop_check.hpp.
#include "hapstab/check/stability_loop_check.hpp"

#include <cmath>
#include <iomanip>
#include <sstream>
#include <string>
#include <tuple>

#include <Eigen/Cholesky>
#include <Eigen/Core>

#include "hapstab/check/interpolate.hpp"
#include "hapstab/check/rational_matrix.hpp"
#include "hapstab/check/scene_model.hpp"
#include "hapstab/check/schur_cohn.hpp"
#include "hapstab/numeric/ball.hpp"
#include "hapstab/numeric/error.hpp"
#include "hapstab/numeric/flint.hpp"  // arb_mat_mul (FLINT 2.9 + Arb, or FLINT 3)

namespace hapstab::check {

std::vector<Polynomial<rational>> detail::column_lcms(const std::vector<std::vector<RationalFunction<rational>>>& G) {
  const size_t p = G.size(), q = G.empty() ? 0 : G[0].size();
  std::vector<Polynomial<rational>> d(q, Polynomial<rational>{rational(1)});
  for (size_t j = 0; j < q; ++j)
    for (size_t i = 0; i < p; ++i) {
      const Polynomial<rational>& den = G[i][j].den();
      d[j] = divmod(d[j] * den, gcd(d[j], den)).first.monic();
    }
  return d;
}

namespace {

using P = Polynomial<rational>;
using RF = RationalFunction<rational>;
using rational_matrix::Mat;
using detail::BallRows;
using detail::LoopMatrix;

constexpr size_t kMaxOrder = 1024;       // M's order: one Stein test in balls (arb_mat_mul), ~35 s at ~900
constexpr size_t kMaxHiddenOrder = 160;  // evidence.hidden's basis and A_h: exact elimination, O(n^3) rationals
constexpr long kMaxHoldNorm = 4096;      // |A T|'s largest row sum (loop_matrix)

struct Realisation {
  Mat A, B, C, D;
};

// G (p x q, proper) column by column: column j over the monic lcm d_j of its denominators, in
// controllable companion form (x_t' = x_{t+1}, x_{r-1}' = -sum a_t x_t + u_j: 1/d_j from u_j to x_0,
// x_t = s^t x_0), the strictly proper numerators read off as C, the direct part as D. With `over`, column j
// over over[j] instead (monic, a multiple of every denominator of the column: checked below).
Realisation realise(const std::vector<std::vector<RF>>& G, const std::vector<P>& over = {}) {
  const size_t p = G.size(), q = G.empty() ? 0 : G[0].size();
  std::vector<P> d = over.empty() ? detail::column_lcms(G) : over;
  size_t total = 0;
  for (size_t j = 0; j < q; ++j) total += static_cast<size_t>(d[j].degree());
  Realisation R{rational_matrix::zeros(total, total), rational_matrix::zeros(total, q), rational_matrix::zeros(p, total),
                rational_matrix::zeros(p, q)};
  size_t off = 0;
  for (size_t j = 0; j < q; ++j) {
    const size_t r = static_cast<size_t>(d[j].degree());
    for (size_t t = 0; t + 1 < r; ++t) R.A[off + t][off + t + 1] = 1;
    for (size_t t = 0; t < r; ++t) R.A[off + r - 1][off + t] = -d[j].coeff(static_cast<int>(t));
    if (r > 0) R.B[off + r - 1][j] = 1;
    for (size_t i = 0; i < p; ++i) {
      const auto [factor, rem] = divmod(d[j], G[i][j].den());
      if (!rem.is_zero()) throw InputError("model.scene: a denominator does not divide its column's lcm (checker defect)");
      P num = G[i][j].num() * factor;  // column j = num / d_j, deg num <= r (proper)
      const rational direct = num.degree() >= static_cast<int>(r) ? rational(num.coeff(static_cast<int>(r))) : rational(0);
      R.D[i][j] = direct;
      num = num - d[j] * P{direct};
      for (size_t t = 0; t < r; ++t) R.C[i][off + t] = num.coeff(static_cast<int>(t));
    }
    off += r;
  }
  return R;
}

// The continuous plant of the header, exact: A, B_u, and the index of x_0 (the positions are the
// states pos .. pos + N - 1, after the devices' states).
struct Plant {
  Mat A, B;
  size_t pos = 0;
};

Plant plant(const detail::SceneLoop& L) {
  const size_t N = L.dofs();
  // the devices as one block (Ad, Bd, Cd): a mass-damper DOF j is 1/(m_j s + b_j), one state
  std::vector<Realisation> devs;
  size_t nd = 0;
  for (const auto& d : L.devices) {
    if (!d.block) {
      const size_t j = d.first;
      devs.push_back({Mat{{-L.damping[j] / L.mass[j]}}, Mat{{1 / L.mass[j]}}, Mat{{rational(1)}}, Mat{}});
    } else {
      for (size_t j = d.first; j < d.first + d.dofs; ++j)
        if (L.mass[j] != 0)
          throw InputError("model.scene: an operator's mass on DOF " + std::to_string(j) +
                           ", a device given by tf or ss (beyond this checker; docs/certificates.md lists what it reads of a scene)");
      devs.push_back(d.tf.empty() ? Realisation{d.A, d.B, d.C, Mat{}} : realise(d.tf));
    }
    nd += devs.back().A.size();
  }
  std::vector<Realisation> ops;
  size_t nz = 0;
  for (const auto& o : L.operators) {
    ops.push_back(o.is_ss ? Realisation{o.A, o.B, o.C, o.D} : realise(o.Z));
    nz += ops.back().A.size();
  }
  const size_t ns = nd + N + nz;
  Mat Ad = rational_matrix::zeros(nd, nd), Bd = rational_matrix::zeros(nd, N), Cd = rational_matrix::zeros(N, nd);
  size_t off = 0;
  for (size_t k = 0; k < devs.size(); ++k) {
    const Realisation& R = devs[k];
    const size_t first = L.devices[k].first, n = R.A.size(), dofs = L.devices[k].dofs;
    for (size_t i = 0; i < n; ++i) {
      for (size_t t = 0; t < n; ++t) Ad[off + i][off + t] = R.A[i][t];
      for (size_t c = 0; c < dofs; ++c) Bd[off + i][first + c] = R.B[i][c];
    }
    for (size_t r = 0; r < dofs; ++r)
      for (size_t t = 0; t < n; ++t) Cd[first + r][off + t] = R.C[r][t];
    off += n;
  }
  // forces on the DOFs: f = u - Dv v - K x - Cz zeta, v = Cd xi (Dv: a block DOF's operator b, the
  // tf operators' direct parts; a mass-damper's own b and its operators' are in Ad)
  Mat Dv = rational_matrix::zeros(N, N), Cz = rational_matrix::zeros(N, nz), Bz = rational_matrix::zeros(nz, N);
  Mat Az = rational_matrix::zeros(nz, nz);
  for (const auto& d : L.devices)
    if (d.block)
      for (size_t j = d.first; j < d.first + d.dofs; ++j) Dv[j][j] += L.damping[j];
  off = 0;
  for (size_t o = 0; o < ops.size(); ++o) {
    const Realisation& R = ops[o];
    const std::vector<int>& ports = L.operators[o].ports;
    const size_t n = R.A.size();
    for (size_t a = 0; a < ports.size(); ++a) {
      const size_t pa = static_cast<size_t>(ports[a]);
      for (size_t t = 0; t < n; ++t) Cz[pa][off + t] += R.C[a][t];
      for (size_t c = 0; c < ports.size(); ++c) Dv[pa][static_cast<size_t>(ports[c])] += R.D[a][c];
    }
    for (size_t t = 0; t < n; ++t) {
      for (size_t t2 = 0; t2 < n; ++t2) Az[off + t][off + t2] = R.A[t][t2];
      for (size_t c = 0; c < ports.size(); ++c) Bz[off + t][static_cast<size_t>(ports[c])] += R.B[t][c];
    }
    off += n;
  }
  const Mat BDC = rational_matrix::mul(Bd, rational_matrix::mul(Dv, Cd)), BCz = rational_matrix::mul(Bd, Cz),
            BzC = rational_matrix::mul(Bz, Cd);
  Plant P{rational_matrix::zeros(ns, ns), rational_matrix::zeros(ns, N), nd};
  for (size_t i = 0; i < nd; ++i) {
    for (size_t t = 0; t < nd; ++t) P.A[i][t] = Ad[i][t] - BDC[i][t];
    for (size_t j = 0; j < N; ++j) P.A[i][nd + j] = -Bd[i][j] * L.stiffness[j];
    for (size_t t = 0; t < nz; ++t) P.A[i][nd + N + t] = -BCz[i][t];
    for (size_t j = 0; j < N; ++j) P.B[i][j] = Bd[i][j];
  }
  for (size_t j = 0; j < N; ++j)
    for (size_t t = 0; t < nd; ++t) P.A[nd + j][t] = Cd[j][t];  // x' = v
  for (size_t i = 0; i < nz; ++i) {
    for (size_t t = 0; t < nd; ++t) P.A[nd + N + i][t] = BzC[i][t];
    for (size_t t = 0; t < nz; ++t) P.A[nd + N + i][nd + N + t] = Az[i][t];
  }
  return P;
}

Realisation discrete(const detail::SceneLoop::Discrete& b) { return b.is_ss ? Realisation{b.A, b.B, b.C, b.D} : realise(b.tf); }

// M^-1 by Gauss-Jordan in rationals; InputError when M is singular (det(I + D_E D_V) = 0).
Mat inverse(Mat M) {
  const size_t n = M.size();
  Mat I = rational_matrix::identity(n);
  for (size_t c = 0; c < n; ++c) {
    size_t r = c;
    while (r < n && M[r][c] == 0) ++r;
    if (r == n) throw InputError("model.scene: det(I + D_E D_V) = 0: the coupling's algebraic loop has no solution");
    std::swap(M[r], M[c]);
    std::swap(I[r], I[c]);
    const rational piv = M[c][c];
    for (size_t j = 0; j < n; ++j) M[c][j] /= piv, I[c][j] /= piv;
    for (size_t i = 0; i < n; ++i)
      if (i != c && M[i][c] != 0) {
        const rational f = M[i][c];
        for (size_t j = 0; j < n; ++j) M[i][j] -= f * M[c][j], I[i][j] -= f * I[c][j];
      }
  }
  return I;
}

std::string approx(const rational& x) {
  std::ostringstream o;
  o << std::setprecision(4) << x.convert_to<double>();
  return o.str();
}

BallRows balls(const Mat& M) {
  BallRows out(M.size());
  for (size_t i = 0; i < M.size(); ++i)
    for (const rational& x : M[i]) out[i].push_back(flint::Ball(x));
  return out;
}

BallRows zero_balls(size_t r, size_t c) { return BallRows(r, std::vector<flint::Ball>(c, flint::Ball(0L))); }

// X Y in balls. From order 32 on by Arb's arb_mat_mul (its block algorithm: exact integer products of
// the midpoints' blocks, the radii bounded by a product of upper bounds -- an enclosure like the loop below,
// ~20 times faster at order 448), below by the loop.
BallRows product(const BallRows& X, const BallRows& Y) {
  const size_t r = X.size(), m = Y.size(), c = Y.empty() ? 0 : Y[0].size();
  if (r >= 32 && m >= 32 && c >= 32) {
    arb_mat_t a, b, ab;
    arb_mat_init(a, static_cast<slong>(r), static_cast<slong>(m));
    arb_mat_init(b, static_cast<slong>(m), static_cast<slong>(c));
    arb_mat_init(ab, static_cast<slong>(r), static_cast<slong>(c));
    for (size_t i = 0; i < r; ++i)
      for (size_t j = 0; j < m; ++j) arb_set(arb_mat_entry(a, i, j), X[i][j].get());
    for (size_t i = 0; i < m; ++i)
      for (size_t j = 0; j < c; ++j) arb_set(arb_mat_entry(b, i, j), Y[i][j].get());
    arb_mat_mul(ab, a, b, flint::ball_prec);
    BallRows out = zero_balls(r, c);
    for (size_t i = 0; i < r; ++i)
      for (size_t j = 0; j < c; ++j) arb_set(out[i][j].get(), arb_mat_entry(ab, i, j));
    arb_mat_clear(a);
    arb_mat_clear(b);
    arb_mat_clear(ab);
    return out;
  }
  BallRows out = zero_balls(r, c);
  for (size_t i = 0; i < X.size(); ++i)
    for (size_t k = 0; k < Y.size(); ++k) {
      if (X[i][k].is_zero()) continue;
      for (size_t j = 0; j < out[i].size(); ++j) out[i][j] += X[i][k] * Y[k][j];
    }
  return out;
}

// The conserved quantities of the plant: a basis of {l : l^T [A B] = 0} in reduced echelon form,
// l_i = 1 at its own index c_i and 0 at the others' (c_i: the free columns of [A B]^T's echelon form).
// A discrete block's (header): the same of [A - I, B], its uncontrollable z = 1.
struct Conserved {
  Mat L;                     // k x ns
  std::vector<size_t> at;    // c_1 < ... < c_k
};

// K in reduced row echelon form, exactly, in place: the pivot columns (each pivot 1, the rest of its column 0).
std::vector<size_t> echelon(Mat& K) {
  const size_t cols = K.empty() ? 0 : K[0].size();
  std::vector<size_t> pivot_col;
  size_t row = 0;
  for (size_t c = 0; c < cols && row < K.size(); ++c) {
    size_t r = row;
    while (r < K.size() && K[r][c] == 0) ++r;
    if (r == K.size()) continue;
    std::swap(K[r], K[row]);
    const rational piv = K[row][c];
    for (auto& x : K[row]) x /= piv;
    for (size_t i = 0; i < K.size(); ++i)
      if (i != row && K[i][c] != 0) {
        const rational f = K[i][c];
        for (size_t j = c; j < cols; ++j) K[i][j] -= f * K[row][j];
      }
    pivot_col.push_back(c);
    ++row;
  }
  return pivot_col;
}

// A basis of {v : K v = 0} (K with `ns` columns) in reduced echelon form, v_i = 1 at its own free column c_i.
Conserved null_basis(Mat K, size_t ns) {
  const std::vector<size_t> pivot_col = echelon(K);
  Conserved out;
  std::vector<bool> is_pivot(ns, false);
  for (size_t c : pivot_col) is_pivot[c] = true;
  for (size_t f = 0; f < ns; ++f) {
    if (is_pivot[f]) continue;
    std::vector<rational> l(ns, rational(0));
    l[f] = 1;
    for (size_t r = 0; r < pivot_col.size(); ++r) l[pivot_col[r]] = -K[r][f];
    out.L.push_back(std::move(l));
    out.at.push_back(f);
  }
  return out;
}

Conserved conserved_quantities(const Mat& A, const Mat& B) {
  const size_t ns = A.size(), N = B.empty() ? 0 : B[0].size();
  Mat K = rational_matrix::zeros(ns + N, ns);  // [A B]^T: K l = 0
  for (size_t i = 0; i < ns; ++i) {
    for (size_t j = 0; j < ns; ++j) K[j][i] = A[i][j];
    for (size_t j = 0; j < N; ++j) K[ns + j][i] = B[i][j];
  }
  return null_basis(std::move(K), ns);
}

// M on the quotient by the conserved quantities (header): with y = l^T x = 0, x_c = -L_kept x_kept,
// so M11 = M[kept, kept] - M[kept, c] L[:, kept] (L zero beyond the plant's states).
BallRows reduced(const BallRows& M, const Conserved& q) {
  if (q.at.empty()) return M;
  const size_t n = M.size(), k = q.at.size(), ns = q.L[0].size();
  std::vector<bool> gone(n, false);
  for (size_t c : q.at) gone[c] = true;
  std::vector<size_t> kept;
  for (size_t i = 0; i < n; ++i)
    if (!gone[i]) kept.push_back(i);
  BallRows R = zero_balls(n - k, n - k);
  for (size_t a = 0; a < kept.size(); ++a)
    for (size_t b = 0; b < kept.size(); ++b) {
      flint::Ball x = M[kept[a]][kept[b]];
      if (kept[b] < ns)
        for (size_t i = 0; i < k; ++i)
          if (q.L[i][kept[b]] != 0) x -= M[kept[a]][q.at[i]] * flint::Ball(q.L[i][kept[b]]);
      R[a][b] = x;
    }
  return R;
}

// M on the quotient by right eigenvectors r_j (M r_j = r_j; rows of `R`, independent), in reduced echelon
// form first (r_j 1 at its own c_j, 0 at the others'): pi(x) = x - sum_j x_{c_j} r_j kills span{r_j}, and
// the induced map on the other coordinates is M[a][b] - sum_j r_j[a] M[c_j][b] (well defined: pi M r_j = 0).
BallRows right_reduced(const BallRows& M, Mat R) {
  const size_t n = M.size();
  const std::vector<size_t> at = echelon(R);
  if (at.size() != R.size()) throw NumericalError("the right eigenvectors are dependent (a checker defect)");
  std::vector<bool> gone(n, false);
  for (size_t c : at) gone[c] = true;
  std::vector<size_t> kept;
  for (size_t i = 0; i < n; ++i)
    if (!gone[i]) kept.push_back(i);
  BallRows out = zero_balls(kept.size(), kept.size());
  for (size_t a = 0; a < kept.size(); ++a)
    for (size_t b = 0; b < kept.size(); ++b) {
      flint::Ball x = M[kept[a]][kept[b]];
      for (size_t j = 0; j < at.size(); ++j)
        if (R[j][kept[a]] != 0) x -= flint::Ball(R[j][kept[a]]) * M[at[j]][kept[b]];
      out[a][b] = x;
    }
  return out;
}

// M of the header at the thread's ball precision.
// (Phi_h, Gamma_h): [Phi Gamma; 0 I] = exp([A B; 0 0] h), Arb's arb_mat_exp.
std::pair<BallRows, BallRows> hold(const Mat& A, const Mat& Bu, const rational& h, long bits) {
  const size_t ns = A.size(), N = Bu.empty() ? 0 : Bu[0].size();
  flint::BallMat aug(static_cast<long>(ns + N), static_cast<long>(ns + N)), ex(static_cast<long>(ns + N), static_cast<long>(ns + N));
  for (size_t i = 0; i < ns; ++i) {
    for (size_t j = 0; j < ns; ++j) arb_set(aug.at(static_cast<long>(i), static_cast<long>(j)), flint::Ball(A[i][j] * h).get());
    for (size_t j = 0; j < N; ++j) arb_set(aug.at(static_cast<long>(i), static_cast<long>(ns + j)), flint::Ball(Bu[i][j] * h).get());
  }
  arb_mat_exp(ex.get(), aug.get(), bits);
  BallRows Phi = zero_balls(ns, ns), Gamma = zero_balls(ns, N);
  for (size_t i = 0; i < ns; ++i) {
    for (size_t j = 0; j < ns; ++j) arb_set(Phi[i][j].get(), ex.at(static_cast<long>(i), static_cast<long>(j)));
    for (size_t j = 0; j < N; ++j) arb_set(Gamma[i][j].get(), ex.at(static_cast<long>(i), static_cast<long>(ns + j)));
  }
  return {Phi, Gamma};
}

// The largest row sum of D^-1 A D, D = diag(2^k_i) by Parlett-Reinsch balancing (radix 2, exactly): a
// bound on A's spectral radius that companion forms do not inflate.
rational balanced_norm(Mat A) {
  const size_t n = A.size();
  for (int sweep = 0; sweep < 60; ++sweep) {
    bool changed = false;
    for (size_t i = 0; i < n; ++i) {
      rational c = 0, r = 0;
      for (size_t j = 0; j < n; ++j)
        if (j != i) c += abs(A[j][i]), r += abs(A[i][j]);
      if (c == 0 || r == 0) continue;
      const rational sum = c + r;
      rational f = 1;
      while (c < r / 2) c *= 4, f *= 2;
      while (c >= r * 2) c /= 4, f /= 2;
      if ((c + r) / f < rational(95, 100) * sum) {
        changed = true;
        for (size_t j = 0; j < n; ++j) A[i][j] /= f, A[j][i] *= f;
      }
    }
    if (!changed) break;
  }
  rational norm = 0;
  for (const auto& row : A) {
    rational sum = 0;
    for (const rational& x : row) sum += abs(x);
    if (sum > norm) norm = sum;
  }
  return norm;
}

// What M is built from besides the holds: the controller's realisations, u = F [s; xi; eta] and x_e = X [s;
// xi; eta] (paper 000 (11), the algebraic loop solved exactly), and M's layout.
struct Assembly {
  Realisation E, V;
  Mat F, X;
  size_t N = 0, ns = 0, nE = 0, nV = 0, nc = 0, n = 0, buffers = 0, order = 0;
};

Assembly assembly(const detail::SceneLoop& L, const Plant& pl) {
  Assembly a;
  a.N = L.dofs(), a.ns = pl.A.size();
  const size_t N = a.N, ns = a.ns, pos = pl.pos;
  a.E = discrete(L.E);
  a.V = L.V ? discrete(*L.V) : Realisation{Mat{}, rational_matrix::zeros(0, N), rational_matrix::zeros(N, 0), rational_matrix::zeros(N, N)};
  const Realisation &E = a.E, &V = a.V;
  a.n = static_cast<size_t>(L.delay), a.buffers = a.n + (L.fraction == 0 ? 0 : 1);  // u_{k-1} .. u_{k-buffers} kept
  a.nE = E.A.size(), a.nV = V.A.size(), a.nc = ns + a.nE + a.nV, a.order = a.nc + a.buffers * N;
  const size_t nE = a.nE, nV = a.nV, nc = a.nc;
  if (a.order > kMaxOrder)
    throw InputError("model: the closed loop has " + std::to_string(a.order) + " states, beyond this checker's " +
                     std::to_string(kMaxOrder));
  // the controller (paper 000 (11)): x_e = x + V u, u = -E x_e, the algebraic loop solved exactly:
  // u = F [s; xi; eta] with F = -W [D_E C_x, C_E, D_E C_V], W = (I + D_E D_V)^-1; x_e = X [s; xi; eta]
  Mat W = rational_matrix::add(rational_matrix::identity(N), rational_matrix::mul(E.D, V.D));
  W = inverse(W);
  a.F = rational_matrix::zeros(N, nc), a.X = rational_matrix::zeros(N, nc);
  Mat &F = a.F, &X = a.X;
  for (size_t i = 0; i < N; ++i) {
    for (size_t j = 0; j < N; ++j) {
      for (size_t k = 0; k < N; ++k) F[i][pos + k] -= W[i][j] * E.D[j][k];  // C_x picks the positions
      for (size_t t = 0; t < nE; ++t) F[i][ns + t] -= W[i][j] * E.C[j][t];
      for (size_t t = 0; t < nV; ++t) {
        rational dc = 0;
        for (size_t k = 0; k < N; ++k) dc += E.D[j][k] * V.C[k][t];
        F[i][ns + nE + t] -= W[i][j] * dc;
      }
    }
    X[i][pos + i] += 1;
    for (size_t t = 0; t < nV; ++t) X[i][ns + nE + t] += V.C[i][t];
  }
  X = rational_matrix::add(X, rational_matrix::mul(V.D, F));
  return a;
}

// M over T (flint::Ball: the loop's matrix; rational: the slow matrix, detail::slow_rows) from the holds:
// s+ = Phi s + G0 u_{k-n} (+ G1 u_{k-n-1} when the delay has a fraction f: G1 non-null), `to` converting the
// controller's exact entries.
template <class T, class To>
std::vector<std::vector<T>> assemble(const Assembly& a, const std::vector<std::vector<T>>& Phi, const std::vector<std::vector<T>>& G0,
                                     const std::vector<std::vector<T>>* G1, To to) {
  const size_t N = a.N, ns = a.ns, nE = a.nE, nc = a.nc, n = a.n;
  std::vector<std::vector<T>> M(a.order, std::vector<T>(a.order, to(rational(0))));
  for (size_t i = 0; i < ns; ++i)
    for (size_t j = 0; j < ns; ++j) M[i][j] = Phi[i][j];
  // u_{k-age} on s: age 0 is u_k = F [s; xi; eta] (now), age a >= 1 the buffer's block a
  const auto drive = [&](const std::vector<std::vector<T>>& G, size_t age) {
    for (size_t i = 0; i < ns; ++i)
      if (age == 0) {  // M += G F, the product summed first (as product())
        std::vector<T> GF(nc, to(rational(0)));
        for (size_t k = 0; k < N; ++k)
          for (size_t j = 0; j < nc; ++j) GF[j] += G[i][k] * to(a.F[k][j]);
        for (size_t j = 0; j < nc; ++j) M[i][j] += GF[j];
      } else {
        for (size_t j = 0; j < N; ++j) M[i][nc + (age - 1) * N + j] = G[i][j];
      }
  };
  drive(G0, n);
  if (G1) drive(*G1, n + 1);
  if (a.buffers > 0) {
    for (size_t i = 0; i < N; ++i)  // the buffer's first block: u_k
      for (size_t j = 0; j < nc; ++j) M[nc + i][j] = to(a.F[i][j]);
    for (size_t b = 1; b < a.buffers; ++b)  // and each block moves one down
      for (size_t i = 0; i < N; ++i) M[nc + b * N + i][nc + (b - 1) * N + i] = to(rational(1));
  }
  const Mat BX = rational_matrix::mul(a.E.B, a.X), BF = rational_matrix::mul(a.V.B, a.F);  // xi+ = A_E xi + B_E x_e, eta+ = A_V eta + B_V u
  for (size_t i = 0; i < nE; ++i)
    for (size_t j = 0; j < nc; ++j) M[ns + i][j] = to(BX[i][j] + (j >= ns && j < ns + nE ? a.E.A[i][j - ns] : rational(0)));
  for (size_t i = 0; i < a.nV; ++i)
    for (size_t j = 0; j < nc; ++j) M[ns + nE + i][j] = to(BF[i][j] + (j >= ns + nE ? a.V.A[i][j - ns - nE] : rational(0)));
  return M;
}

}  // namespace

detail::SceneLoop::Discrete detail::column_realisation(const std::vector<std::vector<RF>>& G, const std::vector<P>& over) {
  Realisation R = realise(G, over);
  detail::SceneLoop::Discrete b;
  b.is_ss = true;
  b.A = std::move(R.A);
  b.B = std::move(R.B);
  b.C = std::move(R.C);
  b.D = std::move(R.D);
  return b;
}

namespace detail {

LoopMatrix loop_matrix(const detail::SceneLoop& L, long bits) {
  const Plant pl = plant(L);
  const Mat &A = pl.A, &Bu = pl.B;
  // the hold's exponent: |A T| beyond 2^12 makes e^{AT} span more than ~6000 binary orders, whose exact
  // midpoints (the Stein test's Q_mid) no longer fit in memory (a fuzzed T of 10^118 took 2 GB). Measured
  // on A balanced (companion forms have row sums far above their rates: 4 x 10^5 T for three lags)
  if (const rational norm = balanced_norm(A) * L.T; norm > kMaxHoldNorm)
    throw InputError("model: the hold e^{AT} has |A T| = " + detail::decimal(norm) + " (A balanced, its largest row sum), more than " +
                     std::to_string(kMaxHoldNorm) + ": beyond this checker (a sample period that long against the plant's rates)");
  // t_d = n T + f: over a period the plant sees u_{k-n-1} on [kT, kT + f) and u_{k-n} after, so
  // s+ = Phi_T s + Phi_{T-f} Gamma_f u_{k-n-1} + Gamma_{T-f} u_{k-n} (sim/closed_loop.hpp's step)
  const rational f = L.fraction * L.T;
  BallRows Phi, G0, G1;  // G0 acts on u_{k-n}, G1 (f > 0) on u_{k-n-1}
  if (f == 0) {
    std::tie(Phi, G0) = hold(A, Bu, L.T, bits);
  } else {
    const auto [Pa, Ga] = hold(A, Bu, L.T - f, bits);
    const auto [Pb, Gb] = hold(A, Bu, f, bits);
    Phi = product(Pa, Pb);
    G0 = Ga;
    G1 = product(Pa, Gb);
  }
  const Assembly as = assembly(L, pl);
  const Realisation &E = as.E, &V = as.V;
  const size_t ns = as.ns, nE = as.nE, nc = as.nc, order = as.order;
  BallRows M = assemble<flint::Ball>(as, Phi, G0, f == 0 ? nullptr : &G1, [](const rational& x) { return flint::Ball(x); });
  Conserved q = conserved_quantities(pl.A, pl.B);
  if (q.at.size() < L.own_conserved)
    throw NumericalError("model.plant: the integrated position carries no conserved quantity (a checker defect)");
  for (auto& l : q.L) l.resize(nc, rational(0));
  // the wall's and the coupling's uncontrollable z = 1 (header): l^T (A - I) = 0, l^T B = 0, in their states
  // and their unobservable z = 1: r with (A - I) r = 0, C r = 0 (right eigenvectors of M, eigenvalue 1: C r = 0
  // keeps the force and x_e at 0); a fully hidden one is both, and the pairing below sets it aside once
  Mat right;  // rows: r over M's states
  {  // the plant's unseen s = 0: A r = 0 with no position in it (y = x blind to r), so Phi_h r = r and M r = r
    Mat Ex = rational_matrix::zeros(ns, pl.B.empty() ? 0 : pl.B[0].size());
    for (size_t j = 0; j < Ex[0].size(); ++j) Ex[pl.pos + j][j] = 1;
    for (const auto& v : conserved_quantities(rational_matrix::transpose(A), Ex).L) {
      std::vector<rational> full(order, rational(0));
      std::copy(v.begin(), v.end(), full.begin());
      right.push_back(std::move(full));
    }
  }
  for (const auto& [R, at] : {std::pair<const Realisation*, size_t>{&E, ns}, {&V, ns + nE}}) {
    if (R->A.empty()) continue;
    const size_t nb = R->A.size();
    const Mat AmI = rational_matrix::add(R->A, rational_matrix::identity(nb), -1);
    const Conserved d = conserved_quantities(AmI, R->B);
    for (size_t i = 0; i < d.at.size(); ++i) {
      std::vector<rational> l(nc, rational(0));
      for (size_t j = 0; j < d.L[i].size(); ++j) l[at + j] = d.L[i][j];
      q.L.push_back(std::move(l));
      q.at.push_back(at + d.at[i]);
    }
    // {r : r^T [(A - I)^T, C^T] = 0}; one the block's own l also sees (a mode no input reaches and no output
    // shows) is paired with it below
    const Mat cols = rational_matrix::transpose(R->C);
    const Conserved r = conserved_quantities(rational_matrix::transpose(AmI), cols);
    for (const auto& v : r.L) {
      std::vector<rational> full(order, rational(0));
      for (size_t j = 0; j < nb; ++j) full[at + j] = v[j];
      right.push_back(std::move(full));
    }
  }
  // Left eigenvectors at z = 1 (rows l of q.L: the plant's conserved quantities, a block's unreached z = 1) beside
  // right ones (rows r of `right`): pair them by G = L R^T (header). With rank G = g, the k - g left ones no r
  // pairs with and the m - g right ones in null(G) (R_u = N^T R, inside ker L) are unpaired. Both kinds unpaired:
  // a constant could move the equilibrium that a sum then integrates (a Jordan block at z = 1, though each block's
  // A is semisimple there; sim/hidden_modes.hpp) -- the quotient by both would hide it. hapstab writes no such
  // certificate (it is undecided there); refused, not checked. Otherwise M is decided on ker L modulo R_u.
  if (!right.empty() && !q.at.empty()) {
    Mat G = rational_matrix::zeros(q.L.size(), right.size());
    for (size_t i = 0; i < q.L.size(); ++i)
      for (size_t j = 0; j < right.size(); ++j)
        for (size_t t = 0; t < q.L[i].size(); ++t) G[i][j] += q.L[i][t] * right[j][t];
    const Mat N = null_basis(G, right.size()).L;  // rows n: G n = 0
    const size_t paired = right.size() - N.size();
    if (paired < q.L.size() && !N.empty())
      throw InputError("model: " + std::to_string(q.L.size() - paired) + " conserved quantities (left eigenvectors at z = 1) beside " +
                       std::to_string(N.size()) + " unseen z = 1 (right eigenvectors), neither paired with the other (l^T r = 0): whether "
                       "the constant reaches the sum (a Jordan block at z = 1) is not decided by this kind");
    Mat unpaired;
    for (const auto& n : N) {
      std::vector<rational> r(order, rational(0));
      for (size_t j = 0; j < n.size(); ++j)
        if (n[j] != 0)
          for (size_t t = 0; t < order; ++t) r[t] += n[j] * right[j][t];
      unpaired.push_back(std::move(r));
    }
    right = std::move(unpaired);
  }
  // a right eigenvector set aside with a part in the plant: --max's kinds refuse it (it could move with a plant parameter)
  bool plant_right = false;
  for (const auto& r : right)
    for (size_t t = 0; t < ns; ++t) plant_right = plant_right || r[t] != 0;
  BallRows M11 = reduced(M, q);
  Mat embedding;  // x = E y on {l^T x = 0}: x_kept = y, x_c = -L[:, kept] y
  if (!q.at.empty()) {
    std::vector<bool> gone(order, false);
    for (size_t c : q.at) gone[c] = true;
    std::vector<size_t> kept;
    for (size_t i = 0; i < order; ++i)
      if (!gone[i]) kept.push_back(i);
    embedding = rational_matrix::zeros(order, kept.size());
    for (size_t b = 0; b < kept.size(); ++b) {
      embedding[kept[b]][b] = 1;
      for (size_t i = 0; i < q.at.size(); ++i)
        if (kept[b] < q.L[i].size()) embedding[q.at[i]][b] = -q.L[i][kept[b]];
    }
  }
  if (!right.empty()) {  // on M11's coordinates (the kept ones), renormalised, then the quotient by them
    std::vector<bool> gone(order, false);
    for (size_t c : q.at) gone[c] = true;
    Mat kept_rows;
    for (const auto& r : right) {
      std::vector<rational> k;
      for (size_t i = 0; i < order; ++i)
        if (!gone[i]) k.push_back(r[i]);
      kept_rows.push_back(std::move(k));
    }
    M11 = right_reduced(M11, kept_rows);
  }
  const Mat DED = rational_matrix::mul(E.D, V.D), DDE = rational_matrix::mul(V.D, E.D);
  const auto zero = [](const Mat& X) {
    for (const auto& row : X)
      for (const rational& x : row)
        if (!x.is_zero()) return false;
    return true;
  };
  return {M11, q.at.size() + right.size() - L.own_conserved, order, {E.A, E.B, E.C, E.D, V.A, V.B, V.C, V.D}, !(zero(DED) && zero(DDE)),
          embedding, !right.empty(), plant_right};
}

namespace {

// Every symmetric matrix in the balls S, each widened by r in the spectral norm, is positive definite, proven:
// X ~ L^-T from a double Cholesky of Smid (S's midpoints; upper triangular with a non-zero diagonal: non-singular,
// its doubles taken as exact), then in balls G = X^T S X (it holds X^T A X for every A in S) and f = ||X||_F^2 >=
// ||X||_2^2; Gershgorin on G and Weyl give lambda_min(X^T (A + E) X) >= min_i (G_ii - sum_{j != i} |G_ij|) - f r > 0
// for ||E||_2 <= r. A double Cholesky that fails, or a row that does not pass, proves nothing (false).
bool congruence_shows_positive(const BallRows& S, const Eigen::MatrixXd& Smid, const flint::Ball& r) {
  const size_t n = S.size();
  const Eigen::LLT<Eigen::MatrixXd> llt(Smid);
  if (llt.info() != Eigen::Success) return false;
  const Eigen::MatrixXd X = llt.matrixU().solve(Eigen::MatrixXd::Identity(Eigen::Index(n), Eigen::Index(n)));  // U^-1 = L^-T
  BallRows Xb = zero_balls(n, n), Xt = zero_balls(n, n);
  flint::Ball f(0L);
  for (size_t i = 0; i < n; ++i)
    for (size_t j = 0; j < n; ++j) {
      const double x = X(Eigen::Index(i), Eigen::Index(j));
      if (!std::isfinite(x) || (i == j && x == 0) || (i > j && x != 0)) return false;  // upper triangular, non-singular
      Xb[i][j] = flint::Ball(x);
      Xt[j][i] = Xb[i][j];
      f += Xb[i][j] * Xb[i][j];
    }
  const BallRows G = product(Xt, product(S, Xb));
  const flint::Ball fr = f * r;
  for (size_t i = 0; i < n; ++i) {
    flint::Ball row = G[i][i] - fr;
    for (size_t j = 0; j < n; ++j)
      if (j != i) row -= flint::abs(G[i][j]);
    if (!row.positive()) return false;
  }
  return true;
}

}  // namespace

// Every symmetric matrix within r of S (spectral norm) is positive definite (congruence_shows_positive on S's
// exact balls).
bool positive_definite_within(const Mat& S, const rational& r) {
  const size_t n = S.size();
  Eigen::MatrixXd Sd(n, n);
  for (size_t i = 0; i < n; ++i)
    for (size_t j = 0; j < n; ++j) Sd(Eigen::Index(i), Eigen::Index(j)) = S[i][j].convert_to<double>();
  return congruence_shows_positive(balls(S), Sd, flint::Ball(r));
}

bool positive_definite(const Mat& P) {
  if (positive_definite_within(P, rational(0))) return true;
  return P.size() <= 24 && rational_matrix::positive_definite(P, true);
}

// Every symmetric matrix in the balls Q is positive definite (the header): in balls throughout. A symmetric A in Q
// has A_ij = (A_ij + A_ji)/2 in (Q_ij + Q_ji)/2, so D A D lies in S = D (Q + Q^T)/2 D, D = diag(2^-k_i), 2^k_i ~
// sqrt(mid Q_ii) (exact: powers of two; D A D has A's inertia, and its diagonal near 1 weighs the radii of a
// badly scaled Q -- a fast lag beside a slow mass -- where they act); then the congruence test on S.
bool ball_positive_definite(const BallRows& Q, std::string& why) {
  const size_t n = Q.size();
  std::vector<long> k(n, 0);
  for (size_t i = 0; i < n; ++i) {
    const double m = Q[i][i].to_double();
    if (std::isfinite(m) && m > 0) {  // m = f 2^e, 1/2 <= f < 1: log2 m in [e - 1, e); k = floor((e - 1) / 2)
      int e = 0;
      std::frexp(m, &e);
      k[i] = (e - 1) >= 0 ? (e - 1) / 2 : -((2 - e) / 2);
    }
  }
  BallRows S = zero_balls(n, n);
  Eigen::MatrixXd Sd(n, n);
  for (size_t i = 0; i < n; ++i)
    for (size_t j = 0; j < n; ++j) {
      if (!Q[i][j].finite()) {
        why = "not shown positive definite (an entry's ball is not finite)";
        return false;
      }
      S[i][j] = Q[i][j] + Q[j][i];
      arb_mul_2exp_si(S[i][j].get(), S[i][j].get(), -1 - k[i] - k[j]);
      Sd(Eigen::Index(i), Eigen::Index(j)) = S[i][j].to_double();
    }
  if (congruence_shows_positive(S, Sd, flint::Ball(0L))) return true;
  why = "not shown positive definite (the symmetrised balls, scaled: no congruence to a diagonally dominant matrix found)";
  return false;
}

// Q = P - M^T P M > 0 for every M in the balls (ball_positive_definite).
bool stein_holds(const Mat& Pm, const BallRows& M, std::string& why) {
  const size_t n = Pm.size();
  const BallRows Pb = balls(Pm);
  BallRows Mt = zero_balls(n, n);
  for (size_t i = 0; i < n; ++i)
    for (size_t j = 0; j < n; ++j) Mt[i][j] = M[j][i];
  const BallRows MPM = product(Mt, product(Pb, M));
  BallRows Q = zero_balls(n, n);
  for (size_t i = 0; i < n; ++i)
    for (size_t j = 0; j < n; ++j) Q[i][j] = Pb[i][j] - MPM[i][j];
  if (ball_positive_definite(Q, why)) return true;
  why = "P - M^T P M is " + why;
  return false;
}

// P(t) = (1 - t) Pa + t Pb and M(t) = (1 - t) Ma + t Mb on t in [0, 1]: S(t) = P(t) - M(t)^T P(t) M(t) is a
// cubic in t, sum_s C_s B_s(t) in the Bernstein basis B_s(t) = (3 choose s) (1 - t)^(3 - s) t^s (>= 0, summing
// to 1), with C_s = ((3 - s) Pa + s Pb)/3 - (3 choose s)^-1 sum_{i + j + k = s} X_i^T P_j X_k (X_0 = Ma, X_1 =
// Mb, P_0 = Pa, P_1 = Pb): every C_s > 0 (balls) gives S(t) > 0 on [0, 1] (stability_loop_max_check.hpp).
bool bernstein_stein_holds(const Mat& Pa, const Mat& Pb, const BallRows& Ma, const BallRows& Mb, std::string& why) {
  const size_t n = Pa.size();
  const BallRows P[2] = {balls(Pa), balls(Pb)};
  const BallRows* X[2] = {&Ma, &Mb};
  BallRows Xt[2] = {zero_balls(n, n), zero_balls(n, n)};
  for (int a = 0; a < 2; ++a)
    for (size_t i = 0; i < n; ++i)
      for (size_t j = 0; j < n; ++j) Xt[a][i][j] = (*X[a])[j][i];
  BallRows PX[2][2];  // PX[j][k] = P_j X_k
  for (int j = 0; j < 2; ++j)
    for (int k = 0; k < 2; ++k) PX[j][k] = product(P[j], *X[k]);
  for (int s = 0; s <= 3; ++s) {
    BallRows C = zero_balls(n, n);
    int terms = 0;
    for (int i = 0; i < 2; ++i)
      for (int j = 0; j < 2; ++j)
        for (int k = 0; k < 2; ++k) {
          if (i + j + k != s) continue;
          const BallRows XPX = product(Xt[i], PX[j][k]);
          for (size_t a = 0; a < n; ++a)
            for (size_t b = 0; b < n; ++b) C[a][b] -= XPX[a][b];
          ++terms;
        }
    const flint::Ball w(rational(1, terms)), wa(rational(3 - s, 3)), wb(rational(s, 3));
    for (size_t a = 0; a < n; ++a)
      for (size_t b = 0; b < n; ++b) C[a][b] = wa * P[0][a][b] + wb * P[1][a][b] + w * C[a][b];
    if (!ball_positive_definite(C, why)) {
      why = "the Bernstein coefficient C_" + std::to_string(s) + " of P(t) - M(t)^T P(t) M(t) is " + why;
      return false;
    }
  }
  return true;
}

// The rows l of the loop's slow modes at p = 0 (stability_loop_max_check.hpp's first-order start): a basis,
// in reduced row echelon form, of {l : l^T (M~(0) - I) = 0, l_p^T A = 0}, M~(0) = 2 M~(1) - M~(2) with M~
// the exact slow matrix (each hold e^{Ah} -> I, Gamma_h -> h B) of the loops read at p = 1 and 2. For l_p^T
// A = 0, l_p^T e^{Ah} = l_p^T and l_p^T Gamma_h = h l_p^T B exactly, so l^T M(p) = l^T M~(p): l^T M(0) = l^T.
BallRows restricted(const BallRows& M, const Mat& L) {
  Mat K = L;
  return reduced(M, Conserved{L, echelon(K)});  // L already in reduced echelon form: its pivots
}

Mat slow_rows(const SceneLoop& L1, const SceneLoop& L2, const LoopMatrix& m1) {
  if (m1.right_quotient)
    throw InputError("evidence.first_order: a loop on a quotient by a block's unobservable z = 1 (right eigenvectors): beyond this kind");
  const auto slow = [](const SceneLoop& L) {
    const Plant pl = plant(L);
    const size_t ns = pl.A.size();
    const rational f = L.fraction * L.T;
    Mat hB0 = pl.B, hB1 = pl.B;
    for (auto& row : hB0)
      for (auto& x : row) x *= rational(L.T - f);
    for (auto& row : hB1)
      for (auto& x : row) x *= f;
    return std::pair{assemble<rational>(assembly(L, pl), rational_matrix::identity(ns), hB0, f == 0 ? nullptr : &hB1,
                                        [](const rational& x) { return x; }),
                     pl.A};
  };
  const auto [S1, A] = slow(L1);
  const Mat S2 = slow(L2).first;
  if (S1.size() != S2.size()) throw NumericalError("the loops at p = 1 and 2 differ in order (a checker defect)");
  const size_t n = S1.size(), ns = A.size();
  Mat M0mI = rational_matrix::zeros(n, n), Ap = rational_matrix::zeros(n, ns);
  for (size_t i = 0; i < n; ++i) {
    for (size_t j = 0; j < n; ++j) M0mI[i][j] = 2 * S1[i][j] - S2[i][j] - (i == j ? rational(1) : rational(0));
    if (i < ns) Ap[i] = A[i];
  }
  Mat L = conserved_quantities(M0mI, Ap).L;
  if (L.empty()) return L;
  if (!m1.embedding.empty()) L = rational_matrix::mul(L, m1.embedding);  // on the quotient: r = l^T E
  L.resize(echelon(L).size());  // reduced echelon form; the conserved rows' own images (0) dropped
  return L;
}

std::optional<Mat> exact_loop_matrix(const SceneLoop& L) {
  const Plant pl = plant(L);
  const size_t ns = pl.A.size();
  // A nilpotent: A^ns = 0 exactly, then e^{Ah} = sum_{k < ns} (Ah)^k / k! and Gamma_h = sum_{k < ns} A^k h^{k+1} / (k+1)! B
  Mat Ak = rational_matrix::identity(ns);
  for (size_t k = 0; k < ns; ++k) Ak = rational_matrix::mul(Ak, pl.A);
  for (const auto& row : Ak)
    for (const rational& x : row)
      if (!x.is_zero()) return std::nullopt;
  const auto hold_exact = [&](const rational& h) {
    Mat Phi = rational_matrix::zeros(ns, ns), term = rational_matrix::identity(ns), S = rational_matrix::zeros(ns, ns);
    rational fact = 1, hk = 1;
    for (size_t k = 0; k < ns; ++k) {  // term = A^k; Phi += A^k h^k / k!, S += A^k h^{k+1} / (k+1)!
      for (size_t i = 0; i < ns; ++i)
        for (size_t j = 0; j < ns; ++j) {
          Phi[i][j] += term[i][j] * hk / fact;
          S[i][j] += term[i][j] * hk * h / (fact * rational(long(k + 1)));
        }
      term = rational_matrix::mul(term, pl.A);
      fact *= rational(long(k + 1));
      hk *= h;
    }
    return std::pair{Phi, rational_matrix::mul(S, pl.B)};
  };
  const rational f = L.fraction * L.T;
  Mat Phi, G0, G1;
  if (f == 0) {
    std::tie(Phi, G0) = hold_exact(L.T);
  } else {
    const auto [Pa, Ga] = hold_exact(L.T - f);
    const auto [Pb, Gb] = hold_exact(f);
    Phi = rational_matrix::mul(Pa, Pb);
    G0 = Ga;
    G1 = rational_matrix::mul(Pa, Gb);
  }
  return assemble<rational>(assembly(L, pl), Phi, G0, f == 0 ? nullptr : &G1, [](const rational& x) { return x; });
}

}  // namespace detail

SceneLoopMatrix scene_loop_matrix(const nlohmann::json& model, long bits) {
  const detail::SceneLoop L = detail::read_scene_loop(model);
  flint::BallPrecision scope(bits);
  const LoopMatrix lm = detail::loop_matrix(L, bits);
  SceneLoopMatrix out;
  out.conserved = lm.conserved;
  out.M.resize(lm.M.size());
  for (size_t i = 0; i < lm.M.size(); ++i)
    for (const auto& x : lm.M[i]) {
      const auto e = x.bounds();
      out.M[i].emplace_back(e.lo, e.hi);
    }
  return out;
}

namespace {

// Every root of p in Re s < 0, by the Cayley map z = (1 + s)/(1 - s), which takes Re s < 0 onto |z| < 1:
// p(1) = 0 is a root at s = 1 (not); else q(z) = (z + 1)^d p((z - 1)/(z + 1)) = sum p_k (z - 1)^k (z + 1)^(d - k)
// has degree d (its leading coefficient is p(1)) and its roots are the images of p's: Schur-Cohn on q.
SchurCohn hurwitz(const P& p) {
  if (p(rational(1)).is_zero()) return {false, "a root at s = 1"};
  const int d = p.degree();
  const P zm1{rational(-1), rational(1)}, zp1{rational(1), rational(1)};
  P q;
  for (int k = 0; k <= d; ++k) {
    P term(p.coeff(k));
    for (int i = 0; i < k; ++i) term = term * zm1;
    for (int i = k; i < d; ++i) term = term * zp1;
    q = q + term;
  }
  return schur_cohn(q);
}

// NOT stable by a hidden mode of a block written as ss (header): evidence.hidden {block, [name,] kind,
// basis, A_h}. The block's (A, B, C) as the checker reads it; unobservable: basis Vb (n x r), C Vb = 0,
// A Vb = Vb A_h; uncontrollable: basis Wb (r x n), Wb B = 0, Wb A = A_h Wb; the basis of full rank r (its
// Gram matrix regular). Discrete (environment, coupling): charpoly(A_h) = (z - 1)^k q(z), q(1) != 0, q not
// Schur stable. Continuous (a device, an operator): charpoly(A_h) = s^k q(s), q(0) != 0, q not Hurwitz:
// a root lambda != 0 with Re lambda >= 0, so e^{lambda T} has |.| >= 1 and is not 1 (lambda T = 2 pi j m
// is impossible for an algebraic lambda != 0 and a rational T: pi is transcendental). Either way M has
// an eigenvalue != 1 with |z| >= 1.
}  // namespace

Verdict detail::hidden_mode_verdict(const detail::SceneLoop& L, const nlohmann::json& h) {
  using namespace rational_matrix;
  if (!h.is_object()) throw InputError("evidence.hidden: not an object");
  const auto text = [&](const char* key) {
    if (!h.contains(key) || !h.at(key).is_string()) throw InputError(std::string("evidence.hidden.") + key + ": missing or not a string");
    return h.at(key).get<std::string>();
  };
  const std::string block = text("block"), kind = text("kind");
  const bool named = block == "device" || block == "operator";
  if (named) detail::only_fields(h, {"block", "name", "kind", "basis", "A_h"}, "evidence.hidden");
  else detail::only_fields(h, {"block", "kind", "basis", "A_h"}, "evidence.hidden");
  if (kind != "unobservable" && kind != "uncontrollable")
    throw InputError("evidence.hidden.kind: \"unobservable\" or \"uncontrollable\", got \"" + kind + "\"");
  const Mat *A = nullptr, *B = nullptr, *C = nullptr;
  std::string what = block;
  if (block == "environment" || block == "coupling") {
    const detail::SceneLoop::Discrete* d = block == "environment" ? &L.E : (L.V ? &*L.V : nullptr);
    if (!d) throw InputError("evidence.hidden.block: the scene has no [coupling]");
    if (!d->is_ss)
      throw InputError("evidence.hidden.block: the " + block + " is written as tf (its realisation is the checker's own): a hidden "
                       "mode is certified of an ss block as written");
    A = &d->A, B = &d->B, C = &d->C;
  } else if (named) {
    const std::string name = text("name");
    what = block + " '" + name + "'";
    if (block == "device") {
      for (const auto& dv : L.devices)
        if (dv.block && dv.tf.empty() && dv.name == name) A = &dv.A, B = &dv.B, C = &dv.C;
    } else {
      for (const auto& op : L.operators)
        if (op.is_ss && op.name == name) A = &op.A, B = &op.B, C = &op.C;
    }
    if (!A) throw InputError("evidence.hidden.name: no " + block + " named '" + name + "' given by ss in the scene");
  } else {
    throw InputError("evidence.hidden.block: \"environment\", \"coupling\", \"device\" or \"operator\", got \"" + block + "\"");
  }
  const bool continuous = named;
  const Mat basis = detail::exact_matrix(h, "basis", "evidence.hidden", kMaxHiddenOrder);
  const Mat Ah = detail::exact_matrix(h, "A_h", "evidence.hidden", kMaxHiddenOrder);
  const size_t n = A->size(), r = Ah.size();
  const bool unobs = kind == "unobservable";
  if (n == 0) throw InputError("evidence.hidden: the " + what + " has no state");
  if (r == 0 || Ah[0].size() != r) throw InputError("evidence.hidden.A_h: empty or not square");
  if (unobs ? (basis.size() != n || basis[0].size() != r) : (basis.size() != r || basis[0].size() != n))
    throw InputError("evidence.hidden.basis: must be " + (unobs ? std::to_string(n) + " x " + std::to_string(r) : std::to_string(r) + " x " + std::to_string(n)) +
                     " (the " + what + "'s " + std::to_string(n) + " states, A_h's order " + std::to_string(r) + ")");
  const Mat zero_out = unobs ? mul(*C, basis) : mul(basis, *B);
  for (const auto& row : zero_out)
    for (const rational& x : row)
      if (!x.is_zero()) return {false, std::string("evidence.hidden: ") + (unobs ? "C basis != 0 (the output shows it)" : "basis B != 0 (the input reaches it)")};
  const Mat lhs = unobs ? mul(*A, basis) : mul(basis, *A), rhs = unobs ? mul(basis, Ah) : mul(Ah, basis);
  if (lhs != rhs) return {false, std::string("evidence.hidden: ") + (unobs ? "A basis != basis A_h" : "basis A != A_h basis") + " (not an invariant subspace with A_h)"};
  const Mat gram = unobs ? mul(transpose(basis), basis) : mul(basis, transpose(basis));
  if (det(gram).is_zero()) return {false, "evidence.hidden.basis: not of full rank " + std::to_string(r)};
  // charpoly(A_h) by r + 1 exact determinants and interpolation
  std::vector<rational> xs, ys;
  for (size_t k = 0; k <= r; ++k) {
    const rational t(static_cast<long>(k));
    xs.push_back(t);
    ys.push_back(det(add(add(zeros(r, r), identity(r), t), Ah, -1)));
  }
  P q = interpolate(xs, ys);
  long k1 = 0;
  const rational marginal = continuous ? rational(0) : rational(1);  // the eigenvalue that may settle
  const P x_minus{-marginal, rational(1)};
  while (q.degree() > 0 && q(marginal).is_zero()) q = divmod(q, x_minus).first, ++k1;
  const SchurCohn sc = continuous ? hurwitz(q) : schur_cohn(q);
  const std::string var = continuous ? "s" : "(z - 1)";
  if (sc.stable) {
    // the marginal eigenvalue itself not semisimple in A_h (geometric multiplicity r - rank(A_h - marginal I) below
    // k1): A_h, or e^{A_h T}, is M on that invariant subspace (or on the quotient by it), so M has a Jordan block at
    // z = 1 and the loop grows polynomially: NOT stable too (since stop 89)
    Mat shifted = add(Ah, identity(r), -marginal);
    const size_t geometric = r - echelon(shifted).size();
    if (k1 > 0 && geometric < static_cast<size_t>(k1))
      return {true, "NOT stable [exact]: the " + what + " (ss as written) hides an " + kind + " subspace of dimension " + std::to_string(r) +
                        " (" + (unobs ? "C V = 0, A V = V A_h" : "W B = 0, W A = A_h W") + ", exactly), invariant in the loop; A_h has " +
                        (continuous ? "s = 0" : "z = 1") + " of algebraic multiplicity " + std::to_string(k1) + " and geometric " +
                        std::to_string(geometric) + ": a Jordan block of M at z = 1 (the loop grows polynomially)"};
    return {false, "evidence.hidden: every eigenvalue of A_h other than " + std::string(continuous ? "s = 0" : "z = 1") + " lies in " +
                       (continuous ? "Re s < 0" : "the unit disc") + " (" + sc.why + "), and it is semisimple: no eigenvalue of the loop with " +
                       "|z| >= 1, z != 1, nor a Jordan block at 1, shown"};
  }
  return {true, "NOT stable [exact]: the " + what + " (ss as written) hides an " + kind + " subspace of dimension " +
                    std::to_string(r) + " (" + (unobs ? "C V = 0, A V = V A_h" : "W B = 0, W A = A_h W") +
                    ", exactly), an invariant subspace of the loop whatever the rest does; charpoly(A_h) = " + var + "^" +
                    std::to_string(k1) + " q with q not " + (continuous ? "Hurwitz (Cayley map, " : "Schur stable (") + sc.why +
                    "): M has an eigenvalue lambda != 1 with |lambda| >= 1"};
}

Verdict check_stability_loop(const nlohmann::json& cert) {
  const auto [model, claim, evidence] = detail::certificate_parts(cert);
  detail::only_fields(claim, {"quantity", "status", "stable", "conserved"}, "claim");
  if (evidence.contains("hidden")) {  // NOT stable by a hidden mode, exactly (header)
    detail::only_fields(evidence, {"hidden"}, "evidence");
    detail::only_fields(claim, {"quantity", "status", "stable"}, "claim");
    if (!claim.contains("status") || claim.at("status") != "exact")
      throw InputError("claim.status: a hidden mode's verdict is \"exact\" (rational evidence, no enclosure)");
    if (!claim.contains("stable") || claim.at("stable") != false) throw InputError("claim.stable: a hidden mode shows NOT stable (false) only");
    return detail::hidden_mode_verdict(detail::read_scene_loop(model), evidence.at("hidden"));
  }
  detail::only_fields(evidence, {"P", "w"}, "evidence");
  if (!claim.contains("status") || claim.at("status") != "certified")
    throw InputError("claim.status: missing or not \"certified\" (the loop holds exponentials: an enclosure decides)");
  if (!claim.contains("stable") || !claim.at("stable").is_boolean()) throw InputError("claim.stable: missing or not true/false");
  const bool stable = claim.at("stable").get<bool>();
  const long conserved = claim.contains("conserved") ? detail::integer_field(claim, "conserved", "claim", 0, static_cast<long>(kMaxOrder)) : 0;
  return detail::stein_verdict(detail::read_scene_loop(model), evidence, stable, conserved, "evidence");
}

Verdict detail::stein_verdict(const SceneLoop& L, const nlohmann::json& evidence, bool stable, long conserved, const std::string& where) {
  const Mat Pm = detail::exact_matrix(evidence, "P", where, kMaxOrder);
  if (Pm.empty() || Pm[0].size() != Pm.size()) throw InputError(where + ".P: not a square matrix");  // [[]] once reached the test below
  // before anything is computed in balls (e^{AT} of a 128-DOF plant takes seconds): the quotient keeps at least
  // one state per DOF (rank [A B] >= N: each DOF's force enters its own velocity; a block's z = 1 rows and
  // vectors at most its states), so a P of lower order cannot be the loop's
  if (Pm.size() < L.dofs())
    throw InputError(where + ".P: order " + std::to_string(Pm.size()) + ", below the loop's " + std::to_string(L.dofs()) +
                     " DOFs (its matrix keeps at least one state per DOF)");
  if (!rational_matrix::symmetric(Pm)) throw InputError(where + ".P: not symmetric");
  if (stable == evidence.contains("w")) throw InputError(where + (stable ? ".w: only for NOT stable" : ".w: missing (NOT stable needs w with w^T P w < 0)"));
  std::string sign;
  if (stable) {
    // the congruence test, then exact elimination for small P (exact elimination of large dyadic P is slow)
    const bool pd = detail::positive_definite(Pm);
    if (!pd) return {false, "claim: stable, but " + where + ".P is not shown positive definite"};
    sign = "P > 0";
  } else {
    const auto w = detail::exact_matrix(nlohmann::json{{"w", nlohmann::json::array({evidence.at("w")})}}, "w", where, kMaxOrder);
    if (w[0].size() != Pm.size()) throw InputError(where + ".w: not of P's order");
    const Mat Pw = rational_matrix::mul(Pm, rational_matrix::transpose(w));
    rational q = 0;
    for (size_t i = 0; i < Pm.size(); ++i) q += w[0][i] * Pw[i][0];
    if (q >= 0) return {false, "claim: NOT stable, but w^T P w = " + approx(q) + " >= 0"};
    sign = "w^T P w < 0 (an eigenvalue with |z| > 1)";
  }
  std::string why;
  for (long bits : {128L, 256L, 512L}) {
    flint::BallPrecision scope(bits);
    const LoopMatrix lm = detail::loop_matrix(L, bits);
    if (static_cast<long>(lm.conserved) != conserved)
      return {false, "claim: " + std::to_string(conserved) + " conserved quantities, but the loop has " +
                         std::to_string(lm.conserved) + " (l^T [A B] = 0 of the plant, l^T [A - I, B] = 0 of the wall or coupling, "
                         "exactly: each an eigenvalue 1 of M)"};
    const BallRows& M = lm.M;
    if (M.size() != Pm.size())
      throw InputError(where + ".P: order " + std::to_string(Pm.size()) + ", the loop's " + std::to_string(M.size()) +
                       (lm.conserved || L.own_conserved ? " (on the quotient by its conserved quantities)" : ""));
    if (detail::stein_holds(Pm, M, why))
      return {true, std::string(stable ? "stable" : "NOT stable") + ": the closed loop M (" + std::to_string(lm.order) + " states, " +
                        std::to_string(L.dofs()) + " DOF, delay " + rational(L.delay + L.fraction).str() +
                        " samples) built from the model, e^{AT} in balls (" + std::to_string(bits) + " bits)" +
                        (lm.conserved ? ", on the quotient by its conserved quantities (k = " + std::to_string(lm.conserved) +
                                            ": l^T [A B] = 0 exactly, l^T M = l^T)"
                                      : std::string()) +
                        (L.own_conserved ? ", the position the checker integrates set to P's output (the quotient by its "
                                           "own conserved quantity: the model as written)"
                                         : "") +
                        "; P - M^T P M > 0 for every M in them and " + sign + " (Stein inertia)"};
  }
  return {false, "claim: " + std::string(stable ? "stable" : "NOT stable") + ", but " + why + " at 512 bits"};
}

}  // namespace hapstab::check
