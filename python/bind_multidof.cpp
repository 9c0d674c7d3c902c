// python/bind_multidof.cpp -- paper 000 in Python: hapstab.multidof.analyze (Theorem 5) and
// design (Theorem 6) over the library's one entry point, multidof/scene_analysis.hpp
// (analyze_scene, design_scene: the study `hapstab multidof analyze|design` prints), run on a
// worker thread that Ctrl-C stops at its next interruption point (each LMI solve, each Riccati
// point, the simulation's progress: run_interruptible). The results are the library's fields:
// matrices as numpy float64 arrays, the designed V also exact (a hapstab.StateSpace), the
// premises, the loops decided as written and the hidden modes as lists of dicts.
#include <chrono>

#include "hapstab/lmi/backend.hpp"
#include "hapstab/multidof/scene_analysis.hpp"
#include "hapstab/multidof/symmetry.hpp"
#include "hapstab/multidof/witness_json.hpp"
#include "hapstab/numeric/error.hpp"
#include "python/binding.hpp"

namespace hapstab::python {
namespace {

py::array_t<double> matrix(const Eigen::MatrixXd& M) {
  py::array_t<double> a({py::ssize_t(M.rows()), py::ssize_t(M.cols())});
  auto w = a.mutable_unchecked<2>();
  for (Eigen::Index i = 0; i < M.rows(); ++i)
    for (Eigen::Index j = 0; j < M.cols(); ++j) w(i, j) = M(i, j);
  return a;
}

const char* outcome_word(const Verdict& v) { return v.holds() ? "holds" : v.fails() ? "fails" : "undecided"; }

/// Assumption 1, then the hidden-mode premises: [{name, holds, outcome, certified, detail}].
py::list premises(const std::vector<multidof::AssumptionCheck>& checks) {
  py::list l;
  for (const auto& c : checks) {
    py::dict d;
    d["name"] = c.name;
    d["holds"] = c.verdict.holds();
    d["outcome"] = outcome_word(c.verdict);
    d["certified"] = c.verdict.decided() && c.verdict.status == Status::exact;
    d["detail"] = c.verdict.evidence;
    l.append(d);
  }
  return l;
}

/// A loop decided as written: {stable (True/False/None), coupling, method, status, why, states,
/// spectral_radius_numeric, theorem4_witness}.
py::dict loop_dict(const multidof::LoopAsWritten& law) {
  py::dict d;
  d["stable"] = law.stable ? py::object(py::bool_(*law.stable)) : py::object(py::none());
  d["coupling"] = law.coupling;
  d["method"] = law.method;
  d["status"] = law.stable ? to_string(law.status) : "undecided";
  d["why"] = law.why;
  d["states"] = law.states;
  d["spectral_radius_numeric"] = law.spectral_radius ? py::object(py::float_(*law.spectral_radius)) : py::object(py::none());
  d["theorem4_witness"] = from_json(multidof::coupling_witness_json(law.theorem4_witness));
  return d;
}

lmi::Options lmi_options(const std::string& backend) {
  lmi::Options o;
  o.backend = lmi::parse_backend(backend);
  return o;
}

/// What every study of a scene returns about the scene itself.
void scene_fields(py::dict& d, const scene::Scene& sc, const multidof::SceneProblem& sp) {
  d["scene"] = sc.file;
  d["T"] = sc.T.str();
  d["dofs"] = sp.problem.structure.m();
  d["delay"] = sp.delay;
  d["delay_text"] = sp.delay > 0 ? py::object(py::str(multidof::delay_text(sp))) : py::object(py::none());
  d["hidden_modes"] = hidden_modes(sp.hidden);
}

py::dict analyze(const std::string& scene, bool is_text, const std::map<std::string, std::string>& overrides,
                 const std::string& backend) {
  multidof::SceneAnalysisOptions opt;
  opt.lmi = lmi_options(backend);
  const auto t0 = std::chrono::steady_clock::now();
  const scene::Scene sc = scene_arg(scene, is_text, overrides);
  opt.load_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  multidof::SceneAnalysis a;
  run_interruptible([&] { a = multidof::analyze_scene(sc, opt); });
  const auto& r = a.lmis;
  py::dict d;
  scene_fields(d, sc, a.scene);
  d["ok"] = a.ok();
  d["feasible"] = a.feasible;
  d["certified"] = a.certified;
  d["stability_concluded"] = a.stability_concluded;
  d["premises_hold"] = a.premises_hold;
  d["premise_failure"] = multidof::premise_failure(a.premises);
  d["verdict"] = a.verdict();
  d["certificate"] = r.verdict.evidence;
  d["margin"] = r.margin;
  d["gamma"] = r.gamma_sqrt;
  d["x"] = r.gamma;
  d["q_v"] = matrix(r.Q_V);
  d["delta_v_required"] = matrix(r.delta_V);
  d["facial_reduction"] = r.facial.explanation;
  d["solver"] = r.solver_detail;
  d["assumptions"] = premises(a.premises);
  d["loop_as_written"] = loop_dict(a.loop);
  d["path"] = r.path.empty() ? py::object(py::none()) : py::object(py::str(r.path));
  d["witness"] = from_json(multidof::frequency_witness_json(r.witness));
  d["weighted_witness"] = from_json(multidof::weighted_witness_json(r.weighted_witness));
  d["symmetry"] = from_json(multidof::symmetry_json(r));
  if (r.min_found) {
    py::dict m;
    m["q_v"] = matrix(r.Q_V_min);
    m["norm"] = r.Q_V_min_norm;
    m["delta_v"] = matrix(r.delta_V_min);
    m["gamma"] = r.gamma_sqrt_min;
    m["point_certified"] = r.min_point_certified;
    m["minimality"] = "numeric: the solver's optimum or the structured path's floating-point bisection (only the point "
                      "is checked exactly)";
    d["least_dissipative"] = m;
  } else {
    d["least_dissipative"] = py::none();
  }
  py::dict s;
  s["realisation"] = a.seconds.realisation;
  s["sdp"] = r.sdp_seconds;
  s["certificate"] = r.seconds - r.sdp_seconds;
  s["assumptions"] = a.seconds.assumptions;
  s["loop_as_written"] = a.seconds.loop_as_written;
  s["total"] = a.seconds.total;
  d["seconds"] = s;
  return d;
}

py::dict design(const std::string& scene, bool is_text, const std::map<std::string, std::string>& overrides,
                const std::string& backend, int iterations, double duration) {
  multidof::SceneDesignOptions opt;
  opt.design.lmi = lmi_options(backend);
  opt.design.max_iterations = iterations;
  opt.duration = duration;
  const scene::Scene sc = scene_arg(scene, is_text, overrides);
  multidof::SceneDesign g;
  run_interruptible([&] { g = multidof::design_scene(sc, opt); });
  if (!g.contradiction.empty())  // the command's exit 3: nothing here may be taken as a verdict
    throw NumericalError(sc.file + ": " + g.contradiction);
  const auto& r = g.design;
  py::dict d;
  scene_fields(d, sc, g.scene);
  d["ok"] = g.ok();
  d["feasible"] = g.feasible;
  d["certified"] = g.certified;
  d["premise_failure"] = g.premise_failure;
  d["converged"] = r.converged;
  d["iterations"] = r.iterations;
  d["trace_gap"] = r.trace_gap;
  d["trace_history"] = r.trace_history;
  d["convex_infeasible"] = r.verdict.fails();
  d["convex_certified"] = r.verdict.fails() && r.verdict.proven();
  const bool hasV = g.has_v();
  const Eigen::MatrixXd none(0, 0);
  d["A_V"] = matrix(hasV ? multidof::to_double(r.V.A) : none);
  d["B_V"] = matrix(hasV ? multidof::to_double(r.V.B) : none);
  d["C_V"] = matrix(hasV ? multidof::to_double(r.V.C) : none);
  d["D_V"] = matrix(hasV ? multidof::to_double(r.V.D) : none);
  d["V_exact"] = hasV ? py::cast(r.V) : py::object(py::none());
  d["gamma"] = r.gamma_sqrt;
  d["q_v"] = matrix(r.Q_V);
  d["delta_v"] = matrix(r.delta_V);
  py::list ver;
  for (const auto& v : r.verification) {
    py::dict e;
    e["name"] = v.name;
    e["verdict"] = v.verdict.holds() ? "pass" : v.verdict.fails() ? "fail" : "undecided";
    e["certified"] = v.verdict.proven();
    e["status"] = to_string(v.verdict.status);
    e["detail"] = v.verdict.evidence;
    e["witness"] = from_json(multidof::coupling_witness_json(v.witness));
    ver.append(e);
  }
  d["verification"] = ver;
  d["path"] = r.path.empty() ? py::object(py::none()) : py::object(py::str(r.path));
  py::list plan;  // the planner's record (multidof/planner.hpp), as the command's JSON "plan"
  for (const auto& s : r.plan) {
    py::dict e;
    e["path"] = s.path;
    e["fate"] = s.fate;
    e["why"] = s.why;
    plan.append(e);
  }
  d["plan"] = plan;
  d["loop_with_v"] = g.loop_with_v ? py::object(loop_dict(*g.loop_with_v)) : py::object(py::none());
  if (g.simulation) {
    py::dict s;
    s["decays"] = g.simulation->decays;
    s["text"] = g.simulation->text;
    d["simulation"] = s;
  } else {
    d["simulation"] = py::none();
  }
  d["facial_reduction"] = r.facial.explanation;
  d["warning"] = g.warning.empty() ? py::object(py::none()) : py::object(py::str(g.warning));
  d["message"] = r.verdict.evidence;
  d["assumptions"] = premises(g.premises);
  return d;
}

}  // namespace

void register_multidof(py::module_& m) {
  m.def("multidof_analyze", &analyze, py::arg("scene"), py::arg("is_text"), py::arg("overrides"), py::arg("backend"),
        "Theorem 5 on a scene (multidof::analyze_scene): the LMIs (16), the premises, the loop as written.");
  m.def("multidof_design", &design, py::arg("scene"), py::arg("is_text"), py::arg("overrides"), py::arg("backend"),
        py::arg("iterations"), py::arg("duration"),
        "Theorem 6 on a scene (multidof::design_scene): V by CCL, its verification, the loop with V decided and "
        "simulated.");
}

}  // namespace hapstab::python
