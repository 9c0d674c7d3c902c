// `hapstab multidof analyze --scene FILE [--json] [--quiet] [--set NAME=VALUE]... [--backend auto|dsdp|csdp|ipm] [--no-symmetry]
//                         [--certificate FILE]` (multidof-feasible / multidof-witness: cli/multidof_certificate.hpp)
// `hapstab multidof design  --scene FILE [--json] [--quiet] [--set NAME=VALUE]... [--iterations N] [--no-symmetry]
//                         [--certificate FILE]` (multidof-coupling: cli/multidof_certificate.hpp)
// A run longer than 2 s names its stages on stderr (cli/progress.hpp); --quiet silences them.
// Paper 000: Theorem 5 (the LMI test (16), facial reduction of its first LMI, exact certificate,
// Gamma = sqrt(X), the coupling requirement Delta_V >= Gamma^-1 Q_V Gamma^-1, the least
// dissipative Q_V) and Theorem 6 (structured coupling design by CCL, returned by (23)-(24) and
// verified independently). The study itself -- the premises, the loop as written, the design's
// closed-loop decision and simulated cross-check -- is hapstab/multidof/scene_analysis.hpp
// (analyze_scene, design_scene), which Python's hapstab.multidof calls too; this file reads the
// options and prints its results. Scene schema: docs/scene.md (scene/schema.hpp), [multidof] read
// by hapstab/multidof/scene_multidof.hpp.
// JSON keys, analyze: feasible, stability_concluded (feasible, certified and Assumption 1 holds:
//   Theorem 5's conclusion, stable for every coupling whose Delta_V >= delta_v_required),
//   loop_as_written {stable (true|false|null), coupling, method, status, why, states,
//   spectral_radius_numeric, theorem4_witness (cli/witness_json.hpp: the two-frequency witness that
//   proved Theorem 4's program with the scene's coupling infeasible, or null)} (the scene's own
//   loop: multidof/loop_as_written.hpp), witness and weighted_witness (the frequency-domain
//   witnesses of (16)'s infeasibility, or null), hidden_modes
//   [{block, kind, where, abs|re, stable}] (sim/hidden_modes.hpp), delay (n of [delay] z^-n, folded
//   into E), symmetry (null, or {group, classes, blocks [{name, copies, dofs, states, path, verdict
//   (feasible, infeasible, undecided, or "not needed" after a block proved the whole infeasible),
//   certified, seconds}]}: (16) split by the permutations of identical DOFs, multidof/symmetry.hpp),
//   certified, verdict, certificate, gamma (gamma_i of Gamma), x (the g_i of X), q_v,
//   delta_v_required, margin, facial_reduction, least_dissipative {q_v, norm, delta_v, gamma,
//   point_certified, minimality (numeric: only the point is checked exactly)}, assumptions [{name,
//   holds, outcome (holds|fails|undecided), certified, detail}] (Assumption 1, then the premises on
//   the blocks' hidden modes).
// JSON keys, design: stability_concluded (a verified V, every premise holding, no contradiction:
//   the exit-0 verdict), verdict (the text's last line), feasible and certified (a V passed the
//   LMI checks; with a premise failing that is no stability conclusion), converged, iterations, trace_gap, convex_infeasible,
//   convex_certified, A_V, B_V, C_V, D_V, gamma, q_v, verification [{name, verdict (pass|fail|
//   undecided), certified, detail, witness (Theorem 4's two-frequency witness, or null)}], loop_with_v (as loop_as_written, for the loop with the designed
//   V), facial_reduction, path (the design path that decided, or null), plan [{path, fate, why}]
//   (multidof/planner.hpp: every design path's fate), hidden_modes, warning (the simulation's numeric observation, or null),
//   contradiction (a simulation against a certificate, or null: exit 3), message, assumptions.
// It also registers Fig. 6 and Fig. 7 of paper 000 (`hapstab figure multidof_fig6|multidof_fig7`):
// velocity data without coupling, with the designed V and with the paper's (27).
// Human output ends with a verdict line "=> ..." in every case.
// Exit codes: 0 stability concluded and the loop as written not proven unstable (analyze) / a
// stabilising V found and verified (design), 1 (16) proven infeasible, Assumption 1 fails, or the
// loop as written is proven unstable (analyze) / not feasible, not verified, or Assumption 1 fails
// (design), 2 bad input (inconsistent block sizes, unstable E, non-square E, a
// fractional [delay], a declared osp above the device's level, a size beyond numeric/limits.hpp),
// 3 undecided -- (16) not proven either way, or a premise undecided and none failing
// (SceneAnalysis::undecided, SceneDesign::undecided) -- numerical failure, or a contradiction
// between the simulation and a certificate (design).
#include <cmath>
#include <filesystem>
#include <fstream>
#include <algorithm>
#include <iostream>
#include <chrono>
#include <iomanip>
#include <sstream>
#include <memory>

#include "cli/certificate.hpp"
#include "cli/command.hpp"
#include "cli/figure.hpp"
#include "cli/multidof_certificate.hpp"
#include "hapstab/multidof/symmetry.hpp"
#include "cli/progress.hpp"
#include "hapstab/lmi/certify.hpp"
#include "hapstab/multidof/example.hpp"
#include "hapstab/multidof/scene_analysis.hpp"
#include "hapstab/multidof/witness_json.hpp"
#include "hapstab/numeric/error.hpp"

namespace hapstab::cli::cmd_multidof {  // its own namespace: the commands compile in unity batches
namespace {

using nlohmann::json;

struct Opts {
  std::string scene, backend = "auto", certificate, premise_certificate;
  double duration = 10;
  std::vector<std::string> sets;
  bool json = false, quiet = false, no_symmetry = false;
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
// (multidof::scene_premises).
json assumptions_json(const std::vector<multidof::AssumptionCheck>& checks) {
  json a = json::array();
  for (const auto& c : checks)
    a.push_back({{"name", c.name},
                 {"holds", c.verdict.holds()},
                 {"outcome", outcome_word(c.verdict)},
                 {"certified", c.verdict.decided() && c.verdict.status == Status::exact},
                 {"detail", c.verdict.evidence}});
  return a;
}

void print_assumptions(const std::vector<multidof::AssumptionCheck>& checks) {
  for (const auto& c : checks) {
    const char* o = outcome_word(c.verdict);
    std::cout << "  [" << (o == std::string("holds") ? "ok" : o == std::string("fails") ? "FAILS" : "undecided") << "] "
              << c.name << ": " << c.verdict.evidence << "\n";
  }
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
          {"spectral_radius_numeric", law.spectral_radius ? nlohmann::json(*law.spectral_radius) : nlohmann::json(nullptr)},
          {"theorem4_witness", multidof::coupling_witness_json(law.theorem4_witness)}};
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
json plan_json(const std::vector<multidof::PlanStep>& plan) {
  json a = json::array();
  for (const auto& s : plan) a.push_back({{"path", s.path}, {"fate", s.fate}, {"why", s.why}});
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

std::string plan_text(const std::string& path, const std::vector<multidof::PlanStep>& plan) {
  if (path == "facial conditions") return "path: none needed: the facial conditions decided, exactly, before any path ran";
  std::string t = "path: " + (path.empty() ? std::string("no path decided") : "the " + path + " path decided");
  for (const auto& s : plan)
    if (s.fate == "decided" && s.path == path && !s.why.empty()) t += " (" + s.why + ")";
  for (const auto& s : plan)
    if (s.fate != "decided") t += "; " + s.path + ": " + s.fate + (s.why.empty() || s.fate == "not needed" ? "" : " (" + s.why + ")");
  return t;
}
std::string plan_text(const multidof::AnalysisResult& r) {
  if (!r.components.empty())
    return "path: decomposed: the scene splits into " + std::to_string(r.components.size()) +
           " independent components (E block diagonal exactly, no operator spans two), each planned alone:";
  return plan_text(r.path, r.plan);
}

// The scene, its reading timed (multidof::SceneAnalysisOptions::load_seconds).
scene::Scene read_scene(const Opts& o, double& seconds) {
  const auto t0 = std::chrono::steady_clock::now();
  auto sc = scene::load_scene(o.scene, parse_sets(o.sets));
  seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return sc;
}

int run_analyze(const Opts& o) {
  multidof::SceneAnalysisOptions opt;
  scene::Scene sc;
  opt.lmi = lmi_options(o);
  const multidof::SceneAnalysis a = [&] {  // the progress ends (its shares printed) before the results
    StageProgress progress("multidof analyze",
                           {"reading the scene", "realising the blocks", "Theorem 5's LMIs (16)", "the premises",
                            "the loop as written"},
                           o.quiet);
    progress.stage();
    sc = read_scene(o, opt.load_seconds);
    if (!o.certificate.empty())  // refused before the analysis runs when the model cannot be written
      if (const std::string why = multidof_certificate_premise(sc); !why.empty())
        throw InputError("--certificate: " + why + ": no certificate");
    opt.stage = [&progress](const std::string& name) { progress.stage(name); };
    opt.symmetry = !o.no_symmetry;
    return multidof::analyze_scene(sc, opt);
  }();
  if (!o.certificate.empty())  // checked before it is written: a refusal (exit 2) prints no answer
    write_certificate(o.certificate, multidof_certificate(sc, a));
  if (!o.premise_certificate.empty()) {  // (16) feasible, an operator not passive: why Theorem 5 concludes nothing
    const auto op = operator_passivity_certificate(o.scene, o.sets, a);
    if (!op)
      throw InputError("--premise-certificate: no failing premise with a certificate kind here (one: (16) proven feasible and "
                       "Assumption 1(b) failing for an operator given by tf or ss, in a scene the checkers read): no certificate");
    write_certificate(o.premise_certificate, *op);
  }
  const auto& sp = a.scene;
  const auto& r = a.lmis;
  const auto& law = a.loop;
  const bool feasible = a.feasible, certified = a.certified, stable = a.stability_concluded;
  const std::string verdict = a.verdict();
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
         {"plan", plan_json(r.plan)},
         {"components", components_json(r)},
         {"symmetry", multidof::symmetry_json(r)},
         {"witness", multidof::frequency_witness_json(r.witness)},
         {"weighted_witness", multidof::weighted_witness_json(r.weighted_witness)},
         {"assumptions", assumptions_json(a.premises)},
         {"seconds", {{"realisation", a.seconds.realisation},
                      {"sdp", r.sdp_seconds},
                      {"certificate", r.seconds - r.sdp_seconds},
                      {"assumptions", a.seconds.assumptions},
                      {"loop_as_written", a.seconds.loop_as_written},
                      {"total", a.seconds.total}}}};
  if (r.min_found)
    j["least_dissipative"] = {{"q_v", mat(r.Q_V_min)},
                              {"norm", r.Q_V_min_norm},
                              {"delta_v", mat(r.delta_V_min)},
                              {"gamma", r.gamma_sqrt_min},
                              {"point_certified", r.min_point_certified},
                              {"minimality", "numeric: the solver's optimum or the structured path's floating-point "
                                             "bisection (only the point is checked exactly)"}};
  const bool as_written_unstable = a.as_written_unstable();
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
    if (r.symmetry)
      for (const auto& b : r.symmetry->blocks) {
        std::cout << "    block: " << b.name << ", E of order " << b.problem.E.states() << ": ";
        if (!b.analysed)
          std::cout << "not needed (an earlier block proved the whole infeasible)\n";
        else
          std::cout << lmi::to_string(lmi::feasibility_of(b.result.verdict.outcome)) << " ["
                    << to_string(b.result.verdict.status) << "] by the " << b.result.path << " path, "
                    << b.result.seconds << " s\n";
      }
    if (sp.delay > 0) std::cout << "  " << multidof::delay_text(sp) << "\n";
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
    print_assumptions(a.premises);
    std::cout << "  loop as written (coupling: " << law.coupling << "): " << law_word(law) << "\n    " << law.why << "\n";
    const std::string law_tail = "; the loop as written (coupling: " + law.coupling + "): " + law_word(law);
    std::cout << "=> ";
    if (stable && !as_written_unstable)
      std::cout << "stable for every coupling with Delta_V >= Gamma^-1 Q_V Gamma^-1 (Theorem 5, certified)" << law_tail;
    else if (stable)
      std::cout << "stable for every coupling with Delta_V >= Gamma^-1 Q_V Gamma^-1 (Theorem 5, certified)" << law_tail;
    else if (feasible && certified)
      std::cout << "no conclusion from Theorem 5: the LMIs are feasible, but " << multidof::premise_failure(a.premises)
                << law_tail;
    else if (feasible)
      std::cout << "no conclusion from Theorem 5: the LMIs are feasible but not certified" << law_tail;
    else
      std::cout << "no conclusion from Theorem 5: the LMIs (16) are " << verdict << (certified ? " (certified)" : "")
                << ", and Theorem 5 is sufficient only" << law_tail;
    std::cout << "\n";
  }
  return a.ok() ? exit_ok : a.undecided() ? exit_numerical : exit_property_fails;
}

// The designed V: whole when small; else V = blockdiag(V_1, .., V_N) (R2) block by block, each
// distinct block once with the DOFs it serves (a 1024-device array's V is 1024 copies of a few).
void print_coupling(const StateSpace<rational>& V, const multidof::CouplingStructure& cs) {
  auto whole = [&] {
    std::cout << "A_V =\n" << multidof::to_double(V.A) << "\nB_V =\n" << multidof::to_double(V.B) << "\nC_V =\n"
              << multidof::to_double(V.C) << "\nD_V =\n" << multidof::to_double(V.D) << "\n";
  };
  if (V.D.rows() <= 16) return whole();
  struct Block {
    StateSpace<rational> V;
    std::vector<int> dofs;  // first DOF of each copy, 1-based
  };
  std::vector<Block> distinct;
  int c = 0, st = 0;
  for (size_t i = 0; i < cs.mbar.size(); ++i) {
    const int m = cs.mbar[i], n = cs.nbar[i];
    StateSpace<rational> b;
    b.T = V.T;
    b.A = V.A.block(st, st, n, n);
    b.B = V.B.block(st, c, n, m);
    b.C = V.C.block(c, st, m, n);
    b.D = V.D.block(c, c, m, m);
    auto same = [&](const Block& x) { return x.V.A == b.A && x.V.B == b.B && x.V.C == b.C && x.V.D == b.D; };
    auto it = std::find_if(distinct.begin(), distinct.end(), same);
    if (it == distinct.end()) distinct.push_back({b, {}}), it = distinct.end() - 1;
    it->dofs.push_back(c + 1);
    c += m;
    st += n;
  }
  std::cout << "V = blockdiag(V_1, .., V_" << cs.mbar.size() << "), " << distinct.size() << " distinct block"
            << (distinct.size() == 1 ? "" : "s") << " (--json has the whole matrices):\n";
  for (const Block& b : distinct) {
    std::cout << "  for the block" << (b.dofs.size() == 1 ? "" : "s") << " at DOF";
    for (size_t k = 0; k < b.dofs.size() && k < 8; ++k) std::cout << (k ? ", " : " ") << b.dofs[k];
    if (b.dofs.size() > 8) std::cout << ", .. (" << b.dofs.size() << " in all)";
    std::cout << ":\n  A = " << multidof::to_double(b.V.A).format(Eigen::IOFormat(6, 0, ", ", "; ", "", "", "[", "]"))
              << "  B = " << multidof::to_double(b.V.B).format(Eigen::IOFormat(6, 0, ", ", "; ", "", "", "[", "]"))
              << "  C = " << multidof::to_double(b.V.C).format(Eigen::IOFormat(6, 0, ", ", "; ", "", "", "[", "]"))
              << "  D = " << multidof::to_double(b.V.D).format(Eigen::IOFormat(6, 0, ", ", "; ", "", "", "[", "]")) << "\n";
  }
}

int run_design(const Opts& o) {
  if (o.iterations < 1 || o.iterations > 10000)
    throw InputError("--iterations must be in [1, 10000], got " + std::to_string(o.iterations));
  if (!(o.duration > 0 && o.duration <= 1e6))
    throw InputError("--duration must be in (0, 1e6] seconds, got " + std::to_string(o.duration));
  multidof::SceneDesignOptions opt;
  opt.design.max_iterations = o.iterations;
  opt.design.lmi = lmi_options(o);
  opt.duration = o.duration;
  opt.symmetry = !o.no_symmetry;
  scene::Scene sc;
  const multidof::SceneDesign d = [&] {  // the progress ends (its shares printed) before the results
    StageProgress progress("multidof design",
                           {"reading the scene", "realising the blocks", "Theorem 6's design", "the premises",
                            "the loop with the designed V", "the simulated cross-check"},
                           o.quiet);
    progress.stage();
    double load_seconds = 0;
    sc = read_scene(o, load_seconds);
    if (!o.certificate.empty())  // refused before the design runs when the model cannot be written
      if (const std::string why = multidof_certificate_premise(sc); !why.empty())
        throw InputError("--certificate: " + why + ": no certificate");
    opt.stage = [&progress](const std::string& name) { progress.stage(name); };
    return multidof::design_scene(sc, opt);
  }();
  if (!o.certificate.empty())  // checked before it is written: a refusal (exit 2) prints no answer
    write_certificate(o.certificate, design_certificate(sc, d, opt.design.lmi));
  const auto& sp = d.scene;
  const auto& r = d.design;
  const bool hasV = d.has_v(), feasible = d.feasible, certified = d.certified;
  const std::string& premise = d.premise_failure;
  json ver = json::array();
  for (const auto& v : r.verification)
    ver.push_back({{"name", v.name},
                   {"verdict", v.verdict.holds() ? "pass" : v.verdict.fails() ? "fail" : "undecided"},
                   {"certified", v.verdict.proven()},
                   {"detail", v.verdict.evidence},
                   {"witness", multidof::coupling_witness_json(v.witness)}});
  // the one verdict, in the text's last line and in JSON alike ("feasible"/"certified" say only that
  // a V passed the LMI checks; with a premise failing there is no stability conclusion)
  std::ostringstream vt;
  if (!d.contradiction.empty())
    vt << "CONTRADICTION: " << d.contradiction;
  else if (feasible && premise.empty())
    vt << "a stabilising coupling V found and verified" << (certified ? " (certified)" : "")
       << ": the loop with this V is stable (Theorem 6, checked by Theorem 4 and the closed-loop decision"
       << (d.simulation ? "; simulated as a numeric cross-check)" : "; not simulated: too large for the cross-check)");
  else if (feasible)
    vt << "a coupling V passed the LMI checks, but " << premise << ": no stability conclusion";
  else if (r.verdict.fails())
    vt << "no stabilising coupling of this structure from Theorem 6: its convex part is infeasible"
       << (r.verdict.proven() ? " (certified)" : "");
  else
    vt << "no verified coupling V (" << (hasV ? "a candidate failed its independent checks" : "CCL found none")
       << "); Theorem 6 is sufficient only";
  const std::string verdict = vt.str();
  json j{{"stability_concluded", d.ok()},
         {"verdict", verdict},
         {"feasible", feasible},
         {"certified", certified},
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
         {"loop_with_v", d.loop_with_v ? law_json(*d.loop_with_v) : json(nullptr)},
         {"facial_reduction", r.facial.explanation},
         {"path", r.path.empty() ? json(nullptr) : json(r.path)},
         {"plan", plan_json(r.plan)},
         {"hidden_modes", hidden_json(sp.hidden)},
         {"warning", d.warning.empty() ? json(nullptr) : json(d.warning)},
         {"contradiction", d.contradiction.empty() ? json(nullptr) : json(d.contradiction)},
         {"message", r.verdict.evidence},
         {"assumptions", assumptions_json(d.premises)}};
  if (o.json) {
    print_json(j);
  } else {
    std::cout << "Theorem 6 design for " << o.scene << ": " << (!feasible ? "no verified V" : d.premise_failure.empty() ? "a stabilising V found" : "a V that passes the LMI checks found, but " + d.premise_failure + ", so no stability conclusion")
              << (certified ? " (certified)" : "") << "; CCL " << (r.converged ? "converged" : "not converged")
              << " after " << r.iterations << " iterations. " << r.verdict.evidence << "\n";
    if (!r.facial.explanation.empty()) std::cout << "  " << r.facial.explanation << "\n";
    std::cout << "  " << plan_text(r.path, r.plan) << "\n";
    if (hasV) print_coupling(r.V, sp.problem.coupling);
    for (const auto& v : r.verification)
      std::cout << "  [" << (v.verdict.holds() ? "pass" : v.verdict.fails() ? "FAIL" : "undecided")
                << (v.verdict.proven() ? ", certified" : v.verdict.status == Status::numeric ? ", numeric" : "") << "] "
                << v.name << "\n      " << v.verdict.evidence << "\n";
    if (sp.delay > 0) std::cout << "  " << multidof::delay_text(sp) << "; the designed V is fed the applied force\n";
    print_assumptions(d.premises);
    if (!d.warning.empty()) std::cout << "  warning: " << d.warning << "\n";
    std::cout << "=> " << verdict << "\n";
  }
  if (!d.contradiction.empty()) return exit_numerical;
  return d.ok() ? exit_ok : d.undecided() ? exit_numerical : exit_property_fails;
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
    const auto sr = multidof::simulate_with_coupling(sp, V, 10.0);
    std::ofstream f(datadir / (stem + "_" + name + ".dat"));
    const auto [ok, text] = multidof::velocities_decay(sr, to_real<double>(sp.problem.T()));
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
                                 sub->add_flag("--quiet", o->quiet, "No progress on stderr (shown for runs longer than 2 s)");
                                 sub->add_option("--set", o->sets, "Override a scene parameter: NAME=VALUE (exact)");
                                 sub->add_option("--backend", o->backend, "SDP back-end: auto (default: the built-in IPM, kept when exactly certified, else DSDP), dsdp, csdp or ipm");
                                 sub->add_option("--certificate", o->certificate,
                                                 nm == "analyze"
                                                     ? "write the certificate of (16)'s verdict (JSON: feasible, its exact point; "
                                                       "infeasible, its frequency witness or the facial conditions) to FILE, for "
                                                       "`hapstab check FILE` (docs/certificates.md)"
                                                     : "write the certificate that the designed V meets Theorem 4 (JSON: (16)'s "
                                                       "exact point and V-hat's storage P_V) to FILE, for `hapstab check FILE` "
                                                       "(docs/certificates.md)");
                                 if (nm == "analyze")
                                   sub->add_option("--premise-certificate", o->premise_certificate,
                                                   "where (16) is feasible but an operator given by tf is not passive "
                                                   "(Assumption 1(b): Theorem 5 concludes nothing), write that premise's "
                                                   "certificate (kind operator-passivity: a negative principal minor of He Z(jw)) "
                                                   "to FILE, for `hapstab check FILE`; exit 2 where there is none");
                                 sub->add_flag("--no-symmetry", o->no_symmetry,
                                               nm == "analyze" ? "solve (16) whole, not split by the permutations of identical "
                                                                 "DOFs (the same verdict, for comparison; docs/multidof.md)"
                                                               : "design on the whole, not on the split by the permutations of "
                                                                 "identical DOFs (for comparison; docs/multidof.md)");
                                 if (std::string(name) == "design")
                                   sub->add_option("--iterations", o->iterations, "Maximum CCL iterations (default 40)");
                                 sub->callback([mode, name]() { *mode = name; });
                               }
                               return [o, mode]() {
                                 return *mode == "analyze" ? run_analyze(*o) : run_design(*o);
                               };
                             }});

}  // namespace
}  // namespace hapstab::cli::cmd_multidof
