// python/bind_stability.cpp -- the sampled loop's Schur stability and largest stable gain
// (stability/sampled_loop.hpp, built by stability/loop_from_text.hpp as `hapstab stability`
// builds it), a scene's loop as written for any number of DOF (stability/loop_as_written.hpp's
// decide_loop, as `hapstab stability --scene`; the blocks' hidden modes with it), and the OSP/ISP
// levels of paper 000 (lmi/passivity_level_report.hpp, as `hapstab passivity-level` reports
// them); each scalar and vectorised over parameter columns on threads.
//
// `--max NAME` on a scene (the largest stable scene parameter, any number of DOF, with
// conservatism=True Theorem 5's beside it: issue 42) is bound as the command line computes it
// (cli/cmd_stability.cpp): a scene whose blocks hide an unstable mode is NOT stable for every
// value; a one-DOF scene without [coupling] takes stability::max_gain on its loop
// (stability/scene_loop.hpp, NAME a gain of [environment], checked affine); any other scene the
// closed-loop matrix (stability/loop_max.hpp max_parameter, NAME affine), or, where the loop is not
// affine in NAME, the bisection on certified verdicts (conservatism/theorem5_max.hpp
// exact_max_by_verdicts: a change of verdict, not a supremum). The record's value is the supremum
// only where it is proven (status certified/exact); otherwise status 'undecided', value NaN, and
// what is proven beside it (stable_on, change_in).
#include <cmath>
#include <filesystem>
#include <limits>

#include "hapstab/conservatism/theorem5_max.hpp"
#include "hapstab/multidof/witness_json.hpp"
#include "hapstab/lmi/passivity_level_report.hpp"
#include "hapstab/lti/realization.hpp"
#include "hapstab/numeric/decimal.hpp"
#include "hapstab/numeric/error.hpp"
#include "hapstab/report/paths.hpp"
#include "hapstab/scene/schema.hpp"
#include "hapstab/sim/hidden_modes.hpp"
#include "hapstab/stability/loop_as_written.hpp"
#include "hapstab/stability/loop_from_text.hpp"
#include "hapstab/stability/loop_max.hpp"
#include "hapstab/scene/parameter_degree.hpp"
#include "hapstab/stability/scene_loop.hpp"
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

// ---- the largest stable scene parameter (`hapstab stability --scene S --max NAME`) ---------------

/// A record whose quantity is not proven: status undecided, value and ends NaN (no comparison decides).
py::dict record_undecided(const std::string& method, const std::string& note) {
  py::dict d;
  const double nan = std::numeric_limits<double>::quiet_NaN();
  d["value_exact"] = py::none();
  d["mid"] = nan;
  d["lo"] = nan;
  d["hi"] = nan;
  d["lo_text"] = py::none();
  d["hi_text"] = py::none();
  d["status"] = "undecided";
  d["method"] = method;
  d["note"] = note;
  return d;
}

py::tuple decimals(const rational& lo, const rational& hi, int digits) {
  return py::make_tuple(decimal_outward(lo, digits, -1), decimal_outward(hi, digits, +1));
}

py::object point(const std::optional<conservatism::PointVerdict>& v) {
  if (!v) return py::none();
  py::dict d;
  d["at"] = to_decimal(v->at, 17);
  d["status"] = to_string(v->status);
  d["why"] = v->why;
  return d;
}

/// The fields every answer of stability(scene=..., max=NAME) has, None where they do not apply.
py::dict scene_max_fields(const std::string& name, const std::string& path, const std::string& outcome) {
  py::dict d;
  d["name"] = name;
  d["path"] = path;
  d["outcome"] = outcome;
  for (const char* k : {"crossing", "theta", "omega", "stable_on", "gap", "stable_at", "unstable_at", "change_in",
                        "not_affine", "theorem5", "conservatism", "conservatism_note"})
    d[k] = py::none();
  d["supremum_proven"] = false;
  d["open_at_zero"] = false;
  d["contradiction"] = false;
  return d;
}


/// Theorem 5's side of stability(scene, max, conservatism=True): its bracket, and the ratio of
/// suprema only where both regions are proven intervals (docs/stability.md).
void add_theorem5(py::dict& d, const conservatism::VerdictBracket& t5, const scene::Scene& sc, const std::string& name,
                  const std::optional<Enclosure<rational>>& exact_side, bool exact_is_supremum,
                  const stability::LoopAt& loop_at) {
  py::dict t;
  t["bracket"] = t5.lo && t5.hi ? py::object(decimals(t5.lo->at, t5.hi->at, 17)) : py::object(py::none());
  t["concludes_at"] = point(t5.lo);
  t["not_at"] = point(t5.hi);
  if (t5.hi)  // Theorem 5's not_at: how it was proven (the command's theorem5.not_at.theorem4_witness)
    t["not_at"].cast<py::dict>()["theorem4_witness"] = from_json(multidof::coupling_witness_json(t5.hi->witness));
  t["note"] = t5.note;
  t["programs"] = t5.steps.size();
  t["seconds"] = t5.seconds;
  d["theorem5"] = t;
  // a ratio of suprema only where both regions are proven intervals (0, sup): the exact side's by
  // its certified cover from 0, Theorem 5's when NAME is the gain of [environment] (its region
  // scales: docs/stability.md); otherwise the two brackets are boundaries found, not suprema
  const bool t5_interval = sc.root["environment"]["gain"].value_or(std::string()) == name;
  const bool both_intervals = exact_is_supremum && t5_interval;
  const auto r = exact_side && both_intervals ? conservatism::ratio(*exact_side, t5) : std::nullopt;
  d["conservatism"] = r ? py::object(decimals(r->lo, r->hi, 4)) : py::object(py::none());
  std::string why;
  if (!exact_is_supremum) why = "the exact side's bracket is not proven to be the supremum of an interval (0, sup)";
  if (!t5_interval)
    why += (why.empty() ? "" : "; ") + std::string("Theorem 5's region in ") + name +
           " is not proven an interval (only an [environment] gain's is)";
  d["conservatism_note"] = both_intervals ? std::string("exact supremum / Theorem 5's supremum") : "no ratio of suprema: " + why;
  // Theorem 5 is sound: a conclusion where the loop is proven NOT stable is a contradiction (above
  // the exact side's first NOT-stable value the loop may be stable again: decided there)
  if (exact_side && t5.lo && t5.lo->at > exact_side->hi) {
    stability::LoopVerdict v;
    run_interruptible([&] { v = stability::decide_loop(loop_at(t5.lo->at)); });
    if (v.stable && !*v.stable) d["contradiction"] = true;
  }
}

/// stability(scene=S, max=NAME[, conservatism=True]): {"record": the value record, and the fields
/// of scene_max_fields}. digits: of the crossing (1..1000; the closed-loop matrix takes up to 60,
/// the bisection 12, Theorem 5 6, as the command does).
py::dict stability_scene_max(const std::string& scene, bool is_text, const std::map<std::string, std::string>& overrides,
                             const std::string& name, int digits, bool conservatism) {
  if (digits < 1 || digits > 1000) throw InputError("digits must be in [1, 1000], got " + std::to_string(digits));
  std::map<std::string, rational> params;
  for (const auto& [k, v] : overrides) params[k] = exact_arg(v, k);
  const std::string file = is_text ? std::string("scene") : scene;
  const auto scene_at = [&](const rational& p) {
    std::map<std::string, rational> q = params;
    q[name] = p;
    return is_text ? scene::parse_scene(scene, "scene", q) : scene::load_scene(scene, q);
  };
  const scene::Scene sc = scene_arg(scene, is_text, overrides);
  const auto it = sc.parameters.find(name);
  if (it == sc.parameters.end())
    throw InputError("max='" + name + "': the scene has no parameter " + name + " ([parameters])");
  py::dict d;
  // a block that hides a mode outside the stability region: NOT stable for every value (exact)
  const sim::LoopHiddenModes hidden = sim::hidden_modes(sc.loop);
  if (!hidden.stable()) {
    d = scene_max_fields(name, "hidden_modes", "fails");
    d["record"] = record(Certified<rational>::exact_value(0, "a block's hidden mode (sim/hidden_modes.hpp)"), digits);
    d["note"] = "NOT stable for every " + name + " [exact]: " + hidden.summary();
    return d;
  }
  if (!hidden.undecided.empty()) {  // set-aside modes at z = 1 that may chain: no supremum is stated
    d = scene_max_fields(name, "hidden_modes", "undecided");
    d["record"] = record_undecided("sim::hidden_modes", hidden.undecided);
    d["note"] = "undecided: " + hidden.undecided;
    return d;
  }
  const bool one_dof = sc.loop.dofs() == 1 && sc.loop.devices.size() == 1 && sc.loop.operators.size() <= 1 &&
                       !sc.loop.coupling && !conservatism;
  if (one_dof) {  // stability::max_gain on the one-DOF loop
    const stability::Loop loop = stability::scene_loop_affine(scene_at, name, "max='" + name + "': ");
    stability::MaxGain m;
    run_interruptible([&] { m = stability::max_gain(loop, digits, name); });
    LoopInput in{"", "", "", name, loop.T, 0, digits};
    py::dict r = max_record(m, in);
    d = scene_max_fields(name, "one_dof", to_string(m.outcome));
    d["record"] = r["max"].is_none() ? py::object(record_undecided("stability::max_gain", m.note)) : r["max"];
    d["crossing"] = r["crossing"];
    if (r.contains("theta")) d["theta"] = r["theta"], d["omega"] = r["omega"];
    d["supremum_proven"] = m.outcome != Outcome::undecided;
    d["note"] = m.note;
    d["precision_bits"] = m.precision_bits;
    return d;
  }
  scene::check_command(sc.root, file, "stability");  // what it does not model is refused
  const rational reference = it->second > 0 ? it->second : rational(1);
  const stability::LoopAt loop_at = [&](const rational& p) { return scene_at(p).loop; };
  std::optional<conservatism::VerdictBracket> t5;
  std::string not_affine;
  long points = 0;  // how many values prove M(p) affine (scene/parameter_degree.hpp)
  std::optional<Enclosure<rational>> exact_side;  // holds the exact side's boundary (certified)
  bool exact_is_supremum = false;                 // stability on (0, exact_side) proven
  run_interruptible([&] {
    // Theorem 5 first: its refusals (no [coupling], a [delay]) come before any long computation
    if (conservatism) t5 = conservatism::theorem5_max(scene_at, reference, name, std::min(digits, 6));
    try {
      points = scene::points_needed(scene::parameter_degree(sc, name));  // from the scene's text
      stability::loop_family(loop_at, reference, name, points);
    } catch (const InputError& e) {
      not_affine = e.what();
    }
  });
  if (!not_affine.empty()) {  // a change of certified verdicts: not a supremum
    conservatism::VerdictBracket b;
    run_interruptible([&] { b = conservatism::exact_max_by_verdicts(loop_at, reference, name, std::min(digits, 12)); });
    d = scene_max_fields(name, "bisection_on_verdicts", "undecided");
    d["record"] = record_undecided("conservatism::exact_max_by_verdicts (bisection on certified verdicts)", b.note);
    d["not_affine"] = not_affine;
    if (b.lo && b.hi) {
      exact_side = b.bracket();
      d["change_in"] = decimals(b.lo->at, b.hi->at, 17);
    }
    d["stable_at"] = point(b.lo);
    d["unstable_at"] = point(b.hi);
    d["verdicts"] = b.steps.size();
    d["verdicts_outcome"] = to_string(b.outcome);  // holds: a certified bracket (or yes at every value tried)
    d["note"] = b.note + " (the closed loop is not affine in " + name +
                ": a change of certified verdicts, not a proven supremum)";
  } else {
    stability::LoopMax m;
    run_interruptible([&] { m = stability::max_parameter(loop_at, reference, name, points, std::min(digits, 60)); });
    const bool proven_stable = m.stable_to > m.stable_from;
    d = scene_max_fields(name, "closed_loop_matrix", to_string(m.outcome));
    d["note"] = m.note;
    d["states"] = m.states;
    d["fixed_modes"] = m.fixed_modes;
    d["precision_bits"] = m.precision_bits;
    d["cover_intervals"] = m.cover_intervals;
    if (m.outcome == Outcome::fails) {  // a fixed mode outside (exact), or M(0) unstable (certified): sup = 0
      d["record"] = record(Enclosure<rational>{0, 0}, 0, m.status == Status::failed ? Status::exact : m.status,
                           "stability::max_parameter: NOT stable for small values", m.note, digits);
      d["supremum_proven"] = true;
    } else if (m.outcome == Outcome::holds) {
      exact_side = m.sup;
      exact_is_supremum = true;
      d["record"] = record(m.sup, (m.sup.lo + m.sup.hi) / 2, m.status,
                           "stability::max_parameter: the smallest certified crossing of the closed-loop matrix, "
                           "stable below it (certified)", m.note, 17);
      d["supremum_proven"] = true;
      d["gap"] = m.gap;
      py::dict c;
      c["at"] = m.where;
      c["crossing"] = decimals(m.crossing.lo, m.crossing.hi, digits + 3);
      c["theta"] = decimals(m.theta.lo, m.theta.hi, 17);
      c["omega"] = decimals(m.theta.lo / m.T, m.theta.hi / m.T, 17);
      py::dict mode;
      size_t k = 0;
      for (const auto& dev : sc.loop.devices)
        for (Eigen::Index i = 0; i < dev.dofs() && k < m.mode.size(); ++i, ++k)
          mode[py::str(dev.dofs() == 1 ? dev.name : dev.name + "[" + std::to_string(i) + "]")] = m.mode[k];
      c["mode"] = mode;
      d["crossing"] = c;
      d["theta"] = py::make_tuple(double_outward(m.theta.lo, -1), double_outward(m.theta.hi, +1));
      d["omega"] = py::make_tuple(double_outward(m.theta.lo / m.T, -1), double_outward(m.theta.hi / m.T, +1));
    } else {  // undecided: what is proven (stable on [a, b]) beside it, never called a supremum
      d["record"] = record_undecided("stability::max_parameter", m.note);
      if (proven_stable && m.crossing.hi > 0) {
        py::dict c;
        c["crossing"] = decimals(m.crossing.lo, m.crossing.hi, digits + 3);
        d["crossing"] = c;
      }
    }
    // inward: a proven set's printed ends lie inside it (as the command's stable_on)
    if (proven_stable) d["stable_on"] = py::make_tuple(decimal_outward(m.stable_from, 17, +1), decimal_outward(m.stable_to, 17, -1));
    d["open_at_zero"] = m.open_at_zero;  // stable_on excludes 0: M(0) has the eigenvalue 1 (position integrators)
    if (m.stable_at) d["stable_at"] = to_decimal(*m.stable_at, 17);
    if (m.unstable_at) d["unstable_at"] = to_decimal(*m.unstable_at, 17);
  }
  if (t5) add_theorem5(d, *t5, sc, name, exact_side, exact_is_supremum, loop_at);
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
  m.def("stability_scene_max", &stability_scene_max, py::arg("scene"), py::arg("is_text"), py::arg("overrides"),
        py::arg("name"), py::arg("digits"), py::arg("conservatism"),
        "The largest stable scene parameter (`hapstab stability --scene S --max NAME [--conservatism]`).");
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
