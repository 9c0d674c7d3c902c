// `hapstab passivity-level (--H EXPR | --num C --den C | --mat FILE[:VAR]) --T T [--set NAME=VALUE]... | --ss FILE)
//   [--kind osp|isp]
//   [--backend auto|dsdp|csdp|ipm] [--lemma 1|2] [--grid N] [--digits D] [--json]`
// OSP level delta or ISP level phi (scalar, Delta = delta I, Phi = phi I) of a discrete-time
// system, paper 000 Definition 2, by the Lemma 1 (or Lemma 2) LMI with an exact certificate
// of a lower bound, cross-checked by the frequency-domain computation (lmi/passivity_level.hpp).
//
// --ss FILE is a JSON object with the matrices as arrays of rows and T exact:
//   {"A": [[0.5]], "B": [[1]], "C": [[1]], "D": [[1]], "T": "1/100"}
// Entries may be numbers or strings with exact decimals/fractions ("1/3"); they are rounded
// to double for the SDP (the certificate then holds for these doubles' exact values).
// --mat FILE:VAR takes num/den or A, B, C, D from a MATLAB .mat file (cli/mat_file.hpp; the
// doubles at their exact values), with the sample period from --T.
// Every system also gets the certified frequency-domain level (an enclosure of the level
// itself, exact when it is rational; SISO: passivity_level_certified, exact when the minimiser
// is rational; square MIMO: passivity_level_certified_mimo, about the model as written in
// --ss), which is then the main result; otherwise the LMI level (numeric, with an exactly
// certified lower bound).
// JSON output keys: level, method, status (exact|certified|numeric|upper_bound|failed), certified,
// lower_bound / upper_bound (decimal to --digits, rounded outward: the level lies between them when
// both are given), exact ("p/q" when the level is exact, else null), value (the certified level to
// --digits), theta (minimiser), kind, certified_frequency {level,
// value, status, is_level, lower_bound, upper_bound, exact, theta, note} (is_level false for an
// OSP value <= 0, an upper bound on Lemma 1's level only), lmi {level, method, status,
// certified, lower_bound, note}, frequency {level, theta, status, note} (grid), note.
// Exit codes: 0 a level was computed, 2 bad input (including a pole on or outside the unit
// circle), 3 numerical failure (no method gave a level).
#include <Eigen/Eigenvalues>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <cmath>
#include <memory>
#include <optional>
#include <sstream>

#include "cli/command.hpp"
#include "cli/mat_file.hpp"
#include "cli/tf_options.hpp"
#include "hapstab/lmi/passivity_level.hpp"
#include "hapstab/lti/realization.hpp"
#include "hapstab/lti/state_space_json.hpp"
#include "hapstab/numeric/decimal.hpp"
#include "hapstab/numeric/error.hpp"
#include "hapstab/passivity/bound.hpp"

namespace hapstab::cli {
namespace {

const TfRules tf_rules{/*period_required=*/true, /*causal=*/true, /*with_delay=*/false};

struct Opts {
  TfOptions tf;
  std::string ss, kind = "osp", backend = "auto";
  int lemma = 1, grid = 4096, digits = 17;
  bool json = false;
};

StateSpace<rational> read_ss(const std::string& file) {
  std::error_code ec;
  const auto size = std::filesystem::file_size(file, ec);
  if (ec) throw InputError("--ss: cannot read '" + file + "': " + ec.message());
  if (size > 64u << 20) throw InputError("--ss " + file + ": " + std::to_string(size) + " bytes, more than 64 MB");
  std::ifstream in(file);
  if (!in) throw InputError("--ss: cannot read '" + file + "'");
  std::stringstream text;
  text << in.rdbuf();
  return state_space_from_json_exact(text.str(), "--ss " + file);
}

nlohmann::json json_or_null(bool ok, double v) { return ok && std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(nullptr); }

// The system of --H (exact SISO G kept in `G`) or --ss, which must be Schur stable; `exact` is
// the model as written (--ss: its exact entries; --mat: the doubles' exact values), what the
// certified MIMO level is about (the SDP works on the doubles).
StateSpace<double> read_model(const Opts& o, std::optional<RationalFunction<rational>>& G,
                              std::optional<StateSpace<rational>>& exact) {
  StateSpace<double> sys;
  if (!o.ss.empty()) {
    if (!o.tf.T.empty()) throw InputError("--T: the sample period of --ss comes from the file");
    exact = read_ss(o.ss);
    auto rounded = [](const Mat<rational>& M) {
      return Mat<double>(M.unaryExpr([](const rational& x) { return to_real<double>(x); }));
    };
    sys = {rounded(exact->A), rounded(exact->B), rounded(exact->C), rounded(exact->D), exact->T};
    for (const auto* M : {&sys.A, &sys.B, &sys.C, &sys.D})
      if (!M->allFinite()) throw InputError("--ss " + o.ss + ": an entry is not finite (a number beyond the range of double)");
  } else if (std::optional<MatModel> m = o.tf.mat.empty() ? std::nullopt : std::optional(read_mat_model(o.tf.mat, "--mat"));
             m && m->ss) {
    if (!o.tf.sets.empty()) throw InputError("--set names parameters of --H; --mat holds numbers");
    sys = *m->ss;
    sys.T = parse_period(o.tf, tf_rules);
    sys.validate(m->where);
    auto ex = [](const Mat<double>& M) { return Mat<rational>(M.unaryExpr([](double x) { return exact_rational(x); })); };
    exact = StateSpace<rational>{ex(sys.A), ex(sys.B), ex(sys.C), ex(sys.D), sys.T};
  } else {
    const TransferFunction tfG = parse_tf_options(o.tf, tf_rules);
    G = tfG.H;
    sys = tf2ss(tfG).cast<double>();
    sys.T = tfG.T;
  }
  if (sys.states() > 0) {  // the levels of Lemmas 1-2 are defined for (Schur) stable systems
    const Eigen::VectorXcd ev = Eigen::EigenSolver<Eigen::MatrixXd>(sys.A).eigenvalues();
    for (Eigen::Index i = 0; i < ev.size(); ++i)
      if (std::abs(ev(i)) > 1 - 1e-9) {
        std::ostringstream os;
        os << (!o.ss.empty() ? "--ss" : !o.tf.mat.empty() ? "--mat" : "--H") << ": pole at z = " << ev(i).real() << (ev(i).imag() >= 0 ? " + " : " - ")
           << std::abs(ev(i).imag()) << "j, |z| = " << std::abs(ev(i))
           << (std::abs(ev(i)) > 1 + 1e-9 ? " > 1: the system is unstable" : ": on the unit circle (within 1e-9)")
           << "; passivity levels (Lemmas 1-2) need a Schur-stable system";
        throw InputError(os.str());
      }
  }
  return sys;
}

// The three levels (LMI l, frequency grid f, certified frequency c) and which is the result.
struct Levels {
  lmi::PassivityLevel l, f, c;
  bool lmi_ok = false, freq_ok = false, cert_ok = false;
  bool cert_is_level = false;  ///< c is the level (ISP, or OSP with delta* > 0)
  bool only_bound = false;     ///< the result is c as an upper bound (OSP delta* <= 0, no LMI level)
  bool any = false;            ///< some method gave a level
  enum class Main { lmi, freq, cert } which = Main::freq;
  std::string note;
  const lmi::PassivityLevel& main() const { return which == Main::cert ? c : which == Main::lmi ? l : f; }
};

Levels compute_levels(const Opts& o, lmi::Backend backend, const StateSpace<double>& sys,
                      const std::optional<RationalFunction<rational>>& G, const std::optional<StateSpace<rational>>& exact) {
  const auto kind = o.kind == "osp" ? lmi::PassivityKind::osp : lmi::PassivityKind::isp;
  Levels v;
  auto &l = v.l, &f = v.f, &c = v.c;
  l.status = f.status = c.status = Status::failed;
  if (sys.states() == 0) l.note = f.note = c.note = "static gain: no state";
  if (sys.states() > 0) {
    l = lmi::passivity_level_lmi(sys, kind, o.lemma, backend);
    f = lmi::passivity_level_freq(sys, kind, o.grid);
    if (sys.inputs() == 1)
      c = G ? lmi::passivity_level_certified(*G, kind, o.digits) : lmi::passivity_level_certified(sys, kind, o.digits);
    else if (exact)
      c = lmi::passivity_level_certified_mimo(*exact, kind, o.digits, f.status != Status::failed ? f.theta_min : -1.0);
    else c.note = "certified frequency path: no exact model";
  }
  v.lmi_ok = l.status != Status::failed, v.freq_ok = f.status != Status::failed, v.cert_ok = c.status != Status::failed;
  // The certified value is the level of Definition 2 for ISP, and for OSP when delta* > 0
  // (passivity_level.hpp); an OSP delta* <= 0 is an upper bound on Lemma 1's level only.
  v.cert_is_level = v.cert_ok && (kind == lmi::PassivityKind::isp || c.level > 0);
  // main result: the certified level (an enclosure of the level itself), else the LMI
  // (a numeric level with a certified lower bound), else the frequency grid (numeric)
  using M = Levels::Main;
  v.which = v.cert_is_level ? M::cert : v.lmi_ok ? M::lmi : v.cert_ok ? M::cert : M::freq;
  v.only_bound = v.which == M::cert && !v.cert_is_level;  // OSP delta* <= 0 and no LMI level
  v.note = v.main().note;
  auto add = [&](const std::string& what, const std::string& n, M from) {
    if (!n.empty() && v.which != from) v.note += (v.note.empty() ? "" : "; ") + what + n;
  };
  add(sys.inputs() == 1 ? "certified frequency path: " : "", c.note, M::cert);
  if (!v.lmi_ok) add("LMI: ", l.note, M::lmi);
  // compared only where the frequency value is the level (ISP; OSP > 0): an OSP value <= 0 is
  // an upper bound that the LMI level may lie below
  const double ref = v.cert_ok ? c.level : f.level;
  const bool comparable = kind == lmi::PassivityKind::isp || ref > 0;
  if (v.lmi_ok && (v.cert_ok || v.freq_ok) && comparable && std::isfinite(ref) &&
      std::abs(l.level - ref) > 1e-5 * std::max(1.0, std::abs(ref)))
    v.note += (v.note.empty() ? "" : "; ") + std::string("LMI and frequency-domain levels disagree beyond 1e-5");
  v.any = v.cert_ok || v.lmi_ok || v.freq_ok;
  return v;
}

void report_json(const Opts& o, const Levels& v) {
  const auto &main = v.main(), &l = v.l, &f = v.f, &c = v.c;
  const bool any = v.any, only_bound = v.only_bound, cert_ok = v.cert_ok, lmi_ok = v.lmi_ok, freq_ok = v.freq_ok;
  const bool cert_is_level = v.cert_is_level;
  const std::string& note = v.note;
  // bounds rounded outward (cli/command.hpp), the exact level as a fraction where it is exact
  const auto down = [&](const std::optional<rational>& q) { return lower_bound_json(q, o.digits); };
  const auto up = [&](const std::optional<rational>& q) { return upper_bound_json(q, o.digits); };
  auto lo = [](const lmi::PassivityLevel& p) { return p.enclosure ? std::optional<rational>(p.enclosure->lo) : std::nullopt; };
  auto hi = [](const lmi::PassivityLevel& p) { return p.enclosure ? std::optional<rational>(p.enclosure->hi) : std::nullopt; };
  auto exact = [](const lmi::PassivityLevel& p) {
    return p.status == Status::exact && p.enclosure && p.enclosure->lo == p.enclosure->hi ? std::optional<rational>(p.enclosure->lo)
                                                                                          : std::nullopt;
  };
  nlohmann::json j{{"kind", o.kind},
                   {"level", any ? (std::isfinite(main.level) ? nlohmann::json(main.level) : nlohmann::json(main.value))
                                 : nlohmann::json(nullptr)},
                   {"method", main.method},
                   {"status", !any ? "failed" : only_bound ? "upper_bound" : to_string(main.status)},
                   {"certified", main.proven() && !only_bound},
                   {"lower_bound", down(!only_bound && std::isfinite(main.level) ? main.lower_bound : std::nullopt)},
                   {"upper_bound", up(hi(main))},
                   {"exact", exact_json(any && !only_bound ? exact(main) : std::nullopt)},
                   {"value", &main == &c ? nlohmann::json(c.value) : nlohmann::json(nullptr)},
                   {"certified_frequency",
                    {{"level", cert_ok ? (std::isfinite(c.level) ? nlohmann::json(c.level) : nlohmann::json(c.value))
                                       : nlohmann::json(nullptr)},
                     {"value", c.value},
                     {"status", to_string(c.status)},
                     {"is_level", cert_is_level},
                     {"lower_bound", down(lo(c))},
                     {"upper_bound", up(hi(c))},
                     {"exact", exact_json(exact(c))},
                     {"theta", json_or_null(cert_ok, c.theta_min)},
                     {"note", c.note}}},
                   {"lmi",
                    {{"level", json_or_null(lmi_ok, l.level)},
                     {"method", l.method},
                     {"status", to_string(l.status)},
                     {"certified", l.proven()},
                     {"lower_bound", down(l.lower_bound)},
                     {"note", l.note}}},
                   {"frequency",
                    {{"level", json_or_null(freq_ok, f.level)},
                     {"theta", json_or_null(freq_ok, f.theta_min)},
                     {"status", freq_ok ? "numeric" : "failed"},
                     {"note", f.note}}},
                   {"theta", json_or_null(cert_ok || freq_ok, cert_ok ? c.theta_min : f.theta_min)},
                   {"note", note}};
  print_json(j);
}

void report_text(const Opts& o, const Levels& v) {
  const auto &main = v.main(), &l = v.l, &f = v.f, &c = v.c;
  const bool any = v.any, only_bound = v.only_bound, cert_ok = v.cert_ok, lmi_ok = v.lmi_ok, freq_ok = v.freq_ok;
  const std::string& note = v.note;
  std::cout << o.kind << " level";
  if (&main == &c) {
    std::cout << (only_bound ? " <= " : " = ") << c.value << "   [" << to_string(c.status) << (only_bound ? " upper bound" : "")
              << ", " << c.method << "]\n";
    if (c.enclosure && c.enclosure->lo != c.enclosure->hi) {
      const std::string lo = decimal_outward(c.enclosure->lo, o.digits, -1);
      const std::string hi = decimal_outward(c.enclosure->hi, o.digits, +1);
      if (lo != hi) std::cout << "  enclosure: [" << lo << ", " << hi << "]\n";
    }
    std::cout.precision(12);
    std::cout << "  at theta = " << c.theta_min << " (omega = theta/T)\n";
  } else if (any) {
    std::cout.precision(12);
    std::cout << " = " << main.level << "   [numeric, " << main.method << "]\n";
  } else {
    std::cout << ": no method produced a level\n";
  }
  std::cout.precision(12);
  if (lmi_ok) {
    std::cout << "  LMI: " << l.level << "   [numeric, " << l.method << "]\n";
    if (l.lower_bound)
      std::cout << "  LMI certificate: " << o.kind << " level >= " << decimal_outward(*l.lower_bound, o.digits, -1)
                << (*l.lower_bound > 0 ? " > 0: the system is " + o.kind
                                      : " (not positive: the system is not shown " + o.kind + ")")
                << "   [exact LDL^T check of the rounded LMI solution]\n";
  }
  if (cert_ok && &main != &c)
    std::cout << "  certified frequency value: " << c.value << " at theta = " << c.theta_min << "   [" << to_string(c.status)
              << ", not the level: see note]\n";
  if (freq_ok) std::cout << "  frequency grid: " << f.level << " at theta = " << f.theta_min << "   [numeric]\n";
  if (!note.empty()) std::cout << "  note: " << note << "\n";
  if (!f.note.empty()) std::cout << "  frequency note: " << f.note << "\n";
}

int run(const Opts& o) {
  if (o.kind != "osp" && o.kind != "isp") throw InputError("--kind: expected osp or isp, got '" + o.kind + "'");
  const auto backend = lmi::parse_backend(o.backend);
  if (o.lemma != 1 && o.lemma != 2) throw InputError("--lemma: expected 1 or 2");
  if (o.grid < 16 || o.grid > 10000000) throw InputError("--grid: expected 16..10^7 points");
  if (o.digits < 10 || o.digits > 100) throw InputError("--digits: expected 10..100");
  if (has_tf(o.tf) == !o.ss.empty())
    throw InputError("give exactly one of --H EXPR, --num/--den or --mat FILE:VAR (with --T), or --ss FILE");
  std::optional<RationalFunction<rational>> G;  // exact SISO transfer function (--H)
  std::optional<StateSpace<rational>> exact;     // the model as written (--ss, --mat)
  const StateSpace<double> sys = read_model(o, G, exact);
  const Levels v = compute_levels(o, backend, sys, G, exact);
  if (o.json) report_json(o, v);
  else report_text(o, v);
  return v.any ? exit_ok : exit_numerical;
}

const Register reg({"passivity-level",
                    "OSP level delta / ISP level phi of a discrete LTI system (paper 000 Lemmas 1-2): certified "
                    "frequency-domain level, LMI with an exact lower-bound certificate, frequency grid",
                    [](CLI::App& app) {
                      auto o = std::make_shared<Opts>();
                      add_tf_options(app, o->tf, tf_rules, "Transfer function in z, exact (e.g. \"1 + 1/(z-0.5)\"); needs --T");
                      app.add_option("--ss", o->ss, "JSON file {\"A\":[[..]],\"B\":..,\"C\":..,\"D\":..,\"T\":\"1/100\"}");
                      app.add_option("--kind", o->kind, "osp (default) or isp");
                      app.add_option("--backend", o->backend, "auto (default: built-in IPM when exactly certified, else DSDP), dsdp, csdp or ipm");
                      app.add_option("--lemma", o->lemma, "1 (KYP LMI (2), default) or 2 (Schur form)");
                      app.add_option("--grid", o->grid, "Frequency grid points on [0, pi] (default 4096)");
                      app.add_option("--digits", o->digits, "Digits of the certified level (10..100, default 17)");
                      app.add_flag("--json", o->json, "Print JSON (keys level, method, status, certified, "
                                                      "lower_bound, upper_bound, exact, value, theta, kind, "
                                                      "certified_frequency, lmi, frequency, note)");
                      return [o]() { return run(*o); };
                    }});

}  // namespace
}  // namespace hapstab::cli
