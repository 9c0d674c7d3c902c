// c2d and expm (see discretize.hpp). Explicit instantiations for double, mp50, mp100
// (and rational for tustin / backward Euler).
#include "hapstab/lti/discretize.hpp"

#include <Eigen/LU>
#include <cmath>
#include <limits>

namespace hapstab {

namespace {

template <class S>
S inf_norm(const Mat<S>& A) {
  S best = 0;
  for (Eigen::Index i = 0; i < A.rows(); ++i) {
    S row = 0;
    for (Eigen::Index j = 0; j < A.cols(); ++j) {
      using std::abs;
      row += abs(A(i, j));
    }
    if (row > best) best = row;
  }
  return best;
}

template <class S>
bool is_finite_matrix(const Mat<S>& M) {
  for (Eigen::Index i = 0; i < M.size(); ++i) {
    using std::isfinite;
    using boost::multiprecision::isfinite;
    if (!isfinite(M.data()[i])) return false;
  }
  return true;
}

}  // namespace

C2dMethod parse_c2d_method(const std::string& name, const std::string& what) {
  if (name == "zoh") return C2dMethod::zoh;
  if (name == "tustin" || name == "bilinear") return C2dMethod::tustin;
  if (name == "backward_euler" || name == "euler" || name == "bd") return C2dMethod::backward_euler;
  throw InputError(what + ": unknown discretisation '" + name + "' (expected zoh, tustin or backward_euler)");
}

template <class S>
Mat<S> expm(const Mat<S>& A) {
  if (A.rows() != A.cols()) throw InputError("expm: matrix must be square");
  const Eigen::Index n = A.rows();
  if (n == 0) return A;
  if (!is_finite_matrix(A)) throw NumericalError("expm: matrix has a non-finite entry");
  const S eps = std::numeric_limits<S>::epsilon();
  // Scale X = A / 2^s with ||X||_inf <= 1/2.
  S nrm = inf_norm(A);
  int s = 0;
  while (nrm > S(0.5)) {
    nrm /= 2;
    ++s;
  }
  Mat<S> X = A;
  if (s > 0) {
    S scale = 1;
    for (int i = 0; i < s; ++i) scale /= 2;  // exact power of two
    X *= scale;
  }
  // Taylor: E = sum_k X^k / k!. With ||X|| <= 1/2 the tail after term k is bounded by
  // 2 ||X||^{k+1}/(k+1)!; stop when that bound falls below eps/8 (relative to ||E|| >= 1/2).
  Mat<S> E = Mat<S>::Identity(n, n);
  Mat<S> term = Mat<S>::Identity(n, n);
  S bound = 1;  // ||X||^k / k!
  for (int k = 1; k < 400; ++k) {
    term = (term * X) / S(k);
    E += term;
    bound = bound * nrm / S(k);
    if (S(2) * bound * nrm / S(k + 1) <= eps / 8) break;
  }
  for (int i = 0; i < s; ++i) E = (E * E).eval();
  if (!is_finite_matrix(E)) throw NumericalError("expm: overflow (||A|| too large for the scalar type)");
  return E;
}

template <class S>
ZohPair<S> zoh_pair(const Mat<S>& A, const Mat<S>& B, const S& t) {
  const Eigen::Index n = A.rows(), m = B.cols();
  if (A.cols() != n || B.rows() != n) throw InputError("zoh_pair: A must be square and B must have A's rows");
  if (t < 0) throw InputError("zoh_pair: negative time step");
  Mat<S> M = Mat<S>::Zero(n + m, n + m);
  M.topLeftCorner(n, n) = A * t;
  M.topRightCorner(n, m) = B * t;
  Mat<S> E = expm<S>(M);
  return {E.topLeftCorner(n, n), E.topRightCorner(n, m)};
}

template <class S>
StateSpace<S> c2d(const StateSpace<S>& sys, const rational& T, C2dMethod method) {
  sys.validate("c2d");
  if (sys.is_discrete()) throw InputError("c2d: the system is already discrete (T = " + T.str() + ")");
  if (T <= 0) throw InputError("c2d: sample period T must be > 0, got " + T.str());
  const Eigen::Index n = sys.states();
  StateSpace<S> d;
  d.T = T;
  const S Ts = to_real<S>(T);
  if (method == C2dMethod::zoh) {
    if constexpr (std::is_same_v<S, rational>) {
      throw InputError("c2d: zoh needs e^{AT}, which is not rational; use double or mpfloat");
    } else {
      auto p = zoh_pair<S>(sys.A, sys.B, Ts);
      d.A = p.Phi;
      d.B = p.Gamma;
      d.C = sys.C;
      d.D = sys.D;
      return d;
    }
  }
  // Generalised bilinear transform (alpha = 1/2 Tustin, alpha = 1 backward Euler):
  //   Ad = (I - a T A)^{-1}(I + (1-a) T A), Bd = (I - a T A)^{-1} T B,
  //   Cd = C (I - a T A)^{-1},             Dd = D + a C Bd.
  // Its transfer function is G(s) at s = (z-1)/(T(a z + 1 - a)).
  const S a = method == C2dMethod::tustin ? S(1) / S(2) : S(1);
  const Mat<S> I = Mat<S>::Identity(n, n);
  const Mat<S> M = I - a * Ts * sys.A;
  Eigen::FullPivLU<Mat<S>> lu(M);
  bool singular = false;
  if constexpr (std::is_same_v<S, rational>) singular = lu.rank() < n;
  else singular = !(lu.rank() == n) || !is_finite_matrix<S>(lu.inverse());
  if (singular)
    throw InputError(std::string("c2d: ") + (method == C2dMethod::tustin ? "tustin" : "backward_euler") +
                     " is singular: A has an eigenvalue at s = " + (method == C2dMethod::tustin ? "2/T" : "1/T"));
  const Mat<S> Minv = lu.inverse();
  d.A = Minv * (I + (S(1) - a) * Ts * sys.A);
  d.B = Minv * (Ts * sys.B);
  d.C = sys.C * Minv;
  d.D = sys.D + a * sys.C * d.B;
  return d;
}

#define HAPSTAB_DISCRETIZE_REAL(S)                                         \
  template Mat<S> expm<S>(const Mat<S>&);                                  \
  template ZohPair<S> zoh_pair<S>(const Mat<S>&, const Mat<S>&, const S&); \
  template StateSpace<S> c2d<S>(const StateSpace<S>&, const rational&, C2dMethod);

HAPSTAB_DISCRETIZE_REAL(double)
HAPSTAB_DISCRETIZE_REAL(mp50)
HAPSTAB_DISCRETIZE_REAL(mp100)
template StateSpace<rational> c2d<rational>(const StateSpace<rational>&, const rational&, C2dMethod);

}  // namespace hapstab
