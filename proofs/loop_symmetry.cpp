// proofs/loop_symmetry.cpp -- why the loop as written of identical DOFs splits into small loops
// (stability/symmetry.hpp, issue 48 item 2).
//
// Argument. Let the DOFs fall into classes C_1 .. C_r of identical ones (device, operator, and the
// column block (A_j, B_j) of each discrete block, with C_j(i, :) and D(i, j) depending only on the
// classes of i and j and on i = j). Permuting DOFs within classes, and with them each DOF's plant
// states, delay buffer and column block, maps the closed loop's state equation to itself: M
// commutes with every such permutation Pi. Two subspaces are then M-invariant:
//  * the fixed space (each DOF's states equal across its class): there the force on DOF i in C_a
//    is sum over classes b of [sum over j in C_b of C_j(i, :)] xi_b + [sum of D(i, j)] eta_b, the
//    r-DOF loop with those row sums;
//  * for a class a with two DOFs i != j, the vectors with states +v on i, -v on j, 0 elsewhere:
//    the force on i is (C_i(i, :) - C_j(i, :)) v + (D(i, i) - D(i, j)) eta, on j its negative,
//    on any other DOF l zero (C_i(l, :) = C_j(l, :): both off-diagonal entries of the class pair);
//    the one-DOF loop under E(i, i) - E(i, j). The k_a - 1 differences (DOF 1 of the class minus
//    DOF m) span the class's zero-sum space, each a copy.
// Their dimensions add up to the order of M (sum_a n_a + sum_a (k_a - 1) n_a), so
//   det(zI - M) = det(zI - M_fixed) prod_a det(zI - M_a)^(k_a - 1).
// The claim checks this identity exactly on random loops of pure masses (M rational), in 1-3
// classes, with walls, static and dynamic contact entries, operators' springs left out (they add
// conserved quantities the plant's reduction removes) and delays of 0-2 samples.
#include <random>
#include <sstream>

#include "hapstab/lti/realization.hpp"
#include "hapstab/sim/closed_loop.hpp"
#include "hapstab/stability/symmetry.hpp"
#include "proofs/proof.hpp"

namespace {

using namespace hapstab;
using Q = rational;
using Pq = Polynomial<Q>;

Pq loop_charpoly(const sim::LoopSpec& s, bool& exact) {
  const sim::SampledClosedLoop cl = sim::sampled_closed_loop(s);
  exact = exact && cl.exact && cl.removed.empty();
  return cl.exact ? charpoly(*cl.exact) : Pq();
}

}  // namespace

HAPSTAB_PROOF(loop_symmetry_split, "ext", "The loop of identical DOFs splits into the fixed-space loop and one loop per class") {
  std::mt19937 g(4861);
  std::uniform_int_distribution<int> u(1, 9), n_dofs(2, 6), n_classes(1, 3), dl(0, 2);
  bool ok = true;
  proofs::Instances splits{"loops split with a class of two DOFs or more", 20}, two{"loops with two such classes", 5};
  std::ostringstream ev;
  for (int c = 0; c < 30; ++c) {
    const Q T(1, 1000);
    const int N = n_dofs(g), r = std::min(n_classes(g), N);
    std::vector<int> cls;
    for (int i = 0; i < N; ++i) cls.push_back(i < r ? i : u(g) % r);
    std::vector<Q> m, K, B, k, p;
    for (int a = 0; a < r * r; ++a) k.push_back(Q(u(g) * 30 - 150)), p.push_back(Q(u(g) - 5, 10));
    for (int a = 0; a < r; ++a) m.push_back(Q(u(g), 10)), K.push_back(Q(400 * u(g))), B.push_back(Q(u(g), 4));
    sim::LoopSpec s;
    s.T = T;
    s.delay = Q(dl(g)) * T;
    TransferMatrix E;
    E.domain = Domain::z;
    E.T = T;
    const Pq z({Q(0), Q(1)});
    for (int i = 0; i < N; ++i) {
      const size_t a = static_cast<size_t>(cls[static_cast<size_t>(i)]);
      s.devices.push_back(sim::mass_damper("d" + std::to_string(i), m[a], Q(0)));
      E.entries.emplace_back();
      for (int j = 0; j < N; ++j) {
        const size_t ab = a * static_cast<size_t>(r) + static_cast<size_t>(cls[static_cast<size_t>(j)]);
        E.entries.back().push_back(i == j      ? tf(Pq({-B[a] / T, K[a] + B[a] / T}), z, T)
                                   : ab % 2 == 0 ? tf(Pq({k[ab]}), Pq({Q(1)}), T)
                                                 : tf(Pq({-k[ab] * p[ab], k[ab]}), z, T));
      }
    }
    s.environment = tf2ss(E);
    std::string why;
    const auto split = stability::detail::split_by_symmetry(s, why);
    if (!split) continue;
    bool exact = true;
    Pq product = loop_charpoly(split->fixed, exact);
    int classes_of_two = 0;
    for (size_t a = 0; a < split->standard.size(); ++a) {
      const size_t size = split->classes[static_cast<size_t>(split->standard_class[a])].size();
      classes_of_two += 1;
      product = product * loop_charpoly(split->standard[a], exact).pow(static_cast<unsigned>(size - 1));
    }
    const Pq whole = loop_charpoly(s, exact);
    const bool holds = exact && whole == product;
    ok = ok && holds;
    splits.count(classes_of_two >= 1);
    two.count(classes_of_two >= 2);
    if (!holds) ev << "case " << c << ": det(zI - M) differs from the product of the small loops'; ";
  }
  ev << "30 random loops of 2-6 pure masses in 1-3 classes, delays 0-2: det(zI - M) of the whole loop equals "
        "det(zI - M_fixed) prod_a det(zI - M_a)^(k_a - 1), every polynomial exact";
  check.claim("ext.symmetry.isotypic_split", "loop as written, identical DOFs",
              "a loop invariant under the permutations of its identical DOFs has the spectrum of the loop on the fixed "
              "space and of one one-DOF loop per class under E(i, i) - E(i, j), with multiplicity k_a - 1 -- checked "
              "as an exact identity of characteristic polynomials on 30 random loops",
              Status::exact, ok, ev.str(), {splits, two});
}
