// `hapstab multidof analyze --scene FILE [--json] [--set NAME=VALUE]... [--backend auto|dsdp|csdp|ipm]`
// `hapstab multidof design  --scene FILE [--json] [--set NAME=VALUE]... [--iterations N]`
// Paper 000: Theorem 5 (the LMI test (16), facial reduction of its first LMI, exact certificate,
// Gamma = sqrt(X), the coupling requirement Delta_V >= Gamma^-1 Q_V Gamma^-1, the least
// dissipative Q_V) and Theorem 6 (structured coupling design by CCL, returned by (23)-(24) and
// verified independently). Scene schema: docs/scene.md (scene/schema.hpp), [multidof] read by
// hapstab/multidof/scene_multidof.hpp.
// JSON keys, analyze: feasible, stability_concluded (feasible, certified and Assumption 1 holds:
//   Theorem 5's conclusion, stable for every coupling whose Delta_V >= delta_v_required),
//   loop_as_written {stable (true|false|null), coupling, method, status, why, states,
//   spectral_radius_numeric} (the scene's own loop: multidof/loop_as_written.hpp), hidden_modes
//   [{block, kind, where, abs|re, stable}] (sim/hidden_modes.hpp), delay (n of [delay] z^-n, folded
//   into E), certified, verdict, certificate, gamma (gamma_i of Gamma), x (the g_i of X), q_v,
//   delta_v_required, margin, facial_reduction, least_dissipative {q_v, norm, delta_v, gamma,
//   point_certified, minimality (numeric: only the point is checked exactly)}, assumptions [{name,
//   holds, outcome (holds|fails|undecided), certified, detail}] (Assumption 1, then the premises on
//   the blocks' hidden modes).
// JSON keys, design: feasible, certified, converged, iterations, trace_gap, convex_infeasible,
//   convex_certified, A_V, B_V, C_V, D_V, gamma, q_v, verification [{name, verdict (pass|fail|
//   undecided), certified, detail}], loop_with_v (as loop_as_written, for the loop with the designed
//   V), facial_reduction, hidden_modes, warning (the simulation's numeric observation, or null),
//   contradiction (a simulation against a certificate, or null: exit 3), message, assumptions.
// It also registers Fig. 6 and Fig. 7 of paper 000 (`hapstab figure multidof_fig6|multidof_fig7`):
// velocity data without coupling, with the designed V and with the paper's (27).
// Human output ends with a verdict line "=> ..." in every case.
// Exit codes: 0 stability concluded and the loop as written not proven unstable (analyze) / a
// stabilising V found and verified (design), 1 not feasible, not verified, Assumption 1 fails
// or is undecided, or the loop as written is proven unstable, 2 bad input (inconsistent block
// sizes, unstable E, non-square E, a fractional [delay], a declared osp above the device's
// level, a size beyond numeric/limits.hpp), 3 numerical failure or a contradiction between the
// simulation and a certificate (design).
#include <cmath>
#include <filesystem>
#include <fstream>
#include <algorithm>
#include <iostream>
#include <chrono>
#include <iomanip>
#include <sstream>
#include <memory>

#include "cli/command.hpp"
#include "cli/figure.hpp"
#include "hapstab/lmi/certify.hpp"
#include "hapstab/multidof/assumptions.hpp"
#include "hapstab/multidof/design.hpp"
#include "hapstab/multidof/loop_as_written.hpp"
#include "hapstab/multidof/scene_multidof.hpp"
#include "hapstab/numeric/error.hpp"
#include "hapstab/scene/schema.hpp"
#include "hapstab/sim/simulator.hpp"
#include "hapstab/multidof/example.hpp"

namespace hapstab::cli {
namespace {

using nlohmann::json;

struct Opts {
  std::string scene, backend = "auto";
  double duration = 10;
  std::vector<std::string> sets;
  bool json = false;
  int iterations = 40;
};

json mat(const Eigen::MatrixXd& M) {
  json j = json::array();
  for (Eigen::Index i = 0; i < M.rows(); ++i) {
    json r = json::array();
    for (Eigen::Index c = 0; c < M.cols(); ++c) r.push_back(M(i, c));
    j.push_back(r);
  }
  return j;
}

lmi::Options lmi_options(const Opts& o) {
  lmi::Options op;
  op.backend = lmi::parse_backend(o.backend);
  return op;
}

const char* outcome_word(const Verdict& v) { return v.holds() ? "holds" : v.fails() ? "fails" : "undecided"; }

// Assumption 1 on the reduced blocks, then the premises the realisations as written must meet
// (their hidden modes: multidof::hidden_mode_premises).
json assumptions(const multidof::SceneProblem& sp) {
  json a = json::array();
  auto checks = multidof::check_assumptions(sp.problem.structure, sp.operators, sp.operator_names, sp.device_evidence);
  for (auto& c : multidof::hidden_mode_premises(sp)) checks.push_back(std::move(c));
  for (const auto& c : checks)
    a.push_back({{"name", c.name},
                 {"holds", c.verdict.holds()},
                 {"outcome", outcome_word(c.verdict)},
                 {"certified", c.verdict.decided() && c.verdict.status == Status::exact},
                 {"detail", c.verdict.evidence}});
  return a;
}

void print_assumptions(const json& assume) {
  for (const auto& a : assume) {
    const std::string o = a["outcome"].get<std::string>();
    std::cout << "  [" << (o == "holds" ? "ok" : o == "fails" ? "FAILS" : "undecided") << "] "
              << a["name"].get<std::string>() << ": " << a["detail"].get<std::string>() << "\n";
  }
}

// "Assumption 1 fails" / "... is undecided" (the first line that does not hold)
std::string assumption_failure(const json& assume) {
  for (const auto& a : assume)
    if (!a["holds"].get<bool>()) {
      const std::string name = a["name"].get<std::string>();
      return (name.rfind("Assumption 1", 0) == 0 ? "Assumption 1 " : "a premise ") +
             std::string(a["outcome"].get<std::string>() == "fails" ? "fails" : "is undecided") + " (" + name + ")";
    }
  return "";
}

std::string delay_text(const multidof::SceneProblem& sp) {
  const int m = sp.problem.structure.m();
  return "[delay] " + std::to_string(sp.delay) + " sample period(s): E := z^-" + std::to_string(sp.delay) +
         " E (the force computed at kT acts from (k + " + std::to_string(sp.delay) + ")T; " +
         std::to_string(sp.delay * m) + " shift states folded into E's realisation, exact)";
}

// Prints a matrix row by row, indented; beyond 8 x 8 only its size and largest |entry|.
void print_matrix(const Eigen::MatrixXd& M) {
  if (M.rows() > 8 || M.cols() > 8) {
    std::cout << "    (" << M.rows() << " x " << M.cols() << ", largest |entry| " << M.cwiseAbs().maxCoeff()
              << "; --json gives every entry)\n";
    return;
  }
  for (Eigen::Index i = 0; i < M.rows(); ++i) {
    std::cout << "   ";
    for (Eigen::Index j = 0; j < M.cols(); ++j) std::cout << " " << std::setw(12) << M(i, j);
    std::cout << "\n";
  }
}

json law_json(const multidof::LoopAsWritten& law) {
  return {{"stable", law.stable ? json(*law.stable) : json(nullptr)},
          {"coupling", law.coupling},
          {"method", law.method},
          {"status", law.stable ? to_string(law.status) : "undecided"},
          {"why", law.why},
          {"states", law.states},
          {"spectral_radius_numeric", law.spectral_radius}};
}

// Every hidden mode of every block as written: {block, kind, where, abs ([lo, hi], discrete
// blocks) or re ([lo, hi], continuous), stable}.
json hidden_json(const sim::LoopHiddenModes& h) {
  json a = json::array();
  for (const auto& m : h.modes)
    a.push_back({{"block", m.block},
                 {"kind", m.kind},
                 {"where", m.where.text(m.discrete ? "z" : "s", m.pair)},
                 {m.discrete ? "abs" : "re", m.discrete ? json::array({m.where.abs_lo, m.where.abs_hi})
                                                        : json::array({m.where.re_lo, m.where.re_hi})},
                 {"stable", m.stable}});
  return a;
}

std::string law_word(const multidof::LoopAsWritten& l) {
  if (!l.stable) return "not decided";
  return std::string(*l.stable ? "stable" : "NOT stable") + " [" + to_string(l.status) + "]";
}

// The planner's record (multidof/planner.hpp): each path, what became of it and why.
json plan_json(const multidof::AnalysisResult& r) {
  json a = json::array();
  for (const auto& s : r.plan) a.push_back({{"path", s.path}, {"fate", s.fate}, {"why", s.why}});
  return a;
}

// How the scene split (multidof/components.hpp): one entry per independent component.
json components_json(const multidof::AnalysisResult& r) {
  json a = json::array();
  for (const auto& c : r.components)
    a.push_back({{"name", c.name}, {"dofs", c.dofs}, {"path", c.path}, {"verdict", to_string(c.verdict.outcome)},
                 {"certified", c.verdict.proven()}, {"seconds", c.seconds}});
  return a;
}

std::string plan_text(const multidof::AnalysisResult& r) {
  if (!r.components.empty())
    return "path: decomposed: the scene splits into " + std::to_string(r.components.size()) +
           " independent components (E block diagonal exactly, no operator spans two), each planned alone:";
  if (r.path == "facial conditions") return "path: none needed: the facial conditions decided, exactly, before any path ran";
  std::string t = "path: " + (r.path.empty() ? std::string("no path decided") : "the " + r.path + " path decided");
  for (const auto& s : r.plan)
    if (s.fate != "decided") t += "; " + s.path + ": " + s.fate + (s.why.empty() || s.fate == "not needed" ? "" : " (" + s.why + ")");
  return t;
}

int run_analyze(const Opts& o) {
  const auto t0 = std::chrono::steady_clock::now();
  auto since = [](std::chrono::steady_clock::time_point t) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
  };
  const auto sc = scene::load_scene(o.scene, parse_sets(o.sets));
  scene::check_command(sc.root, o.scene, "multidof analyze");  // what it does not model is refused
  const auto sp = multidof::problem_from_scene(sc);
  const double realisation = since(t0);
  const auto r = multidof::analyze(sp.problem, lmi_options(o));
  const bool feasible = r.verdict.holds();
  const bool certified = r.verdict.proven();
  const char* verdict = lmi::to_string(lmi::feasibility_of(r.verdict.outcome));
  const auto t1 = std::chrono::steady_clock::now();
  const json assume = assumptions(sp);
  const double assumption_seconds = since(t1);
  bool assumptions_hold = true;
  for (const auto& a : assume) assumptions_hold = assumptions_hold && a["holds"].get<bool>();
  // Theorem 5 concludes stability only when the LMIs are certified feasible AND Assumption 1 holds
  const bool stable = feasible && certified && assumptions_hold;
  const auto t2 = std::chrono::steady_clock::now();
  const multidof::LoopAsWritten law = multidof::loop_as_written(sp, assumptions_hold, lmi_options(o));
  const double law_seconds = since(t2);
  json j{{"feasible", feasible},
         {"stability_concluded", stable},
         {"loop_as_written", law_json(law)},
         {"hidden_modes", hidden_json(sp.hidden)},
         {"delay", sp.delay},
         {"certified", certified},
         {"verdict", verdict},
         {"certificate", r.verdict.evidence},
         {"gamma", r.gamma_sqrt},
         {"x", r.gamma},
         {"q_v", mat(r.Q_V)},
         {"delta_v_required", mat(r.delta_V)},
         {"margin", r.margin},
         {"facial_reduction", r.facial.explanation},
         {"solver", r.solver_detail},
         {"path", r.path},
         {"plan", plan_json(r)},
         {"components", components_json(r)},
         {"assumptions", assume},
         {"seconds", {{"realisation", realisation},
                      {"sdp", r.sdp_seconds},
                      {"certificate", r.seconds - r.sdp_seconds},
                      {"assumptions", assumption_seconds},
                      {"loop_as_written", law_seconds},
                      {"total", since(t0)}}}};
  if (r.min_found)
    j["least_dissipative"] = {{"q_v", mat(r.Q_V_min)},
                              {"norm", r.Q_V_min_norm},
                              {"delta_v", mat(r.delta_V_min)},
                              {"gamma", r.gamma_sqrt_min},
                              {"point_certified", r.min_point_certified},
                              {"minimality", "numeric: the solver's optimum or the structured path's floating-point "
                                             "bisection (only the point is checked exactly)"}};
  const bool as_written_unstable = law.stable && !*law.stable;
  if (o.json) {
    print_json(j);
  } else {
    std::cout << "Theorem 5 (LMIs (16)) for " << o.scene << ": " << verdict
              << (certified ? " (certified)" : " (not certified)") << "\n  " << r.verdict.evidence << "\n";
    if (r.verdict.evidence.find(r.facial.explanation) == std::string::npos) std::cout << "  " << r.facial.explanation << "\n";
    std::cout << "  " << plan_text(r) << "\n";
    for (size_t k = 0; k < r.components.size(); ++k) {
      const auto& c = r.components[k];
      std::cout << "    component " << k + 1 << " " << c.name << ": " << to_string(c.verdict.outcome) << " ["
                << to_string(c.verdict.status) << "] by the " << (c.path.empty() ? "(no)" : c.path) << " path, " << c.seconds
                << " s\n";
    }
    if (sp.delay > 0) std::cout << "  " << delay_text(sp) << "\n";
    if (feasible) {
      std::cout << "  one feasible point (" << (r.solver_detail.find("Riccati") == std::string::npos ? "the SDP solver's" : "the Riccati equation's") << "): Gamma = sqrt(X): gamma =";
      for (double g : r.gamma_sqrt) std::cout << " " << g;
      std::cout << "\n  Q_V =\n";
      print_matrix(r.Q_V);
      std::cout << "  Theorem 5 then concludes: the loop is stable for every coupling V whose V-hat^Gamma is "
                   "Delta_V-OSP with Delta_V >= Gamma^-1 Q_V Gamma^-1 =\n";
      print_matrix(r.delta_V);
      if (r.min_found)
        std::cout << "  least dissipative point: ||Q_V||_2 = " << r.Q_V_min_norm
                  << (r.min_point_certified ? " (certified point)" : "")
                  << (r.Q_V_min_norm < 1e-6 * std::max(1.0, r.Q_V.norm())
                          ? "; Q_V > 0 can be made this small, so the requirement on the coupling shrinks with it "
                            "(the infimum 0 is not attained)\n"
                          : "; no smaller Q_V was found (its minimality is numeric: the solver's optimum, or the "
                            "bisection of the structured path)\n");
    }
    print_assumptions(j["assumptions"]);
    std::cout << "  loop as written (coupling: " << law.coupling << "): " << law_word(law) << "\n    " << law.why << "\n";
    const std::string law_tail = "; the loop as written (coupling: " + law.coupling + "): " + law_word(law);
    std::cout << "=> ";
    if (stable && !as_written_unstable)
      std::cout << "stable for every coupling with Delta_V >= Gamma^-1 Q_V Gamma^-1 (Theorem 5, certified)" << law_tail;
    else if (stable)
      std::cout << "stable for every coupling with Delta_V >= Gamma^-1 Q_V Gamma^-1 (Theorem 5, certified)" << law_tail;
    else if (feasible && certified)
      std::cout << "no conclusion from Theorem 5: the LMIs are feasible, but " << assumption_failure(j["assumptions"])
                << law_tail;
    else if (feasible)
      std::cout << "no conclusion from Theorem 5: the LMIs are feasible but not certified" << law_tail;
    else
      std::cout << "no conclusion from Theorem 5: the LMIs (16) are " << verdict << (certified ? " (certified)" : "")
                << ", and Theorem 5 is sufficient only" << law_tail;
    std::cout << "\n";
  }
  return stable && !as_written_unstable ? exit_ok : exit_property_fails;
}

std::string seconds_text(double s) {
  std::ostringstream o;
  o << s;
  return o.str();
}

// The loop Theorem 6 designs V for, as the scene writes its blocks: the environment as written
// (perturb_C applied) with the [delay] folded in as z^-n E (V is fed the applied force), and V
// (none if V is null) in parallel with the devices.
sim::LoopSpec design_loop(const multidof::SceneProblem& sp, const StateSpace<rational>* V) {
  sim::LoopSpec spec = sp.loop;
  spec.environment = multidof::delayed(sp.E_written, sp.delay);
  spec.delay = 0;
  if (V) spec.coupling = *V;
  else spec.coupling.reset();
  return spec;
}

// That loop simulated from the scene's inputs and initial state (exact ZOH).
sim::SimResult simulate_loop(const multidof::SceneProblem& sp, const StateSpace<rational>* V, double duration) {
  sim::SimOptions so;
  so.steps = static_cast<long>(std::ceil(duration / to_real<double>(sp.problem.T())));
  so.energy = false;
  so.max_velocity = 1e6;
  return sim::Simulator(design_loop(sp, V)).run(so);
}

// velocities -> 0: the last second's largest |v| below 1e-3 of the run's peak (or 1e-9 absolute)
std::pair<bool, std::string> decays(const sim::SimResult& r, double T) {
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
  o << "simulated " << r.summary.steps_run << " steps (exact ZOH, sim/): peak |v| = " << peak << ", max |v| over the last second = "
    << tail << ", trend " << r.summary.trend << (r.summary.diverged ? " (diverged)" : "");
  return {!r.summary.diverged && (tail <= 1e-3 * peak || tail < 1e-9), o.str()};
}

int run_design(const Opts& o) {
  if (o.iterations < 1 || o.iterations > 10000)
    throw InputError("--iterations must be in [1, 10000], got " + std::to_string(o.iterations));
  if (!(o.duration > 0 && o.duration <= 1e6))
    throw InputError("--duration must be in (0, 1e6] seconds, got " + std::to_string(o.duration));
  const auto sc = scene::load_scene(o.scene, parse_sets(o.sets));
  scene::check_command(sc.root, o.scene, "multidof design");  // what it does not model is refused
  const auto sp = multidof::problem_from_scene(sc);
  multidof::DesignOptions dop;
  dop.max_iterations = o.iterations;
  dop.lmi = lmi_options(o);
  auto r = multidof::design(sp.problem, dop);
  const bool hasV = r.V.D.rows() > 0;
  const json assume = assumptions(sp);
  const std::string premise = assumption_failure(assume);  // "" when Assumption 1 and the blocks' premises hold
  // The library's verdict rests on certified checks (Theorem 4, V Schur stable). Beside them: the
  // loop with this V decided as written (certified), and the simulation, a numeric cross-check
  // that can warn but never decides; a simulation that diverges where a certificate proves
  // stability is a contradiction (exit 3).
  bool feasible = r.verdict.holds();
  const bool certified = feasible && r.verdict.proven();
  std::optional<multidof::LoopAsWritten> law;
  std::string warning, contradiction;
  if (hasV) {
    law = multidof::decided_loop(design_loop(sp, &r.V), "the designed V");
    r.verification.push_back({"the loop with this V, as written, is Schur stable (" + law->method + ")",
                              law->stable ? Verdict::of(*law->stable, law->status, law->why)
                                          : Verdict{Outcome::undecided, Status::failed, law->why}});
    if (law->stable && !*law->stable) feasible = false;
    const auto sr = simulate_loop(sp, &r.V, o.duration);
    const auto [ok, text] = decays(sr, to_real<double>(sp.problem.T()));
    r.verification.push_back({"closed loop simulated, velocities -> 0 (numeric cross-check; scene's devices, operators, inputs)",
                              Verdict::of(ok, Status::numeric, text)});
    // Theorem 6's certificate proves the loop stable only when its premises hold (hidden modes
    // included); the closed-loop decision proves or refutes it directly
    const bool theorem_proves = certified && premise.empty();
    const bool law_proves = law->stable && *law->stable, law_refutes = law->stable && !*law->stable;
    if (theorem_proves && law_refutes)
      contradiction = "Theorem 6's certified checks and Assumption 1 say the loop with this V is stable, but the closed-loop "
                      "decision proves it NOT stable (" + law->why + "): a contradiction to investigate";
    else if (sr.summary.diverged && (law_proves || (theorem_proves && !law_refutes)))
      contradiction = "the simulation diverged although the loop with this V is proven stable (" +
                      (law_proves ? law->why : r.verdict.evidence) + "): a contradiction to investigate";
    const bool proven_stable = law_proves || (theorem_proves && !law_refutes);
    if (contradiction.empty() && !ok)
      warning = "the simulated velocities have not decayed within " + seconds_text(o.duration) + " s (" + text +
                "); this is a numeric observation, not a verdict" +
                (proven_stable ? std::string(" (the loop is proven stable: slow decay)") : std::string());
  }
  json ver = json::array();
  for (const auto& v : r.verification)
    ver.push_back({{"name", v.name},
                   {"verdict", v.verdict.holds() ? "pass" : v.verdict.fails() ? "fail" : "undecided"},
                   {"certified", v.verdict.proven()},
                   {"detail", v.verdict.evidence}});
  json j{{"feasible", feasible},
         {"certified", certified && feasible},
         {"converged", r.converged},
         {"iterations", r.iterations},
         {"trace_gap", r.trace_gap},
         {"convex_infeasible", r.verdict.fails()},
         {"convex_certified", r.verdict.fails() && r.verdict.proven()},
         {"A_V", hasV ? mat(multidof::to_double(r.V.A)) : json::array()},
         {"B_V", hasV ? mat(multidof::to_double(r.V.B)) : json::array()},
         {"C_V", hasV ? mat(multidof::to_double(r.V.C)) : json::array()},
         {"D_V", hasV ? mat(multidof::to_double(r.V.D)) : json::array()},
         {"gamma", r.gamma_sqrt},
         {"q_v", mat(r.Q_V)},
         {"verification", ver},
         {"loop_with_v", law ? law_json(*law) : json(nullptr)},
         {"facial_reduction", r.facial.explanation},
         {"hidden_modes", hidden_json(sp.hidden)},
         {"warning", warning.empty() ? json(nullptr) : json(warning)},
         {"contradiction", contradiction.empty() ? json(nullptr) : json(contradiction)},
         {"message", r.verdict.evidence},
         {"assumptions", assume}};
  if (o.json) {
    print_json(j);
  } else {
    std::cout << "Theorem 6 design for " << o.scene << ": " << (feasible ? "a stabilising V found" : "no verified V")
              << (certified && feasible ? " (certified)" : "") << "; CCL " << (r.converged ? "converged" : "not converged")
              << " after " << r.iterations << " iterations. " << r.verdict.evidence << "\n";
    if (!r.facial.explanation.empty()) std::cout << "  " << r.facial.explanation << "\n";
    if (hasV)
      std::cout << "A_V =\n" << multidof::to_double(r.V.A) << "\nB_V =\n" << multidof::to_double(r.V.B) << "\nC_V =\n"
                << multidof::to_double(r.V.C) << "\nD_V =\n" << multidof::to_double(r.V.D) << "\n";
    for (const auto& v : r.verification)
      std::cout << "  [" << (v.verdict.holds() ? "pass" : v.verdict.fails() ? "FAIL" : "undecided")
                << (v.verdict.proven() ? ", certified" : v.verdict.status == Status::numeric ? ", numeric" : "") << "] "
                << v.name << "\n      " << v.verdict.evidence << "\n";
    if (sp.delay > 0) std::cout << "  " << delay_text(sp) << "; the designed V is fed the applied force\n";
    print_assumptions(j["assumptions"]);
    if (!warning.empty()) std::cout << "  warning: " << warning << "\n";
    std::cout << "=> ";
    if (!contradiction.empty())
      std::cout << "CONTRADICTION: " << contradiction;
    else if (feasible && premise.empty())
      std::cout << "a stabilising coupling V found and verified" << (certified ? " (certified)" : "")
                << ": the loop with this V is stable (Theorem 6, checked by Theorem 4 and the closed-loop decision; "
                   "simulated as a numeric cross-check)";
    else if (feasible)
      std::cout << "a coupling V passed the LMI checks, but " << premise << ": no stability conclusion";
    else if (r.verdict.fails())
      std::cout << "no stabilising coupling of this structure from Theorem 6: its convex part is infeasible"
                << (r.verdict.proven() ? " (certified)" : "");
    else
      std::cout << "no verified coupling V (" << (hasV ? "a candidate failed its independent checks" : "CCL found none")
                << "); Theorem 6 is sufficient only";
    std::cout << "\n";
  }
  if (!contradiction.empty()) return exit_numerical;
  return feasible && premise.empty() ? exit_ok : exit_property_fails;
}

// Fig. 6 / Fig. 7 data: velocity responses without coupling, with the designed V and with (27)
// (the latter for 2-DOF scenes), 10 s after the scene's force impulse; files DATADIR/STEM_*.dat.
void write_velocity_data(const std::string& scene_name, const std::string& stem, const std::filesystem::path& datadir) {
  const std::string file = (examples_dir() / scene_name).string();
  const auto sc = scene::load_scene(file);
  const auto sp = multidof::problem_from_scene(sc);
  const auto d = multidof::design(sp.problem, multidof::DesignOptions{});
  if (d.V.D.rows() == 0) throw NumericalError(file + ": Theorem 6 found no coupling to simulate (" + d.verdict.evidence + ")");
  std::vector<std::pair<std::string, const StateSpace<rational>*>> runs{{"none", nullptr}, {"designed", &d.V}};
  const auto V27 = multidof::example::controller27();
  if (sp.problem.structure.m() == 2) runs.emplace_back("paper27", &V27);
  for (const auto& [name, V] : runs) {
    const auto sr = simulate_loop(sp, V, 10.0);
    std::ofstream f(datadir / (stem + "_" + name + ".dat"));
    const auto [ok, text] = decays(sr, to_real<double>(sp.problem.T()));
    f << "# t[s] v_1 ... v_N [m/s]  (" << name << " coupling; " << scene_name << ")\n# "
      << (ok ? "velocities -> 0: " : "NOT decaying: ") << text << "\n";
    const auto& tr = sr.samples;
    for (size_t i = 0; i < tr.rows(); ++i) {
      f << tr.t[i];
      for (int k = 0; k < tr.N; ++k) f << " " << tr.v[i * static_cast<size_t>(tr.N) + static_cast<size_t>(k)];
      f << "\n";
    }
  }
}

const RegisterFigure fig6({"multidof_fig6", "000",
                           "Fig. 6: case i (one operator on both devices, nominal environment), velocities after a "
                           "force impulse on d_a: (a) no coupling, (b) the coupling designed by Theorem 6, (b') the "
                           "paper's (27)",
                           [](const std::filesystem::path& d) {
                             write_velocity_data("multidof_case_i_nominal.toml", "multidof_fig6", d);
                           }});
const RegisterFigure fig7({"multidof_fig7", "000",
                           "Fig. 7: case ii (an operator per device, perturbed environment), velocities after a "
                           "force impulse on d_a: (a) no coupling, (b) the coupling designed by Theorem 6",
                           [](const std::filesystem::path& d) {
                             write_velocity_data("multidof_case_ii_perturbed.toml", "multidof_fig7", d);
                           }});

const Register multidof_cmd({"multidof",
                             "Paper 000: multi-operator multi-device stability test (Theorem 5) and structured coupling design (Theorem 6)",
                             [](CLI::App& app) {
                               auto o = std::make_shared<Opts>();
                               auto mode = std::make_shared<std::string>();
                               app.require_subcommand(1);
                               for (const char* name : {"analyze", "design"}) {
                                 const std::string nm = name;
                                 auto* sub = app.add_subcommand(name, nm == "analyze" ? "Theorem 5: LMIs (16), exact certificate"
                                                                      : "Theorem 6: structured coupling by CCL, independently verified");
                                 if (nm != "analyze")
                                   sub->add_option("--duration", o->duration, "Simulated time in seconds (default 10)");
                                 sub->add_option("--scene", o->scene, "Scene file (TOML; examples/multidof_*.toml)")->required();
                                 sub->add_flag("--json", o->json, "JSON output");
                                 sub->add_option("--set", o->sets, "Override a scene parameter: NAME=VALUE (exact)");
                                 sub->add_option("--backend", o->backend, "SDP back-end: auto (default: the built-in IPM, kept when exactly certified, else DSDP), dsdp, csdp or ipm");
                                 if (std::string(name) == "design")
                                   sub->add_option("--iterations", o->iterations, "Maximum CCL iterations (default 40)");
                                 sub->callback([mode, name]() { *mode = name; });
                               }
                               return [o, mode]() {
                                 return *mode == "analyze" ? run_analyze(*o) : run_design(*o);
                               };
                             }});

}  // namespace
}  // namespace hapstab::cli
