// proofs/ext_conservatism.cpp -- beyond the papers: the exact pre-check of conservatism/
// theorem5_max.hpp (issue 42). Lemma 1's facial reduction (multidof/analysis.hpp, check_vhat_osp)
// makes V-hat^Gamma's OSP level require X (V(1) - K) symmetric positive definite, K = T/2 Delta_D^-1;
// with X = blockdiag(g_i I) every diagonal entry of V(1) - K must be > 0. For a coupling V/kc that
// is kc < kc_DC = min_j V(1)_jj / K_jj, and theorem5_at answers "does not conclude [exact]" above
// kc_DC without solving anything. Checked here against Theorem 4's program itself
// (multidof::check_theorem4, no pre-check): at 1.01 kc_DC it does not hold (the solver's verdict:
// numeric), at 0.9 kc_DC it holds with its exact re-check -- on Sec. VI case ii (nominal and
// perturbed E, the paper's (27)) and the contact scene N = 2 ((27)'s first block per device; larger N
// cost seconds per infeasible program).
#include <sstream>

#include "hapstab/conservatism/example.hpp"
#include "hapstab/conservatism/theorem5_max.hpp"
#include "hapstab/multidof/analysis.hpp"
#include "hapstab/multidof/example.hpp"
#include "hapstab/multidof/scene_multidof.hpp"
#include "hapstab/multidof/structure.hpp"
#include "hapstab/scene/scene.hpp"
#include "proofs/proof.hpp"

namespace {

using namespace hapstab;
using Q = rational;

StateSpace<Q> scaled(StateSpace<Q> V, const Q& kc) {  // V / kc
  V.C /= kc;
  V.D /= kc;
  return V;
}

Q dc_bound(const StateSpace<Q>& V, const MatQ& K) {  // min_j V(1)_jj / K_jj
  const Eigen::Index n = V.A.rows();
  const MatQ V1 = V.D + V.C * multidof::inverse(MatQ(MatQ::Identity(n, n) - V.A), "I - A_V") * V.B;
  Q best = V1(0, 0) / K(0, 0);
  for (Eigen::Index j = 1; j < V1.rows(); ++j) best = std::min(best, V1(j, j) / K(j, j));
  return best;
}

}  // namespace

HAPSTAB_PROOF(ext_conservatism, "ext", "Lemma 1's DC condition bounds where Theorem 5 concludes for a coupling V/kc") {
  proofs::Instances cases{"scene + coupling whose Theorem 4 program was solved on both sides of kc_DC", 3};
  bool ok = true;
  std::ostringstream e;
  struct Case {
    std::string name;
    multidof::Problem pb;
    StateSpace<Q> V;
  };
  std::vector<Case> all;
  for (const bool perturbed : {false, true})
    all.push_back({perturbed ? "case ii perturbed" : "case ii nominal", multidof::example::problem(2, perturbed),
                   multidof::example::controller27()});
  for (const int N : {2}) {  // the coupling of the study's scene at kc = 1 (gain 1/kc)
    const scene::Scene sc = scene::parse_scene(
        conservatism::with_coupling27(multidof::example::contact_scene(N), N, false), "contact", {{"kc", Q(1)}});
    all.push_back({"contact N = " + std::to_string(N), multidof::problem_from_scene(sc).problem, *sc.loop.coupling});
  }
  for (const Case& c : all) {
    const Q kc = dc_bound(c.V, c.pb.structure.K(c.pb.T()));
    const multidof::CouplingCheck above = multidof::check_theorem4(c.pb, scaled(c.V, kc * Q(101, 100)));
    const multidof::CouplingCheck below = multidof::check_theorem4(c.pb, scaled(c.V, kc * Q(9, 10)));
    const bool good = !above.verdict.holds() && below.verdict.holds() && below.verdict.status == Status::exact;
    cases.count(true);
    ok = ok && good;
    e << c.name << ": kc_DC = " << to_decimal(kc, 6) << ", above " << to_string(above.verdict.outcome) << " ("
      << to_string(above.verdict.status) << "), below " << to_string(below.verdict.outcome) << " ("
      << to_string(below.verdict.status) << ")" << (&c == &all.back() ? "" : "; ");
  }
  check.claim("ext.conservatism.dc_bound", "Lemma 1 at z = 1",
              "Theorem 5 concludes for a coupling V/kc only if kc < kc_DC = min_j V(1)_jj / K_jj, K = T/2 Delta_D^-1 "
              "(X (V(1)/kc - K) > 0 with X in G): Theorem 4's program does not hold at 1.01 kc_DC and holds (exact re-check) "
              "at 0.9 kc_DC -- Sec. VI case ii nominal and perturbed with (27), the contact scene N = 2",
              Status::numeric, ok, e.str(), {cases});
}
