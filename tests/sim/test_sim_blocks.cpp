// The simulator's step matrices on the parts of the plant they depend on (issue 33,
// sim/simulator.cpp): Phi, Gamma per connected component of the plant and each port's energy
// Gram matrix W_j on the closure of its support, against the enclosures of the whole matrices
// (numeric/ball_expm.hpp on the full plant, as before issue 33), on a 4-DOF loop whose DOFs 1 and
// 2 are coupled (one 2-port operator with inertia) and whose DOFs 0 and 3 are not.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "hapstab/numeric/ball_expm.hpp"
#include "hapstab/sim/simulator.hpp"

using namespace hapstab;
using namespace hapstab::sim;

namespace {

using Q = rational;

// DOF 0: a pure-inertia hand; DOFs 1, 2: one 2-port operator (two states, cross terms, inertia);
// DOF 3: an operator Z = 0 (an idle state). A static 4 x 4 environment couples all DOFs
// (through the held force only).
// Fractional delay 3T/10: two pieces per period, both with energy Gram matrices.
LoopSpec four_dof_loop() {
  LoopSpec s;
  s.T = Q(1, 1000);
  s.delay = Q(3, 10000);
  for (int i = 0; i < 4; ++i) s.devices.push_back(mass_damper("d" + std::to_string(i), Q(i + 1, 10), Q(1, 2)));
  s.operators.push_back(mass_spring_damper_operator("hand", 0, Q(1, 5), Q(0), Q(0)));
  OperatorBlock pair;
  pair.name = "pair";
  pair.ports = {1, 2};
  pair.mass = {Q(1, 10), Q(1, 20)};
  Mat<Q> A(2, 2), B(2, 2), C(2, 2), D(2, 2);
  A << -3, 0, 1, -5;
  B << 1, 1, 0, 1;
  C << 2, 0, 1, 3;
  D << 1, Q(1, 2), Q(1, 2), 2;
  pair.Z = StateSpace<Q>{A, B, C, D, 0};
  s.operators.push_back(pair);
  // DOF 3: Z = 0 with one idle state (neither driven nor seen): a component of the plant that
  // no input feeds (Gamma's block has no columns)
  OperatorBlock idle;
  idle.name = "idle";
  idle.ports = {3};
  idle.Z = StateSpace<Q>{Mat<Q>::Constant(1, 1, Q(-1)), Mat<Q>::Zero(1, 1), Mat<Q>::Zero(1, 1), Mat<Q>::Zero(1, 1), 0};
  s.operators.push_back(idle);
  Mat<Q> De = Mat<Q>::Constant(4, 4, Q(-5));
  for (int i = 0; i < 4; ++i) De(i, i) = 100;
  s.environment = StateSpace<Q>{Mat<Q>::Zero(0, 0), Mat<Q>::Zero(0, 4), Mat<Q>::Zero(4, 0), De, s.T};
  s.biases = {{0, Q(2), 0}, {3, Q(-1), 0}, {1, Q(1, 2), 0}};
  s.x0 = {Q(1, 100), Q(-1, 100), Q(2, 100), 0};
  return s;
}

// |a - b| <= ra + rb entry by entry: the two enclosures of one exact matrix overlap.
void expect_same_exact(const Mat<double>& a, double ra, const Mat<double>& b, double rb, const std::string& what) {
  ASSERT_EQ(a.rows(), b.rows()) << what;
  ASSERT_EQ(a.cols(), b.cols()) << what;
  for (Eigen::Index i = 0; i < a.rows(); ++i)
    for (Eigen::Index k = 0; k < a.cols(); ++k)
      EXPECT_LE(std::fabs(a(i, k) - b(i, k)), ra + rb) << what << " (" << i << ", " << k << ")";
}

bool disjoint(std::vector<Eigen::Index> a, std::vector<Eigen::Index> b) {
  std::vector<Eigen::Index> c;
  std::set_intersection(a.begin(), a.end(), b.begin(), b.end(), std::back_inserter(c));
  return c.empty();
}

}  // namespace

// Blockwise Phi, Gamma, W_j enclose the same exact matrices as the enclosures of the whole:
// the midpoints agree within the sum of the two proven radii, and both radii are near the
// rounding of an O(1) entry to double (below 1e-15: Arb works at 128 bits).
TEST(SimBlocks, BlockwiseStepMatricesMatchTheWholePlant) {
  Simulator sim(four_dof_loop());
  const ComposedLoop& L = sim.loop();
  const auto& P = L.plant;
  const int N = L.N;
  const auto n = P.A.rows(), nz = n + 2 * N;
  const rational f(3, 10000);
  Mat<rational> M = Mat<rational>::Zero(nz, nz);
  M.topLeftCorner(n, n) = P.A;
  M.topRightCorner(n, 2 * N) = P.B;
  for (const auto& [pc, h] : {std::pair{&sim.piece_before(), f}, std::pair{&sim.piece_after(), L.T - f}}) {
    EXPECT_DOUBLE_EQ(pc->h, to_real<double>(h));
    EXPECT_GT(pc->radius, 0);
    EXPECT_LT(pc->radius, 1e-15);
    const ZohEnclosure whole = zoh_enclosure(P.A, P.B, h);
    EXPECT_LT(std::max(whole.Phi.radius, whole.Gamma.radius), 1e-15);
    expect_same_exact(pc->Phi, pc->radius, whole.Phi.mid, whole.Phi.radius, "Phi");
    expect_same_exact(pc->Gu, pc->radius, whole.Gamma.mid.leftCols(N), whole.Gamma.radius, "Gu");
    expect_same_exact(pc->Gw, pc->radius, whole.Gamma.mid.rightCols(N), whole.Gamma.radius, "Gw");
    ASSERT_EQ(int(pc->W.size()), N);
    for (int j = 0; j < N; ++j) {
      Mat<rational> a(1, nz), b(1, nz);
      a << P.C.row(2 * N + j), P.D.row(2 * N + j);
      b << P.C.row(N + j), P.D.row(N + j);
      const Mat<rational> Qj = (a.transpose() * b + b.transpose() * a) / rational(2);
      const DoubleEnclosure W = gram_enclosure(M, Qj, h);
      EXPECT_LT(W.radius, 1e-15);
      expect_same_exact(pc->W[size_t(j)].dense(nz), pc->radius, W.mid, W.radius, "W_" + std::to_string(j));
      EXPECT_GT(W.mid.cwiseAbs().maxCoeff(), 1e-6) << "port " << j << " carries power";
    }
  }
}

// The supports: the coupled ports 1 and 2 share theirs, the uncoupled DOFs 0 and 3 see only
// their own device, operator and inputs, and every W_j is a proper block of the (n + 2N)^2 one.
TEST(SimBlocks, PortSupportsFollowTheCoupling) {
  Simulator sim(four_dof_loop());
  const ComposedLoop& L = sim.loop();
  const auto n = L.plant.states(), nz = n + 2 * L.N;
  const auto& W = sim.piece_after().W;
  EXPECT_EQ(W[1].support, W[2].support);
  EXPECT_TRUE(disjoint(W[0].support, W[3].support));
  EXPECT_TRUE(disjoint(W[0].support, W[1].support));
  EXPECT_TRUE(disjoint(W[3].support, W[1].support));
  for (const auto& g : W) {
    EXPECT_LT(Eigen::Index(g.support.size()), nz);
    EXPECT_EQ(g.W.rows(), Eigen::Index(g.support.size()));
    EXPECT_TRUE(std::is_sorted(g.support.begin(), g.support.end()));
  }
  // DOF 3 (device state 3, Z = 0): v_3 = s_3, f_h3 = w_3, and s_3' involves u_3 and w_3
  const std::vector<Eigen::Index> dof3 = {3, n + 3, n + L.N + 3};
  EXPECT_EQ(W[3].support, dof3);
}

// The port energies of a run in the dynamic-size engine (4 DOFs), on the supports, against
// closed forms: DOF 3 has only its bias F3 at the port, so E_port_3 = F3 (x_3(t) - x_3(0));
// DOF 0 has a pure inertia m_o and its bias F0, so E_port_0 = F0 (x_0 - x_0(0)) - m_o v_0^2 / 2.
// Tolerance 1e-9 of the energy scale: 400 periods of double recursion (~1e-16 each) and the
// step matrices' radius (< 1e-15) stay far below it.
TEST(SimBlocks, PortEnergiesOnTheSupportsMatchClosedForms) {
  const LoopSpec spec = four_dof_loop();
  Simulator sim(spec);
  SimOptions o;
  o.steps = 400;
  const SimResult r = sim.run(o);
  const auto& S = r.samples;
  const int N = S.N;
  ASSERT_EQ(N, 4);
  const double F0 = 2, F3 = -1, mo = 0.2, x00 = 0.01;
  double scale = 0;
  for (size_t i = 0; i < S.rows(); ++i) scale = std::max({scale, std::fabs(S.e_port[i * 4]), std::fabs(S.e_port[i * 4 + 3])});
  ASSERT_GT(scale, 1e-6);
  for (size_t i = 0; i < S.rows(); ++i) {
    const double v0 = S.v[i * 4], x0 = S.x[i * 4], x3 = S.x[i * 4 + 3];
    EXPECT_NEAR(S.e_port[i * 4 + 3], F3 * x3, 1e-9 * scale) << "row " << i;
    EXPECT_NEAR(S.e_port[i * 4], F0 * (x0 - x00) - 0.5 * mo * v0 * v0, 1e-9 * scale) << "row " << i;
  }
}
