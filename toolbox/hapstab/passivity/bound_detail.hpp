// hapstab/passivity/bound_detail.hpp -- internal to the passivity bound (45), (54): what its
// implementation files share. Not part of the public API (bound.hpp is).
//
//   objective.cpp         the c = cos(wT) form of the objective, exact (objective) and in
//                         double-double (FastBound) from ONE template, c_form<C> below; the
//                         objective evaluated on the unit circle (grid, objective_at)
//   certified.cpp         certified maximisation of the rational objective f(c) (bound_certified)
//   fractional_delay.cpp  t_d not a multiple of T (54): exact when t_d/T = p/q with small q
//   max_gain.cpp          the largest K with b*(H0 + K H1) < b (max_gain.hpp), on the same maximiser
//   long_delay.cpp        any delay nu = n + t_d/T without expanding z^-n: ball branch-and-bound
//                         over w (certified) and its double-precision twin (fast)
//   fast.cpp              the double-double fast path (FastBound)
//   grid.cpp              the comparison grid (bound_grid)
//   bound.cpp             assumptions, the planner (exact or long-delay path), the dispatcher
//                         bound(), the necessary condition (14), (15)
#pragma once

#include <algorithm>
#include <array>
#include <optional>
#include <string>
#include <vector>

#include "hapstab/numeric/ball.hpp"
#include "hapstab/numeric/dinterval.hpp"
#include "hapstab/numeric/scalar.hpp"
#include "hapstab/passivity/bound.hpp"

namespace hapstab::passivity::detail {

// ---- the c-form of the objective, for any coefficient type ---------------------------------
// With W = N/D' (D' = D z^n) and c = cos(wT) (see bound.hpp):
//   N conj(D') = sum_m (a_m cos m wT + j cs_m sin m wT),  |D'|^2 = sum_m e_m cos m wT,
//   R = sum a_m T_m(c),  Q = sum cs_m U_{m-1}(c),  B = sum e_m T_m(c),  A = R - (1 + c) Q,
// so that the objective without delay is f(c) = (T/2) A(c)/B(c).

/// Monomial coefficients (ascending) of the Chebyshev polynomials T_0..T_M and U_0..U_M, by the
/// recurrence X_{m+1} = 2c X_m - X_{m-1}. Integers (exact in double for M < 50).
template <class C>
struct ChebyshevTables {
  std::vector<std::vector<C>> T, U;
};
template <class C>
ChebyshevTables<C> chebyshev_tables(int M) {
  ChebyshevTables<C> t;
  t.T = {{C(1)}};
  t.U = {{C(1)}};
  if (M >= 1) {
    t.T.push_back({C(0), C(1)});
    t.U.push_back({C(0), C(2)});
  }
  for (int m = 2; m <= M; ++m) {
    for (auto* tab : {&t.T, &t.U}) {
      const auto& a = (*tab)[m - 1];
      const auto& b = (*tab)[m - 2];
      std::vector<C> c(static_cast<size_t>(m) + 1, C(0));
      for (size_t i = 0; i < a.size(); ++i) c[i + 1] += 2 * a[i];
      for (size_t i = 0; i < b.size(); ++i) c[i] -= b[i];
      tab->push_back(std::move(c));
    }
  }
  return t;
}

/// The pieces R, Q, B and A = R - (1 + c) Q in monomials of c, for coefficients C (integer
/// for the exact objective, dd for the fast path), with a Chebyshev table of entries Basis.
template <class C>
struct CForm {
  std::vector<C> R, Q, B, A;
};

/// N (ascending, numerator of W) and Dn (ascending, D z^n). `is_zero(x)` skips a vanishing
/// Chebyshev coefficient; `to_coeff(b)` turns a table entry into a coefficient. The sums run in
/// the same order for every C (the fast path's double-double rounding depends on it).
template <class C, class Basis, class IsZero, class ToCoeff>
CForm<C> c_form(const std::vector<C>& N, const std::vector<C>& Dn, const ChebyshevTables<Basis>& ct, IsZero is_zero,
                ToCoeff to_coeff) {
  const int nn = static_cast<int>(N.size()), nd = static_cast<int>(Dn.size());
  const int M = std::max(nn, nd);
  std::vector<C> a(M + 1, C{}), cs(M + 1, C{}), e(M + 1, C{});
  for (int k = 0; k < nn; ++k)
    for (int l = 0; l < nd; ++l) {
      const C pr = N[k] * Dn[l];
      const int m = k - l;
      if (m == 0) a[0] = a[0] + pr;
      else if (m > 0) { a[m] = a[m] + pr; cs[m] = cs[m] + pr; }
      else { a[-m] = a[-m] + pr; cs[-m] = cs[-m] - pr; }
    }
  for (int l = 0; l < nd; ++l)
    for (int l2 = l; l2 < nd; ++l2) {
      const C pr = Dn[l] * Dn[l2];
      if (l2 == l) e[0] = e[0] + pr;
      else e[l2 - l] = e[l2 - l] + pr + pr;
    }
  // Chebyshev -> monomial
  auto add_cheb = [&](std::vector<C>& acc, const std::vector<Basis>& basis, const C& coef) {
    if (is_zero(coef)) return;
    if (acc.size() < basis.size()) acc.resize(basis.size(), C{});
    for (size_t i = 0; i < basis.size(); ++i)
      if (basis[i] != 0) acc[i] = acc[i] + coef * to_coeff(basis[i]);
  };
  CForm<C> f;
  for (int m = 0; m <= M; ++m) {
    add_cheb(f.R, ct.T[m], a[m]);
    if (m >= 1) add_cheb(f.Q, ct.U[m - 1], cs[m]);
    add_cheb(f.B, ct.T[m], e[m]);
  }
  // A = R - (1 + c) Q
  f.A.assign(std::max(f.R.size(), f.Q.size() + 1), C{});
  for (size_t i = 0; i < f.R.size(); ++i) f.A[i] = f.A[i] + f.R[i];
  for (size_t i = 0; i < f.Q.size(); ++i) {
    f.A[i] = f.A[i] - f.Q[i];
    f.A[i + 1] = f.A[i + 1] - f.Q[i];
  }
  return f;
}

// ---- shared by the methods -------------------------------------------------------------------

/// An uncancelled pole of H at z = 1: b* = +inf (see certified.cpp); nullopt otherwise.
std::optional<Bound> integrator_pole(const BoundProblem& p);

/// Best decimal for an enclosure: the common rounding at `digits` digits, else fewer digits.
std::string enclosure_decimal(const rational& lo, const rational& hi, int digits);

/// The objective at theta = wT > 0 evaluated on the unit circle in the scalar R (double, mp50),
/// with the problem's numbers converted to R once (a grid evaluates it many times).
template <class R>
struct CircleObjective {
  std::vector<R> num, den;  ///< H's coefficients, ascending
  R T, eta, lag, frac;      ///< lag = n, frac = t_d/T (samples)
  bool has_frac = false;
  explicit CircleObjective(const BoundProblem& p);
  R operator()(const R& th) const;
};
template <class R>
R objective_on_circle(const BoundProblem& p, const R& th) {
  return CircleObjective<R>(p)(th);
}
/// The limit of the objective at theta = 0 (exact c-form value at c = 1, with t_d's term).
double objective_at_zero(const BoundProblem& p);

/// The domain of the maximisation in certified_rational: c in [c_end, 1], where c = cos(wT/q) and
/// c_end = cos(pi/q) is the image of w = pi/T. q = 1 (c = cos wT, c_end = -1) without a fractional
/// delay; q > 1 for t_d = (p/q) T (certified_frac_exact). [end_lo, end_hi] are rational bounds of
/// c_end, equal when c_end is rational (q = 1, 2, 3).
struct Domain {
  rational end_lo = -1, end_hi = -1;
  int q = 1;
  bool end_exact() const { return end_lo == end_hi; }
};

/// Certified maximum of the rational f(c) over the domain at working precision D (50, 100, 300);
/// false when D was not enough for `digits` digits (certified.cpp).
template <unsigned D>
bool certified_rational(const RationalFunction<rational>& f, const BoundProblem& pb, int digits, Bound& out,
                        const Domain& dom = {});

/// The exact path of bound_certified for q = with_integer_delay(p) (certified.cpp).
Bound certified_exact(const BoundProblem& q, int digits);

/// t_d = (p/q) T (q >= 2) as an integer-delay problem in w = e^{j wT/q}: `problem` (H(w^q)/(1 + w + ...
/// + w^{q-1}), delay nq + p, no t_d) maximised over `domain` gives b* exactly as t_d does
/// (fractional_delay.cpp; max_gain.cpp uses it too). nullopt without t_d, for q = 1, or when the
/// degree q (order + n) + p + q exceeds max_degree. The end cos(pi/q) is enclosed at working precision D.
struct FracExact {
  BoundProblem problem;
  Domain domain;
};
template <unsigned D>
std::optional<FracExact> frac_exact_problem(const BoundProblem& pb, int max_degree);

/// bound_certified for a fractional delay t_d by the exact path (fractional_delay.cpp): t_d/T = p/q
/// made exact in cos(wT/q); false when that objective's degree exceeds `max_degree`.
bool certified_fractional_exact(const BoundProblem& pb, int digits, int max_degree, Bound& out);
/// b* = +inf when a pole of H at z = -1 meets a fractional delay (exact divergence test at wT = pi);
/// nullopt otherwise (the objective is then finite there, or its behaviour undecided by the test).
std::optional<Bound> fractional_divergence(const BoundProblem& pb);
/// A simple pole z0 = e^{j theta0} of H inside the band (0 < theta0 < pi) at which the objective tends to
/// +inf (circle_pole.cpp): cos(theta0) is the root of q (exact; z^-m C(z) = q(cos theta) for H's
/// palindromic factor C on the circle) in [c_lo, c_hi], and f = Im(c)/(theta - theta0) + O(1) there with
/// Im(c) of the sign `side` (+1: +inf from above), shown in balls. nullopt when no such pole is shown.
struct CirclePole {
  QPoly q;
  rational c_lo, c_hi, theta_lo, theta_hi;
  int side = 0;
};
std::optional<CirclePole> circle_pole(const BoundProblem& p);
/// b* = +inf [certified] from circle_pole, at any delay; nullopt when it shows none.
std::optional<Bound> circle_pole_divergence(const BoundProblem& p);
/// The degree of that objective, q (max(deg N, deg D) + n) + p + q (0 without a fractional delay).
long fractional_exact_degree(const BoundProblem& pb);

/// The exact path's degree limit for a fractional delay: 96 where the long-delay path applies (it is
/// cheaper beyond), 240 where it does not -- a pole of H on the unit circle other than a simple one
/// at z = -1 -- and the exact path is the only one (fractional_delay.cpp says why 240).
long fractional_exact_limit(const BoundProblem& pb);

/// Exact divergence test at wT = pi for a pole of W at z = -1 with e^{-j tau wT} (o: the
/// objective of H z^-n without tau). +1: f -> +inf, -1: -> -inf, 0: finite or undecided
/// (`decided` says which).
int divergence_at_pi(const Objective& o, const rational& T, const rational& tau, bool& decided);

// ---- the long-delay path (long_delay.cpp) ----------------------------------------------------
/// The objective of (45)/(54) for the delay nu = n + t_d/T (samples) as low-order exact pieces:
///   f(theta) = (T/2)[(A/B + rho) cos(nu theta) + (E/B + rho/2) S_nu(theta) - (rho/2) sin(nu theta) tan(theta/2)] + eta,
/// S_nu(theta) = sin(nu theta) cot(theta/2) (numeric/jet.hpp), A = R - (1+c)Q, E = R + (1-c)Q, B
/// the c-form of H~ = H - rho/(z + 1) without delay, rho = the residue of H at a simple pole z = -1.
struct DelayForm {
  QPoly A, E, B;
  rational rho = 0, nu = 0, T = 0, eta = 0;
  long n = 0;                     ///< nu when it is a whole number
  bool integer_nu = true;
  rational at_zero;               ///< f(0), exact
  std::optional<rational> at_pi;  ///< f(pi), exact for an integer delay
  bool constant = false;          ///< f = eta everywhere (H = 0)
};
/// nullopt (and why) when the long-delay path does not apply: a pole of H on the unit circle other
/// than a simple one at z = -1, or that pole met by a fractional delay that sends f to +inf at pi
/// (b* = +inf, fractional_divergence; the -inf sign is taken, long_delay.cpp's tail).
std::optional<DelayForm> delay_form(const BoundProblem& p, std::string* why);
/// delay_form's test alone, without its exact pieces (the planner's question, plan_bound: a gcd
/// instead of the objective): nullopt (and why) exactly when delay_form's is; else H's simple
/// pole at z = -1, if any, and its residue rho.
struct LongDelayPole {
  bool at_minus_one = false;
  rational rho = 0;
};
std::optional<LongDelayPole> long_delay_applies(const BoundProblem& p, std::string* why);
/// The certified long-delay path (the problem's assumptions already checked); its double twin is
/// fast_long_delay (bound.hpp). double_pruning: boxes are first tried in double intervals with
/// rounding bounds (numeric/dinterval.hpp) and only those they cannot prune go to Arb; false: Arb
/// for every box (the path before issue 48, kept for the benchmark's comparison and the tests).
/// budget > 0: at most that many Arb evaluations, one attempt, NumericalError when b* is not settled
/// within it (the caller has the exact path behind; bound.cpp).
Bound certified_long_delay(const BoundProblem& p, int digits, bool double_pruning = true, long budget = 0);
/// The long-delay objective's f, f', f'' as the branch-and-bound evaluates them, for the tests:
/// in double intervals at theta = pi k/D, or over [pi (k - 1)/D, pi (k + 1)/D] when box (nullopt
/// when the integers exceed 128 bits), and in Arb balls at theta (every point of the ball).
std::optional<std::array<Dint, 3>> delay_objective_double(const DelayForm& f, __int128 k, __int128 D, bool box);
std::array<flint::Ball, 3> delay_objective_ball(const DelayForm& f, const flint::Ball& theta);

}  // namespace hapstab::passivity::detail
