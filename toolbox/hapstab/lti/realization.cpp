#include "hapstab/lti/realization.hpp"

#include <algorithm>
#include <map>

#include <Eigen/LU>

#include "hapstab/numeric/error.hpp"
#include "hapstab/numeric/exact_matrix.hpp"
#include "hapstab/poly/flint_poly.hpp"
#include "hapstab/poly/roots.hpp"

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
  std::vector<TransferFunction> entries;
  entries.reserve(p * m);
  for (size_t i = 0; i < p; ++i) {
    if (G.entries.at(i).size() != m) throw InputError("tf2ss: row " + std::to_string(i + 1) + " has a different length");
    for (size_t j = 0; j < m; ++j) entries.push_back(G.entries[i][j]);
  }
  std::vector<int> index(p * m);
  for (size_t k = 0; k < index.size(); ++k) index[k] = static_cast<int>(k);
  return tf2ss(entries, index, p, m, G.T);
}

StateSpace<Q> tf2ss(const std::vector<TransferFunction>& distinct, const std::vector<int>& index, size_t p, size_t m,
                    const rational& T) {
  if (p == 0 || m == 0) throw InputError("tf2ss: empty transfer matrix");
  if (index.size() != p * m) throw InputError("tf2ss: the index holds " + std::to_string(index.size()) + " entries, not p m");
  for (size_t k = 0; k < index.size(); ++k)
    if (index[k] < 0 || static_cast<size_t>(index[k]) >= distinct.size())
      throw InputError("tf2ss: entry (" + std::to_string(k / m + 1) + "," + std::to_string(k % m + 1) + ") has no transfer function");
  for (size_t k = 0; k < distinct.size(); ++k)
    if (!distinct[k].is_proper()) {
      size_t at = 0;
      while (at < index.size() && static_cast<size_t>(index[at]) != k) ++at;
      if (at < index.size())
        throw InputError("tf2ss: entry (" + std::to_string(at / m + 1) + "," + std::to_string(at % m + 1) + ") " +
                         distinct[k].to_string() + " is not proper");
    }
  // One controllable form per input column j with the column's common denominator d_j (the
  // monic lcm of its entries' denominators): column j = N_j(x)/d_j(x), N_j a p-vector of
  // polynomials. Columns with the same set of distinct entries share d_j, and an entry over a
  // given d_j is reduced once: a compact scene's N x N matrix costs its distinct columns.
  std::map<std::vector<int>, size_t> column_kind;  // sorted distinct ids of a column -> its d_j
  std::vector<Polynomial<Q>> dens;
  std::vector<size_t> kind_of(m);
  int total = 0;
  for (size_t j = 0; j < m; ++j) {
    std::vector<int> ids(p);
    for (size_t i = 0; i < p; ++i) ids[i] = index[i * m + j];
    std::sort(ids.begin(), ids.end());
    ids.erase(std::unique(ids.begin(), ids.end()), ids.end());
    auto [it, fresh] = column_kind.try_emplace(std::move(ids), dens.size());
    if (fresh) {
      Polynomial<Q> d(Q(1));
      for (int id : it->first) {
        const auto& den = distinct[static_cast<size_t>(id)].den();
        d = divmod(d * den, gcd(d, den)).first;
      }
      dens.push_back(d.monic());
    }
    kind_of[j] = it->second;
    total += dens[it->second].degree();
  }
  MQ A = MQ::Zero(total, total), B = MQ::Zero(total, static_cast<Eigen::Index>(m)),
     C = MQ::Zero(static_cast<Eigen::Index>(p), total), D = MQ::Zero(static_cast<Eigen::Index>(p), static_cast<Eigen::Index>(m));
  // entry id over denominator kind -> its D value and C row (the remainder's coefficients)
  std::map<std::pair<int, size_t>, std::pair<Q, std::vector<Q>>> over;
  int off = 0;
  for (size_t j = 0; j < m; ++j) {
    const auto& d = dens[kind_of[j]];
    const int n = d.degree();
    for (int k = 0; k + 1 < n; ++k) A(off + k, off + k + 1) = 1;
    for (int k = 0; k < n; ++k) A(off + n - 1, off + k) = -d.coeff(k);
    if (n > 0) B(off + n - 1, static_cast<Eigen::Index>(j)) = 1;
    for (size_t i = 0; i < p; ++i) {
      const int id = index[i * m + j];
      auto [it, fresh] = over.try_emplace({id, kind_of[j]});
      if (fresh) {
        const auto& e = distinct[static_cast<size_t>(id)];
        Polynomial<Q> num = e.num() * divmod(d, e.den()).first;  // entry over the common denominator
        auto [qq, rr] = divmod(num, d);
        it->second.first = qq.coeff(0);
        for (int k = 0; k < n; ++k) it->second.second.push_back(rr.coeff(k));
      }
      const auto ii = static_cast<Eigen::Index>(i);
      D(ii, static_cast<Eigen::Index>(j)) = it->second.first;
      for (int k = 0; k < n; ++k) C(ii, off + k) = it->second.second[static_cast<size_t>(k)];
    }
    off += n;
  }
  return {std::move(A), std::move(B), std::move(C), std::move(D), T};
}

namespace {
Polynomial<Q> flint_charpoly(const MQ& A) {
  const long n = static_cast<long>(A.rows());
  flint::QMat M(n, n);
  for (long i = 0; i < n; ++i)
    for (long j = 0; j < n; ++j) flint::set(M.at(i, j), A(i, j));
  flint::FmpqPoly p;
  fmpq_mat_charpoly(p.get(), M.get());
  return flint::from_flint(p);
}

// f(A) by Horner, exactly.
MQ evaluate(const Polynomial<Q>& f, const MQ& A) {
  const Eigen::Index n = A.rows();
  MQ R = MQ::Identity(n, n) * f.coeff(f.degree());
  for (int k = f.degree() - 1; k >= 0; --k) {
    R = exact_product(R, A);
    R.diagonal().array() += f.coeff(k);
  }
  return R;
}
}  // namespace

Polynomial<Q> charpoly(const MQ& A) {
  // FLINT's fmpq_mat_charpoly (fraction-free over the common denominator): an order-40 matrix in
  // milliseconds, where Faddeev-LeVerrier in rationals took seconds. A large matrix with few
  // distinct eigenvalues (the hidden part of a transfer-matrix realisation: one quadratic to the
  // power 127 at order 254) goes through its minimal polynomial instead (FLINT, multimodular):
  // m = prod f_k^{e_k} over Q, the algebraic multiplicity of f_k is nullity(f_k(A)^{e_k}) / deg f_k
  // (exact rank), and det(xI - A) = prod f_k^{mult_k}. The
  // charpoly of the whole is what costs there (degree 254, coefficients of hundreds of digits).
  // The minimal polynomial only proposes the factors: the nullities below prove the product.
  const long n = static_cast<long>(A.rows());
  if (n == 0) return Polynomial<Q>(Q(1));
  if (n <= 48) return flint_charpoly(A);
  flint::QMat M(n, n);
  for (long i = 0; i < n; ++i)
    for (long j = 0; j < n; ++j) flint::set(M.at(i, j), A(i, j));
  flint::FmpqPoly mp;
  fmpq_mat_minpoly(mp.get(), M.get());
  const Polynomial<Q> m = flint::from_flint(mp);
  // A minimal polynomial of degree n would be the charpoly -- if it is right. FLINT 2.9's
  // multimodular minpoly may stop at a coefficient bound that was wrong upstream until 3.4, so it is
  // never returned as it is: proving it by nullities would take n products of n x n matrices (its
  // factors have degrees summing to n), so the charpoly is computed instead (fraction-free,
  // Hessenberg modulo primes under a proven Hadamard bound).
  if (m.degree() == n) return flint_charpoly(A);
  const std::vector<IrreducibleFactor> factors = factor_over_q(m);
  if (factors.size() > 4) return flint_charpoly(A);  // many nullities cost more than the charpoly
  // Every nullity is computed, the last one too: nullity(f_k(A)^{e_k}) <= deg f_k * (algebraic
  // multiplicity of f_k), and the f_k are distinct irreducibles, so a sum of n proves each bound
  // tight and no other eigenvalue: the product is det(xI - A) whatever the minimal polynomial's
  // computation got right. A sum short of n (the 128-device design's loop met one: a minimal
  // polynomial whose factors miss an eigenvalue) goes to the charpoly itself, never to a guess.
  Polynomial<Q> p(Q(1));
  long total = 0;
  for (const IrreducibleFactor& factor : factors) {
    const Polynomial<Q> f = factor.f.monic();
    const long d = f.degree();
    const MQ F = evaluate(f.pow(static_cast<unsigned>(factor.multiplicity)), A);
    const long nullity = n - exact_rank(F);
    if (nullity % d != 0) return flint_charpoly(A);
    total += nullity;
    p = p * f.pow(static_cast<unsigned>(nullity / d));
  }
  return total == n ? p : flint_charpoly(A);
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

using flint::from_qmat;
using flint::to_qmat;

// Columns of M (n x c) that are pivots of its reduced row echelon form: the first linearly
// independent columns, left to right (FLINT's fraction-free rref).
std::vector<long> pivot_columns(flint::QMat& M) {
  const long n = fmpq_mat_nrows(M.get()), c = fmpq_mat_ncols(M.get());
  flint::QMat R(n, c);
  const long rank = fmpq_mat_rref(R.get(), M.get());
  std::vector<long> piv;
  for (long i = 0, j = 0; i < rank; ++i) {
    while (j < c && fmpq_is_zero(R.at(i, j))) ++j;
    piv.push_back(j++);
  }
  return piv;
}

// Keeps the controllable part. The Krylov blocks B, AB, A^2 B, ... are appended until the rank
// stops growing; the independent Krylov columns K, completed by unit vectors to V = [K, E],
// give the coordinates x = V xi in which the uncontrollable part is the trailing block.
// Everything on fmpq_mat (multimodular / fraction-free): the N = 32 contact scene's 96-state
// realisation in ~0.1 s, where Gaussian elimination on Boost rationals took 20 s.
KalmanSplit split(const StateSpace<Q>& s) {
  const long n = static_cast<long>(s.states()), m = static_cast<long>(s.B.cols());
  if (n == 0) return {s, MQ(0, 0)};
  flint::QMat A = to_qmat(s.A), blk = to_qmat(s.B);
  MQ K(n, 0);
  long rank = 0;
  for (long k = 0; k < n; ++k) {
    MQ next(n, K.cols() + m);
    next << K, from_qmat(blk, n, m);
    flint::QMat nq = to_qmat(next);
    const std::vector<long> piv = pivot_columns(nq);
    MQ basis(n, static_cast<Eigen::Index>(piv.size()));
    for (size_t c = 0; c < piv.size(); ++c) basis.col(static_cast<Eigen::Index>(c)) = next.col(piv[c]);
    const bool grew = static_cast<long>(piv.size()) > rank;
    K = basis;
    rank = static_cast<long>(piv.size());
    if (!grew || rank == n) break;
    flint::QMat prod(n, m);
    fmpq_mat_mul(prod.get(), A.get(), blk.get());
    fmpq_mat_swap(prod.get(), blk.get());
  }
  if (rank == n) return {s, MQ(0, 0)};
  MQ KI(n, rank + n);
  KI << K, MQ::Identity(n, n);
  flint::QMat kiq = to_qmat(KI);
  const std::vector<long> piv = pivot_columns(kiq);  // K's columns first, then the unit vectors
  MQ V(n, n);
  for (long c = 0; c < n; ++c) V.col(c) = KI.col(piv[static_cast<size_t>(c)]);
  MQ rhs(n, n + m);
  rhs << exact_product(s.A, V), s.B;
  flint::QMat Vq = to_qmat(V), Rq = to_qmat(rhs), X(n, n + m);
  if (!fmpq_mat_solve(X.get(), Vq.get(), Rq.get())) throw NumericalError("minreal: singular change of coordinates");
  const MQ At = from_qmat(X, rank, rank), Bt = from_qmat(X, rank, m, 0, n);
  const MQ Ct = exact_product(s.C, MQ(V.leftCols(rank)));
  return {{At, Bt, Ct, s.D, s.T}, from_qmat(X, n - rank, n - rank, rank, rank)};
}

StateSpace<Q> controllable_part(const StateSpace<Q>& s) { return split(s).controllable; }

StateSpace<Q> dual(const StateSpace<Q>& s) {
  return {s.A.transpose(), s.C.transpose(), s.B.transpose(), s.D.transpose(), s.T};
}

}  // namespace

StateSpace<Q> minreal(const StateSpace<Q>& sys) {
  sys.validate("minreal");
  return dual(controllable_part(dual(controllable_part(sys))));
}

KalmanSplit controllable_split(const StateSpace<Q>& sys) {
  sys.validate("controllable_split");
  return split(sys);
}

HiddenModes hidden_modes(const StateSpace<Q>& sys) {
  sys.validate("hidden_modes");
  // the Kalman forms are block triangular: the hidden factors are the charpolys of the blocks the
  // splits remove (the uncontrollable block; the uncontrollable block of the dual of the rest)
  const KalmanSplit c = split(sys);
  const KalmanSplit o = split(dual(c.controllable));
  HiddenModes h;
  h.minimal = dual(o.controllable);
  h.uncontrollable = PolynomialProduct(charpoly(c.uncontrollable_A).monic());
  h.unobservable = PolynomialProduct(charpoly(o.uncontrollable_A).monic());
  return h;
}

bool hidden_marginal_semisimple(const StateSpace<Q>& sys) {
  sys.validate("hidden_marginal_semisimple");
  const Q at = sys.is_discrete() ? Q(1) : Q(0);
  // the uncontrollable quotient (the trailing block of the controllability split) and the unobservable
  // restriction (the same block of the dual's split, transposed: semisimplicity does not see a transpose)
  return semisimple_eigenvalue(split(sys).uncontrollable_A, at) && semisimple_eigenvalue(split(dual(sys)).uncontrollable_A, at);
}

bool semisimple_eigenvalue(const MQ& A, const Q& lambda) {
  Polynomial<Q> p = charpoly(A);
  const Polynomial<Q> lin(std::vector<Q>{-lambda, Q(1)});
  long alg = 0;
  while (p.degree() > 0 && p(lambda) == 0) {
    p = divmod(p, lin).first;
    ++alg;
  }
  if (alg == 0) return true;
  const MQ shifted = A - MQ::Identity(A.rows(), A.cols()) * lambda;
  return A.rows() - exact_rank(shifted) == alg;
}

void PolynomialProduct::multiply(const Polynomial<Q>& p, int power) {
  if (p.degree() < 1 || power < 1) return;
  for (auto& [f, k] : factors)
    if (f == p) {
      k += power;
      return;
    }
  factors.emplace_back(p, power);
}

void PolynomialProduct::multiply(const PolynomialProduct& q, int power) {
  for (const auto& [f, k] : q.factors) multiply(f, k * power);
}

int PolynomialProduct::degree() const {
  int d = 0;
  for (const auto& [f, k] : factors) d += f.degree() * k;
  return d;
}

bool PolynomialProduct::vanishes_at(const Q& x) const {
  for (const auto& [f, k] : factors)
    if (f(x) == 0) return true;
  return false;
}

Polynomial<Q> PolynomialProduct::expanded() const {
  Polynomial<Q> p(Q(1));
  for (const auto& [f, k] : factors)
    for (int i = 0; i < k; ++i) p = p * f;
  return p;
}

}  // namespace hapstab
