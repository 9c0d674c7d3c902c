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
// enclosure [lo, hi] (decimals to --digits, rounded outward; a missing end "-inf" / "inf"; null when
// neither is known), lower_bound / upper_bound (its ends under their old names, null when missing;
// deprecated, kept for one release), exact ("p/q" when the level is exact, else null), value (the certified level to
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

#include "cli/certificate.hpp"
#include "cli/command.hpp"
#include "cli/mat_file.hpp"
#include "cli/tf_options.hpp"
#include "hapstab/lmi/passivity_level_report.hpp"
#include "hapstab/lti/realization.hpp"
#include "hapstab/lti/state_space_json.hpp"
#include "hapstab/numeric/decimal.hpp"
#include "hapstab/numeric/error.hpp"
#include "hapstab/passivity/bound.hpp"

namespace hapstab::cli::cmd_passivity_level {  // its own namespace: the commands compile in unity batches
namespace {

const TfRules tf_rules{/*period_required=*/true, /*causal=*/true, /*with_delay=*/false};

struct Opts {
  TfOptions tf;
  std::string ss, kind = "osp", backend = "auto", certificate;
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
  lmi::check_schur_stable(sys, !o.ss.empty() ? "--ss" : !o.tf.mat.empty() ? "--mat" : "--H");
  return sys;
}

using lmi::Levels;

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
                   // the certified frequency value bounds the level from above also where it is not the level
                   // (an OSP value <= 0 beside the LMI's level): the enclosure [LMI lower bound, its hi]
                   {"upper_bound", up(hi(cert_ok ? c : main))},
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
  // the enclosure under the name every command gives it (docs/json.md): [lower_bound, upper_bound],
  // a missing end unbounded; lower_bound/upper_bound stay for one release, marked deprecated
  const auto enclose = [](nlohmann::json& o) {
    const auto end = [&](const char* key, const char* open) { return o[key].is_null() ? nlohmann::json(open) : o[key]; };
    o["enclosure"] = o["lower_bound"].is_null() && o["upper_bound"].is_null()
                         ? nlohmann::json(nullptr)
                         : nlohmann::json::array({end("lower_bound", "-inf"), end("upper_bound", "inf")});
  };
  enclose(j);
  enclose(j["certified_frequency"]);
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
                << "   [exact LDL^T check of the rounded LMI solution, on the model as written]\n";
    else if (!l.note.empty()) std::cout << "  LMI certificate: none: " << l.note << "\n";
  }
  if (cert_ok && &main != &c)
    std::cout << "  certified frequency value: " << c.value << " at theta = " << c.theta_min << "   [" << to_string(c.status)
              << " upper bound on the level, not the level: see note]\n";
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
  const Levels v = lmi::passivity_levels({sys, G, exact}, o.kind == "osp" ? lmi::PassivityKind::osp : lmi::PassivityKind::isp,
                                          o.lemma, backend, o.grid, o.digits);
  if (!o.certificate.empty()) {
    const bool is_level = v.cert_ok && v.cert_is_level && &v.main() == &v.c;
    // an OSP value <= 0 is an upper bound on Lemma 1's level, printed as the result or beside the LMI's level
    const bool upper_only = v.cert_ok && !v.cert_is_level;
    if (G) {
      write_certificate(o.certificate, passivity_level_certificate(o.tf, *G, o.kind == "osp", v.c, v.l, is_level, upper_only, o.digits));
    } else {  // --ss, or a .mat's A, B, C, D (its doubles exactly): the state-space kind, any number of inputs
      write_certificate(o.certificate, passivity_level_mimo_certificate(*exact, o.kind == "osp", v.c, v.l, is_level, upper_only, o.digits));
    }
  }
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
                      app.add_option("--certificate", o->certificate,
                                     "write the certified level's certificate (JSON: G as written by --H, --num/--den or --mat, or a state space) to "
                                     "FILE, for `hapstab check FILE` (docs/certificates.md)");
                      app.add_flag("--json", o->json, "Print JSON (keys level, method, status, certified, "
                                                      "enclosure, lower_bound, upper_bound, exact, value, theta, kind, "
                                                      "certified_frequency, lmi, frequency, note)");
                      return [o]() { return run(*o); };
                    }});

}  // namespace
}  // namespace hapstab::cli::cmd_passivity_level
