// The loop as written split by the permutations of its identical DOFs (stability/symmetry.hpp,
// issue 48 item 2), on random loops of 2-7 DOFs in 1-3 classes of identical devices, operators,
// environment entries and, in a quarter, coupling entries:
//  - the exact characteristic polynomial of the whole closed-loop matrix (pure masses: M
//    rational) equals that of the fixed-space loop times each class's one-DOF loop to the power
//    k_a - 1 -- the decomposition theorem, checked as a polynomial identity;
//  - decide_loop with the symmetry and the whole matrix (Decider::matrix) never contradict;
//  - one entry changed (an almost symmetric loop) falls back to the whole matrix, the entry named.
#include "hapstab_paths.hpp"  // HAPSTAB_SOURCE_DIR
#include <gtest/gtest.h>

#include <random>

#include "hapstab/lti/realization.hpp"
#include "hapstab/scene/scene.hpp"
#include "hapstab/sim/closed_loop.hpp"
#include "hapstab/stability/loop_as_written.hpp"
#include "hapstab/stability/symmetry.hpp"

using namespace hapstab;
using namespace hapstab::sim;
using stability::Decider;
using stability::decide_loop;
using stability::detail::split_by_symmetry;

namespace {
using Q = rational;
using Pq = Polynomial<Q>;

struct Draw {
  LoopSpec spec;
  std::vector<int> class_of;
  TransferMatrix E;
};

/// N DOFs in r classes: class a's device m_a s + b_a (b = 0 and no hand when `masses`: M exact),
/// a hand b + k/s or none, E(i, i) = K_a + B_a (z - 1)/(T z), E(i, j) = c_ab (z - p_ab)/z (i != j); delay 0-2.
Draw draw(std::mt19937_64& g, bool masses) {
  std::uniform_int_distribution<int> u(1, 9), classes(1, 3), dofs(2, 7), coin(0, 1), dl(0, 2);
  Draw d;
  const Q T(1, 1000);
  const int N = dofs(g), r = std::min(classes(g), N);
  for (int i = 0; i < N; ++i) d.class_of.push_back(i < r ? i : static_cast<int>(g() % static_cast<unsigned>(r)));
  std::vector<Q> m, b, K, B, hb, hk;
  std::vector<bool> hand;
  for (int a = 0; a < r; ++a) {
    m.push_back(Q(u(g), 10));
    b.push_back(masses ? Q(0) : Q(u(g), 2));
    K.push_back(Q(500 * u(g)));
    B.push_back(Q(u(g), 4));
    hand.push_back(!masses && coin(g));  // pure masses: no hand (its damper's pole would make M transcendental)
    hb.push_back(Q(u(g), 4));
    hk.push_back(coin(g) ? Q(20 * u(g)) : Q(0));
  }
  std::vector<std::vector<Q>> c(static_cast<size_t>(r), std::vector<Q>(static_cast<size_t>(r))), p = c;
  for (auto& row : c)
    for (auto& x : row) x = Q(static_cast<long>(u(g)) * 40 - 200);
  for (auto& row : p)
    for (auto& x : row) x = Q(u(g) - 5, 10);
  d.spec.T = T;
  d.spec.delay = Q(dl(g)) * T;
  d.E.domain = Domain::z;
  d.E.T = T;
  const Pq z({Q(0), Q(1)});
  for (int i = 0; i < N; ++i) {
    const size_t a = static_cast<size_t>(d.class_of[static_cast<size_t>(i)]);
    d.spec.devices.push_back(mass_damper("d" + std::to_string(i + 1), m[a], b[a]));
    if (hand[a]) d.spec.operators.push_back(mass_spring_damper_operator("h" + std::to_string(i + 1), i, Q(0), hb[a], hk[a]));
    d.E.entries.emplace_back();
    for (int j = 0; j < N; ++j) {
      const size_t bb = static_cast<size_t>(d.class_of[static_cast<size_t>(j)]);
      d.E.entries.back().push_back(i == j ? tf(Pq({-B[a] / T, K[a] + B[a] / T}), z, T)
                                          : tf(Pq({-c[a][bb] * p[a][bb], c[a][bb]}), z, T));
    }
  }
  d.spec.environment = tf2ss(d.E);
  if (coin(g) && coin(g)) {  // a coupling V(z) by the same classes: V(i, i) = v_a/(z - q_a), V(i, j) = w_ab
    TransferMatrix V;
    V.domain = Domain::z;
    V.T = T;
    std::vector<Q> v;
    for (int a = 0; a < r; ++a) v.push_back(Q(u(g), 20000));
    for (int i = 0; i < N; ++i) {
      const size_t a = static_cast<size_t>(d.class_of[static_cast<size_t>(i)]);
      V.entries.emplace_back();
      for (int j = 0; j < N; ++j) {
        const size_t bb = static_cast<size_t>(d.class_of[static_cast<size_t>(j)]);
        V.entries.back().push_back(i == j ? tf(Pq({v[a]}), Pq({-Q(static_cast<long>(a) + 1, 10), Q(1)}), T)
                                          : tf(Pq({Q(static_cast<long>(a + 2 * bb) - 2, 100000)}), Pq({Q(1)}), T));
      }
    }
    d.spec.coupling = tf2ss(V);
    if (coin(g)) {  // and a state no input reaches (x+ = x/3), seen at every output: set aside by the split
      StateSpace<Q>& W = *d.spec.coupling;
      const Eigen::Index n = W.states();
      W.A.conservativeResize(n + 1, n + 1);
      W.A.row(n).setZero();
      W.A.col(n).setZero();
      W.A(n, n) = Q(1, 3);
      W.B.conservativeResize(n + 1, Eigen::NoChange);
      W.B.row(n).setZero();
      W.C.conservativeResize(Eigen::NoChange, n + 1);
      W.C.col(n).setConstant(Q(1, 100000));
    }
  }
  return d;
}

Pq exact_charpoly(const LoopSpec& s) {
  const SampledClosedLoop cl = sampled_closed_loop(s);
  EXPECT_TRUE(cl.removed.empty()) << cl.removed;
  if (!cl.exact) {
    ADD_FAILURE() << "M is not exact";
    return Pq();
  }
  return charpoly(*cl.exact);
}

}  // namespace

TEST(LoopSymmetry, CharacteristicPolynomialFactors) {
  std::mt19937_64 g(4802);
  int split = 0, classes_of_two = 0, with_coupling = 0, set_aside = 0;
  for (int k = 0; k < 40; ++k) {
    const Draw d = draw(g, true);
    SCOPED_TRACE("case " + std::to_string(k));
    std::string why;
    const auto s = split_by_symmetry(d.spec, why);
    if (!s) {  // only when no two DOFs are alike
      EXPECT_TRUE(why.empty()) << why;
      continue;
    }
    ++split;
    with_coupling += d.spec.coupling.has_value();
    Pq product = exact_charpoly(s->fixed);
    for (size_t a = 0; a < s->standard.size(); ++a) {
      const size_t size = s->classes[static_cast<size_t>(s->standard_class[a])].size();
      classes_of_two += size >= 2;
      product = product * exact_charpoly(s->standard[a]).pow(static_cast<unsigned>(size - 1));
    }
    // the coupling's states no input reaches: their own factor (x+ = x/3 here)
    if (d.spec.coupling)
      for (Eigen::Index k = 0; k < d.spec.coupling->states(); ++k)
        if (d.spec.coupling->B.row(k).isZero() && d.spec.coupling->A(k, k) == Q(1, 3)) {
          product = product * Pq({Q(-1, 3), Q(1)});
          ++set_aside;
        }
    EXPECT_EQ(exact_charpoly(d.spec), product);
  }
  EXPECT_GE(split, 30);
  EXPECT_GE(classes_of_two, 40);
  EXPECT_GE(with_coupling, 5);
  EXPECT_GE(set_aside, 2);
}

TEST(LoopSymmetry, VerdictsAgreeWithTheWholeMatrix) {
  std::mt19937_64 g(4803);
  int both = 0, stable = 0, unstable = 0, by_symmetry = 0;
  for (int k = 0; k < 60; ++k) {
    const Draw d = draw(g, k % 3 == 0);
    const auto sym = decide_loop(d.spec), whole = decide_loop(d.spec, Decider::matrix);
    by_symmetry += sym.path == "symmetry";
    if (sym.path != "symmetry") std::cerr << "DBG " << d.class_of.size() << " " << (d.spec.coupling ? "V " : "- ") << sym.path << " " << sym.why.substr(sym.why.size() > 160 ? sym.why.size() - 160 : 0) << "\n";
    if (sym.stable && whole.stable) {
      ++both;
      EXPECT_EQ(*sym.stable, *whole.stable) << "case " << k << ": " << sym.why << " | " << whole.why;
      (*sym.stable ? stable : unstable)++;
    }
  }
  EXPECT_GE(by_symmetry, 45);
  EXPECT_GE(both, 50);
  EXPECT_GE(stable, 10);
  EXPECT_GE(unstable, 10);
}

TEST(LoopSymmetry, AnAlmostSymmetricLoopFallsBackWithTheEntryNamed) {
  std::mt19937_64 g(4804);
  Draw d = draw(g, false);
  while (d.class_of.size() < 3 || d.class_of[2] != d.class_of[0]) d = draw(g, false);
  std::string why;
  ASSERT_TRUE(split_by_symmetry(d.spec, why).has_value()) << why;
  // DOF 3 alike DOF 1; E(3, 2) moved off E(1, 2)
  d.E.entries[2][1] = tf(d.E.entries[2][1].num() * Q(2), d.E.entries[2][1].den(), d.E.T);
  d.spec.environment = tf2ss(d.E);
  EXPECT_FALSE(split_by_symmetry(d.spec, why).has_value());
  EXPECT_NE(why.find("entry (3, 2) differs from (1, 2)"), std::string::npos) << why;
  const auto v = decide_loop(d.spec);
  EXPECT_NE(v.path, "symmetry");
  EXPECT_NE(v.why.find("no symmetry of identical DOFs used: the environment's entry"), std::string::npos) << v.why;
}

// The environment's hidden modes by the split (environment_hidden_modes) against the whole's
// Kalman decompositions (lti::hidden_modes): the same hidden factors, a minimal realisation of the
// same order and the same transfer matrix -- on the random loops above and on the contact scenes,
// whose tf realisations hide modes (unobservable, several copies).
TEST(LoopSymmetry, EnvironmentHiddenModesAsTheWholes) {
  auto same_transfer = [](const StateSpace<Q>& a, const StateSpace<Q>& b) {
    const TransferMatrix A = ss2tf(a), B = ss2tf(b);
    for (size_t i = 0; i < A.entries.size(); ++i)
      for (size_t j = 0; j < A.entries[i].size(); ++j)
        for (const Q& z : {Q(2), Q(-3, 7), Q(5, 2)}) {
          const auto &x = A.entries[i][j], &y = B.entries[i][j];
          if (x.num()(z) * y.den()(z) != y.num()(z) * x.den()(z)) return false;
        }
    return true;
  };
  std::vector<LoopSpec> loops;
  std::mt19937_64 g(4804);
  for (int k = 0; k < 30; ++k) loops.push_back(draw(g, k % 2 == 0).spec);
  for (const char* f : {"symmetric_contact_6.toml", "contact_8_identical.toml"})
    loops.push_back(scene::load_scene(std::string(HAPSTAB_SOURCE_DIR) + "/tests/cli/scenes/" + f).loop);
  int compared = 0, hiding = 0;
  for (size_t k = 0; k < loops.size(); ++k) {
    SCOPED_TRACE("loop " + std::to_string(k));
    std::string why;
    const auto s = split_by_symmetry(loops[k], why);
    if (!s) continue;
    const StateSpace<Q>& E = *loops[k].environment;
    const HiddenModes whole = hidden_modes(E), split = stability::detail::environment_hidden_modes(*s, E);
    EXPECT_EQ(split.uncontrollable.expanded(), whole.uncontrollable.expanded());
    EXPECT_EQ(split.unobservable.expanded(), whole.unobservable.expanded());
    EXPECT_EQ(split.minimal.states(), whole.minimal.states());
    EXPECT_TRUE(same_transfer(split.minimal, E));
    ++compared;
    hiding += whole.any();
  }
  EXPECT_GE(compared, 20);
  EXPECT_GE(hiding, 2);
}
