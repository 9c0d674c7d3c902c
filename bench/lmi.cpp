// bench/lmi.cpp -- LMI layer speed: a problem of Theorem 5's shape (paper 000, (16)) solved
// and certified, and its growth with the number of DOF m: DSDP, CSDP and the built-in dense
// IPM in the same run, and `auto` (Solve's default: the IPM, kept because certified).
//
// Problem (Theorem 5's structure, with a random stable m-input environment E of n states;
// size benchmarks: m = 2, n = 8 (blocks 10x10 and 4x4, 43 scalar variables) and m = 4, n = 8
// (blocks 12x12 and 8x8, 54 variables: Theorem5Size12), B, C entries
// 0.3 N(0,1); scaling sweep m = 2..32: n = m/2 + 2 states (a Fig. 5-like environment has m + 2;
// n = 2m, as before, makes P alone 2080 variables at m = 32, minutes per solve on reference
// BLAS), B, C entries 0.6/sqrt(n) N(0,1) so that every size is strictly feasible:
//   P > 0,  X in G(m; 1..1) > 0,  Q_V in BD(m; 1..1) > 0,  Q_E symmetric,
//   [[A'PA - P, A'PB - C'X/2], [., B'PB - (XD + D'X)/2 - Q_E]] < 0,
//   [[Delta_D X - Q_E, -Q_E], [-Q_E, Q_V - Q_E]] > 0,  X <= 10 I, Q_V <= 10 I (bounded),
// feasibility with the best margin. (The real Ê has an accumulator with eigenvalues at 1 and
// needs facial_reduce; a stable E keeps the timing about the solver.)
// Counters: vars, block (largest LMI size), feasible, certified (1/0), csdp_fallback (1/0),
// bits (rounding that passed the exact check), min_eig (smallest eigenvalue of the strict LMIs
// at the solution, original coordinates: the certification margin reached).
//
//   bench/chart-lmi OUTDIR  (runs bench_lmi and writes lmi_scaling.dat)
// HAPSTAB_BENCH_DETAIL=1 prints each solve's solver and detail to stderr (why a point failed).
#include <benchmark/benchmark.h>

#include <Eigen/Eigenvalues>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <random>

#include "hapstab/lmi/solve.hpp"

using namespace hapstab::lmi;
using Eigen::MatrixXd;

namespace {

struct Problem {
  Program prog;
  int vars = 0, block = 0;
};

Problem theorem5_shape(int m, int n, unsigned seed, double bc = 0.3, bool cap_qv = false) {
  std::mt19937 g(seed);
  std::normal_distribution<double> N(0, 1);
  MatrixXd A(n, n), B(n, m), C(m, n), D(m, m);
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) A(i, j) = N(g);
  A *= 0.8 / Eigen::EigenSolver<MatrixXd>(A, false).eigenvalues().cwiseAbs().maxCoeff();
  // A strongly input-strictly-passive environment (D = 2I, small B, C) so that (16) is
  // strictly feasible and the benchmark measures a solve + certificate, not an infeasibility.
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < m; ++j) B(i, j) = bc * N(g), C(j, i) = bc * N(g);
  D = 2.0 * MatrixXd::Identity(m, m);
  Problem p;
  auto P = p.prog.new_symmetric(n, "P");
  auto X = p.prog.new_scalar_identity_blocks(std::vector<int>(static_cast<size_t>(m), 1), "X");
  auto QV = p.prog.new_block_diagonal(std::vector<int>(static_cast<size_t>(m), 1), "Q_V");
  auto QE = p.prog.new_symmetric(m, "Q_E");
  const double DeltaD = 1.37;
  Expr Pe(P), Xe(X), QVe(QV), QEe(QE);
  p.prog.add_lmi("P > 0", Pe);
  p.prog.add_lmi("X > 0", Xe);
  p.prog.add_lmi("X <= 10 I", Expr(MatrixXd(10 * MatrixXd::Identity(m, m))) - Xe, Strictness::nonstrict);
  p.prog.add_lmi("Q_V > 0", QVe);
  // scaling sweep: Q_V bounded too -- with only X capped, the m = 8 instance drifted along an
  // unbounded Q_V (DSDP: indefinite Schur matrix; the IPM: 60 iterations without convergence)
  if (cap_qv) p.prog.add_lmi("Q_V <= 10 I", Expr(MatrixXd(10 * MatrixXd::Identity(m, m))) - QVe, Strictness::nonstrict);
  Expr M11 = A.transpose() * Pe * A - Pe;
  Expr M12 = A.transpose() * Pe * B - 0.5 * (C.transpose() * Xe);
  Expr M22 = B.transpose() * Pe * B - 0.5 * (Xe * D + D.transpose() * Xe) - QEe;
  p.prog.add_lmi("(16) first", -blocks({{M11, M12}, {Expr(), M22}}));
  p.prog.add_lmi("(16) second", {{DeltaD * Xe - QEe, -QEe}, {Expr(), QVe - QEe}});
  p.vars = p.prog.num_scalars();
  p.block = n + m;
  return p;
}

void run(benchmark::State& st, Backend b, int m, int n, bool certify, double bc = 0.3, bool cap_qv = false) {
  Problem p = theorem5_shape(m, n, 1234u + static_cast<unsigned>(m), bc, cap_qv);
  Options o;
  o.backend = b;
  o.certify = certify;
  SolveResult r;
  for (auto _ : st) {
    r = solve(p.prog, o);
    benchmark::DoNotOptimize(r.margin);
  }
  if (getenv("HAPSTAB_BENCH_DETAIL")) fprintf(stderr, "%s: %s\n", r.solver.c_str(), r.detail.c_str());
  st.counters["vars"] = p.vars;
  st.counters["block"] = p.block;
  st.counters["m"] = m;
  st.counters["feasible"] = r.is_success();
  st.counters["certified"] = r.certified();
  st.counters["bits"] = r.rounding_bits;
  st.counters["iterations"] = r.iterations;
  // 1 when DSDP stopped in trouble and Solve's CSDP fallback produced the result (the time is
  // then DSDP's attempts plus CSDP's; seen at m = 8: DSDP stop reason -8, indefinite Schur matrix)
  st.counters["csdp_fallback"] = r.solver.find("fallback") != std::string::npos;
  // the certification margin: smallest eigenvalue over the STRICT LMIs at the solution
  // (original coordinates); the non-strict caps X, Q_V <= 10 I may be active (eigenvalue 0)
  double me = INFINITY;
  for (size_t i = 0; i < r.min_eigenvalue.size(); ++i)
    if (p.prog.lmis()[i].strictness == Strictness::strict) me = std::min(me, r.min_eigenvalue[i]);
  st.counters["min_eig"] = me;
  st.counters["err_max"] = std::max({std::abs(r.dimacs[0]), std::abs(r.dimacs[1]), std::abs(r.dimacs[3]),
                                     std::abs(r.dimacs[4]), std::abs(r.dimacs[5])});
}

}  // namespace

int main(int argc, char** argv) {
  auto name = [](Backend b) {
    return std::string(b == Backend::automatic ? "auto" : b == Backend::dsdp ? "dsdp" : b == Backend::csdp ? "csdp" : "ipm");
  };
  // auto = Solve's default: the built-in IPM (certified) for a program this small
  for (Backend b : {Backend::automatic, Backend::dsdp, Backend::csdp, Backend::ipm}) {
    const std::string bn = name(b);
    benchmark::RegisterBenchmark(("Theorem5Size/solve_certify/" + bn).c_str(),
                                 [b](benchmark::State& st) { run(st, b, 2, 8, true); })
        ->Unit(benchmark::kMillisecond);
    // the upper size: blocks 12x12 (m = 4, n = 8; the second LMI of (16) is 8x8), 54 variables
    benchmark::RegisterBenchmark(("Theorem5Size12/solve_certify/" + bn).c_str(),
                                 [b](benchmark::State& st) { run(st, b, 4, 8, true); })
        ->Unit(benchmark::kMillisecond);
    if (b == Backend::automatic) continue;  // without certify, automatic is DSDP
    benchmark::RegisterBenchmark(("Theorem5Size/solve_only/" + bn).c_str(),
                                 [b](benchmark::State& st) { run(st, b, 2, 8, false); })
        ->Unit(benchmark::kMillisecond);
    benchmark::RegisterBenchmark(("Theorem5Size12/solve_only/" + bn).c_str(),
                                 [b](benchmark::State& st) { run(st, b, 4, 8, false); })
        ->Unit(benchmark::kMillisecond);
  }
  for (Backend b : {Backend::dsdp, Backend::csdp, Backend::ipm}) {
    const std::string bn = name(b);
    for (int m : {2, 4, 8, 16, 32}) {
      auto* bm = benchmark::RegisterBenchmark(("Scaling/" + bn + "/" + std::to_string(m)).c_str(), [b, m](benchmark::State& st) {
        const int n = m / 2 + 2;
        run(st, b, m, n, true, 0.6 / std::sqrt(static_cast<double>(n)), true);
      });
      bm->Unit(benchmark::kMillisecond);
      if (m >= 16) bm->Iterations(1);  // 0.2 s (m = 16) to 9 s (m = 32) per solve: one timed run
    }
  }
  benchmark::Initialize(&argc, argv);
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
}
