// hapstab/multidof/scene_analysis.cpp -- see scene_analysis.hpp.
#include "hapstab/multidof/scene_analysis.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <sstream>

#include "hapstab/lmi/certify.hpp"
#include "hapstab/multidof/symmetry.hpp"
#include "hapstab/numeric/error.hpp"
#include "hapstab/numeric/interrupt.hpp"
#include "hapstab/scene/schema.hpp"

namespace hapstab::multidof {

namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

std::string seconds_text(double s) {
  std::ostringstream o;
  o << s;
  return o.str();
}

}  // namespace

std::vector<AssumptionCheck> scene_premises(const SceneProblem& sp) {
  auto checks = check_assumptions(sp.problem.structure, sp.operators, sp.operator_names, sp.device_evidence);
  for (auto& c : hidden_mode_premises(sp)) checks.push_back(std::move(c));
  return checks;
}

std::string premise_failure(const std::vector<AssumptionCheck>& premises) {
  for (const auto& a : premises)
    if (!a.verdict.holds())
      return (a.name.rfind("Assumption 1", 0) == 0 ? "Assumption 1 " : "a premise ") +
             std::string(a.verdict.fails() ? "fails" : "is undecided") + " (" + a.name + ")";
  return "";
}

std::string delay_text(const SceneProblem& sp) {
  const int m = sp.problem.structure.m();
  return "[delay] " + std::to_string(sp.delay) + " sample period(s): E := z^-" + std::to_string(sp.delay) +
         " E (the force computed at kT acts from (k + " + std::to_string(sp.delay) + ")T; " +
         std::to_string(sp.delay * m) + " shift states folded into E's realisation, exact)";
}

std::string SceneAnalysis::verdict() const { return lmi::to_string(lmi::feasibility_of(lmis.verdict.outcome)); }

namespace {
struct PremiseState {
  bool some_fails = false, some_undecided = false;
};
PremiseState premise_state(const std::vector<AssumptionCheck>& premises) {
  PremiseState s;
  for (const auto& p : premises) {
    s.some_fails = s.some_fails || p.verdict.fails();
    s.some_undecided = s.some_undecided || !p.verdict.decided();
  }
  return s;
}
}  // namespace

bool SceneDesign::undecided() const {
  if (ok() || !contradiction.empty() || !feasible) return false;
  const PremiseState s = premise_state(premises);
  return !s.some_fails && s.some_undecided;
}

bool SceneAnalysis::undecided() const {
  if (ok() || as_written_unstable()) return false;
  const PremiseState s = premise_state(premises);
  if (s.some_fails) return false;  // a premise fails: no conclusion, whatever (16) is
  if (!certified) return true;     // (16) not proven either way
  return feasible && s.some_undecided;  // (16) proven infeasible: Theorem 5 does not conclude
}

AnalysisResult analyze_scene_lmis(const SceneProblem& sp, const lmi::Options& opt, bool symmetry) {
  std::string why_not;
  std::optional<SymmetryResult> split;
  if (symmetry) split = split_problem(sp, why_not);
  if (split) {
    const std::string group = split->group;
    if (auto r = analyze_by_symmetry(sp, std::move(*split), opt, why_not)) return std::move(*r);
    why_not = "the split by " + group + " did not decide: " + why_not;
  }
  if (sp.problem.E.states() > limits::multidof_states)  // problem_from_scene let it through for the split
    throw InputError("E has " + std::to_string(sp.problem.E.states()) + " states (reduced), more than the limit of " +
                     std::to_string(limits::multidof_states) + " for Theorem 5's whole program; " +
                     (symmetry ? why_not : "the split by identical DOFs would work on its blocks (without --no-symmetry)"));
  AnalysisResult r = analyze(sp.problem, opt);
  if (!why_not.empty()) r.plan.insert(r.plan.begin(), PlanStep{"symmetry of identical DOFs", split ? "did not decide" : "skipped", why_not});
  else if (!symmetry) r.plan.insert(r.plan.begin(), PlanStep{"symmetry of identical DOFs", "skipped", "--no-symmetry"});
  return r;
}

SceneAnalysis analyze_scene(const scene::Scene& sc, const SceneAnalysisOptions& opt) {
  const auto t0 = Clock::now();
  SceneAnalysis a;
  scene::check_command(sc.root, sc.file, "multidof analyze");  // what it does not model is refused
  const auto stage = [&](const char* name) {
    if (opt.stage) opt.stage(name);
  };
  stage("realising the blocks (E reduced, hidden modes)");
  a.scene = problem_from_scene(sc, SceneUse::analyze);
  a.seconds.realisation = opt.load_seconds + seconds_since(t0);
  stage("Theorem 5's LMIs (16) and their certificate");
  a.lmis = analyze_scene_lmis(a.scene, opt.lmi, opt.symmetry);
  a.feasible = a.lmis.verdict.holds();
  a.certified = a.lmis.verdict.proven();
  const auto t1 = Clock::now();
  stage("Assumption 1 and the hidden modes");
  a.premises = scene_premises(a.scene);
  a.seconds.assumptions = seconds_since(t1);
  a.premises_hold = all_hold(a.premises);
  a.stability_concluded = a.feasible && a.certified && a.premises_hold;
  const auto t2 = Clock::now();
  stage("the loop as written (closed-loop decision)");
  a.loop = loop_as_written(a.scene, a.premises_hold, opt.lmi);
  a.seconds.loop_as_written = seconds_since(t2);
  a.seconds.total = opt.load_seconds + seconds_since(t0);
  return a;
}

sim::LoopSpec loop_with_coupling(const SceneProblem& sp, const StateSpace<rational>* V) {
  sim::LoopSpec spec = sp.loop;  // one copy of E as written, not two (a 1024-device one is 2 GB)
  if (sp.delay > 0) spec.environment = delayed(sp.E_written(), sp.delay);
  spec.delay = 0;
  if (V) spec.coupling = *V;
  else spec.coupling.reset();
  return spec;
}

sim::SimResult simulate_with_coupling(const SceneProblem& sp, const StateSpace<rational>* V, double duration) {
  sim::SimOptions so;
  so.steps = static_cast<long>(std::ceil(duration / to_real<double>(sp.problem.T())));
  so.energy = false;
  so.max_velocity = 1e6;
  so.progress = [](double) { interruption_point(); };
  return sim::Simulator(loop_with_coupling(sp, V)).run(so);
}

Decay velocities_decay(const sim::SimResult& r, double T) {
  const auto& tr = r.samples;
  const int N = tr.N;
  double peak = 0, tail = 0;
  const size_t rows = tr.rows();
  const size_t tail_rows = static_cast<size_t>(std::max(1.0, 1.0 / T));
  for (size_t i = 0; i < rows; ++i)
    for (int j = 0; j < N; ++j) {
      const double a = std::abs(tr.v[i * static_cast<size_t>(N) + static_cast<size_t>(j)]);
      peak = std::max(peak, a);
      if (i + tail_rows >= rows) tail = std::max(tail, a);
    }
  std::ostringstream o;
  o << "simulated " << r.summary.steps_run << " steps (exact ZOH, sim/): peak |v| = " << peak
    << ", max |v| over the last second = " << tail << ", trend " << r.summary.trend
    << (r.summary.diverged ? " (diverged)" : "");
  return {!r.summary.diverged && (tail <= 1e-3 * peak || tail < 1e-9), o.str()};
}

namespace {

// Theorem 6 on the scene: by the symmetry split of identical DOFs where the scene has it
// (design_by_symmetry), else the whole's design() -- within the whole's size limits, which
// problem_from_scene left to this point for a symmetric scene.
DesignResult design_scene_coupling(const scene::Scene& sc, const SceneProblem& sp, const DesignOptions& opt, bool symmetry) {
  std::string why_not;
  std::optional<SymmetryResult> split;
  if (sp.symmetric && !symmetry) why_not = "--no-symmetry";
  if (sp.symmetric && symmetry) split = split_problem(sp, why_not);
  if (split) {
    if (auto r = design_by_symmetry(sp, *split, opt, why_not)) {
      if (r->verdict.decided() && r->verdict.proven()) return std::move(*r);
      why_not = "its coupling was not verified: " + r->verdict.evidence;
    }
    why_not = "the split by " + split->group + " did not decide: " + why_not;
  }
  const std::string f = sc.file + ": ";
  if (sp.problem.E.states() > limits::multidof_states)
    throw InputError(f + "E has " + std::to_string(sp.problem.E.states()) + " states (reduced), more than the limit of " +
                     std::to_string(limits::multidof_states) + " that multidof design models" +
                     (why_not.empty() ? std::string() : " (" + why_not + ")"));
  CouplingStructure c = sp.problem.coupling;
  if (sp.symmetric) {
    try {
      check_coupling_structure(c, sp.problem.structure.m(), SceneUse::design, true, f);
    } catch (const InputError& e) {
      throw InputError(std::string(e.what()) + (why_not.empty() ? std::string() : " (" + why_not + ")"));
    }
  }
  DesignResult r = design(sp.problem, opt);
  if (!why_not.empty())
    r.plan.insert(r.plan.begin(), PlanStep{"symmetry of identical DOFs (block-wise)", split ? "did not decide" : "skipped", why_not});
  return r;
}

}  // namespace

SceneDesign design_scene(const scene::Scene& sc, const SceneDesignOptions& opt) {
  if (opt.design.max_iterations < 1 || opt.design.max_iterations > 10000)
    throw InputError("iterations must be in [1, 10000], got " + std::to_string(opt.design.max_iterations));
  if (!(opt.duration > 0 && opt.duration <= 1e6))
    throw InputError("duration must be in (0, 1e6] seconds, got " + seconds_text(opt.duration));
  SceneDesign d;
  scene::check_command(sc.root, sc.file, "multidof design");  // what it does not model is refused
  const auto stage = [&](const char* name) {
    if (opt.stage) opt.stage(name);
  };
  stage("realising the blocks (E reduced, hidden modes)");
  d.scene = problem_from_scene(sc);
  const SceneProblem& sp = d.scene;
  stage("Theorem 6's design (CCL) and its verification");
  d.design = design_scene_coupling(sc, sp, opt.design, opt.symmetry);
  DesignResult& r = d.design;
  stage("Assumption 1 and the hidden modes");
  d.premises = scene_premises(sp);
  d.premise_failure = premise_failure(d.premises);
  // The design's verdict rests on certified checks (Theorem 4, V Schur stable). Beside them: the
  // loop with this V decided as written (certified), and the simulation, a numeric cross-check
  // that can warn but never decides.
  d.feasible = r.verdict.holds();
  const bool certified = d.feasible && r.verdict.proven();
  if (d.has_v()) {
    stage("the loop with the designed V (closed-loop decision)");
    if (sp.delay == 0 && sp.loop.environment) {  // E as written moved into the loop and back: one copy, not two (2 GB at N = 1024)
      auto E = std::move(d.scene.loop.environment);
      d.scene.loop.environment.reset();
      sim::LoopSpec spec = loop_with_coupling(d.scene, &r.V);
      spec.environment = std::move(E);
      d.loop_with_v = decided_loop(spec, "the designed V");
      d.scene.loop.environment = std::move(spec.environment);
    } else {
      d.loop_with_v = decided_loop(loop_with_coupling(sp, &r.V), "the designed V");
    }
    const LoopAsWritten& law = *d.loop_with_v;
    r.verification.push_back({"the loop with this V, as written, is Schur stable (" + law.method + ")",
                              law.stable ? Verdict::of(*law.stable, law.status, law.why)
                                         : Verdict{Outcome::undecided, Status::failed, law.why}});
    if (law.stable && !*law.stable) d.feasible = false;
    stage("the simulated cross-check");
    long plant_states = 0;
    for (const auto& dev : sp.loop.devices) plant_states += dev.G.states();
    for (const auto& op : sp.loop.operators) plant_states += op.Z.states();
    const std::string sim_name = "closed loop simulated, velocities -> 0 (numeric cross-check; scene's devices, operators, inputs)";
    std::optional<sim::SimResult> sr;
    if (plant_states > limits::crosscheck_simulation_states)
      r.verification.push_back(
          {sim_name,
           {Outcome::undecided, Status::numeric,
            "not simulated: the devices and operators have " + std::to_string(plant_states) +
                " continuous states, more than the " + std::to_string(limits::crosscheck_simulation_states) +
                " this cross-check simulates (numeric/limits.hpp; `hapstab simulate` runs the scene); the "
                "closed-loop decision above decides"}});
    else {
      sr = simulate_with_coupling(sp, &r.V, opt.duration);
      d.simulation = velocities_decay(*sr, to_real<double>(sp.problem.T()));
      r.verification.push_back({sim_name, Verdict::of(d.simulation->decays, Status::numeric, d.simulation->text)});
    }
    // Theorem 6's certificate proves the loop stable only when its premises hold (hidden modes
    // included); the closed-loop decision proves or refutes it directly
    const bool theorem_proves = certified && d.premise_failure.empty();
    const bool law_proves = law.stable && *law.stable, law_refutes = law.stable && !*law.stable;
    if (theorem_proves && law_refutes)
      d.contradiction = "Theorem 6's certified checks and Assumption 1 say the loop with this V is stable, but the "
                        "closed-loop decision proves it NOT stable (" + law.why + "): a contradiction to investigate";
    else if (sr && sr->summary.diverged && (law_proves || (theorem_proves && !law_refutes)))
      d.contradiction = "the simulation diverged although the loop with this V is proven stable (" +
                        (law_proves ? law.why : r.verdict.evidence) + "): a contradiction to investigate";
    const bool proven_stable = law_proves || (theorem_proves && !law_refutes);
    if (d.contradiction.empty() && d.simulation && !d.simulation->decays)
      d.warning = "the simulated velocities have not decayed within " + seconds_text(opt.duration) + " s (" +
                  d.simulation->text + "); this is a numeric observation, not a verdict" +
                  (proven_stable ? std::string(" (the loop is proven stable: slow decay)") : std::string());
  }
  d.certified = certified && d.feasible;
  return d;
}

}  // namespace hapstab::multidof
