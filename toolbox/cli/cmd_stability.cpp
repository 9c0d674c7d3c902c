// cli/cmd_stability.cpp -- `hapstab stability`: Schur stability of the sampled-data haptic loop
// (issue 19), and the largest gain that keeps it stable.
//
//   hapstab stability --plant "1/(m*s^2 + b*s)" --H "K + B*(z-1)/(T*z)" --T 1/1000
//                     --set m=1 --set b=1/10 --set K=1000 --set B=2 [--delay n]
//                     [--operator "bh + kh/s"] [--max K] [--digits D] [--json]
//   hapstab stability --scene FILE [--set NAME=VALUE] --max NAME      (a one-DOF scene, [delay] as z^-n)
// The loop (stability/sampled_loop.hpp): device P(s) (force -> position) behind a zero-order
// hold, position sampled every T, force = -z^-n H(z) x(kT); the operator impedance Z_op(s) acts
// on the device as force -Z_op(s) * velocity, so the loop sees 1/(1/P + s Z_op).
// JSON: stable, status, spectral_radius [lo, hi] (null on the long-delay path), degree, device,
// path ("polynomial" or "long_delay") and plan (why); with --max NAME: max ("inf" when stable for
// every NAME > 0), enclosure [lo, hi], status, crossing {at, theta, omega}, path, plan.
//   hapstab stability --scene FILE [--set NAME=VALUE]... [--json]
// The loop a scene writes, any number of DOF, each block's realisation as written
// (stability/loop_as_written.hpp: hidden modes, the one-DOF exact test, the closed-loop matrix
// with a certified Schur decision): the decider `multidof analyze` and `simulate` share.
// JSON: stable (true|false|null), status, method, evidence, states, spectral_radius_numeric,
// hidden_modes [{block, kind, where, stable}]. With --max NAME: a one-DOF scene without [coupling]
// as above (stability/scene_loop.hpp, NAME a gain of its [environment]); any other scene through
// its closed-loop matrix (stability/loop_max.hpp, NAME affine), or, where the loop is not affine in
// NAME, by bisection on certified verdicts (conservatism/theorem5_max.hpp: a change of verdict).
// --conservatism adds Theorem 5's largest NAME for the scene's [coupling] and the ratio exact /
// Theorem 5 (JSON theorem5, conservatism; docs/stability.md).
// With --scene and --max, a run longer than 2 s names its stages on stderr (cli/progress.hpp);
// --quiet silences them.
// --certificate FILE: the verdict's certificate (kind stability; a --scene beyond one DOF, kind
// stability-loop), with --max NAME the supremum's (kind stability-max); checked before it is written
// where the checkers decide alone (cli/certificate.hpp, docs/certificates.md).
// Exit: 0 stable (or a supremum found), 1 unstable (--max: unstable for every small gain),
// 2 bad input, 3 undecided (a root on or too near the unit circle).
#include <iostream>
#include <sstream>
#include <memory>

#include "cli/certificate.hpp"
#include "cli/loop_max_certificate.hpp"
#include "cli/command.hpp"
#include "cli/progress.hpp"
#include "hapstab/conservatism/theorem5_max.hpp"
#include "hapstab/multidof/witness_json.hpp"
#include "hapstab/numeric/decimal.hpp"
#include "hapstab/numeric/shared_decimal.hpp"
#include "hapstab/numeric/error.hpp"
#include "hapstab/numeric/limits.hpp"
#include "hapstab/scene/parameter_degree.hpp"
#include "hapstab/scene/scene.hpp"
#include "hapstab/scene/schema.hpp"
#include "hapstab/sim/hidden_modes.hpp"
#include "hapstab/stability/loop_as_written.hpp"
#include "hapstab/stability/loop_from_text.hpp"
#include "hapstab/stability/loop_max.hpp"
#include "hapstab/stability/loop_max_symmetric.hpp"
#include "hapstab/stability/sampled_loop.hpp"
#include "hapstab/stability/scene_loop.hpp"

namespace hapstab::cli::cmd_stability {  // its own namespace: the commands compile in unity batches
namespace {

using namespace hapstab;

struct StabilityOpts {
  std::string plant, H, T, op, max_name, scene, certificate;
  std::vector<std::string> sets;
  int delay = 0, digits = 20;
  bool json = false, conservatism = false, quiet = false, no_symmetry = false;
};


/// --scene: a one-DOF scene's loop (stability/scene_loop.hpp); with --max NAME, NAME is a scene
/// parameter of [environment] only, split as --H is: H = H0 + NAME H1, proven: the scene's text
/// bounds H's degree in NAME (scene/parameter_degree.hpp), and H is checked equal to H0 + NAME H1
/// at that many values (at least 5).
stability::Loop scene_loop_of(const StabilityOpts& o) {
  if (!o.plant.empty() || !o.H.empty() || !o.op.empty() || !o.T.empty() || o.delay != 0)
    throw InputError("--scene replaces --plant, --H, --operator, --T and --delay (the scene holds them)");
  const std::map<std::string, rational> params = cli::parse_sets(o.sets);
  const auto scene_at = [&](const rational& k) {
    std::map<std::string, rational> p = params;
    p[o.max_name] = k;
    return scene::load_scene(o.scene, p);
  };
  try {
    if (o.max_name.empty()) return stability::scene_loop(scene::load_scene(o.scene, params));
    return stability::scene_loop_affine(scene_at, o.max_name, "--max " + o.max_name + ": ");
  } catch (const InputError& e) {
    const std::string w = e.what();
    throw InputError(w.rfind("--max", 0) == 0 ? w : "--scene: " + w);
  }
}

stability::Loop make_loop(const StabilityOpts& o) {
  if (!o.scene.empty()) return scene_loop_of(o);
  if (o.T.empty()) throw InputError("--T is required (the sample period)");
  const rational T = cli::option_rational(o.T, "--T");
  if (T <= 0) throw InputError("--T: the sample period must be > 0, got '" + o.T + "'");
  if (o.digits < 1 || o.digits > 1000) throw InputError("--digits must be in [1, 1000], got " + std::to_string(o.digits));
  cli::refuse_unnamed_sets(o.sets, {{"--plant", o.plant}, {"--H", o.H}, {"--operator", o.op}});
  return stability::loop_from_text({o.plant, o.H, o.op, T, o.delay, cli::parse_sets(o.sets), o.max_name});
}

using cli::enclosure_json;  // every printed enclosure rounds outward (cli/command.hpp)

int run_decide(const StabilityOpts& o, const stability::Loop& loop) {
  // the certificate's evidence first: what has none is refused (exit 2) before any verdict is printed;
  // a device beyond the stability kind (three poles off s = 0 or more) gets the closed-loop matrix's
  const bool as_matrix = !o.certificate.empty() && cli::beyond_stability_kind(loop);
  const nlohmann::json evidence = o.certificate.empty() || as_matrix ? nlohmann::json() : cli::stability_evidence(loop);
  const stability::StabilityResult r = stability::decide(loop);
  const bool undecided = !r.verdict.decided();
  const cli::StabilityText text{o.plant, o.H, o.op, o.delay, o.sets, o.scene};
  if (!o.certificate.empty() && !undecided)
    cli::write_certificate(o.certificate, as_matrix ? cli::stability_loop_certificate(text, loop.T, r.verdict.holds())
                                                    : cli::stability_certificate(text, loop, r, evidence));
  nlohmann::json j;
  j["stable"] = undecided ? nlohmann::json(nullptr) : nlohmann::json(r.verdict.holds());
  j["status"] = undecided ? "undecided" : to_string(r.verdict.status);
  j["spectral_radius"] = r.spectral_radius ? enclosure_json(*r.spectral_radius, 17) : nlohmann::json(nullptr);
  j["degree"] = r.degree;
  j["device"] = tf(stability::effective_device(loop).num(), stability::effective_device(loop).den()).to_string();
  j["evidence"] = r.verdict.evidence;
  j["precision_bits"] = r.precision_bits;
  j["path"] = r.path;
  j["plan"] = r.plan;
  if (o.json) cli::print_json(j);
  else {
    std::cout << (undecided ? "undecided" : r.verdict.holds() ? "stable" : "NOT stable") << "   ["
              << j["status"].get<std::string>() << "]\n  " << r.verdict.evidence << "\n";
    if (r.spectral_radius)
      std::cout << "  spectral radius in [" << j["spectral_radius"][0].get<std::string>() << ", "
                << j["spectral_radius"][1].get<std::string>() << "]\n";
    if (r.path == "long_delay") std::cout << "  path: " << r.plan << "\n";
  }
  if (undecided && !o.certificate.empty()) std::cerr << "--certificate: undecided, so no certificate was written\n";
  if (undecided) return cli::exit_numerical;
  return r.verdict.holds() ? cli::exit_ok : cli::exit_property_fails;
}

nlohmann::json max_json(const stability::MaxGain& m, const StabilityOpts& o, const rational& T) {
  nlohmann::json j;
  j["name"] = o.max_name;
  const bool found = m.outcome == Outcome::holds;
  j["status"] = m.outcome == Outcome::undecided ? "undecided" : to_string(m.status);
  int shared = o.digits;  // the significant digits of "max" that are certified
  if (!found) j["max"] = m.outcome == Outcome::fails ? nlohmann::json("0") : nlohmann::json(nullptr);
  else if (m.infinite) j["max"] = "inf";
  else if (m.exact) j["max"] = to_decimal(*m.exact, o.digits);
  else {  // only the digits both ends of the enclosure share
    const SharedDecimal d = shared_decimal(m.enclosure.lo, m.enclosure.hi, o.digits);
    j["max"] = d.text;
    shared = d.digits;
  }
  j["digits_certified"] = found && !m.infinite ? nlohmann::json(shared) : nlohmann::json(nullptr);
  j["max_digits"] = j["digits_certified"];  // its old name, deprecated: kept for one release (docs/json.md)
  j["enclosure"] = found && !m.infinite ? enclosure_json(m.enclosure, o.digits + 3) : nlohmann::json(nullptr);
  if (m.exact) j["exact"] = m.exact->str();
  if (found && !m.infinite) {
    nlohmann::json c{{"at", m.crossing}};
    if (m.theta) {
      c["theta"] = enclosure_json(*m.theta, 17);
      c["omega"] = enclosure_json({m.theta->lo / T, m.theta->hi / T}, 17);  // rad/s
    }
    j["crossing"] = c;
  } else {
    j["crossing"] = nullptr;
  }
  j["note"] = m.note;
  j["precision_bits"] = m.precision_bits;
  j["digits"] = o.digits;
  j["path"] = m.path;
  j["plan"] = m.plan;
  return j;
}

// What the certificate proves, printed beside the answer.
std::string certificate_line(const StabilityOpts& o, const nlohmann::json& certified, bool open_at_zero) {
  if (certified[1] == "0")
    return "  certificate " + o.certificate + ": sup " + o.max_name + " = 0 (an eigenvalue outside the circle for every small " + o.max_name +
           " > 0; verified before it was written)\n";
  return "  certificate " + o.certificate + ": sup " + o.max_name + " in [" + certified[0].get<std::string>() + ", " +
         certified[1].get<std::string>() + "] (stable on " + (open_at_zero ? "(0" : "[0") +
         ", lo], NOT stable at hi; verified before it was written)\n";
}

int run_max(const StabilityOpts& o, const stability::Loop& loop) {
  const stability::MaxGain m = stability::max_gain(loop, o.digits, o.max_name);
  // checked before it is written: a refusal (exit 2) prints no answer. A device pole off s = 0 gets the
  // stability-loop-max kind, whose enclosure is wider than the answer's: what it proves is printed too
  nlohmann::json certified, c;
  if (!o.certificate.empty()) {
    c = cli::stability_max_certificate({o.plant, o.H, o.op, o.delay, o.sets, o.scene}, o.max_name, loop, m, o.digits);
    cli::write_certificate(o.certificate, c);
    if (c["kind"] == "stability-loop-max") certified = {c["claim"]["printed_lo"], c["claim"]["printed_hi"]};
  }
  nlohmann::json j = max_json(m, o, loop.T);
  if (!certified.is_null()) j["certificate_claim"] = certified;
  if (o.json) cli::print_json(j);
  else {
    const int shared = j["digits_certified"].is_null() ? o.digits : j["digits_certified"].get<int>();
    // "max" is null when nothing was found (undecided): printed as such, never read as a string
    const std::string shown = j["max"].is_null() ? std::string("undecided")
                              : shared > 0       ? j["max"].get<std::string>()
                                                 : std::string("(no digit certified)");
    std::cout << "sup " << o.max_name << " = " << shown << "   ["
              << j["status"].get<std::string>();
    if (shared < o.digits)
      std::cout << ", " << shared << " of " << o.digits << " digits: the enclosure did not narrow further";
    std::cout << "]\n";
    if (!j["enclosure"].is_null())
      std::cout << "  enclosure [" << j["enclosure"][0].get<std::string>() << ", "
                << j["enclosure"][1].get<std::string>() << "]\n  roots leave the unit disk at "
                << j["crossing"]["at"].get<std::string>()
                << (j["crossing"].contains("omega") ? ", omega = " + j["crossing"]["omega"][0].get<std::string>() + " rad/s"
                                                    : std::string())
                << "\n";
    std::cout << "  " << m.note << "\n";
    if (m.path == "long_delay") std::cout << "  path: " << m.plan << "\n";
    if (!certified.is_null()) std::cout << certificate_line(o, certified, c["evidence"].contains("first_order"));
  }
  if (m.outcome == Outcome::undecided) return cli::exit_numerical;
  return m.outcome == Outcome::fails ? cli::exit_property_fails : cli::exit_ok;
}

bool one_dof_scene(const scene::Scene& sc) {
  return sc.loop.dofs() == 1 && sc.loop.devices.size() == 1 && sc.loop.operators.size() <= 1 && !sc.loop.coupling;
}

// --scene --certificate: a one-DOF scene's verdict on its transfer-function loop (stability/
// scene_loop.hpp, the loop of --plant/--H), whose certificate holds the scene's text (kind
// stability; the checkers read the loop from the scene themselves, check/scene_model.hpp). Other
// scenes: kind stability-loop (cli::stability_loop_certificate).
nlohmann::json scene_certificate(const StabilityOpts& o, const scene::Scene& sc) {
  stability::Loop loop;
  try {
    loop = stability::scene_loop(sc);
  } catch (const InputError& e) {
    throw InputError(std::string("--certificate: ") + e.what());
  }
  const nlohmann::json evidence = cli::stability_evidence(loop);
  const stability::StabilityResult r = stability::decide(loop);
  if (!r.verdict.decided()) throw InputError("--certificate: the one-DOF loop is undecided: there is no claim to certify");
  return cli::stability_certificate({"", "", "", 0, o.sets, o.scene}, loop, r, evidence);
}

// --scene: the loop as written (stability/loop_as_written.hpp).
int run_scene(const StabilityOpts& o) {
  if (!o.plant.empty() || !o.H.empty() || !o.op.empty() || !o.T.empty() || o.delay != 0)
    throw InputError("--scene replaces --plant, --H, --operator, --T and --delay (the scene holds them)");
  const auto sc = [&] {
    try {
      return scene::load_scene(o.scene, cli::parse_sets(o.sets));
    } catch (const InputError& e) {
      throw InputError(std::string("--scene: ") + e.what());
    }
  }();
  scene::check_command(sc.root, o.scene, "stability");  // what it does not model is refused
  // a one-DOF loop: kind stability (its exact polynomial where it has one); else, or where that kind
  // does not read the scene (an ss device), kind stability-loop
  nlohmann::json certificate;
  std::string one_dof_refusal;
  if (!o.certificate.empty() && one_dof_scene(sc)) try {
      certificate = scene_certificate(o, sc);
    } catch (const InputError& e) {
      one_dof_refusal = e.what();
    }
  const stability::LoopVerdict v =
      stability::decide_loop(sc.loop, o.no_symmetry ? stability::Decider::no_symmetry : stability::Decider::automatic);
  if (!o.certificate.empty() && v.stable) {  // undecided: the verdict is printed, no certificate (below)
    if (!certificate.is_null() && *v.stable != certificate["claim"]["stable"].get<bool>())
      throw NumericalError("--certificate: the loop as written and its one-DOF loop got different verdicts (a defect): no certificate");
    if (certificate.is_null() && !*v.stable && v.path == "hidden_modes")  // exact: the hidden subspace, not M
      if (auto h = cli::hidden_mode_certificate({"", "", "", 0, o.sets, o.scene}, sc.T, sc.loop))
        certificate = *h;
    if (certificate.is_null()) try {
        certificate = cli::stability_loop_certificate({"", "", "", 0, o.sets, o.scene}, sc.T, *v.stable);
      } catch (const InputError& e) {
        if (one_dof_refusal.empty()) throw;
        throw InputError(one_dof_refusal + "; as a closed-loop matrix (kind stability-loop): " + e.what());
      }
    cli::write_certificate(o.certificate, certificate);
  }
  nlohmann::json hidden = nlohmann::json::array();
  for (const auto& h : v.hidden.modes)
    hidden.push_back({{"block", h.block}, {"kind", h.kind}, {"where", h.where.text(h.discrete ? "z" : "s", h.pair)}, {"stable", h.stable}});
  nlohmann::json j{{"stable", v.stable ? nlohmann::json(*v.stable) : nlohmann::json(nullptr)},
                   {"status", v.stable ? to_string(v.status) : "undecided"},
                   {"method", v.method},
                   {"path", v.path.empty() ? nlohmann::json(nullptr) : nlohmann::json(v.path)},
                   {"evidence", v.why},
                   {"dofs", sc.loop.dofs()},
                   {"states", v.states},
                   {"spectral_radius_numeric", v.spectral_radius ? nlohmann::json(*v.spectral_radius) : nlohmann::json(nullptr)},
                   {"hidden_modes", hidden}};
  if (o.json) cli::print_json(j);
  else
    std::cout << (v.stable ? (*v.stable ? "stable" : "NOT stable") : "undecided") << "   [" << j["status"].get<std::string>()
              << "]   (" << sc.loop.dofs() << " DOF, " << (v.method.empty() ? "not decided" : v.method) << ")\n  " << v.why << "\n"
              << (v.hidden.modes.empty() || !v.hidden.stable() ? "" : "  " + v.hidden.summary() + "\n");
  if (!v.stable && !o.certificate.empty()) std::cerr << "--certificate: undecided, so no certificate was written\n";
  if (!v.stable) return cli::exit_numerical;  // undecided (the nonlinear parts were refused above)
  return *v.stable ? cli::exit_ok : cli::exit_property_fails;
}

/// The interval proven stable, rounded INWARD (a proven set: its printed ends must lie inside it;
/// rounded outward, its upper end landed above the certified crossing, where the loop is not stable).
nlohmann::json stable_interval_json(const stability::LoopMax& m) {
  return {decimal_outward(m.stable_from, 17, +1), decimal_outward(m.stable_to, 17, -1)};
}

// --scene --max NAME beyond one DOF (or with a [coupling]): the closed-loop matrix, affine in NAME
// (stability/loop_max.hpp).
nlohmann::json loop_max_json(const stability::LoopMax& m, const StabilityOpts& o, const scene::Scene& sc) {
  nlohmann::json j;
  j["name"] = o.max_name;
  const bool found = m.outcome == Outcome::holds;
  j["status"] = found ? to_string(m.status) : "undecided";
  j["path"] = "closed_loop_matrix";
  j["states"] = m.states;
  j["fixed_modes"] = m.fixed_modes;
  j["note"] = m.note;
  j["digits"] = o.digits;
  j["precision_bits"] = m.precision_bits;
  j["supremum_proven"] = found;
  if (!found) {
    j["max"] = nullptr;
    // what is proven all the same: an interval of stable values (certified), below a certified crossing
    if (m.stable_to > m.stable_from) {
      j["stable_on"] = stable_interval_json(m);
      j["enclosure"] = m.crossing.hi > 0 ? enclosure_json(m.crossing, o.digits + 3) : nlohmann::json(nullptr);
    }
    return j;
  }
  const SharedDecimal d = shared_decimal(m.sup.lo, m.sup.hi, o.digits);
  j["max"] = d.text;
  j["digits_certified"] = d.digits;
  j["max_digits"] = d.digits;  // its old name, deprecated: kept for one release (docs/json.md)
  j["enclosure"] = enclosure_json(m.crossing, o.digits + 3);
  j["sup_enclosure"] = enclosure_json(m.sup, 17);
  j["stable_on"] = stable_interval_json(m);
  j["open_at_zero"] = m.open_at_zero;
  if (m.no_crossing_to > 0) j["no_crossing_to"] = decimal_outward(m.no_crossing_to, 17, -1);  // (0, a]: the resultant, rounded inward
  j["gap"] = m.gap;
  j["stable_at"] = to_decimal(*m.stable_at, 17);
  j["unstable_at"] = to_decimal(*m.unstable_at, 17);
  nlohmann::json c{{"at", m.where}, {"theta", enclosure_json(m.theta, 17)}, {"omega", enclosure_json({m.theta.lo / m.T, m.theta.hi / m.T}, 17)}};
  nlohmann::json mode = nlohmann::json::object();
  size_t k = 0;
  for (const auto& dev : sc.loop.devices)
    for (Eigen::Index i = 0; i < dev.dofs() && k < m.mode.size(); ++i, ++k)
      mode[dev.dofs() == 1 ? dev.name : dev.name + "[" + std::to_string(i) + "]"] = m.mode[k];
  c["mode"] = mode;
  j["crossing"] = c;
  j["cover_intervals"] = m.cover_intervals;
  return j;
}

nlohmann::json point_json(const conservatism::PointVerdict& v) {
  return {{"at", to_decimal(v.at, 17)}, {"status", to_string(v.status)}, {"why", v.why}};
}

/// The exact side when the closed loop is not affine in NAME (a coupling with a feedthrough):
/// bisection on certified verdicts (conservatism/theorem5_max.hpp), a change of verdict.
nlohmann::json verdict_change_json(const conservatism::VerdictBracket& b, const StabilityOpts& o, const std::string& why) {
  nlohmann::json j{{"name", o.max_name}, {"path", "bisection_on_verdicts"}, {"supremum_proven", false}, {"not_affine", why},
                   {"note", b.note}, {"verdicts", b.steps.size()}, {"digits", std::min(o.digits, 12)}};
  // certified: a bracket, or a certified NOT stable at every value tried (exit 1); else undecided (exit 3)
  j["status"] = (b.lo && b.hi) || b.outcome == Outcome::fails ? "certified" : "undecided";
  j["max"] = nullptr;
  j["change_in"] = b.lo && b.hi ? enclosure_json(b.bracket(), 17) : nlohmann::json(nullptr);
  j["stable_at"] = b.lo ? point_json(*b.lo) : nlohmann::json(nullptr);
  j["unstable_at"] = b.hi ? point_json(*b.hi) : nlohmann::json(nullptr);
  return j;
}

nlohmann::json theorem5_json(const conservatism::VerdictBracket& b) {
  nlohmann::json j{{"criterion", "Theorem 5 concludes for the scene's coupling: Theorem 4's program with it (check_theorem4), "
                                 "Assumption 1 and the blocks' hidden modes (docs/stability.md)"},
                   {"note", b.note}, {"programs", b.steps.size()}, {"seconds", b.seconds}};
  j["bracket"] = b.lo && b.hi ? enclosure_json(b.bracket(), 17) : nlohmann::json(nullptr);
  j["concludes_at"] = b.lo ? point_json(*b.lo) : nlohmann::json(nullptr);
  j["not_at"] = b.hi ? point_json(*b.hi) : nlohmann::json(nullptr);
  if (b.hi) j["not_at"]["theorem4_witness"] = multidof::coupling_witness_json(b.hi->witness);
  return j;
}

// The certificate (kind stability-loop-max): sup p in [lo, hi], its ends a relative 10^-12 .. 10^-4 outside
// the crossing's enclosure (Krawczyk's, narrower, is not part of it), or sup p = 0; written before anything
// is printed, and its claim printed with the answer ("certificate: ..."); else a refusal by name.
// Kind stability-loop-max-symmetric where the supremum was found on the split by identical DOFs.
// sup = 0 where the Stein forms fail (a block's unstable mode that no p moves keeps an eigenvalue outside at every p,
// M(0) included, beside one on the circle): the hidden form (loop_max_certificate.hpp), where the mode is one.
nlohmann::json write_loop_max_certificate(const StabilityOpts& o, const scene::Scene& sc, const stability::LoopMax& m, bool split) {
  const nlohmann::json model = cli::scene_model_json(o.scene, o.sets);
  nlohmann::json c;
  try {
    c = split ? cli::stability_loop_max_symmetric_certificate(model, o.max_name, cli::sup_claim(m))
              : cli::stability_loop_max_certificate(model, o.max_name, cli::sup_claim(m));
  } catch (const InputError&) {
    if (m.outcome != Outcome::fails) throw;
    const auto h = cli::hidden_mode_certificate({"", "", "", 0, o.sets, o.scene}, sc.T, sc.loop);
    if (!h) throw;
    c = cli::stability_loop_max_hidden_certificate(model, o.max_name, (*h)["evidence"]["hidden"]);
  }
  cli::write_certificate(o.certificate, c);
  if (c["evidence"].contains("hidden")) return {"0", "0"};
  return {c["claim"]["printed_lo"], c["claim"]["printed_hi"]};
}

// The split supremum's blocks in the JSON (docs/json.md): path "symmetry", each block's label and supremum.
void add_split_json(nlohmann::json& j, const stability::LoopMaxSplit& s) {
  j["path"] = "symmetry";
  j["group"] = s.group;
  j["deciding_block"] = s.deciding;
  nlohmann::json blocks = nlohmann::json::array();
  for (const auto& b : s.blocks) {
    nlohmann::json x{{"label", b.label}, {"class", b.cls < 0 ? nlohmann::json(nullptr) : nlohmann::json(b.cls)},
                     {"outcome", b.max.outcome == Outcome::holds ? "holds" : b.max.outcome == Outcome::fails ? "fails" : "undecided"},
                     {"states", b.max.states}, {"cover_intervals", b.max.cover_intervals}};
    if (b.max.outcome == Outcome::holds) x["sup_enclosure"] = enclosure_json(b.max.sup, 17);
    else if (b.max.outcome == Outcome::fails) x["sup_enclosure"] = enclosure_json({rational(0), rational(0)}, 17);
    blocks.push_back(x);
  }
  j["blocks"] = blocks;
}

// The certificate of the bisection on verdicts (kind stability-loop-verdicts): the verdicts the answer states --
// stable at lo and NOT stable at hi, or every proven one (NOT stable at every value tried, stable at every value
// tried); an undecided answer has none. Its line of text, or "" without --certificate.
std::string write_verdicts_certificate(const StabilityOpts& o, const scene::Scene& sc, const conservatism::VerdictBracket& b,
                                       nlohmann::json& j) {
  if (o.certificate.empty()) return "";
  if (b.outcome == Outcome::undecided) return "  certificate: none written (an undecided answer has none)\n";
  std::vector<std::pair<rational, bool>> verdicts;
  if (b.lo && b.hi) verdicts = {{b.lo->at, true}, {b.hi->at, false}};
  else
    for (const auto& v : b.steps)
      if (v.proven()) verdicts.emplace_back(v.at, *v.yes);
  cli::write_certificate(o.certificate, cli::stability_loop_verdicts_certificate(o.scene, o.sets, sc.T, o.max_name, verdicts));
  j["certificate_claim"] = {{"verdicts", verdicts.size()}};
  return "  certificate " + o.certificate + ": " + std::to_string(verdicts.size()) + " certified verdicts of the loop at values of " +
         o.max_name + " (each a stability-loop certificate; verified before it was written)\n";
}

// The text of a certified supremum (loop_max_json's fields j), on the whole or the split (`split`, else null).
std::string supremum_text(const StabilityOpts& o, const scene::Scene& sc, const stability::LoopMax& m, nlohmann::json& j,
                          const stability::LoopMaxSplit* split) {
  std::ostringstream t;
  t << "sup " << o.max_name << " = " << j["max"].get<std::string>() << "   [certified crossing, " << j["digits_certified"].get<int>()
    << " digits; " << sc.loop.dofs() << " DOF, "
    << (split ? std::to_string(split->blocks.size()) + " small loops of " + std::to_string(m.states) + " states in all (" + split->group + ")"
              : "closed-loop matrix of order " + std::to_string(m.states))
    << (m.fixed_modes > 0 ? " + " + std::to_string(m.fixed_modes) + " fixed modes" : std::string()) << "]\n"
    << "  crossing enclosure [" << j["enclosure"][0].get<std::string>() << ", " << j["enclosure"][1].get<std::string>() << "]\n"
    << "  stable for every " << o.max_name << " in " << (m.open_at_zero ? "(" : "[") << j["stable_on"][0].get<std::string>()
    << ", " << j["stable_on"][1].get<std::string>() << "] (certified"
    << (m.open_at_zero ? "; at " + o.max_name + " = 0 only marginally: position integrators" : std::string())
    << "), NOT stable at " << j["unstable_at"].get<std::string>() << "\n"
    << "  the root leaves the unit disk at " << m.where << ", omega = " << j["crossing"]["omega"][0].get<std::string>()
    << " rad/s; mode |x| per DOF:";
  int shown = 0;  // a split's mode names every DOF: its nonzero entries, the first 8
  for (auto& [dof, a] : j["crossing"]["mode"].items())
    if (!split || (a.get<double>() != 0 && ++shown <= 8)) t << " " << dof << " " << to_decimal(rational(a.get<double>()), 3);
  if (shown > 8) t << " ... (" << shown << " DOFs)";
  t << "\n  " << m.note << "\n";
  return t.str();
}

// Whether the closed loop is proven affine in NAME ("" when it is, else why not), and `points`, the values that
// prove it (scene/parameter_degree.hpp). Where the loop splits by identical DOFs (`split`: wanted, and on return
// whether it splits) the small loops' families are checked instead of the whole's (stability/loop_max_symmetric.hpp).
std::string dependence(const StabilityOpts& o, const scene::Scene& sc, const stability::LoopAt& at, const rational& reference, long& points,
                       bool& split) {
  try {
    points = scene::points_needed(scene::parameter_degree(sc, o.max_name));
    const std::optional<std::string> by_split = split ? stability::split_not_affine(at, reference, o.max_name, points) : std::nullopt;
    split = by_split.has_value();
    if (by_split) return *by_split;
    stability::loop_family(at, reference, o.max_name, points);
  } catch (const InputError& e) {
    split = false;
    return e.what();
  }
  return "";
}

// Undecided on the whole where the loop splits (a crossing repeated by identical DOFs in classes of two defeats
// Krawczyk's enclosure of one simple eigenvalue; a walk stalled beside an eigenvalue of another block): the split's
// small loops, every block affine, and their answer where it decides; else nullopt.
std::optional<stability::LoopMaxSplit> split_where_whole_undecided(const StabilityOpts& o, const stability::LoopAt& at, const rational& reference,
                                                                   long points) {
  const std::optional<std::string> blocks_not_affine = stability::split_not_affine(at, reference, o.max_name, points);
  if (!blocks_not_affine || !blocks_not_affine->empty()) return std::nullopt;
  std::string why;
  auto s = stability::max_parameter_by_symmetry(at, reference, o.max_name, points, std::min(o.digits, 60), why);
  if (s && s->whole.outcome != Outcome::undecided) return s;
  return std::nullopt;
}

// Whether every unstable hidden mode (at the scene's value of NAME) is unstable for every value: its block is
// one NAME does not enter (scene/parameter_degree.hpp, proven from the text: NAME enters only [environment] and
// [coupling]), or an uncontrollable mode of one whose A and B NAME does not move. Anything else -- NAME in a
// block's A or B, an unobservable mode where C may move, a parameter_degree refusal -- is not proven: the caller
// then decides the loop as written (a mode on z = 2 at g = 2 may be z = g, stable at g = 1/2).
bool hidden_for_every_value(const scene::Scene& sc, const sim::LoopHiddenModes& hidden, const std::string& name) {
  scene::ParameterDegree d;
  try {
    d = scene::parameter_degree(sc, name);
  } catch (const InputError&) {
    return false;
  }
  for (const auto& m : hidden.modes) {
    if (m.stable) continue;
    const bool entered = (m.block == "environment" && d.environment) || (m.block == "coupling" && d.coupling);
    if (entered && !(m.kind == "uncontrollable" && !d.dynamics_move)) return false;
  }
  return true;
}

int run_loop_max(const StabilityOpts& o, const scene::Scene& sc, cli::StageProgress& progress) {
  if (!o.certificate.empty() && o.conservatism)
    throw InputError("--certificate: stability --max --conservatism has no certificate (Theorem 5's side is a bracket of LMI "
                     "verdicts); without --conservatism the exact side's supremum has one");
  scene::check_command(sc.root, o.scene, "stability");
  const std::map<std::string, rational> params = cli::parse_sets(o.sets);
  const auto it = sc.parameters.find(o.max_name);
  if (it == sc.parameters.end())
    throw InputError("--max " + o.max_name + ": the scene has no parameter " + o.max_name + " ([parameters])");
  const rational reference = it->second > 0 ? it->second : rational(1);
  const conservatism::SceneAt scene_at = [&](const rational& p) {
    std::map<std::string, rational> q = params;
    q[o.max_name] = p;
    return scene::load_scene(o.scene, q);
  };
  const stability::LoopAt at = [&](const rational& p) { return scene_at(p).loop; };
  // Theorem 5 first: its refusals (no [coupling], a [delay]) come before any long computation.
  std::optional<conservatism::VerdictBracket> t5;
  if (o.conservatism) progress.stage("Theorem 5's largest " + o.max_name + " (LMI programs, bisection)");
  if (o.conservatism) t5 = conservatism::theorem5_max(scene_at, reference, o.max_name, std::min(o.digits, 6));
  long points = 0;  // how many values prove M(p) affine, from the scene's text (scene/parameter_degree.hpp)
  progress.stage("the closed loop's dependence on " + o.max_name);
  bool split_wanted = !o.no_symmetry && stability::split_pays(sc.loop);
  const std::string not_affine = dependence(o, sc, at, reference, points, split_wanted);
  nlohmann::json j;
  int rc = cli::exit_ok;
  std::optional<Enclosure<rational>> exact;  // holds the exact side's boundary (certified)
  bool exact_is_supremum = false;            // stability on (0, exact) proven: the supremum of an interval
  std::string text;
  progress.stage(not_affine.empty() ? "the supremum: certified crossing of the closed-loop matrix"
                                     : "the supremum: bisection on certified verdicts");
  if (!not_affine.empty()) {
    const conservatism::VerdictBracket b = conservatism::exact_max_by_verdicts(at, reference, o.max_name, std::min(o.digits, 12));
    j = verdict_change_json(b, o, not_affine);
    std::ostringstream t;
    if (b.lo && b.hi) {
      exact = b.bracket();
      t << o.max_name << ": stable at " << to_decimal(b.lo->at, 17) << ", NOT stable at " << to_decimal(b.hi->at, 17)
        << "   [certified verdicts, bisection; " << sc.loop.dofs() << " DOF]\n";
    } else if (b.lo) {  // stable up to lo; above it nothing NOT stable was proven: no supremum (exit 3)
      t << o.max_name << ": stable at " << to_decimal(b.lo->at, 17) << ", no NOT-stable value proven above it: supremum undecided"
        << "   [certified verdicts, bisection; " << sc.loop.dofs() << " DOF]\n";
      rc = cli::exit_numerical;
    } else {
      t << o.max_name << ": no certified stable value found\n";
      rc = b.outcome == Outcome::fails ? cli::exit_property_fails : cli::exit_numerical;
    }
    t << "  " << b.note << "\n  (the certified crossing of --max does not apply, it needs the closed loop proven affine in "
      << o.max_name << ": " << not_affine << ")\n";
    text = t.str() + write_verdicts_certificate(o, sc, b, j);
  } else {
    std::optional<stability::LoopMaxSplit> split;
    std::string no_split = o.no_symmetry ? "--no-symmetry" : "no split pays";
    if (split_wanted) split = stability::max_parameter_by_symmetry(at, reference, o.max_name, points, std::min(o.digits, 60), no_split);
    if (!split && sc.loop.dofs() > stability::kWholeMaxDofs)
      throw InputError("--max " + o.max_name + ": " + std::to_string(sc.loop.dofs()) + " DOFs, not split by identical DOFs (" +
                       no_split + "): the whole closed-loop matrix's supremum is refused beyond " + std::to_string(stability::kWholeMaxDofs) +
                       " DOFs (its cover of eigenvalue enclosures costs minutes to hours there)");
    stability::LoopMax m = split ? split->whole : stability::max_parameter(at, reference, o.max_name, points, std::min(o.digits, 60));
    if (!split && m.outcome == Outcome::undecided && !o.no_symmetry)
      if ((split = split_where_whole_undecided(o, at, reference, points))) m = split->whole;
    // an undecided supremum writes no certificate and keeps its exit code 3 (docs/certificates.md)
    const nlohmann::json certified =
        o.certificate.empty() || m.outcome == Outcome::undecided ? nlohmann::json() : write_loop_max_certificate(o, sc, m, split.has_value());
    if (m.outcome == Outcome::fails) {  // a fixed mode outside (exact), M(0) unstable or the first-order mirror (certified): sup = 0
      j = {{"name", o.max_name}, {"max", "0"}, {"status", to_string(m.status)},
           {"path", "closed_loop_matrix"}, {"note", m.note}, {"digits", o.digits}};
      if (const rational u = m.first_order_to > 0 ? m.first_order_to : m.no_crossing_to; u > 0)  // (0, eps], rounded inward
        j["unstable_on"] = {"0", decimal_outward(u, 17, -1)};
      if (split) add_split_json(j, *split);
      text = "sup " + o.max_name + " = 0   [" + to_string(m.status) + "]\n  " + m.note + "\n";
      rc = cli::exit_property_fails;
    } else {
      j = loop_max_json(m, o, sc);
      if (split) add_split_json(j, *split);
      if (m.outcome != Outcome::holds) {
        text = "sup " + o.max_name + ": undecided\n";
        if (j.contains("stable_on"))
          text += "  stable for every " + o.max_name + " in " + (m.open_at_zero ? "(" : "[") + j["stable_on"][0].get<std::string>() + ", " +
                  j["stable_on"][1].get<std::string>() + "] [certified]\n";
        text += "  " + m.note + "\n";
        if (!o.certificate.empty()) text += "  certificate: none written (an undecided supremum has none)\n";
        rc = cli::exit_numerical;
      } else {
        exact = m.sup;
        exact_is_supremum = true;
        text = supremum_text(o, sc, m, j, split ? &*split : nullptr);
      }
    }
    if (!certified.is_null()) j["certificate_claim"] = certified, text += certificate_line(o, certified, m.open_at_zero);
  }
  if (t5) {
    j["theorem5"] = theorem5_json(*t5);
    // a ratio of suprema only where both regions are proven intervals (0, sup): the exact side's by
    // the certified cover from 0, Theorem 5's when NAME is the gain of [environment] (its region
    // scales: docs/stability.md); otherwise the two brackets are boundaries, not suprema
    const bool t5_interval = sc.root["environment"]["gain"].value_or(std::string()) == o.max_name;
    const bool both_intervals = exact_is_supremum && t5_interval;
    const auto r = exact && both_intervals ? conservatism::ratio(*exact, *t5) : std::nullopt;
    j["conservatism"] = r ? enclosure_json(*r, 4) : nlohmann::json(nullptr);
    j["conservatism_note"] = both_intervals ? "exact supremum / Theorem 5's supremum"
                             : std::string("no ratio of suprema: ") +
                                   (exact_is_supremum ? "" : "the exact side's bracket is not proven to be the supremum of an interval (0, sup)") +
                                   (!exact_is_supremum && !t5_interval ? "; " : "") +
                                   (t5_interval ? "" : "Theorem 5's region in " + o.max_name + " is not proven an interval (only an [environment] gain's is)");
    std::ostringstream t;
    if (t5->lo && t5->hi)
      t << "Theorem 5: concludes at " << o.max_name << " = " << to_decimal(t5->lo->at, 17) << ", not at "
        << to_decimal(t5->hi->at, 17) << "   [" << t5->steps.size() << " LMI programs]\n";
    else
      t << "Theorem 5: no certified bracket   [" << t5->steps.size() << " LMI programs]\n";
    t << "  " << t5->note << "\n";
    if (t5->lo) t << "  at " << to_decimal(t5->lo->at, 17) << ": " << t5->lo->why << "\n";
    if (t5->hi) t << "  at " << to_decimal(t5->hi->at, 17) << ": " << t5->hi->why << "\n";
    if (r)
      t << "conservatism: exact / Theorem 5 in [" << j["conservatism"][0].get<std::string>() << ", "
        << j["conservatism"][1].get<std::string>() << "]   (certified: a ratio of suprema of intervals, both brackets' ends certified verdicts)\n";
    else if (!both_intervals)
      t << "conservatism: not a ratio (" << j["conservatism_note"].get<std::string>() << "); the brackets above are boundaries found\n";
    else
      t << "conservatism: not determined (a bracket has no certified upper end)\n";
    text += t.str();
    // Theorem 5 is sound: a conclusion where the loop is proven NOT stable is a contradiction (a
    // conclusion above the exact side's first NOT-stable value is not: the loop may be stable again there)
    if (t5->lo && exact && t5->lo->at > exact->hi) {
      const stability::LoopVerdict v = stability::decide_loop(at(t5->lo->at));
      if (v.stable && !*v.stable) {
        text += "CONTRADICTION: Theorem 5 concludes at " + o.max_name + " = " + to_decimal(t5->lo->at, 17) +
                ", where the loop is proven NOT stable (" + to_string(v.status) + ")\n";
        j["contradiction"] = true;
        rc = cli::exit_numerical;
      } else {
        text += "  note: Theorem 5 concludes at " + o.max_name + " = " + to_decimal(t5->lo->at, 17) +
                ", above the exact side's first NOT-stable value: the stable set is not an interval there" +
                (v.stable ? std::string(" (the loop is stable again, ") + to_string(v.status) + ")" : std::string(" (the loop there: undecided)")) + "\n";
      }
    }
  }
  progress.finish();
  if (o.json) cli::print_json(j);
  else std::cout << text;
  return rc;
}

const cli::Register reg(
    {"stability",
     "Schur stability of the sampled haptic loop (device P(s), ZOH, wall H(z), delay); --max NAME: the largest stable gain",
     [](CLI::App& app) {
       auto o = std::make_shared<StabilityOpts>();
       app.add_option("--plant", o->plant, "device P(s), force -> position, e.g. \"1/(m*s^2 + b*s)\"");
       app.add_option("--H", o->H, "virtual environment H(z), e.g. \"K + B*(z-1)/(T*z)\" (force = -z^-n H x)");
       app.add_option("--T", o->T, "sample period T > 0 (exact: 0.001 or 1/1000)");
       app.add_option("--delay", o->delay, "integer delay n >= 0: z^-n (any n up to 10^6: beyond a few hundred samples the long-delay path)")->capture_default_str();
       app.add_option("--scene", o->scene, "a scene (TOML) instead of --plant/--H/--operator/--T/--delay: its loop as written, any number of DOF");
       app.add_option("--operator", o->op, "operator impedance Z_op(s) on the device (force per velocity), e.g. \"bh + kh/s\"");
       app.add_option("--set", o->sets, "parameter NAME=VALUE (repeatable)");
       app.add_option("--max", o->max_name, "gain NAME of --H (affine in it) to maximise: sup{NAME : stable on (0, sup)}");
       app.add_option("--digits", o->digits, "significant digits of --max (1..1000)")->capture_default_str();
       app.add_flag("--conservatism", o->conservatism, "with --scene and --max: also the largest NAME for which Theorem 5 "
                    "concludes (the scene's [coupling]) and the ratio exact / Theorem 5");
       app.add_flag("--no-symmetry", o->no_symmetry, "with --scene: decide the whole closed-loop matrix, not the small loops "
                    "that the permutations of identical DOFs split it into (for comparison; the verdicts are the same); with --max, "
                    "the whole's supremum beyond 8 DOFs (up to 64)");
       app.add_flag("--json", o->json, "JSON output");
       app.add_flag("--quiet", o->quiet, "No progress on stderr (--scene --max: shown for runs longer than 2 s)");
       app.add_option("--certificate", o->certificate, "write the verdict's certificate (JSON) to FILE, for `hapstab check "
                      "FILE`: kind stability (one-DOF --plant/--H loop, every device pole at s = 0 or one real pole off it, "
                      "a mass-damper, a spring; or a one-DOF --scene, its text the model), stability-loop for another --scene "
                      "or a --plant with three poles off s = 0 or more (the closed-loop matrix the checkers "
                      "build from the model), or stability-max with --max (every device pole at s = 0); refused by name: "
                      "what the checkers do not read (count, diagonal, contact, ...), --scene --max beyond one DOF, "
                      "--max with a device pole off s = 0, degree above the checkers' limit; an undecided answer writes "
                      "none; docs/certificates.md)");
       return [o]() -> int {
         if (o->conservatism && (o->scene.empty() || o->max_name.empty()))
           throw InputError("--conservatism compares Theorem 5 with the loop as written on a scene: it needs --scene and --max");
         if (o->no_symmetry && o->scene.empty())
           throw InputError("--no-symmetry applies to --scene (the only path that splits a loop by the permutations of its identical DOFs)");
         if (!o->scene.empty() && o->max_name.empty()) return run_scene(*o);
         if (!o->scene.empty()) {  // --max on a scene: its blocks' hidden modes first (sim/hidden_modes.hpp)
           std::vector<std::string> plan{"reading the scene", "the closed loop's dependence on " + o->max_name, "the supremum"};
           if (o->conservatism) plan.insert(plan.begin() + 1, "Theorem 5's largest " + o->max_name);
           cli::StageProgress progress("stability --max", plan, o->quiet);
           progress.stage();
           const auto sc = [&] {
             try {
               return scene::load_scene(o->scene, cli::parse_sets(o->sets));
             } catch (const InputError& e) {
               throw InputError(std::string("--scene: ") + e.what());
             }
           }();
           const auto hidden = sim::hidden_modes(sc.loop);
           const bool hidden_unstable = !hidden.stable();
           if (hidden_unstable && hidden_for_every_value(sc, hidden, o->max_name)) {
             if (!o->certificate.empty()) {  // the hidden mode's evidence (kind stability-loop's), for every value
               const auto h = cli::hidden_mode_certificate({"", "", "", 0, o->sets, o->scene}, sc.T, sc.loop);
               if (!h)
                 throw InputError("--certificate: sup " + o->max_name + " = 0 is decided by a hidden mode (" + hidden.summary() +
                                  ") that has no certificate form (a block written as tf, or a continuous block's mode on the "
                                  "boundary): no certificate");
               cli::write_certificate(o->certificate, cli::stability_loop_max_hidden_certificate(cli::scene_model_json(o->scene, o->sets),
                                                                                                   o->max_name, (*h)["evidence"]["hidden"]));
             }
             const std::string note = "NOT stable for every " + o->max_name + " [exact]: " + hidden.summary();
             const nlohmann::json zero = {"0", "0"};
             if (o->json) {
               nlohmann::json j = {{"name", o->max_name}, {"max", "0"}, {"status", "exact"}, {"note", note}, {"digits", o->digits},
                                   {"path", "hidden_modes"}};
               if (!o->certificate.empty()) j["certificate_claim"] = zero;
               cli::print_json(j);
             } else {
               std::cout << "sup " << o->max_name << " = 0   [exact]\n  " << note << "\n";
               if (!o->certificate.empty()) std::cout << certificate_line(*o, zero, false);
             }
             return cli::exit_property_fails;
           }
           if (!hidden_unstable && !hidden.undecided.empty()) {  // set-aside modes at z = 1 that may chain
             if (!o->certificate.empty()) std::cerr << "--certificate: undecided, so no certificate was written\n";
             const std::string note = "undecided: " + hidden.undecided + "; " + hidden.summary();
             if (o->json)
               cli::print_json({{"name", o->max_name}, {"max", nullptr}, {"status", "undecided"}, {"note", note}, {"digits", o->digits},
                                {"path", "hidden_modes"}});
             else std::cout << "sup " << o->max_name << " undecided\n  " << note << "\n";
             return cli::exit_numerical;
           }
           // beyond one DOF, or with a [coupling]: the closed-loop matrix (stability/loop_max.hpp)
           if (!(o->plant.empty() && o->H.empty() && o->op.empty() && o->T.empty() && o->delay == 0))
             throw InputError("--scene replaces --plant, --H, --operator, --T and --delay (the scene holds them)");
           // a hidden mode NAME may move (unstable at the scene's value): the loop as written, whose matrix holds it
           if (!one_dof_scene(sc) || o->conservatism || hidden_unstable)
             return run_loop_max(*o, sc, progress);
           progress.replan({"the one-DOF loop's supremum"});
           progress.stage();
           return run_max(*o, make_loop(*o));
         }
         const stability::Loop loop = make_loop(*o);
         return o->max_name.empty() ? run_decide(*o, loop) : run_max(*o, loop);
       };
     }});

}  // namespace
}  // namespace hapstab::cli::cmd_stability
