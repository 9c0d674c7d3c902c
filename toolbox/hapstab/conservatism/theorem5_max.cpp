#include "hapstab/conservatism/theorem5_max.hpp"

#include <chrono>
#include <cmath>

#include "hapstab/multidof/analysis.hpp"
#include "hapstab/multidof/scene_analysis.hpp"
#include "hapstab/multidof/scene_multidof.hpp"
#include "hapstab/multidof/structure.hpp"
#include "hapstab/numeric/decimal.hpp"
#include "hapstab/numeric/error.hpp"
#include "hapstab/numeric/interrupt.hpp"
#include "hapstab/stability/loop_as_written.hpp"

namespace hapstab::conservatism {

namespace {

using Clock = std::chrono::steady_clock;

/// A short decimal strictly inside (lo, hi), near their geometric mean (lo > 0).
rational midpoint(const rational& lo, const rational& hi) {
  const double g = std::sqrt(to_real<double>(lo)) * std::sqrt(to_real<double>(hi));
  for (int d = 3; d <= 40; ++d) {
    const auto q = try_parse_rational(to_decimal(exact_rational(g), d));
    if (q && lo < *q && *q < hi) return *q;
  }
  return (lo + hi) / 2;
}

}  // namespace

PointVerdict theorem5_at(const scene::Scene& sc, const lmi::Options& opt) {
  if (!sc.loop.coupling)
    throw InputError(sc.file + ": Theorem 5 needs the scene's [coupling]: it concludes stability only for a coupling V "
                     "whose V-hat^Gamma is OSP at the level (16) asks, and with no coupling (V = 0) X (V(1) - K) = -X K "
                     "< 0, which Lemma 1 forbids: it never concludes for the direct connection. Write the coupling to "
                     "study in [coupling]");
  const multidof::SceneProblem sp = multidof::problem_from_scene(sc, multidof::SceneUse::analyze);
  if (sp.delay > 0)
    throw InputError(sc.file + ": [delay] with a [coupling]: the delayed loop feeds V the computed force and the devices "
                     "the delayed one, a loop Theorem 4 with z^-n E does not describe; Theorem 5 is not compared here");
  PointVerdict v;
  const std::vector<multidof::AssumptionCheck> premises = multidof::scene_premises(sp);
  const std::string failure = multidof::premise_failure(premises);
  for (const auto& a : premises)
    if (a.verdict.fails() && a.verdict.proven()) {
      v.yes = false;
      v.status = Status::exact;
      v.why = "does not conclude [exact]: " + failure;
      return v;
    }
  // Lemma 1's DC condition (analysis.hpp, check_vhat_osp): V-hat^Gamma OSP forces X (V(1) - K)
  // symmetric positive definite; X = blockdiag(g_i I), g_i > 0, so every diagonal entry of
  // V(1) - K must be > 0. One that is not: no X, no conclusion (exact, no program needed).
  {
    const StateSpace<rational>& V = *sc.loop.coupling;
    const Eigen::Index n = V.A.rows();
    std::optional<MatQ> V1;  // none when V has a pole at z = 1
    try {
      V1 = n == 0 ? V.D : MatQ(V.D + V.C * multidof::inverse(MatQ(MatQ::Identity(n, n) - V.A), "I - A_V") * V.B);
    } catch (const InputError&) {
    }
    if (V1) {
      const MatQ M = *V1 - sp.problem.structure.K(sp.problem.T());
      for (Eigen::Index j = 0; j < M.rows(); ++j)
        if (M(j, j) <= 0) {
          v.yes = false;
          v.status = Status::exact;
          v.why = "does not conclude [exact]: Lemma 1's DC condition fails: (V(1) - K)_" + std::to_string(j + 1) + "," +
                  std::to_string(j + 1) + " = " + to_decimal(M(j, j), 6) + " <= 0 (V(1) = " + to_decimal((*V1)(j, j), 6) +
                  ", K = T/(2 Delta) = " + to_decimal((*V1)(j, j) - M(j, j), 6) +
                  "), so X (V(1) - K) is not positive definite for any X in G";
          return v;
        }
    }
  }
  multidof::CouplingCheck cc;
  try {
    cc = multidof::check_theorem4(sp.problem, *sc.loop.coupling, opt);
  } catch (const InputError& e) {  // a program too large to pose
    cc.verdict = {Outcome::undecided, Status::failed, e.what()};
  }
  if (cc.verdict.holds() && cc.verdict.proven() && failure.empty()) {
    v.yes = true;
    v.status = Status::exact;
    v.why = "concludes [exact]: Theorem 4 holds for the scene's coupling (exact re-check) and every premise holds";
    return v;
  }
  if (cc.verdict.fails() && cc.verdict.proven()) {
    v.yes = false;
    v.status = Status::exact;
    v.why = "does not conclude [exact]: Theorem 4's program for the scene's coupling is infeasible (exact certificate" +
            std::string(cc.witness ? ": a two-frequency witness" : "") + ")";
    v.witness = cc.witness;
    return v;
  }
  // Soundness: where the loop is proven NOT stable, no sufficient test concludes.
  const PointVerdict s = stable_at(sp.loop);
  if (s.proven() && !*s.yes) {
    v.yes = false;
    v.status = s.status;
    v.why = std::string("does not conclude [") + to_string(s.status) + "]: the loop as written is NOT stable there, and Theorem 5 is sound";
    return v;
  }
  v.why = "undecided: " + (failure.empty() ? "Theorem 4's program is " + std::string(cc.verdict.holds() ? "feasible" : "infeasible") +
                                                 " but not certified (" + to_string(cc.verdict.status) + ")"
                                           : failure);
  return v;
}

PointVerdict stable_at(const sim::LoopSpec& loop) {
  const stability::LoopVerdict d = stability::decide_loop(loop);
  PointVerdict v;
  v.yes = d.stable;
  v.status = d.stable ? d.status : Status::failed;
  v.why = d.stable ? std::string(*d.stable ? "stable [" : "NOT stable [") + to_string(d.status) + "]: " + d.method : d.why;
  return v;
}

VerdictBracket bisect_verdicts(const std::function<PointVerdict(const rational&)>& yes_at, const rational& reference,
                               int digits, int steps) {
  if (steps < 1 || steps > 60) throw InputError("steps must be in 1..60, got " + std::to_string(steps));
  if (reference <= 0) throw InputError("the reference value must be > 0");
  if (digits < 1 || digits > 12) throw InputError("digits must be in 1..12, got " + std::to_string(digits));
  const auto t0 = Clock::now();
  VerdictBracket b;
  auto ask = [&](const rational& p) {
    interruption_point();
    PointVerdict v = yes_at(p);
    v.at = p;
    b.steps.push_back(v);
    return v;
  };
  auto done = [&](std::string note) {
    b.note = std::move(note);
    b.seconds = std::chrono::duration<double>(Clock::now() - t0).count();
    return b;
  };
  // 1. a certified yes at or below the reference
  PointVerdict v = ask(reference);
  rational p = reference;
  std::optional<PointVerdict> first_no;  // a certified no met on the way down bounds the search up
  for (int k = 0; !(v.proven() && *v.yes) && k < steps; ++k) {
    if (v.proven() && !first_no) first_no = v;
    p /= 2;
    v = ask(p);
  }
  if (!(v.proven() && *v.yes)) {
    // "no at every value tried" only when every verdict was a proven no: an undecided one is
    // neither answer (it made "NOT stable at every value tried" out of undecided verdicts before)
    long undecided = 0;
    for (const auto& w : b.steps) undecided += w.proven() ? 0 : 1;
    const std::string range = to_decimal(p, 6) + " .. " + to_decimal(reference, 6);
    if (undecided == 0) {
      b.outcome = Outcome::fails;
      return done("a certified no at every value tried, " + range);
    }
    b.outcome = Outcome::undecided;
    return done("no certified yes at the values tried, " + range + ": " + std::to_string(undecided) + " of " +
                std::to_string(b.steps.size()) + " verdicts undecided (" + b.steps.back().why.substr(0, 160) + ")");
  }
  b.lo = v;
  // 2. a certified no above it
  if (first_no) {
    b.hi = *first_no;
    for (auto it = b.steps.rbegin(); it != b.steps.rend(); ++it)  // the smallest no above lo
      if (it->proven() && !*it->yes && it->at > b.lo->at) {
        b.hi = *it;
        break;
      }
  } else {
    for (int k = 0; k < steps; ++k) {
      const PointVerdict w = ask(b.lo->at * 2);
      if (!w.proven()) {  // outcome stays undecided: a yes below, nothing known above
        b.outcome = Outcome::undecided;
        return done("undecided at " + to_decimal(w.at, 8) + " (" + w.why + "): no certified no found above the last yes");
      }
      if (*w.yes) b.lo = w;
      else {
        b.hi = w;
        break;
      }
    }
    if (!b.hi) {
      b.outcome = Outcome::holds;
      return done("yes at every value tried up to " + to_decimal(b.lo->at, 8) + ": no upper end found");
    }
  }
  // 3. bisection
  const rational tol = pow10(-digits);
  while ((b.hi->at - b.lo->at) > tol * b.lo->at) {
    const PointVerdict w = ask(midpoint(b.lo->at, b.hi->at));
    if (!w.proven()) {
      b.outcome = Outcome::holds;
      const std::string why = w.why.size() > 160 ? w.why.substr(0, 157) + "..." : w.why;
      return done("the bisection stopped at an undecided midpoint " + to_decimal(w.at, 8) + " (" + why + ")");
    }
    (*w.yes ? b.lo : b.hi) = w;
  }
  b.outcome = Outcome::holds;
  return done("");
}

VerdictBracket theorem5_max(const SceneAt& at, const rational& reference, const std::string& name, int digits,
                            int steps, const lmi::Options& opt) {
  const scene::Scene first = at(reference);
  theorem5_at(first, opt);  // the refusals (no coupling, delay) before any search
  const bool environment_gain = first.root["environment"]["gain"].value_or(std::string()) == name;
  VerdictBracket b = bisect_verdicts([&](const rational& p) { return theorem5_at(at(p), opt); }, reference, digits, steps);
  const std::string pre = "Theorem 5 (Theorem 4 with the scene's coupling, Assumption 1, hidden modes) ";
  if (b.outcome == Outcome::fails) b.note = pre + "concludes at none of the values of " + name + " tried: " + b.note;
  else if (!b.lo) b.note = pre + "undecided: " + b.note;
  else if (!b.hi && b.outcome == Outcome::undecided)
    b.note = pre + "concludes up to " + name + " = " + to_decimal(b.lo->at, 8) + ", then " + b.note;
  else if (!b.hi) b.note = pre + "concludes up to " + name + " = " + to_decimal(b.lo->at, 8) + (b.note.empty() ? "" : "; " + b.note);
  else
    b.note = pre + "concludes at " + name + " = lo and not at hi: " +
             (environment_gain ? "the supremum of its region lies in [lo, hi] (" + name +
                                     " is the gain of [environment]: the region is an interval (0, sup])"
                               : "a boundary of its region lies in [lo, hi] (the region need not be an interval in " + name + ")") +
             (b.note.empty() ? "" : "; " + b.note);
  return b;
}

VerdictBracket exact_max_by_verdicts(const stability::LoopAt& at, const rational& reference, const std::string& name,
                                     int digits, int steps) {
  VerdictBracket b = bisect_verdicts([&](const rational& p) { return stable_at(at(p)); }, reference, digits, steps);
  if (b.outcome == Outcome::fails) b.note = "NOT stable at every value of " + name + " tried: " + b.note;
  else if (!b.lo) b.note = "undecided: " + b.note;
  else if (!b.hi && b.outcome == Outcome::undecided)
    b.note = "stable up to " + name + " = " + to_decimal(b.lo->at, 8) + ", then " + b.note;
  else if (!b.hi) b.note = "stable at every value of " + name + " tried, up to " + to_decimal(b.lo->at, 8) + (b.note.empty() ? "" : "; " + b.note);
  else
    b.note = "the certified verdict changes from stable (lo) to NOT stable (hi) in [lo, hi]; stability between the "
             "values tried is not proven, so this is not a proven supremum" + (b.note.empty() ? "" : "; " + b.note);
  return b;
}

std::optional<Enclosure<rational>> ratio(const Enclosure<rational>& exact, const VerdictBracket& theorem5) {
  if (!theorem5.lo || !theorem5.hi || exact.lo <= 0 || theorem5.lo->at <= 0) return std::nullopt;
  return Enclosure<rational>{exact.lo / theorem5.hi->at, exact.hi / theorem5.lo->at};
}

}  // namespace hapstab::conservatism
