// hapstab/conservatism/theorem5_max.hpp -- how conservative Theorem 5 is on a scene (issue 42):
// the largest value of a scene parameter p for which Theorem 5 still concludes stability, beside
// the largest for which the loop as written is stable (`hapstab stability --scene S --max NAME
// --conservatism`). Their ratio, exact / Theorem 5 >= 1, is what the LMI test gives up there.
//
// What "Theorem 5 concludes" means for a scene. Theorem 5 is a statement about a family: if (16)
// holds for (P, X, Q_E, Q_V), the loop is stable for every coupling V whose V-hat^Gamma
// (Gamma = sqrt(X)) is Delta_V-OSP with Delta_V >= Gamma^-1 Q_V Gamma^-1. A scene writes ONE
// coupling V ([coupling]). Theorem 5 concludes stability of that loop iff some (P, X, Q_E, Q_V)
// satisfies (16) AND V-hat^Gamma is OSP at a level >= Gamma^-1 Q_V Gamma^-1 for the same X; with
// Q_V := Gamma Delta_V Gamma (Remark 3's substitution) that is exactly Theorem 4's three
// conditions for that V over X in G (an OSP level may always be lowered), posed as one LMI
// program with both storage functions: multidof::check_theorem4. It also needs Theorem 5's
// premises: Assumption 1 and the blocks' hidden modes stable as written (multidof::
// scene_premises). So, at each p:
//   concludes        [exact]     premises hold (exact) and check_theorem4 holds (exact re-check);
//   does not         [exact]     a premise fails (proven); or Lemma 1's DC condition fails: V-hat^Gamma
//                                OSP forces X (V(1) - K) symmetric positive definite (analysis.hpp,
//                                check_vhat_osp), and with X = blockdiag(g_i I) that needs every
//                                diagonal entry of V(1) - K > 0 (checked exactly first, no program);
//                                or check_theorem4 is proven infeasible;
//   does not         [certified] the loop as written is proven NOT stable at p (decide_loop):
//                                Theorem 5 is sound, so it cannot conclude there;
//   undecided                    anything else (a numeric-only verdict is never an end).
// A scene without [coupling] is refused by name: with V = 0, V-hat^Gamma = -(z-1)/(Tz) K has
// X (V(1) - K) = -X K < 0, which Lemma 1 forbids (analysis.hpp): Theorem 5 never concludes for
// the direct connection. A [coupling] with a [delay] is refused too: the delayed loop feeds V the
// computed force and the devices the delayed one, a loop Theorem 4 with z^-n E does not describe
// (multidof/loop_as_written.hpp).
//
// theorem5_max: from the scene's value of p, certified conclusions are sought by factors of 2
// downwards and certified non-conclusions upwards (10 of each by default: a factor of 1024), then bisected (geometric midpoints, short
// decimals) until the bracket [lo, hi] is 10^-digits relative or a midpoint is undecided. Each end
// says what decided it. The region {p : Theorem 5 concludes} need not be an interval in general,
// so the bracket holds a boundary of it ("concludes at lo, not at hi"). For a gain g of the
// environment (E := g E, `gain = "g"`) it is an interval (0, sup]: if (P, X, Q_E, Q_V) with the
// coupling's storage works at g, then (t P, X, t Q_E, Q_V) works at t g, t in (0, 1], because
// E-hat's ISP LMI is homogeneous in (P, Q_E, E) and (14) is affine in t, > 0 at t = 0 and t = 1.
//
// exact_max_by_verdicts: the loop as written's stable -> NOT stable change by bisection on certified
// decide_loop verdicts, for the families stability/loop_max.hpp cannot take (not affine in p:
// a coupling with a feedthrough makes x_e = xi + V u, u = -E x_e an algebraic loop, and
// (I + p D_E D_V)^-1 is not affine). Its bracket holds a change of the verdict, not a proven
// supremum: stability between the sampled points is not proven.
//
// Implements: paper 000 Theorem 4, Theorem 5, Remark 3, Sec. VI.
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "hapstab/lmi/solve.hpp"
#include "hapstab/multidof/analysis.hpp"
#include "hapstab/numeric/result.hpp"
#include "hapstab/scene/scene.hpp"
#include "hapstab/stability/loop_max.hpp"

namespace hapstab::conservatism {

/// The scene with the parameter set to p (a scene loaded with NAME = p).
using SceneAt = std::function<scene::Scene(const rational& p)>;

/// One certified verdict at one value of the parameter.
struct PointVerdict {
  rational at = 0;
  std::optional<bool> yes;  ///< concludes / stable; nullopt: undecided
  Status status = Status::failed;
  std::string why;
  /// theorem5_at: Theorem 4's program proven infeasible by the two-frequency witness (as decided)
  std::optional<multidof::CouplingWitness> witness;
  bool proven() const { return yes.has_value() && (status == Status::exact || status == Status::certified); }
};

/// Does Theorem 5 conclude stability of the scene's loop with its [coupling]? (see the header).
/// InputError for a scene without [coupling], or with a [delay] beside one.
PointVerdict theorem5_at(const scene::Scene& sc, const lmi::Options& opt = {});

/// Is the loop stable (stability::decide_loop)?
PointVerdict stable_at(const sim::LoopSpec& loop);

/// The bracket of a change of a certified verdict, yes at lo, no at hi.
struct VerdictBracket {
  /// holds: a certified bracket, or a certified yes at every value tried (hi empty); fails: a
  /// certified no at every value tried; undecided: anything else (an undecided verdict is never
  /// counted as a yes or a no)
  Outcome outcome = Outcome::undecided;
  std::optional<PointVerdict> lo, hi;    ///< the ends (certified); hi empty: yes up to the largest value tried
  std::vector<PointVerdict> steps;       ///< every verdict computed, in order
  std::string note;                      ///< what the bracket means, or why there is none
  double seconds = 0;
  Enclosure<rational> bracket() const { return {lo ? lo->at : rational(0), hi ? hi->at : rational(0)}; }
};

/// Bisection on a certified verdict `yes_at` from `reference` > 0 (factors of 2: at most `steps`
/// down and `steps` up, 1..60) to 10^-digits relative (digits 1..12).
VerdictBracket bisect_verdicts(const std::function<PointVerdict(const rational&)>& yes_at, const rational& reference,
                               int digits, int steps = 10);

/// Theorem 5's boundary (theorem5_at along p).
VerdictBracket theorem5_max(const SceneAt& at, const rational& reference, const std::string& name, int digits = 6,
                            int steps = 10, const lmi::Options& opt = {});

/// The loop as written's stable -> NOT stable change (stable_at along p).
VerdictBracket exact_max_by_verdicts(const stability::LoopAt& at, const rational& reference, const std::string& name,
                                     int digits = 12, int steps = 10);

/// exact / Theorem 5, rounded outward to a rational enclosure: [exact.lo / t5.hi, exact.hi / t5.lo].
/// nullopt when either side has no finite certified bracket.
std::optional<Enclosure<rational>> ratio(const Enclosure<rational>& exact, const VerdictBracket& theorem5);

}  // namespace hapstab::conservatism
