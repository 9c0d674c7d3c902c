#include "hapstab/lti/realization.hpp"

#include <Eigen/LU>

#include "hapstab/numeric/error.hpp"
#include "hapstab/poly/flint_poly.hpp"

namespace hapstab {

using Q = rational;
using MQ = Mat<Q>;

StateSpace<Q> tf2ss(const TransferFunction& G) {
  if (!G.is_proper())
    throw InputError("tf2ss: " + G.to_string() + " is not proper (degree of numerator > degree of denominator)");
  const auto& den = G.den();  // monic (RationalFunction keeps the denominator monic)
  const int n = den.degree();
  auto [q, r] = divmod(G.num(), den);
  MQ A = MQ::Zero(n, n), B = MQ::Zero(n, 1), C = MQ::Zero(1, n), D(1, 1);
  const Q lead = den.leading();
  for (int i = 0; i + 1 < n; ++i) A(i, i + 1) = 1;
  for (int j = 0; j < n; ++j) {
    A(n - 1, j) = -den.coeff(j) / lead;
    C(0, j) = r.coeff(j) / lead;
  }
  if (n > 0) B(n - 1, 0) = 1;
  D(0, 0) = q.coeff(0);
  return {A, B, C, D, G.T};
}

StateSpace<Q> tf2ss(const TransferMatrix& G) {
  const size_t p = G.outputs(), m = G.inputs();
  if (p == 0 || m == 0) throw InputError("tf2ss: empty transfer matrix");
  // One controllable form per input column j with the column's common denominator d_j:
  // column j = N_j(x)/d_j(x), N_j a p-vector of polynomials.
  std::vector<Polynomial<Q>> dens(m);
  int total = 0;
  for (size_t j = 0; j < m; ++j) {
    Polynomial<Q> d(Q(1));
    for (size_t i = 0; i < p; ++i) {
      const auto& e = G.entries.at(i).at(j);
      if (!e.is_proper()) throw InputError("tf2ss: entry (" + std::to_string(i + 1) + "," + std::to_string(j + 1) +
                                           ") " + e.to_string() + " is not proper");
      auto g = gcd(d, e.den());
      d = divmod(d * e.den(), g).first;
    }
    dens[j] = d.monic();
    total += dens[j].degree();
  }
  MQ A = MQ::Zero(total, total), B = MQ::Zero(total, m), C = MQ::Zero(p, total), D = MQ::Zero(p, m);
  int off = 0;
  for (size_t j = 0; j < m; ++j) {
    const auto& d = dens[j];
    const int n = d.degree();
    for (int k = 0; k + 1 < n; ++k) A(off + k, off + k + 1) = 1;
    for (int k = 0; k < n; ++k) A(off + n - 1, off + k) = -d.coeff(k);
    if (n > 0) B(off + n - 1, j) = 1;
    for (size_t i = 0; i < p; ++i) {
      const auto& e = G.entries[i][j];
      Polynomial<Q> num = e.num() * divmod(d, e.den()).first;  // entry over the common denominator
      auto [qq, rr] = divmod(num, d);
      D(i, j) = qq.coeff(0);
      for (int k = 0; k < n; ++k) C(i, off + k) = rr.coeff(k);
    }
    off += n;
  }
  return {A, B, C, D, G.T};
}

Polynomial<Q> charpoly(const MQ& A) {
  // FLINT's fmpq_mat_charpoly (fraction-free over the common denominator): an order-40 matrix in
  // milliseconds, where Faddeev-LeVerrier in rationals took seconds.
  const long n = static_cast<long>(A.rows());
  if (n == 0) return Polynomial<Q>(Q(1));
  flint::QMat M(n, n);
  for (long i = 0; i < n; ++i)
    for (long j = 0; j < n; ++j) flint::set(M.at(i, j), A(i, j));
  flint::QPoly p;
  fmpq_mat_charpoly(p.get(), M.get());
  return flint::from_flint(p);
}

TransferMatrix ss2tf(const StateSpace<Q>& sys) {
  sys.validate("ss2tf");
  const auto n = sys.states();
  const auto p = sys.outputs(), m = sys.inputs();
  // adj(xI - A) = sum_{k=1..n} x^{n-k} M_k with the Faddeev-LeVerrier matrices M_k.
  std::vector<Q> c(n + 1);
  c[n] = 1;
  std::vector<MQ> Ms;
  MQ M = MQ::Zero(n, n);
  const MQ I = MQ::Identity(n, n);
  for (Eigen::Index k = 1; k <= n; ++k) {
    M = sys.A * M + c[n - k + 1] * I;
    Ms.push_back(M);
    c[n - k] = -(sys.A * M).trace() / Q(k);
  }
  Polynomial<Q> det(c);
  std::vector<MQ> CMB;
  for (const auto& Mk : Ms) CMB.push_back(sys.C * Mk * sys.B);
  TransferMatrix G;
  G.domain = sys.T > 0 ? Domain::z : Domain::s;
  G.T = sys.T;
  G.entries.assign(p, std::vector<TransferFunction>(m));
  for (Eigen::Index i = 0; i < p; ++i)
    for (Eigen::Index j = 0; j < m; ++j) {
      std::vector<Q> num(n + 1, Q(0));
      for (Eigen::Index k = 1; k <= n; ++k) num[n - k] = CMB[k - 1](i, j);
      Polynomial<Q> N = Polynomial<Q>(num) + sys.D(i, j) * det;
      G.entries[i][j] = {RationalFunction<Q>(N, det), G.domain, G.T};
    }
  return G;
}

namespace {

// Exact column echelon basis of the column space of M (Gaussian elimination over Q).
MQ column_basis(const MQ& M) {
  MQ R = M.transpose();  // rows of R span the column space
  const auto rows = R.rows(), cols = R.cols();
  Eigen::Index rank = 0;
  for (Eigen::Index c = 0; c < cols && rank < rows; ++c) {
    Eigen::Index piv = -1;
    for (Eigen::Index r = rank; r < rows; ++r)
      if (R(r, c) != 0) {
        piv = r;
        break;
      }
    if (piv < 0) continue;
    R.row(piv).swap(R.row(rank));
    for (Eigen::Index r = 0; r < rows; ++r)
      if (r != rank && R(r, c) != 0) R.row(r) -= (R(r, c) / R(rank, c)) * R.row(rank);
    ++rank;
  }
  return R.topRows(rank).transpose();
}

// Keeps the controllable part: projects onto the Krylov space span[B, AB, ...].
StateSpace<Q> controllable_part(const StateSpace<Q>& s) {
  const auto n = s.states();
  if (n == 0) return s;
  MQ K(n, 0);
  MQ blk = s.B;
  for (Eigen::Index k = 0; k < n; ++k) {
    MQ next(n, K.cols() + blk.cols());
    next << K, blk;
    K = column_basis(next);
    blk = s.A * blk;
  }
  const auto r = K.cols();
  if (r == n) return s;
  // Coordinates x = V xi with V = [K, E]: E are unit vectors completing K to a basis.
  MQ V = K;
  for (Eigen::Index i = 0; i < n && V.cols() < n; ++i) {
    MQ cand(n, V.cols() + 1);
    cand << V, MQ::Identity(n, n).col(i);
    if (column_basis(cand).cols() > V.cols()) V = cand;
  }
  Eigen::FullPivLU<MQ> lu(V);
  MQ Vi = lu.inverse();
  MQ At = Vi * s.A * V, Bt = Vi * s.B, Ct = s.C * V;
  return {At.topLeftCorner(r, r), Bt.topRows(r), Ct.leftCols(r), s.D, s.T};
}

StateSpace<Q> dual(const StateSpace<Q>& s) {
  return {s.A.transpose(), s.C.transpose(), s.B.transpose(), s.D.transpose(), s.T};
}

}  // namespace

StateSpace<Q> minreal(const StateSpace<Q>& sys) {
  sys.validate("minreal");
  return dual(controllable_part(dual(controllable_part(sys))));
}

}  // namespace hapstab
