// python/bind_scene.cpp -- scenes from Python: simulate (scene/run.hpp prepares the exact-ZOH
// simulator of the scene's [simulate] section as `hapstab simulate` does; the series come back
// as numpy arrays, no files), run on a worker thread that Ctrl-C stops (run_interruptible), and
// the sweep, which still runs in a forked child (core.cpp says why: its own worker processes).
// Also the one reader of a scene argument (scene_arg) that every scene call shares.
#include <chrono>
#include <cmath>
#include <iomanip>
#include <sstream>

#include "cli/command.hpp"
#include "cli/sweep_cli.hpp"
#include "hapstab/numeric/decimal.hpp"
#include "hapstab/numeric/error.hpp"
#include "hapstab/numeric/interrupt.hpp"
#include "hapstab/scene/run.hpp"
#include "python/binding.hpp"
#include "python/forked.hpp"

namespace hapstab::python {
namespace {

/// samples as {t: (rows,), name: (rows, N)} numpy arrays.
py::array_t<double> per_dof(const std::vector<double>& row_major, size_t rows, int N) {
  py::array_t<double> a({py::ssize_t(rows), py::ssize_t(N)});
  std::copy(row_major.begin(), row_major.begin() + std::ptrdiff_t(rows * size_t(N)), a.mutable_data());
  return a;
}

py::dict simulate(const std::string& scene, bool is_text, const std::map<std::string, std::string>& overrides,
                  double max_output_mb, bool force) {
  const scene::Scene sc = scene_arg(scene, is_text, overrides);
  scene::SceneRun prepared = scene::prepare_run(sc);
  const int N = prepared.simulator->loop().N;
  const double bytes = (prepared.rows * (1 + 8 * N) + prepared.fine_rows * (1 + 2 * N)) * 8;
  if (bytes > max_output_mb * 1e6 && !force) {
    std::ostringstream os;
    os << sc.file << ": simulate: the run would hold about " << std::fixed << std::setprecision(0) << bytes / 1e6
       << " MB of arrays, more than max_output=" << std::defaultfloat << std::setprecision(6) << max_output_mb
       << " MB; raise simulate.record_every, narrow simulate.window, or pass force=True (or max_output=MB)";
    throw InputError(os.str());
  }
  // The run on a worker thread; Ctrl-C stops it at its next progress call (every ~1/100 of the steps)
  sim::SimOptions so = prepared.options;
  so.progress = [](double) { interruption_point(); };
  const auto t0 = std::chrono::steady_clock::now();
  sim::SimResult r;
  try {
    run_interruptible([&] { r = prepared.simulator->run(so); });
  } catch (const InputError& e) {
    throw InputError(sc.file + ": " + e.what());
  }
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  const auto& S = r.samples;
  py::dict samples;
  samples["t"] = doubles(S.t);
  const std::pair<const char*, const std::vector<double>*> series[] = {
      {"x", &S.x},           {"v", &S.v},         {"u", &S.u},       {"fh", &S.fh},
      {"E_port", &S.e_port}, {"E_act", &S.e_act}, {"E_po", &S.e_po}, {"storage", &S.storage}};
  for (const auto& [name, data] : series) samples[name] = per_dof(*data, S.rows(), S.N);
  py::object fine = py::none();
  if (r.fine.rows() > 0) {
    py::dict f;
    f["t"] = doubles(r.fine.t);
    f["x"] = per_dof(r.fine.x, r.fine.rows(), r.fine.N);
    f["v"] = per_dof(r.fine.v, r.fine.rows(), r.fine.N);
    fine = f;
  }
  const auto& s = r.summary;
  py::dict summary;
  summary["diverged"] = s.diverged;
  summary["max_velocity"] = s.max_velocity;
  summary["energy_generated"] = s.energy_generated;
  summary["min_port_energy"] = s.min_port_energy;
  summary["trend"] = s.trend;
  summary["steps_run"] = s.steps_run;
  summary["step_matrix_radius"] = s.step_matrix_radius;
  summary["port_energy"] = s.e_port;
  summary["actuator_energy"] = s.e_act;
  summary["passivity_observer"] = s.e_po;
  if (s.limit_cycle) {
    py::dict lc;
    lc["period"] = s.limit_cycle->period;
    lc["amplitude"] = s.limit_cycle->amplitude;
    if (s.limit_cycle->period_samples > 0) lc["period_samples"] = s.limit_cycle->period_samples;
    summary["limit_cycle"] = lc;
  } else {
    summary["limit_cycle"] = py::none();
  }
  if (!sc.loop.coulomb.empty()) summary["friction_events"] = s.friction_events;
  if (!sc.loop.passivity_controller.empty()) {
    summary["pc_dissipated"] = s.pc_dissipated;
    summary["pc_active_samples"] = s.pc_active;
  }
  summary["scene"] = sc.file;
  summary["name"] = sc.name;
  summary["T"] = sc.T.str();
  summary["status"] = "numeric";
  summary["method"] = "exact ZOH discretisation (50-digit Van Loan exponentials rounded to double), double recursion";
  summary["seconds"] = seconds;
  py::dict d;
  d["summary"] = summary;
  d["samples"] = samples;
  d["fine"] = fine;
  return d;
}

}  // namespace

scene::Scene scene_arg(const std::string& scene, bool is_text, const std::map<std::string, std::string>& overrides) {
  std::map<std::string, rational> over;
  for (const auto& [k, v] : overrides) over[k] = exact_arg(v, k);
  return is_text ? scene::parse_scene(scene, "scene", over) : scene::load_scene(scene, over);
}

void register_scene(py::module_& m) {
  m.def("simulate", &simulate, py::arg("scene"), py::arg("is_text"), py::arg("overrides"), py::arg("max_output_mb"),
        py::arg("force"),
        "Simulates a scene (a path, or TOML text with is_text) with the exact-ZOH simulator; the series as numpy arrays.");
  m.def(
      "sweep",
      [](const std::string& spec, bool is_text, const std::string& out, unsigned jobs, const std::string& shard,
         bool resume) {
        const auto answer = run_forked([&] {
          cli::sweep::RunOptions o;
          o.spec = spec;
          o.out = out;
          o.jobs = jobs;
          o.shard = shard;
          o.resume = resume;
          o.quiet = true;
          const int code = is_text ? cli::sweep::run_text(spec, "spec", o) : cli::sweep::run(o);
          return nlohmann::json{{"code", code}};
        });
        return answer["code"].get<int>();
      },
      py::arg("spec"), py::arg("is_text"), py::arg("out"), py::arg("jobs"), py::arg("shard"), py::arg("resume"),
      "Runs a sweep (cli/sweep_cli.hpp) in a forked child with its own worker processes; returns its exit code.");
}

}  // namespace hapstab::python
