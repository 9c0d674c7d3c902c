// bench/exact_core_before.hpp -- the exact-core implementations from BEFORE issue 15 (pure
// Boost.Multiprecision/GMP rationals and integers), kept only as the "before" baseline of
// bench/exact_core.cpp. Each is the previous library code from git history, unchanged except
// for its namespace and names; the library no longer uses any of them:
//   euclid_gcd, square_free_part   git show b2ea151^:toolbox/hapstab/poly/polynomial.hpp
//                                  (schoolbook division, monic Euclid; the modular coprimality
//                                  filter is left out: the inputs here have a common factor)
//   charpoly (Faddeev-LeVerrier)   git show 93c1d8d^:toolbox/hapstab/lti/realization.cpp
//   minreal (Gaussian elimination) git show 30af325^:toolbox/hapstab/lti/realization.cpp
//   Sturm count, Descartes         git show 93fa5fb:toolbox/hapstab/poly/sturm.cpp
//                                  (square-free part there was already FLINT's gcd)
// Rational LDL^T (lmi::exact_definiteness) and the 50-digit Taylor exponential (lti::expm) are
// still library functions and are called from there.
#pragma once

#include <Eigen/LU>
#include <utility>
#include <vector>

#include "hapstab/lti/state_space.hpp"
#include "hapstab/numeric/eigen_traits.hpp"
#include "hapstab/poly/sturm.hpp"

namespace before {

using hapstab::integer;
using hapstab::MatQ;
using hapstab::Polynomial;
using hapstab::rational;
using hapstab::RootInterval;
using hapstab::StateSpace;

// ---- gcd over Q: schoolbook division and monic Euclid --------------------------------------
inline std::pair<Polynomial<rational>, Polynomial<rational>> divmod(const Polynomial<rational>& a,
                                                                    const Polynomial<rational>& b) {
  const int db = b.degree();
  if (a.degree() < db) return {Polynomial<rational>(), a};
  std::vector<rational> r = a.coeffs();
  std::vector<rational> q(static_cast<size_t>(a.degree() - db) + 1, rational(0));
  const rational& lb = b.leading();
  const auto& bc = b.coeffs();
  for (int k = a.degree() - db; k >= 0; --k) {
    rational f = r[k + db] / lb;
    if (f != 0)
      for (int i = 0; i <= db; ++i) r[k + i] -= f * bc[i];
    r[k + db] = 0;
    q[k] = std::move(f);
  }
  r.resize(static_cast<size_t>(db));
  return {Polynomial<rational>(std::move(q)), Polynomial<rational>(std::move(r))};
}

inline Polynomial<rational> gcd(Polynomial<rational> a, Polynomial<rational> b) {
  a = a.monic();
  b = b.monic();
  while (!b.is_zero()) {
    Polynomial<rational> r = divmod(a, b).second.monic();
    a = std::move(b);
    b = std::move(r);
  }
  return a;
}

inline Polynomial<rational> square_free_part(const Polynomial<rational>& p) {
  if (p.degree() <= 0) return p.monic();
  return divmod(p, gcd(p, p.derivative())).first.monic();
}

// ---- characteristic polynomial: Faddeev-LeVerrier in rationals ------------------------------
inline Polynomial<rational> charpoly(const MatQ& A) {
  const auto n = A.rows();
  std::vector<rational> c(static_cast<size_t>(n) + 1);
  c[static_cast<size_t>(n)] = 1;
  MatQ M = MatQ::Zero(n, n);
  const MatQ I = MatQ::Identity(n, n);
  for (Eigen::Index k = 1; k <= n; ++k) {
    M = A * M + c[static_cast<size_t>(n - k + 1)] * I;
    c[static_cast<size_t>(n - k)] = -(A * M).trace() / rational(k);
  }
  return Polynomial<rational>(c);
}

// ---- minimal realisation: Kalman decompositions by Gaussian elimination over Q --------------
inline MatQ column_basis(const MatQ& M) {
  MatQ R = M.transpose();
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

inline StateSpace<rational> controllable_part(const StateSpace<rational>& s) {
  const auto n = s.states();
  if (n == 0) return s;
  MatQ K(n, 0);
  MatQ blk = s.B;
  for (Eigen::Index k = 0; k < n; ++k) {
    MatQ next(n, K.cols() + blk.cols());
    next << K, blk;
    K = column_basis(next);
    blk = s.A * blk;
  }
  const auto r = K.cols();
  if (r == n) return s;
  MatQ V = K;
  for (Eigen::Index i = 0; i < n && V.cols() < n; ++i) {
    MatQ cand(n, V.cols() + 1);
    cand << V, MatQ::Identity(n, n).col(i);
    if (column_basis(cand).cols() > V.cols()) V = cand;
  }
  Eigen::FullPivLU<MatQ> lu(V);
  MatQ Vi = lu.inverse();
  MatQ At = Vi * s.A * V, Bt = Vi * s.B, Ct = s.C * V;
  return {At.topLeftCorner(r, r), Bt.topRows(r), Ct.leftCols(r), s.D, s.T};
}

inline StateSpace<rational> dual(const StateSpace<rational>& s) {
  return {s.A.transpose(), s.C.transpose(), s.B.transpose(), s.D.transpose(), s.T};
}

inline StateSpace<rational> minreal(const StateSpace<rational>& sys) {
  return dual(controllable_part(dual(controllable_part(sys))));
}

// ---- Sturm counting and Descartes isolation on Boost integers/rationals ---------------------
inline Polynomial<rational> positive_normalise(const Polynomial<rational>& p) {
  if (p.is_zero()) return p;
  integer L = 1, G = 0;
  for (const auto& c : p.coeffs()) L = boost::multiprecision::lcm(L, hapstab::den(c));
  for (const auto& c : p.coeffs()) G = boost::multiprecision::gcd(G, hapstab::num(c) * (L / hapstab::den(c)));
  return p * rational(L, G);
}

inline int sign_at(const Polynomial<rational>& p, const rational& x) {
  const auto& c = p.coeffs();
  for (const auto& ci : c)
    if (hapstab::den(ci) != 1) return hapstab::sgn(p(x));
  const integer a = hapstab::num(x), b = hapstab::den(x);
  integer h = hapstab::num(c.back()), bp = 1;
  for (int i = static_cast<int>(c.size()) - 2; i >= 0; --i) {
    bp *= b;
    h = h * a + hapstab::num(c[static_cast<size_t>(i)]) * bp;
  }
  return h > 0 ? 1 : (h < 0 ? -1 : 0);
}

inline Polynomial<rational> negated_pseudo_remainder(const Polynomial<rational>& a, const Polynomial<rational>& b) {
  std::vector<integer> r, B;
  for (const auto& c : a.coeffs()) r.push_back(hapstab::num(c));
  for (const auto& c : b.coeffs()) B.push_back(hapstab::num(c));
  const integer absL = abs(B.back());
  const bool neg = B.back() < 0;
  while (!r.empty() && r.size() >= B.size()) {
    const integer c = neg ? integer(-r.back()) : r.back();
    const size_t k = r.size() - B.size();
    for (auto& x : r) x *= absL;
    for (size_t i = 0; i + 1 < B.size(); ++i) r[k + i] -= c * B[i];
    r.pop_back();
    while (!r.empty() && r.back() == 0) r.pop_back();
  }
  std::vector<rational> out;
  for (auto& x : r) out.emplace_back(-x);
  return positive_normalise(Polynomial<rational>(std::move(out)));
}

inline std::vector<Polynomial<rational>> sturm_sequence(const Polynomial<rational>& p) {
  std::vector<Polynomial<rational>> s;
  s.push_back(positive_normalise(hapstab::square_free_part(p)));
  if (s[0].degree() <= 0) return s;
  s.push_back(positive_normalise(s[0].derivative()));
  for (;;) {
    Polynomial<rational> r = negated_pseudo_remainder(s[s.size() - 2], s.back());
    if (r.is_zero()) break;
    s.push_back(std::move(r));
  }
  return s;
}

inline int sign_variations(const std::vector<Polynomial<rational>>& seq, const rational& x) {
  int v = 0, last = 0;
  for (const auto& p : seq) {
    int s = sign_at(p, x);
    if (s == 0) continue;
    if (last != 0 && s != last) ++v;
    last = s;
  }
  return v;
}

inline int count_real_roots(const Polynomial<rational>& p, const rational& a, const rational& b) {
  if (a >= b) return 0;
  auto s = before::sturm_sequence(p);
  return before::sign_variations(s, a) - before::sign_variations(s, b);
}

using Z = std::vector<integer>;

inline void taylor_shift_1(Z& c) {
  const size_t n = c.size();
  for (size_t i = 0; i + 1 < n; ++i)
    for (size_t j = n - 1; j-- > i;) c[j] += c[j + 1];
}

inline int descartes_var(const Z& c) {
  Z r(c.rbegin(), c.rend());
  taylor_shift_1(r);
  int v = 0, last = 0;
  for (const auto& x : r) {
    const int s = x > 0 ? 1 : (x < 0 ? -1 : 0);
    if (s == 0) continue;
    if (last != 0 && s != last && ++v >= 2) return v;
    last = s;
  }
  return v;
}

inline Z to_unit_interval(const Polynomial<rational>& q, const rational& lo, const rational& hi) {
  std::vector<rational> c = q.coeffs();
  const size_t n = c.size();
  for (size_t i = 0; i + 1 < n; ++i)
    for (size_t j = n - 1; j-- > i;) c[j] += lo * c[j + 1];
  rational w = 1;
  for (size_t k = 1; k < n; ++k) c[k] *= (w *= hi - lo);
  const Polynomial<rational> moved = positive_normalise(Polynomial<rational>(std::move(c)));
  Z out;
  for (const auto& x : moved.coeffs()) out.push_back(hapstab::num(x));
  return out;
}

struct Descartes {
  rational lo, width;
  std::vector<RootInterval>* out;
  rational at(const integer& k, unsigned depth) const { return lo + width * rational(k, integer(1) << depth); }
  void run(Z c, const integer& k, unsigned depth) const {
    const int v = descartes_var(c);
    if (v == 0) return;
    if (v == 1) {
      out->push_back({at(k, depth), at(k + 1, depth)});
      return;
    }
    const size_t n = c.size() - 1;
    for (size_t i = 0; i <= n; ++i) c[i] <<= static_cast<unsigned>(n - i);
    Z right = c;
    taylor_shift_1(right);
    const bool mid_root = right[0] == 0;
    run(std::move(c), 2 * k, depth + 1);
    if (mid_root) {
      out->push_back({at(2 * k + 1, depth + 1), at(2 * k + 1, depth + 1)});
      right.erase(right.begin());
    }
    run(std::move(right), 2 * k + 1, depth + 1);
  }
};

inline std::vector<RootInterval> isolate_real_roots(const Polynomial<rational>& p, const rational& a, const rational& b) {
  std::vector<RootInterval> out;
  const Polynomial<rational> q = positive_normalise(hapstab::square_free_part(p));
  if (q.degree() <= 0) return out;
  const bool root_a = sign_at(q, a) == 0, root_b = sign_at(q, b) == 0;
  if (a == b) {
    if (root_a) out.push_back({a, a});
    return out;
  }
  if (root_a) out.push_back({a, a});
  Descartes{a, b - a, &out}.run(to_unit_interval(q, a, b), integer(0), 0);
  if (root_b) out.push_back({b, b});
  for (auto& r : out) {
    if (r.is_exact()) continue;
    if (sign_at(q, r.lo) == 0)
      for (rational d = (r.hi - r.lo) / 2;; d /= 2)
        if (sign_at(q, r.lo + d) != 0 && descartes_var(to_unit_interval(q, r.lo, r.lo + d)) == 0) {
          r.lo += d;
          break;
        }
    if (sign_at(q, r.hi) == 0)
      for (rational d = (r.hi - r.lo) / 2;; d /= 2)
        if (sign_at(q, r.hi - d) != 0 && descartes_var(to_unit_interval(q, r.hi - d, r.hi)) == 0) {
          r.hi -= d;
          break;
        }
  }
  return out;
}

}  // namespace before
