// proofs/ext_loop_max.cpp -- beyond the papers: the largest stable gain of the loop as written, for
// any number of DOF (stability/loop_max.hpp, `stability --scene S --max NAME` beyond one DOF),
// checked against computations that share none of its numerics (no Arb exponential, Krawczyk
// test, eigenvalue enclosure or deflation):
//   - one DOF, the closed form of ext.stability.pure_mass (device 1/(m s^2), wall K + B(z-1)/(Tz)):
//     K* = (2B/T)(2m - BT)/(2m + BT), exact, inside the supremum's enclosure;
//   - two DOF, pure masses on a spring-damper environment coupling them, scaled by g: the plant's
//     exponentials are rational, so sim/closed_loop.hpp builds M(g) exactly and Schur-Cohn on
//     det(zI - M(g)) decides each g exactly; bisected to 2^-40 of a 2e-6 bracket around the answer,
//     the bracket must meet the supremum's enclosure, itself 1e-15 relative or narrower.
#include <sstream>

#include "hapstab/lti/realization.hpp"
#include "hapstab/poly/stability.hpp"
#include "hapstab/sim/closed_loop.hpp"
#include "hapstab/stability/loop_max.hpp"
#include "proofs/proof.hpp"

namespace {

using namespace hapstab;
using Q = rational;

// K_e + B_e (z - 1)/(T z) on each DOF (states: the previous positions), a spring Kc between them
StateSpace<Q> spring_dampers(const Q& g, const std::vector<Q>& K, const std::vector<Q>& B, const Q& Kc, const Q& T) {
  const long N = static_cast<long>(K.size());
  MatQ C = MatQ::Zero(N, N), D = MatQ::Zero(N, N);
  for (long i = 0; i < N; ++i) {
    C(i, i) = -g * B[static_cast<size_t>(i)] / T;
    D(i, i) = g * (K[static_cast<size_t>(i)] + B[static_cast<size_t>(i)] / T + Kc);
  }
  if (N == 2) D(0, 1) = D(1, 0) = -g * Kc;
  return {MatQ::Zero(N, N), MatQ::Identity(N, N), C, D, T};
}

bool exactly_stable(const sim::LoopSpec& s) {
  const std::optional<MatQ> M = sim::sampled_closed_loop(s).exact;
  return M && schur_stable(charpoly(*M));
}

double rel(const Q& a, const Q& b) { return static_cast<double>(abs(a - b) / b); }

}  // namespace

HAPSTAB_PROOF(ext_loop_max, "ext", "the multi-DOF supremum against closed forms and exact Schur bisection") {
  // ---- one DOF: the pure-mass closed form ---------------------------------------------------------
  proofs::Instances one{"(m, B, T) with 0 < BT < 2m: K* inside the enclosure, 1e-15 wide", 6};
  bool ok1 = true;
  double worst1 = 0;
  for (const Q& m : {Q(1, 10), Q(1)})
    for (const Q& B : {Q(1, 2), Q(2), Q(10)})
      for (const Q& T : {Q(1, 1000), Q(1, 100)}) {
        if (!one.count(B * T < 2 * m)) continue;
        const Q K = 2 * B / T * (2 * m - B * T) / (2 * m + B * T);
        const stability::LoopAt at = [&](const Q& p) {
          sim::LoopSpec s;
          s.T = T;
          s.devices = {sim::mass_damper("d", m, Q(0))};
          s.environment = spring_dampers(Q(1), {p}, {B}, Q(0), T);
          return s;
        };
        const stability::LoopMax r = stability::max_parameter(at, K / 2, "K", 2, 16);  // no coupling, a static wall affine in p: 2 values fix it
        // M(0) has the mass's Jordan block at z = 1, so the walk cannot cover (0, a): the supremum is
        // not stated (undecided); what is certified -- the crossing and [a, b] stable -- must agree
        const bool crossing = r.crossing.lo <= K && K <= r.crossing.hi && rel(r.crossing.hi, r.crossing.lo) <= 1e-15;
        const bool good = crossing && r.stable_to <= K && r.stable_from < r.stable_to &&
                          (r.outcome == Outcome::holds || (r.outcome == Outcome::undecided && r.stable_from > 0));
        worst1 = std::max(worst1, crossing ? rel(r.crossing.hi, r.crossing.lo) : 1.0);
        ok1 = ok1 && good;
        // its certificate: the scene as a user writes it (one DOF: `stability --scene` certifies it by its one-DOF
        // kind, a path that shares nothing with loop_max), the closed form exactly inside
        proofs::CertificateRequest c;
        c.args = {"stability", "--scene", "{input}", "--max", "K", "--quiet"};
        c.input = "[scene]\nname = \"pure mass on a wall\"\nT = \"" + T.str() + "\"\n[parameters]\nK = \"" + (K / 2).str() +
                  "\"\n[[device]]\nname = \"d\"\nm = \"" + m.str() + "\"\nb = \"0\"\n[environment]\ntf = [[\"K + " + B.str() +
                  "*(z-1)/(T*z)\"]]\n";
        c.contains = K.str();
        check.certify("ext.stability.max_multidof_1dof", c);
      }
  std::ostringstream e1;
  e1 << "loop_max's crossing of K on the pure-mass wall contains the closed form at every instance, and its certified "
        "stable interval lies below it; widest enclosure "
     << worst1 << " relative";
  check.claim("ext.stability.max_multidof_1dof", "closed form, n = 0",
              "stability --max through the closed-loop matrix (the multi-DOF path) on a one-DOF pure mass 1/(m s^2) with the "
              "wall K + B(z-1)/(Tz): its certified crossing holds (2B/T)(2m - BT)/(2m + BT), 1e-15 relative wide, and the "
              "interval it proves stable lies below (M(0) has a Jordan block at z = 1, so (0, a) is not covered and the "
              "supremum is not stated); its certificates: sup K of each scene (the one-DOF kind), the closed form inside",
              Status::certified, ok1, e1.str(), {one});

  // ---- two DOF: exact Schur bisection on det(zI - M(g)) --------------------------------------------
  proofs::Instances two{"2-DOF pure-mass loops (masses, coupling spring) whose exact bisection bracket was compared", 4};
  bool ok2 = true;
  double worst2 = 0, width2 = 0;
  std::ostringstream first;
  for (const Q& m2 : {Q(1, 10), Q(3, 10)})
    for (const Q& Kc : {Q(0), Q(20), Q(50)}) {
      const Q T(1, 100);
      const stability::LoopAt at = [&](const Q& g) {
        sim::LoopSpec s;
        s.T = T;
        s.devices = {sim::mass_damper("left", Q(1, 10), Q(0)), sim::mass_damper("right", m2, Q(0))};
        s.environment = spring_dampers(g, {Q(200), Q(300)}, {Q(2), Q(3)}, Kc, T);
        return s;
      };
      const stability::LoopMax r = stability::max_parameter(at, Q(1), "g", 2, 16);  // no coupling, spring_dampers affine in g
      // pure masses: M(0) has Jordan blocks at z = 1; since stop 78 the resultant joins (0, a] (M rational) and the
      // supremum is stated, open at 0
      if (r.crossing.hi == 0 || r.stable_to <= r.stable_from || r.outcome != Outcome::holds || !r.open_at_zero) {
        ok2 = false;
        if (first.str().empty()) first << "; no certified crossing and interval at Kc = " << Kc.str() << ": " << r.note;
        continue;
      }
      Q lo = r.stable_to * (1 - Q(1, 1000000)), hi = r.crossing.hi * (1 + Q(1, 1000000));
      if (!exactly_stable(at(lo)) || exactly_stable(at(hi))) {
        ok2 = false;
        if (first.str().empty()) first << "; the exact verdicts do not bracket the answer at Kc = " << Kc.str();
        continue;
      }
      for (int it = 0; it < 40; ++it) {
        const Q mid = (lo + hi) / 2;
        (exactly_stable(at(mid)) ? lo : hi) = mid;
      }
      two.count(true);
      const bool meet = r.crossing.lo <= hi && lo <= r.crossing.hi && rel(r.crossing.hi, r.crossing.lo) <= 1e-15 &&
                        r.stable_to <= hi && exactly_stable(at(r.stable_to / 1000000)) && exactly_stable(at(r.stable_to / 2));
      worst2 = std::max(worst2, rel((r.crossing.lo + r.crossing.hi) / 2, (lo + hi) / 2));
      // its certificate: the scene as written (kind stability-loop-max), the exact bisection's bracket inside
      proofs::CertificateRequest c;
      c.args = {"stability", "--scene", "{input}", "--max", "g", "--quiet"};
      const std::string k0 = (200 + Kc).str(), k1 = (300 + Kc).str(), off = (-Kc).str();
      c.input = "[scene]\nname = \"two pure masses\"\nT = \"" + T.str() + "\"\n[parameters]\ng = \"1\"\n[[device]]\n"
                "name = \"left\"\nm = \"1/10\"\nb = \"0\"\n[[device]]\nname = \"right\"\nm = \"" + m2.str() +
                "\"\nb = \"0\"\n[environment]\ntf = [[\"" + k0 + " + 2*(z-1)/(T*z)\", \"" + off + "\"], [\"" + off + "\", \"" + k1 +
                " + 3*(z-1)/(T*z)\"]]\ngain = \"g\"\n";
      c.contains = ((lo + hi) / 2).str();
      check.certify("ext.stability.max_multidof_2dof", c);
      width2 = std::max(width2, rel(hi, lo));
      ok2 = ok2 && meet;
    }
  std::ostringstream e2;
  e2 << "the crossing in g of each loop against the exact bisection (Schur-Cohn on det(zI - M(g)), M exact): brackets meet, "
        "the supremum stated (open at 0, by the resultant) and exactly stable at sup/10^6 and sup/2; largest midpoint difference "
     << worst2 << " relative, bracket width <= " << width2 << first.str();
  check.claim("ext.stability.max_multidof_2dof", "det(zI - M(g)), exact",
              "stability --max on a 2-DOF loop (pure masses, coupled spring-damper environment scaled by g): the certified "
              "crossing (1e-15 relative) meets the bracket of an exact Schur-Cohn bisection on the characteristic "
              "polynomial of the exactly built closed-loop matrix, and the supremum is stated (since stop 78: (0, a] by the "
              "resultant) with the loop exactly stable at sup/10^6 and sup/2; its certificates: sup g of each scene (kind "
              "stability-loop-max), the exact bracket's midpoint inside",
              Status::certified, ok2, e2.str(), {two});
}
