// python/bind_stability.cpp -- the sampled loop's Schur stability and largest stable gain
// (stability/sampled_loop.hpp, built by stability/loop_from_text.hpp as `hapstab stability`
// builds it), a scene's loop as written for any number of DOF (stability/loop_as_written.hpp's
// decide_loop, as `hapstab stability --scene`; the blocks' hidden modes with it), and the OSP/ISP
// levels of paper 000 (lmi/passivity_level_report.hpp, as `hapstab passivity-level` reports
// them); each scalar and vectorised over parameter columns on threads.
//
// `--max NAME` on a scene (the largest stable scene parameter, any number of DOF, with
// --conservatism Theorem 5's beside it: issue 42) is not bound here: hapstab.stability(scene=...,
// max=..., conservatism=...) runs the command itself through _core.run (python/hapstab/__init__.py),
// so its JSON -- three result shapes (one DOF, the certified crossing, the bisection on verdicts) --
// has one writer.
#include <cmath>
#include <filesystem>
#include <limits>

#include "hapstab/lmi/passivity_level_report.hpp"
#include "hapstab/lti/realization.hpp"
#include "hapstab/numeric/decimal.hpp"
#include "hapstab/numeric/error.hpp"
#include "hapstab/report/paths.hpp"
#include "hapstab/scene/schema.hpp"
#include "hapstab/stability/loop_as_written.hpp"
#include "hapstab/stability/loop_from_text.hpp"
#include "python/binding.hpp"

namespace hapstab::python {
namespace {

// ---- stability -------------------------------------------------------------------------------

const stability::LoopNames& python_names() {
  static const stability::LoopNames names{"plant", "H", "operator", "max", "delay", "pass params={'{}': ...}", "T=..."};
  return names;
}

struct LoopInput {
  std::string plant, H, op, gain;
  rational T;
  int delay = 0;
  int digits = 20;
};

LoopInput loop_input(const std::string& plant, const std::string& H, const std::optional<std::string>& op,
                     const std::string& T, int delay, const std::optional<std::string>& gain, int digits) {
  LoopInput in{plant, H, op.value_or(""), gain.value_or(""), exact_arg(T, "T"), delay, digits};
  if (in.T <= 0) throw InputError("T: the sample period must be > 0, got " + T);
  if (digits < 1 || digits > 1000) throw InputError("digits must be in [1, 1000], got " + std::to_string(digits));
  return in;
}

stability::Loop make_loop(const LoopInput& in, std::map<std::string, rational> params) {
  return stability::loop_from_text({in.plant, in.H, in.op, in.T, in.delay, std::move(params), in.gain}, python_names());
}

py::dict decide_record(const stability::StabilityResult& r, const stability::Loop& loop) {
  py::dict d;
  const bool decided = r.verdict.decided();
  d["stable"] = decided ? py::object(py::bool_(r.verdict.holds())) : py::object(py::none());
  d["status"] = decided ? to_string(r.verdict.status) : "undecided";
  d["evidence"] = r.verdict.evidence;
  if (r.spectral_radius) {
    const auto& e = *r.spectral_radius;
    d["spectral_radius"] = record(e, (e.lo + e.hi) / 2, e.lo == e.hi ? Status::exact : Status::certified,
                                  "certified root enclosures of the characteristic polynomial", "", 17);
  } else {
    d["spectral_radius"] = py::none();
  }
  d["degree"] = r.degree;
  const auto P = stability::effective_device(loop);
  d["device"] = tf(P.num(), P.den()).to_string();
  d["precision_bits"] = r.precision_bits;
  return d;
}

py::dict max_record(const stability::MaxGain& m, const LoopInput& in) {
  py::dict d;
  d["name"] = in.gain;
  d["outcome"] = to_string(m.outcome);
  const bool found = m.outcome == Outcome::holds;
  if (found && m.infinite) {
    d["max"] = record_infinite(m.status, "stability::max_gain: stable for every gain > 0", m.note);
  } else if (found) {
    const rational mid = m.exact ? *m.exact : (m.enclosure.lo + m.enclosure.hi) / 2;
    d["max"] = record(m.enclosure, mid, m.exact ? Status::exact : m.status,
                      "stability::max_gain: the smallest positive crossing of the unit circle", m.note, in.digits + 3);
  } else if (m.outcome == Outcome::fails) {
    d["max"] = record(Certified<rational>::exact_value(0, "stability::max_gain: unstable for every small gain > 0"),
                      in.digits);
  } else {
    d["max"] = py::none();
  }
  d["crossing"] = m.crossing;
  if (m.theta) {
    d["theta"] = py::make_tuple(double_outward(m.theta->lo, -1), double_outward(m.theta->hi, +1));
    d["omega"] = py::make_tuple(double_outward(m.theta->lo / in.T, -1), double_outward(m.theta->hi / in.T, +1));
  }
  d["note"] = m.note;
  d["precision_bits"] = m.precision_bits;
  return d;
}

py::dict stability_scalar(const LoopInput& in, const std::map<std::string, std::string>& param_texts) {
  std::map<std::string, rational> params;
  for (const auto& [k, v] : param_texts) params[k] = exact_arg(v, "params['" + k + "']");
  const stability::Loop loop = make_loop(in, params);
  py::gil_scoped_release nogil;
  if (in.gain.empty()) {
    const auto r = stability::decide(loop);
    py::gil_scoped_acquire gil;
    return decide_record(r, loop);
  }
  const auto m = stability::max_gain(loop, in.digits, in.gain);
  py::gil_scoped_acquire gil;
  return max_record(m, in);
}

py::dict stability_many(const LoopInput& in, const std::map<std::string, std::string>& fixed_texts,
                        const std::vector<std::string>& names, const py::list& columns, unsigned jobs) {
  std::map<std::string, rational> fixed;
  for (const auto& [k, v] : fixed_texts) fixed[k] = exact_arg(v, "params['" + k + "']");
  const Columns cols = Columns::from_python(names, columns);
  std::map<std::string, rational> named = fixed;
  if (!in.gain.empty()) named[in.gain] = 0;  // the gain maximised is a name of H too
  check_names(in.plant, "plant", 's', named, cols);
  check_names(in.H, "H", 'z', named, cols);
  if (!in.op.empty()) check_names(in.op, "operator", 's', named, cols);
  const size_t n = cols.points;
  PointColumns c(n);
  std::vector<int8_t> stable(n, -1);
  run_points(n, jobs, [&](uint64_t i) {
    try {
      const stability::Loop loop = make_loop(in, cols.at(fixed, i));
      if (in.gain.empty()) {  // the spectral radius, and the verdict
        const auto r = stability::decide(loop);
        if (r.verdict.decided()) {
          stable[i] = r.verdict.holds() ? 1 : 0;
          c.status[i] = status_code(r.verdict.status);
        } else {
          c.error[i] = "undecided: " + r.verdict.evidence;
        }
        if (r.spectral_radius) c.enclose(i, r.spectral_radius->lo, r.spectral_radius->hi, 17);
        return;
      }
      const auto m = stability::max_gain(loop, in.digits, in.gain);
      if (m.outcome == Outcome::undecided) {
        c.error[i] = "undecided: " + m.note;
        return;
      }
      c.status[i] = status_code(m.exact || m.outcome == Outcome::fails ? Status::exact : m.status);
      if (m.outcome == Outcome::fails) {
        c.value[i] = c.lo[i] = c.hi[i] = 0;
        c.exact[i] = "0";
      } else if (m.infinite) {
        c.value[i] = c.lo[i] = c.hi[i] = std::numeric_limits<double>::infinity();
      } else {
        c.enclose(i, m.enclosure.lo, m.enclosure.hi, in.digits + 3);
        if (m.exact) c.value[i] = to_real<double>(*m.exact), c.exact[i] = m.exact->str();
      }
    } catch (const std::exception& e) {
      c.error[i] = point_error(e);
    }
  });
  py::dict d = c.dict();
  if (in.gain.empty()) d["stable"] = codes(stable);
  return d;
}

// ---- a scene's loop as written (stability/loop_as_written.hpp) --------------------------------

/// The outward float ends of an interval of doubles (already an enclosure).
py::tuple ends(double lo, double hi) { return py::make_tuple(lo, hi); }

py::dict scene_record(const stability::LoopVerdict& v, const scene::Scene& sc) {
  py::dict d;
  d["stable"] = v.stable ? py::object(py::bool_(*v.stable)) : py::object(py::none());
  d["status"] = v.stable ? to_string(v.status) : "undecided";
  d["method"] = v.method;
  d["evidence"] = v.why;
  d["dofs"] = sc.loop.dofs();
  d["states"] = v.states;
  d["spectral_radius_numeric"] = v.spectral_radius ? py::object(py::float_(*v.spectral_radius)) : py::object(py::none());
  d["hidden_modes"] = hidden_modes(v.hidden);
  d["hidden_summary"] = v.hidden.summary();
  d["scene"] = sc.file;
  return d;
}

/// `hapstab stability --scene`: the scene's loop as written, any number of DOF (decide_loop).
py::dict stability_scene(const std::string& scene, bool is_text, const std::map<std::string, std::string>& overrides) {
  const scene::Scene sc = scene_arg(scene, is_text, overrides);
  scene::check_command(sc.root, sc.file, "stability");  // what it does not model is refused
  stability::LoopVerdict v;
  {
    py::gil_scoped_release nogil;
    v = stability::decide_loop(sc.loop);
  }
  return scene_record(v, sc);
}

/// The same at every point of scene-parameter columns, on threads: the scene's text read once,
/// parsed with each point's values. value: the numeric spectral radius (status numeric); stable
/// 1/0/-1 undecided and verdict_status (int8 codes) the certified verdict; states, evidence.
py::dict stability_scene_many(const std::string& scene, bool is_text, const std::map<std::string, std::string>& fixed_texts,
                              const std::vector<std::string>& names, const py::list& columns, unsigned jobs) {
  std::map<std::string, rational> fixed;
  for (const auto& [k, v] : fixed_texts) fixed[k] = exact_arg(v, k);
  const Columns cols = Columns::from_python(names, columns);
  const std::string text = is_text ? scene : report::read_input_file(scene, "the scene file", 64u << 20);
  const std::string file = is_text ? std::string("scene") : scene;
  const auto dir = std::filesystem::path(scene).parent_path();
  const std::string base = is_text || dir.empty() ? std::string(".") : dir.string();
  const size_t n = cols.points;
  if (n > 0) {  // what the whole call cannot model is refused once, before the points run
    const scene::Scene first = scene::parse_scene(text, file, cols.at(fixed, 0), base);
    scene::check_command(first.root, first.file, "stability");
  }
  PointColumns c(n);
  std::vector<int8_t> stable(n, -1), verdict(n, code_failed);
  std::vector<double> states(n, 0);
  std::vector<std::optional<std::string>> evidence(n);
  run_points(n, jobs, [&](uint64_t i) {
    try {
      const scene::Scene sc = scene::parse_scene(text, file, cols.at(fixed, i), base);
      const stability::LoopVerdict v = stability::decide_loop(sc.loop);
      c.value[i] = c.lo[i] = c.hi[i] = v.spectral_radius.value_or(std::numeric_limits<double>::quiet_NaN());
      c.status[i] = code_numeric;
      states[i] = double(v.states);
      evidence[i] = v.why;
      if (v.stable) {
        stable[i] = *v.stable ? 1 : 0;
        verdict[i] = status_code(v.status);
      }
    } catch (const std::exception& e) {
      c.error[i] = point_error(e);
    }
  });
  py::dict d = c.dict();
  d["stable"] = codes(stable);
  d["verdict_status"] = codes(verdict);
  d["states"] = doubles(states);
  d["evidence"] = strings(evidence);
  return d;
}

// ---- passivity levels (paper 000) ------------------------------------------------------------

struct LevelOptions {
  lmi::PassivityKind kind = lmi::PassivityKind::osp;
  lmi::Backend backend = lmi::Backend::automatic;
  int lemma = 1, grid = 4096, digits = 17;
};

LevelOptions level_options(const std::string& kind, const std::string& backend, int lemma, int grid, int digits) {
  LevelOptions o;
  if (kind != "osp" && kind != "isp") throw InputError("kind must be 'osp' or 'isp' (got '" + kind + "')");
  o.kind = kind == "osp" ? lmi::PassivityKind::osp : lmi::PassivityKind::isp;
  if (backend == "auto") o.backend = lmi::Backend::automatic;
  else if (backend == "dsdp") o.backend = lmi::Backend::dsdp;
  else if (backend == "csdp") o.backend = lmi::Backend::csdp;
  else if (backend == "ipm") o.backend = lmi::Backend::ipm;
  else throw InputError("backend must be 'auto', 'dsdp', 'csdp' or 'ipm' (got '" + backend + "')");
  if (lemma != 1 && lemma != 2) throw InputError("lemma must be 1 or 2 (got " + std::to_string(lemma) + ")");
  if (grid < 16 || grid > 10000000) throw InputError("grid must be in [16, 1e7] (got " + std::to_string(grid) + ")");
  if (digits < 10 || digits > 100) throw InputError("digits must be in [10, 100] (got " + std::to_string(digits) + ")");
  o.lemma = lemma, o.grid = grid, o.digits = digits;
  return o;
}

lmi::LevelModel model_of(const TransferFunction& G) {
  if (!G.is_discrete()) throw InputError("H: expected a transfer function in z");
  if (!G.is_proper()) throw InputError("H: H(z) = " + G.to_string() + " is not causal (deg num > deg den)");
  lmi::LevelModel m;
  m.G = G.H;
  m.sys = tf2ss(G).cast<double>();
  m.sys.T = G.T;
  lmi::check_schur_stable(m.sys, "H");
  return m;
}

lmi::LevelModel model_of(const StateSpace<rational>& s) {
  lmi::LevelModel m;
  m.exact = s;
  auto rounded = [](const Mat<rational>& M) {
    return Mat<double>(M.unaryExpr([](const rational& x) { return to_real<double>(x); }));
  };
  m.sys = {rounded(s.A), rounded(s.B), rounded(s.C), rounded(s.D), s.T};
  for (const auto* M : {&m.sys.A, &m.sys.B, &m.sys.C, &m.sys.D})
    if (!M->allFinite()) throw InputError("ss: an entry is not finite (a number beyond the range of double)");
  lmi::check_schur_stable(m.sys, "ss");
  return m;
}

/// The reported level as a result record: the main level of lmi::Levels with its proven ends.
py::dict level_record(const lmi::Levels& v, int digits) {
  const lmi::PassivityLevel& main = v.main();
  const double inf = std::numeric_limits<double>::infinity();
  if (!v.any) {
    py::dict d;
    d["value_exact"] = py::none();
    d["mid"] = std::numeric_limits<double>::quiet_NaN();
    d["lo"] = std::numeric_limits<double>::quiet_NaN();
    d["hi"] = std::numeric_limits<double>::quiet_NaN();
    d["lo_text"] = py::none();
    d["hi_text"] = py::none();
    d["status"] = "failed";
    d["method"] = main.method;
    d["note"] = v.note;
    return d;
  }
  if (v.which == lmi::Levels::Main::cert && main.enclosure) {
    py::dict d = record(main.enclosure, (main.enclosure->lo + main.enclosure->hi) / 2, main.status, main.method, v.note,
                        digits + 3);
    if (v.only_bound) {  // OSP delta* <= 0 and no LMI level: an upper bound on Lemma 1's level only
      d["value_exact"] = py::none();
      d["lo"] = -inf;
      d["lo_text"] = "-inf";
      d["status"] = "upper_bound";
    }
    return d;
  }
  // a numeric level (LMI or grid): the estimate; the LMI's exactly checked lower bound as lo
  py::dict d;
  d["value_exact"] = py::none();
  d["mid"] = main.level;
  d["lo"] = main.lower_bound ? double_outward(*main.lower_bound, -1) : main.level;
  d["hi"] = main.level;
  d["lo_text"] = main.lower_bound ? py::object(py::str(decimal_outward(*main.lower_bound, 17, -1))) : py::object(py::none());
  d["hi_text"] = py::none();
  d["status"] = to_string(main.status);
  d["method"] = main.method;
  d["note"] = v.note;
  return d;
}

py::dict levels_scalar(const lmi::LevelModel& model, const LevelOptions& o) {
  lmi::Levels v;
  {
    py::gil_scoped_release nogil;
    v = lmi::passivity_levels(model, o.kind, o.lemma, o.backend, o.grid, o.digits);
  }
  py::dict d;
  d["kind"] = o.kind == lmi::PassivityKind::osp ? "osp" : "isp";
  d["level"] = level_record(v, o.digits);
  d["certified_value"] = v.cert_ok ? py::object(py::str(v.c.value)) : py::object(py::none());
  d["is_level"] = v.cert_is_level;
  d["theta"] = v.cert_ok ? py::object(py::float_(v.c.theta_min)) : v.freq_ok ? py::object(py::float_(v.f.theta_min)) : py::object(py::none());
  d["lmi_level"] = v.lmi_ok ? py::object(py::float_(v.l.level)) : py::object(py::none());
  d["lmi_lower_bound"] = v.l.lower_bound ? py::object(py::str(v.l.lower_bound->str())) : py::object(py::none());
  d["lmi_method"] = v.l.method;
  d["grid_level"] = v.freq_ok ? py::object(py::float_(v.f.level)) : py::object(py::none());
  d["note"] = v.note;
  return d;
}

py::dict levels_many(const std::string& expr, const std::string& T_text, const std::map<std::string, std::string>& fixed_texts,
                     const std::vector<std::string>& names, const py::list& columns, const LevelOptions& o, unsigned jobs) {
  const rational T = exact_arg(T_text, "T");
  if (T <= 0) throw InputError("T: the sample period must be > 0, got " + T_text);
  std::map<std::string, rational> fixed;
  for (const auto& [k, v] : fixed_texts) fixed[k] = exact_arg(v, "params['" + k + "']");
  const Columns cols = Columns::from_python(names, columns);
  const ParsedExpression G_of = parsed(expr, "H", 'z', T, fixed, cols);  // parsed once
  const size_t n = cols.points;
  PointColumns c(n);
  run_points(n, jobs, [&](uint64_t i) {
    try {
      TransferFunction G;
      try {
        G = G_of.at(cols.at({}, i));
      } catch (const InputError& e) {
        throw InputError(std::string("H: ") + e.what());
      }
      const lmi::Levels v = lmi::passivity_levels(model_of(G), o.kind, o.lemma, o.backend, o.grid, o.digits);
      const lmi::PassivityLevel& main = v.main();
      if (!v.any) {
        c.error[i] = "numerical failure: no method gave a level (" + v.note + ")";
        return;
      }
      if (v.which == lmi::Levels::Main::cert && main.enclosure) {
        c.enclose(i, main.enclosure->lo, main.enclosure->hi, o.digits + 3);
        if (v.only_bound) c.lo[i] = -std::numeric_limits<double>::infinity(), c.lo_exact[i] = "-inf";
        c.status[i] = v.only_bound ? code_numeric : status_code(main.status);
        if (main.status == Status::exact && !v.only_bound) c.exact[i] = main.enclosure->lo.str();
        if (v.only_bound) c.error[i] = "upper bound only: " + v.note;
      } else {
        c.value[i] = c.hi[i] = main.level;
        c.lo[i] = main.lower_bound ? double_outward(*main.lower_bound, -1) : main.level;
        c.status[i] = status_code(main.status);
      }
    } catch (const std::exception& e) {
      c.error[i] = point_error(e);
    }
  });
  return c.dict();
}

}  // namespace

py::list hidden_modes(const sim::LoopHiddenModes& h) {
  py::list l;
  for (const auto& m : h.modes) {
    py::dict d;
    d["block"] = m.block;
    d["kind"] = m.kind;
    d["discrete"] = m.discrete;
    d["pair"] = m.pair;
    d["where"] = m.where.text(m.discrete ? "z" : "s", m.pair);
    d["re"] = ends(m.where.re_lo, m.where.re_hi);
    d["im"] = ends(m.where.im_lo, m.where.im_hi);
    d["abs"] = ends(m.where.abs_lo, m.where.abs_hi);
    d["stable"] = m.stable;
    l.append(d);
  }
  return l;
}

void register_stability(py::module_& m) {
  m.def(
      "stability",
      [](const std::string& plant, const std::string& H, const std::optional<std::string>& op, const std::string& T,
         int delay, const std::optional<std::string>& gain, int digits, const std::map<std::string, std::string>& params) {
        return stability_scalar(loop_input(plant, H, op, T, delay, gain, digits), params);
      },
      py::arg("plant"), py::arg("H"), py::arg("operator"), py::arg("T"), py::arg("delay"), py::arg("max"),
      py::arg("digits"), py::arg("params"),
      "Schur stability of the sampled loop (stability::decide), or with max the largest stable gain (max_gain).");
  m.def(
      "stability_many",
      [](const std::string& plant, const std::string& H, const std::optional<std::string>& op, const std::string& T,
         int delay, const std::optional<std::string>& gain, int digits, const std::map<std::string, std::string>& fixed,
         const std::vector<std::string>& names, const py::list& columns, unsigned jobs) {
        return stability_many(loop_input(plant, H, op, T, delay, gain, digits), fixed, names, columns, jobs);
      },
      py::arg("plant"), py::arg("H"), py::arg("operator"), py::arg("T"), py::arg("delay"), py::arg("max"),
      py::arg("digits"), py::arg("fixed"), py::arg("names"), py::arg("columns"), py::arg("jobs"),
      "stability at every point of parameter columns, on threads.");
  m.def("stability_scene", &stability_scene, py::arg("scene"), py::arg("is_text"), py::arg("overrides"),
        "The loop a scene writes, decided as written (stability::decide_loop): any number of DOF, hidden modes.");
  m.def("stability_scene_many", &stability_scene_many, py::arg("scene"), py::arg("is_text"), py::arg("fixed"),
        py::arg("names"), py::arg("columns"), py::arg("jobs"),
        "stability_scene at every point of scene-parameter columns, on threads.");
  m.def(
      "passivity_level",
      [](const TransferFunction& G, const std::string& kind, const std::string& backend, int lemma, int grid, int digits) {
        const LevelOptions o = level_options(kind, backend, lemma, grid, digits);
        return levels_scalar(model_of(G), o);
      },
      py::arg("H"), py::arg("kind"), py::arg("backend"), py::arg("lemma"), py::arg("grid"), py::arg("digits"));
  m.def(
      "passivity_level_ss",
      [](const StateSpace<rational>& s, const std::string& kind, const std::string& backend, int lemma, int grid,
         int digits) {
        const LevelOptions o = level_options(kind, backend, lemma, grid, digits);
        return levels_scalar(model_of(s), o);
      },
      py::arg("ss"), py::arg("kind"), py::arg("backend"), py::arg("lemma"), py::arg("grid"), py::arg("digits"));
  m.def(
      "passivity_level_many",
      [](const std::string& expr, const std::string& T, const std::map<std::string, std::string>& fixed,
         const std::vector<std::string>& names, const py::list& columns, const std::string& kind,
         const std::string& backend, int lemma, int grid, int digits, unsigned jobs) {
        return levels_many(expr, T, fixed, names, columns, level_options(kind, backend, lemma, grid, digits), jobs);
      },
      py::arg("expr"), py::arg("T"), py::arg("fixed"), py::arg("names"), py::arg("columns"), py::arg("kind"),
      py::arg("backend"), py::arg("lemma"), py::arg("grid"), py::arg("digits"), py::arg("jobs"));
}

}  // namespace hapstab::python
