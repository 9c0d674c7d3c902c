// proofs/affine_degree.cpp -- issue 46 item 5: the degree bounds scene/parameter_degree.hpp proves
// `stability --max` affinity with. Every block matrix of [environment] E(p) and [coupling] V(p) a
// polynomial of degree <= 1 in p; the composed controller (sim/loop.cpp, paper 000 (11)) solves
// S [Cu | Du] = -[Ce | De Cv | De] with S = I + De Dv, then Xs = Dv Cu + [0 | Cv], Xm = I + Dv Du,
// Ac = [Ae + Be Xs_e, Be Xs_v; Bv Cu] (+ Av), Bc = [Be Xm; Bv Du]. By Cramer, each entry is
// P(p)/det S(p):
//   S constant (De, Dv fixed):  Cu <= 2, Du <= 1, Xs <= 3, Xm <= 2, Ac <= 4, Bc <= 3: degree <= 4;
//   S moving:                   det S <= 2N, adj S <= 2N - 2, and P <= 2N + 2.
// The closed loop's controller rows Ku = [Du Cx, Cu], Kx = [Bc Cx, Ac] (sim/closed_loop.cpp) inherit
// them (Cx fixed). Checked here in exact arithmetic on random affine blocks: Ku det S and Kx det S
// (det S exact, numeric/exact_matrix.hpp) interpolated at bound + 1 values of p predict their
// values at three more exactly, so their degree is within the bound; and the instances are the
// ones where the bound is needed (degree > 1: a loop not affine in p, which the affine check must
// be able to refuse).
//   ext.stability.affine_degree  the bounds above hold on 40 random coupled loops, N = 1, 2
#include <random>
#include <sstream>

#include "hapstab/numeric/exact_matrix.hpp"
#include "hapstab/sim/closed_loop.hpp"
#include "proofs/proof.hpp"

namespace {

using namespace hapstab;
using hapstab::proofs::Instances;

/// A + p B with small random rational entries (B zero where `moves` is false).
struct Affine {
  MatQ a, b;
  MatQ at(const rational& p) const { return a + b * p; }
};

Affine random_affine(std::mt19937& rng, long r, long c, bool moves, long scale) {
  std::uniform_int_distribution<int> d(-4, 4);
  Affine x{MatQ::Zero(r, c), MatQ::Zero(r, c)};
  for (long i = 0; i < r; ++i)
    for (long j = 0; j < c; ++j) {
      x.a(i, j) = rational(d(rng), scale);
      if (moves) x.b(i, j) = rational(d(rng), scale);
    }
  return x;
}

/// Lagrange: the polynomial of degree <= xs.size() - 1 through (xs, ys), at x.
rational lagrange(const std::vector<rational>& xs, const std::vector<rational>& ys, const rational& x) {
  rational s = 0;
  for (size_t i = 0; i < xs.size(); ++i) {
    rational l = ys[i];
    for (size_t j = 0; j < xs.size(); ++j)
      if (j != i) l *= (x - xs[j]) / (xs[i] - xs[j]);
    s += l;
  }
  return s;
}

HAPSTAB_PROOF(affine_degree, "ext", "the degree in p of the composed controller of affine blocks (stability --max affinity)") {
  std::mt19937 rng(46005);
  Instances fixed{"S constant: controller rows not affine in p (degree > 1)", 10}, moving{"S moving: degree > 1", 10};
  bool ok = true;
  std::ostringstream bad;
  for (int trial = 0; trial < 40; ++trial) {
    const long N = 1 + trial % 2, ne = N, nv = N;
    const bool s_moves = trial % 4 >= 2;
    struct Blocks {
      Affine A, B, C, D;
    };
    const Blocks E{random_affine(rng, ne, ne, true, 8), random_affine(rng, ne, N, true, 4), random_affine(rng, N, ne, true, 2),
                   random_affine(rng, N, N, s_moves, 1)};
    const Blocks V{random_affine(rng, nv, nv, true, 8), random_affine(rng, nv, N, true, 4), random_affine(rng, N, nv, true, 1000),
                   random_affine(rng, N, N, false, 1000)};
    const rational T(1, 100);
    auto spec_at = [&](const rational& p) {
      sim::LoopSpec s;
      s.T = T;
      for (long i = 0; i < N; ++i) s.devices.push_back(sim::mass_damper("d" + std::to_string(i), rational(1), rational(1)));
      s.environment = StateSpace<rational>{E.A.at(p), E.B.at(p), E.C.at(p), E.D.at(p), T};
      s.coupling = StateSpace<rational>{V.A.at(p), V.B.at(p), V.C.at(p), V.D.at(p), T};
      return s;
    };
    const long bound = s_moves ? 2 * N + 2 : 4;
    std::vector<rational> xs;
    std::vector<MatQ> ys;  // [Ku; Kx] det S at each value
    for (long k = 0; static_cast<long>(xs.size()) < bound + 4 && k < 100; ++k) {
      const rational p(k + 1, 3);
      const MatQ S = MatQ::Identity(N, N) + E.D.at(p) * V.D.at(p);
      const rational det = exact_determinant(S);
      if (det == 0) continue;  // the algebraic loop is singular there: not a value of the family
      const sim::SampledClosedLoop cl = sim::sampled_closed_loop(spec_at(p));
      MatQ K(cl.Ku.rows() + cl.Kx.rows(), cl.Ku.cols());
      K << cl.Ku, cl.Kx;
      xs.push_back(p);
      ys.push_back(K * det);
    }
    bool within = static_cast<long>(xs.size()) == bound + 4, affine = true;
    const std::vector<rational> fit_x(xs.begin(), xs.begin() + bound + 1);
    for (Eigen::Index e = 0; within && e < ys[0].size(); ++e) {
      std::vector<rational> fit_y;
      for (long i = 0; i <= bound; ++i) fit_y.push_back(ys[size_t(i)](e));
      for (size_t t = size_t(bound) + 1; t < xs.size(); ++t) within = within && lagrange(fit_x, fit_y, xs[t]) == ys[t](e);
    }
    // non-trivial: Ku, Kx themselves (divided by det S) are not affine in p
    for (size_t t = 2; affine && t < xs.size(); ++t) {
      const rational d0 = exact_determinant(MatQ(MatQ::Identity(N, N) + E.D.at(xs[0]) * V.D.at(xs[0])));
      const rational d1 = exact_determinant(MatQ(MatQ::Identity(N, N) + E.D.at(xs[1]) * V.D.at(xs[1])));
      const rational dt = exact_determinant(MatQ(MatQ::Identity(N, N) + E.D.at(xs[t]) * V.D.at(xs[t])));
      const MatQ k0 = ys[0] / d0, k1 = ys[1] / d1, kt = ys[t] / dt;
      affine = (kt - k0 - (k1 - k0) * ((xs[t] - xs[0]) / (xs[1] - xs[0]))).isZero(0);
    }
    (s_moves ? moving : fixed).count(!affine);
    if (!within) bad << " trial " << trial << " (N = " << N << (s_moves ? ", S moving" : ", S constant") << ")";
    ok = ok && within;
  }
  check.claim("ext.stability.affine_degree", "000 (11), Cramer",
              "with every matrix of E(p) and V(p) of degree <= 1 in p, the composed controller's rows times det(I + D_E D_V) "
              "have degree <= 4 when D_E, D_V do not move and <= 2N + 2 when they do (scene/parameter_degree.hpp's bounds)",
              Status::exact, ok,
              "40 random coupled loops (N = 1, 2): [Ku; Kx] det S interpolated exactly at bound + 1 values of p predicts three "
              "more exactly" + (bad.str().empty() ? std::string() : "; exceeded at" + bad.str()),
              {fixed, moving});
}

}  // namespace
