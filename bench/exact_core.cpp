// The exact core before and after FLINT/Arb (issue 15), on the same inputs in the same run
// (plots/exact_core_speedup.gp via bench/chart-exact-core). Each benchmark runs the previous
// pure Boost/GMP implementation (bench/exact_core_before.hpp, or the library function that
// still is that implementation) and the current one alternately, on the same input, and
// reports as counters
//   before_us, after_us   thread CPU time per call (the machines are shared),
//   speedup               before_us / after_us,
//   same                  1 when both gave the same answer (compared once, outside the timing).
// Inputs are deterministic (fixed seed): small rationals p/q, |p| <= 9, 1 <= q <= 9.
#include <benchmark/benchmark.h>

#include "exact_core_before.hpp"
#include "keep.hpp"

#include <ctime>
#include <random>

#include "hapstab/lmi/certificate.hpp"
#include "hapstab/lti/discretize.hpp"
#include "hapstab/lti/realization.hpp"
#include "hapstab/multidof/environment.hpp"
#include "hapstab/numeric/ball_expm.hpp"
#include "hapstab/numeric/lyapunov.hpp"
#include "hapstab/poly/stability.hpp"
#include "hapstab/poly/sturm.hpp"

using namespace hapstab;

namespace {

double thread_seconds() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

// Times before() and after() alternately; `same` is the agreement of their answers.
template <class Before, class After>
void compare(benchmark::State& st, Before before, After after, bool same) {
  double tb = 0, ta = 0;
  for (auto _ : st) {
    const double t0 = thread_seconds();
    auto b = before();
    const double t1 = thread_seconds();
    auto a = after();
    const double t2 = thread_seconds();
    keep(b);
    keep(a);
    tb += t1 - t0;
    ta += t2 - t1;
    st.SetIterationTime(t2 - t0);
  }
  const double n = static_cast<double>(st.iterations());
  st.counters["before_us"] = 1e6 * tb / n;
  st.counters["after_us"] = 1e6 * ta / n;
  st.counters["speedup"] = tb / ta;
  st.counters["same"] = same ? 1 : 0;
}

std::mt19937& rng() {
  static std::mt19937 g(15);
  return g;
}
rational small_rational() {
  std::uniform_int_distribution<int> p(-9, 9), q(1, 9);
  return rational(p(rng()), q(rng()));
}
QPoly random_poly(int degree) {
  std::vector<rational> c;
  for (int i = 0; i < degree; ++i) c.push_back(small_rational());
  rational lead = small_rational();
  c.push_back(lead == 0 ? rational(1) : lead);
  return QPoly(c);
}
MatQ random_matrix(int n) {
  MatQ A(n, n);
  for (Eigen::Index i = 0; i < A.size(); ++i) A.data()[i] = small_rational();
  return A;
}

// ---- gcd over Q with a common factor of half the degree ------------------------------------
void BM_gcd(benchmark::State& st) {
  const int d = static_cast<int>(st.range(0));
  rng().seed(15 + d);
  const QPoly g = random_poly(d / 2), a = g * random_poly(d - d / 2), b = g * random_poly(d - d / 2 - 1);
  const bool same = before::gcd(a, b) == gcd(a, b);
  compare(st, [&] { return before::gcd(a, b); }, [&] { return gcd(a, b); }, same);
  st.SetLabel("Euclid in mpq | fmpq_poly_gcd");
}
BENCHMARK(BM_gcd)->Arg(6)->Arg(13)->Arg(26)->UseManualTime()->Name("gcd");

// ---- square-free part of f^2 h -------------------------------------------------------------
void BM_square_free(benchmark::State& st) {
  const int d = static_cast<int>(st.range(0));
  rng().seed(115 + d);
  const QPoly f = random_poly(d / 3), p = f * f * random_poly(d - 2 * (d / 3));
  const bool same = before::square_free_part(p) == square_free_part(p);
  compare(st, [&] { return before::square_free_part(p); }, [&] { return square_free_part(p); }, same);
  st.SetLabel("Euclid in mpq | fmpq_poly");
}
BENCHMARK(BM_square_free)->Arg(6)->Arg(13)->Arg(26)->UseManualTime()->Name("square_free");

// ---- characteristic polynomial -------------------------------------------------------------
void BM_charpoly(benchmark::State& st) {
  const int n = static_cast<int>(st.range(0));
  rng().seed(215 + n);
  const MatQ A = random_matrix(n);
  const bool same = before::charpoly(A) == charpoly(A);
  compare(st, [&] { return before::charpoly(A); }, [&] { return charpoly(A); }, same);
  st.SetLabel("Faddeev-LeVerrier in mpq | fmpq_mat_charpoly");
}
BENCHMARK(BM_charpoly)->Arg(8)->Arg(12)->Arg(20)->UseManualTime()->Name("charpoly");

// ---- strict positive definiteness of a rounded solver matrix -------------------------------
// M = G G^T / n + I/10 in double, each entry rounded to 30 significant bits (dyadic), as the LMI
// certificate rounds a solver's point.
void BM_positive_definite(benchmark::State& st) {
  const int n = static_cast<int>(st.range(0));
  std::mt19937 g(315 + n);
  std::normal_distribution<double> N01;
  Eigen::MatrixXd G(n, n);
  for (Eigen::Index i = 0; i < G.size(); ++i) G.data()[i] = N01(g);
  const Eigen::MatrixXd S = G * G.transpose() / n + 0.1 * Eigen::MatrixXd::Identity(n, n);
  MatQ M(n, n);
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) M(i, j) = lmi::round_dyadic(S(std::min(i, j), std::max(i, j)), 30);
  const bool same = lmi::exact_definiteness(M).pd == lmi::exact_pd_bareiss(M);
  compare(st, [&] { return lmi::exact_definiteness(M).pd; }, [&] { return lmi::exact_pd_bareiss(M); }, same);
  st.SetLabel("LDL^T in mpq | Arb ball Cholesky");
}
BENCHMARK(BM_positive_definite)->Arg(12)->Arg(60)->UseManualTime()->Name("positive_definite");

// ---- matrix exponential: 50-digit Taylor against arb_mat_exp --------------------------------
// The mass-damper chain of bench/sim.cpp's zoh_setup, at t = 1 ms. same = the Taylor result lies
// within Arb's proven radius (plus the Taylor result's own 1e-45).
void BM_expm(benchmark::State& st) {
  const int n = static_cast<int>(st.range(0));
  MatQ A = MatQ::Zero(n, n);
  for (int i = 0; i < n; ++i) {
    A(i, i) = rational(-(i + 2), 3);
    if (i + 1 < n) A(i, i + 1) = rational(1, i + 1), A(i + 1, i) = rational(-7, i + 2);
  }
  const rational t(1, 1000);
  auto taylor = [&] {
    Mat<mp50> At(n, n);
    for (Eigen::Index i = 0; i < A.size(); ++i) At.data()[i] = to_real<mp50>(A.data()[i] * t);
    return expm<mp50>(At);
  };
  const Mat<mp50> T = taylor();
  const DoubleEnclosure E = expm_enclosure(A, t);
  bool same = true;
  for (Eigen::Index i = 0; i < T.size(); ++i)
    same = same && std::abs(static_cast<double>(T.data()[i]) - E.mid.data()[i]) <= E.radius + 1e-300;
  compare(st, taylor, [&] { return expm_enclosure(A, t); }, same);
  st.SetLabel("Taylor in mp50 | arb_mat_exp");
}
BENCHMARK(BM_expm)->Arg(4)->Arg(16)->UseManualTime()->Name("expm");

// ---- root counting and isolation: T_d(x) - 1/3 (d real roots in (-1, 1), irrational) ---------
QPoly chebyshev_minus_third(int d) {
  QPoly t0(rational(1)), t1({rational(0), rational(1)}), x({rational(0), rational(1)});
  for (int k = 1; k < d; ++k) {
    QPoly t2 = rational(2) * x * t1 - t0;
    t0 = std::move(t1);
    t1 = std::move(t2);
  }
  return t1 - QPoly(rational(1, 3));
}
void BM_sturm(benchmark::State& st) {
  const QPoly p = chebyshev_minus_third(static_cast<int>(st.range(0)));
  const rational a(-1, 2), b(3, 4);
  const bool same = before::count_real_roots(p, a, b) == count_real_roots(p, a, b);
  compare(st, [&] { return before::count_real_roots(p, a, b); }, [&] { return count_real_roots(p, a, b); }, same);
  st.SetLabel("Sturm in mpz | fmpz_poly");
}
BENCHMARK(BM_sturm)->Arg(6)->Arg(13)->Arg(26)->UseManualTime()->Name("sturm_count");

bool same_intervals(const std::vector<RootInterval>& x, const std::vector<RootInterval>& y) {
  if (x.size() != y.size()) return false;
  for (size_t i = 0; i < x.size(); ++i)
    if (x[i].lo != y[i].lo || x[i].hi != y[i].hi) return false;
  return true;
}
void BM_descartes(benchmark::State& st) {
  const QPoly p = chebyshev_minus_third(static_cast<int>(st.range(0)));
  const rational a(-2), b(2);
  const bool same = same_intervals(before::isolate_real_roots(p, a, b), isolate_real_roots(p, a, b));
  compare(st, [&] { return before::isolate_real_roots(p, a, b); }, [&] { return isolate_real_roots(p, a, b); }, same);
  st.SetLabel("Descartes in mpz | fmpz_poly");
}
BENCHMARK(BM_descartes)->Arg(6)->Arg(13)->Arg(26)->UseManualTime()->Name("descartes_isolate");

// ---- minimal realisation: a k-state system realised twice (2k states, k uncontrollable) ------
void BM_minreal(benchmark::State& st) {
  const int k = static_cast<int>(st.range(0)) / 2;
  rng().seed(415 + k);
  const MatQ A1 = random_matrix(k);
  MatQ B1(k, 2), C1(2, k);
  for (Eigen::Index i = 0; i < B1.size(); ++i) B1.data()[i] = small_rational();
  for (Eigen::Index i = 0; i < C1.size(); ++i) C1.data()[i] = small_rational();
  StateSpace<rational> s;
  s.A = MatQ::Zero(2 * k, 2 * k);
  s.A.topLeftCorner(k, k) = A1;
  s.A.bottomRightCorner(k, k) = A1;
  s.B = MatQ(2 * k, 2);
  s.B << B1, B1;
  s.C = MatQ(2, 2 * k);
  s.C << C1, C1;
  s.D = MatQ::Zero(2, 2);
  s.T = rational(1, 1000);
  const bool same = before::minreal(s).states() == minreal(s).states();
  compare(st, [&] { return before::minreal(s); }, [&] { return minreal(s); }, same);
  st.SetLabel("Gauss in mpq | fmpq_mat rref/solve");
}
BENCHMARK(BM_minreal)->Arg(12)->Arg(24)->UseManualTime()->Name("minreal");

// ---- Schur stability of the N-contact-point environment (bench/contact_scene.py's values,
// backward Euler, N + 2 states): exact Schur-Cohn on det(zI - A) (FLINT charpoly, primitive
// integer recursion) against the Lyapunov certificate (numeric/lyapunov.hpp). Arg 1 = 1: the
// environment made dense by an exact similarity S^-1 A S (S = I + random dyadic lower part).
// Arg 1 = 2: an N x N dense matrix of small rationals p/q divided by 4N (inside the unit disc):
// its characteristic polynomial has large coefficients, and Schur-Cohn grows with them
// (measured: 55 s at N = 128 against 0.14 s for the certificate, left out of the run).
void BM_schur_stable(benchmark::State& st) {
  const int N = static_cast<int>(st.range(0));
  multidof::MechanicalEnvironment env{rational(3, 10), rational(1000), rational(5), {}, {}};
  const rational Bc[] = {rational(1), rational(2), rational(3, 2), rational(5, 2)};
  for (int i = 0; i < N; ++i) {
    env.kc.push_back(rational(500 + 100 * (i % 4)));
    env.Bc.push_back(Bc[i % 4]);
  }
  MatQ A = multidof::mechanical_environment_be_ss(env, rational(1, 100)).A;
  if (st.range(1) == 2) {  // dense small rationals, scaled into the unit disc: big charpoly coefficients
    rng().seed(615 + N);
    A = random_matrix(N) / rational(4 * N);
  } else if (st.range(1) == 1) {
    const auto n = A.rows();
    std::mt19937 g(515 + N);
    std::uniform_int_distribution<int> k(-4, 4);
    MatQ L = MatQ::Zero(n, n), Si = MatQ::Identity(n, n), P = MatQ::Identity(n, n);
    for (Eigen::Index i = 1; i < n; ++i)
      for (Eigen::Index j = 0; j < i; ++j) L(i, j) = rational(k(g), 4);
    for (Eigen::Index p = 1; p < n; ++p) {
      P = (-P * L).eval();
      Si += P;
    }
    A = (Si * A * (MatQ::Identity(n, n) + L)).eval();
  }
  auto exact = [&] { return schur_stable(charpoly(A)); };
  auto lyapunov = [&] { return lyapunov_proves_schur_stable(A); };
  const bool same = exact() == lyapunov();
  compare(st, exact, lyapunov, same);
  st.counters["states"] = static_cast<double>(A.rows());
  st.SetLabel(st.range(1) == 0 ? "scene E: Schur-Cohn | Lyapunov + balls"
              : st.range(1) == 1 ? "scene E, dense similar: Schur-Cohn | Lyapunov + balls"
                                 : "dense random: Schur-Cohn | Lyapunov + balls");
}
BENCHMARK(BM_schur_stable)
    ->Args({16, 0})->Args({32, 0})->Args({16, 1})->Args({32, 1})->Args({16, 2})->Args({32, 2})->Args({64, 2})->UseManualTime()->Name("schur_stable");

}  // namespace

BENCHMARK_MAIN();
