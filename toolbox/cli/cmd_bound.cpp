// cli/cmd_bound.cpp -- `hapstab bound`: the passivity bound b* of paper 001, (45) and (54).
//
//   hapstab bound --H "K + B*(z-1)/(T*z)" --T 1/1000 --set K=1000 --set B=5 [--delay N]
//                 [--frac-delay TD] [--eta ETA] [--digits D] [--method certified|fast|grid]
//                 [--explain] [--json] [--curve FILE] [--quantum DELTA [--coulomb FC]]
//   hapstab bound --batch FILE     (one case per line: expression and options; one JSON line each)
//   --certificate FILE writes b*'s certificate for `hapstab check` (cli/certificate.hpp; integer and fractional delays;
//   with --max, K_max's)
// JSON keys: bound ("inf" when no finite b), omega (rad/s or null), enclosure [lo, hi], status,
// closed_form (name or null), plus method, path ("exact" or "long_delay") and plan (the planner's
// reason), where, closed_form_value; dirichlet_C/_D (certified
// enclosures) for (50); damping {b, passive, eq14_lhs, eq14_holds, eq15_rhs, eq15_holds} with --damping;
// friction {quantum, fc_star, fc_star_exact, l1_norm, taps, tight, status, why, coulomb, holds} with
// --quantum (passivity/friction.hpp: passive iff b > b* and f_c >= f_c* = Delta/2 sum |w_k|), and
// passive (both verdicts) when --damping and --coulomb are given. Exit 1 when a given b or f_c fails.
// --max NAME --damping b: the largest NAME that b keeps passive (cli/bound_max.hpp has its keys).
#include <fstream>
#include <iostream>
#include <memory>
#include <sstream>

#include "cli/batch_line.hpp"
#include "cli/bound_max.hpp"
#include "cli/certificate.hpp"
#include "cli/command.hpp"
#include "cli/tf_options.hpp"
#include "hapstab/lti/parse.hpp"
#include "hapstab/numeric/decimal.hpp"
#include "hapstab/numeric/error.hpp"
#include "hapstab/passivity/bound.hpp"
#include "hapstab/passivity/catalogue.hpp"
#include "hapstab/passivity/friction.hpp"
#include "hapstab/report/paths.hpp"

namespace hapstab::cli::cmd_bound {  // its own namespace: the commands compile in unity batches
namespace {

using namespace hapstab;
using namespace hapstab::passivity;

struct BoundOpts {
  cli::TfOptions tf;
  std::string frac, eta = "0", method = "certified", curve, damping, quantum, coulomb, max, certificate;
  int digits = 30;
  long grid = 100000;
  bool explain = false, json = false, allow_noncausal = false;
};

// Causality is the library's check: H z^-n may be causal where H is not (bound.hpp).
const cli::TfRules tf_rules{/*period_required=*/true, /*causal=*/false, /*with_delay=*/true,
                            /*hidden_poles=*/HiddenPoles::allow_marginal};  // b* sees the frequency response

void add_options(CLI::App& app, BoundOpts& o, bool batch_line) {
  cli::add_tf_options(app, o.tf, tf_rules, "H(z) as an exact expression, e.g. \"K + B*(z-1)/(T*z)\"");
  app.add_option("--frac-delay", o.frac, "delay t_d >= 0 in seconds: e^{-j w t_d}");
  app.add_option("--eta", o.eta, "operator shortage of passivity eta >= 0 (54)")->capture_default_str();
  app.add_option("--digits", o.digits,
                 "significant digits of the certified result (10..280, also with --frac-delay t_d = (p/q) T when the objective in cos(wT/q) has degree <= 96; above that degree the interval branch-and-bound gives at most 20)")
      ->capture_default_str();
  app.add_option("--method", o.method, "certified (default) | fast (double) | grid (comparison only)");
  app.add_option("--grid-points", o.grid, "N for --method grid")->capture_default_str();
  app.add_flag("--explain", o.explain, "name the closed form of Sec. VI/VII that applies and show it beside the result");
  app.add_flag("--allow-noncausal", o.allow_noncausal, "evaluate (45) for a non-causal H (FIR form (47) as written)");
  app.add_option("--damping,--b", o.damping,
                 "device damping b to check: passive iff b > b* (exit 1 when not), with the necessary condition "
                 "(14) <=> (15) evaluated at the maximiser");
  app.add_option("--max", o.max,
                 "parameter NAME of --H (affine in it) to maximise: sup{NAME0 : b > b*(NAME) for 0 <= NAME < NAME0} "
                 "for the device damping --damping b, certified (passivity/max_gain.hpp)");
  app.add_option("--quantum", o.quantum,
                 "encoder resolution Delta > 0 (m): report the Coulomb-friction condition f_c >= f_c* = Delta/2 sum|w_k| "
                 "beside b* (FIR walls; Abbott-Okamura 2005, docs/friction.md)");
  app.add_option("--coulomb", o.coulomb, "device Coulomb friction f_c >= 0 (N) to check against f_c* (needs --quantum; exit 1 when f_c < f_c*)");
  if (!batch_line) {
    app.add_flag("--json", o.json, "JSON output");
    app.add_option("--curve", o.curve, "write 'omega objective' samples (2001 points, 50 digits) to FILE");
    app.add_option("--certificate", o.certificate,
                   "write b*'s certificate (JSON) to FILE, for `hapstab check FILE` (docs/certificates.md)");
  }
}

/// `--damping b`: the verdict b > b* and, at the maximiser w*, the small-gain condition (14)
/// |rH/(2b + rH)| < 1 beside its rewriting (15) b > Re{-rH} (paper 001, Sec. III), for H z^-n.
struct DampingCheck {
  rational b;
  bool passive = false;
  std::optional<NecessaryCheck> at_max;  ///< when w* > 0, t_d = 0 and eta = 0
};

/// `--quantum Delta [--coulomb f_c]`: the friction condition of passivity/friction.hpp.
struct FrictionCheck {
  rational quantum;
  FrictionCondition c;
  std::optional<rational> coulomb;
  bool holds() const { return !coulomb || *coulomb >= c.fc_star; }
};

struct Outcome {
  Bound b;
  std::optional<FrictionCheck> friction;
  std::optional<catalogue::Match> cf;
  BoundProblem p;
  std::optional<DampingCheck> damping;
  std::optional<std::pair<Enclosure<rational>, Enclosure<rational>>> dirichlet;  ///< C, D of (50)
};

BoundProblem problem_of(const BoundOpts& o, const TransferFunction& tf) {
  BoundProblem p;
  p.T = tf.T;
  p.delay = o.tf.delay;
  p.eta = cli::option_rational(o.eta, "--eta");
  if (p.eta < 0) throw InputError("--eta must be >= 0 (got " + o.eta + ")");
  if (!o.frac.empty()) {
    rational td = cli::option_rational(o.frac, "--frac-delay");
    if (td < 0) throw InputError("--frac-delay must be >= 0 (got " + o.frac + ")");
    if (td > 0) p.frac_delay = td;
  }
  p.allow_noncausal = o.allow_noncausal;
  p.H = tf.H;
  return p;
}

/// `--max NAME`: H = H0 + NAME H1, the device's b from --damping.
passivity::BoundMax compute_max(const BoundOpts& o) {
  const std::string opt = "--max " + o.max;
  if (o.damping.empty()) throw InputError(opt + " needs --damping b (the device's damping that must exceed b*)");
  if (o.method != "certified") throw InputError(opt + " is certified only: leave out --method " + o.method);
  if (!o.quantum.empty() || !o.coulomb.empty())
    throw InputError(opt + ": the friction condition (--quantum, --coulomb) is not part of the maximisation; check it with bound at the value found");
  if (!o.curve.empty()) throw InputError(opt + ": --curve draws b* at one value of the parameters; give --set " + o.max + "=VALUE instead");
  const AffineSplit h = cli::parse_tf_affine(o.tf, tf_rules, o.max, "--max");
  passivity::GainProblem g;
  g.base = problem_of(o, h.H0);
  g.H1 = h.H1.H;
  g.b = cli::option_rational(o.damping, "--damping");
  g.name = o.max;
  return passivity::bound_max(std::move(g), o.digits, o.explain);
}

Outcome compute(const BoundOpts& o) {
  const TransferFunction tf = cli::parse_tf_options(o.tf, tf_rules);
  Outcome r;
  r.p = problem_of(o, tf);
  Method m = Method::certified;
  if (o.method == "grid") m = Method::grid;
  else if (o.method == "fast") m = Method::fast;
  else if (o.method != "certified") throw InputError("--method must be certified, fast or grid (got " + o.method + ")");
  if (o.grid < 2 || o.grid > 100000000)
    throw InputError("--grid-points must be in [2, 1e8] (got " + std::to_string(o.grid) + ")");
  r.b = bound(r.p, m, o.digits, o.grid);
  r.cf = catalogue::match(r.p);
  if (r.cf && r.cf->equation.rfind("(50)", 0) == 0)
    r.dirichlet = {catalogue::dirichlet_C(o.digits), catalogue::dirichlet_D(o.digits)};
  if (!o.damping.empty()) {
    DampingCheck d;
    d.b = cli::option_rational(o.damping, "--damping");
    if (d.b <= 0) throw InputError("--damping must be > 0 (got " + o.damping + ")");
    if (r.b.status == Status::numeric && m != Method::certified)
      throw InputError("--damping needs a proven b*: use --method certified (the default)");
    d.passive = !r.b.infinite && d.b > r.b.enclosure->hi;
    if (!r.b.infinite && d.b > r.b.enclosure->lo && d.b <= r.b.enclosure->hi)
      throw NumericalError("--damping " + o.damping + " lies inside the enclosure of b*; raise --digits");
    const BoundProblem q = with_integer_delay(r.p);
    if (!r.b.infinite && !q.frac_delay && q.eta == 0 && r.b.omega_enclosure && r.b.omega_enclosure->lo > 0) {
      std::vector<rational> zn(static_cast<size_t>(q.delay) + 1, rational(0));
      zn.back() = 1;
      RationalFunction<rational> Hn(q.H.num(), q.H.den() * Polynomial<rational>(std::move(zn)));  // H z^-n
      d.at_max = necessary_condition(Hn, q.T, d.b, (r.b.omega_enclosure->lo + r.b.omega_enclosure->hi) / 2);
    }
    r.damping = d;
  }
  if (!o.coulomb.empty() && o.quantum.empty()) throw InputError("--coulomb needs --quantum (the encoder resolution)");
  if (!o.quantum.empty()) {
    FrictionCheck f;
    f.quantum = cli::option_rational(o.quantum, "--quantum");
    if (f.quantum <= 0) throw InputError("--quantum must be > 0 (got " + o.quantum + ")");
    if (!o.coulomb.empty()) {
      f.coulomb = cli::option_rational(o.coulomb, "--coulomb");
      if (*f.coulomb < 0) throw InputError("--coulomb must be >= 0 (got " + o.coulomb + ")");
    }
    const BoundProblem q = with_integer_delay(r.p);
    f.c = friction_condition(q.H, q.delay, f.quantum, q.frac_delay.has_value());
    r.friction = f;
  }
  return r;
}

int exit_code(const Outcome& r) {
  const bool fails = (r.damping && !r.damping->passive) || (r.friction && !r.friction->holds());
  return fails ? cli::exit_property_fails : cli::exit_ok;
}

nlohmann::json friction_json(const FrictionCheck& f) {
  nlohmann::json j;
  j["quantum"] = to_decimal(f.quantum, 17);
  j["fc_star"] = to_decimal(f.c.fc_star, 17);
  j["fc_star_exact"] = f.c.fc_star.str();
  j["l1_norm"] = f.c.l1.str();
  std::vector<std::string> taps;
  for (const rational& w : f.c.taps) taps.push_back(w.str());
  j["taps"] = taps;
  j["status"] = "exact";
  j["tight"] = f.c.tight;
  j["why"] = f.c.why;
  j["condition"] = "f_c >= Delta/2 * sum_k |w_k|";
  if (f.coulomb) {
    j["coulomb"] = to_decimal(*f.coulomb, 17);
    j["holds"] = f.holds();
  }
  return j;
}

nlohmann::json to_json(const Outcome& r, int digits) {
  nlohmann::json j;
  const Bound& b = r.b;
  j["bound"] = b.decimal;
  j["omega"] = b.omega ? nlohmann::json(*b.omega) : nlohmann::json(nullptr);
  const auto [lo, hi] = reported_enclosure(b, digits);
  j["enclosure"] = {lo, hi};
  j["enclosure_rigorous"] = enclosure_rigorous(b);
  j["status"] = to_string(b.status);
  if (b.status == Status::exact && !b.infinite) j["exact"] = b.value.str();  // "p/q": the value itself
  j["closed_form"] = r.cf ? nlohmann::json(r.cf->name) : nlohmann::json(nullptr);
  j["method"] = b.method;
  j["path"] = b.kind == Method::grid ? "grid" : to_string(b.path);  // the path that ran, and why
  j["plan"] = b.plan.empty() ? nlohmann::json(nullptr) : nlohmann::json(b.plan);
  j["where"] = b.where;
  if (r.cf) {
    if (r.cf->infinite) j["closed_form_value"] = "inf";
    else if (r.cf->value) j["closed_form_value"] = to_decimal(*r.cf->value, digits);
    else if (r.cf->approx) j["closed_form_value"] = to_decimal(exact_rational(*r.cf->approx), 16);
    j["closed_form_tight"] = r.cf->tight;
    j["closed_form_equation"] = r.cf->equation;
  }
  if (!b.note.empty()) j["note"] = b.note;
  if (r.dirichlet) {
    const auto& [C, D] = *r.dirichlet;
    j["dirichlet_C"] = cli::enclosure_json(C, digits + 3);  // outward (cli/command.hpp)
    j["dirichlet_D"] = cli::enclosure_json(D, digits + 3);
  }
  if (r.damping) {
    nlohmann::json d;
    d["b"] = to_decimal(r.damping->b, 17);
    d["passive"] = r.damping->passive;
    if (const auto& c = r.damping->at_max) {
      d["eq14_lhs"] = c->lhs14;
      d["eq14_holds"] = c->holds14;
      d["eq15_rhs"] = c->rhs15;
      d["eq15_holds"] = c->holds15;
    }
    j["damping"] = d;
  }
  if (r.friction) {
    j["friction"] = friction_json(*r.friction);
    if (r.damping && r.friction->coulomb) j["passive"] = r.damping->passive && r.friction->holds();
  }
  return j;
}

void print_friction(const FrictionCheck& f) {
  std::cout << "friction (Delta = " << to_decimal(f.quantum, 17) << "): f_c* = Delta/2 sum|w_k| = " << f.c.fc_star.str();
  if (f.c.fc_star.str().find('/') != std::string::npos) std::cout << " = " << to_decimal(f.c.fc_star, 17);
  std::cout << "   [exact]\n  " << (f.c.tight ? "passive iff b > b* and f_c >= f_c*" : "passive if b > b* and f_c >= f_c*")
            << "  (" << f.c.why << ")\n";
  if (f.coulomb)
    std::cout << "coulomb f_c = " << to_decimal(*f.coulomb, 17) << ": "
              << (f.holds() ? "friction condition holds (f_c >= f_c*)"
                            : f.c.tight ? "friction condition FAILS (f_c < f_c*): not passive"
                                        : "friction condition FAILS (f_c < f_c*): passivity not shown")
              << "\n";
}

void print_human(const Outcome& r, const BoundOpts& o) {
  const Bound& b = r.b;
  // an exact b* whose decimal is not exactly it (15 + 1e-40 at 30 digits prints 15): say so, and print the
  // rational where it is short, so that "[exact]" never stands beside a rounded number (stop 87's review)
  std::string exactly;
  if (!b.infinite && b.status == Status::exact && b.enclosure && try_parse_rational(b.decimal) != b.enclosure->lo) {
    const std::string q = b.enclosure->lo.str();
    exactly = q.size() <= 120 ? " (rounded; exactly " + q + ")" : " (rounded to --digits; the exact rational in --json)";
  }
  std::cout << "b* = " << (b.infinite ? "+inf (not passive for any finite b)" : b.decimal + exactly) << "   [" << to_string(b.status)
            << "]\n";
  if (!b.infinite && b.status != Status::exact) {
    const bool grid = b.kind == Method::grid;
    const auto [lo, hi] = reported_enclosure(b, o.digits);
    std::cout << "  enclosure [" << lo << ", " << hi << "]"
              << (b.status == Status::certified ? ""
                  : grid                            ? "  (a grid maximum only bounds b* from below)"
                  : b.path == BoundPath::long_delay
                      ? "  (f's rounding at the maximiser found, not an error of b*: a peak between the samples "
                        "can be missed; --method certified for b*)"
                      : "  (stated error, not a proof)")
              << "\n";
  }
  if (b.omega) std::cout << "  maximiser w = " << *b.omega << " rad/s (" << b.where << ")\n";
  std::cout << "  method: " << b.method << "\n";
  if (!b.plan.empty() && b.path != BoundPath::exact) std::cout << "  path: " << b.plan << "\n";
  if (!b.note.empty()) std::cout << "  note: " << b.note << "\n";
  if (!b.infinite) {
    if (b.kind == Method::grid) std::cout << "  passive only if b > " << b.decimal << " (necessary; the grid may miss the peak)\n";
    else if (b.status == Status::certified && !b.note.empty()) {  // wider than the digits asked: its two ends
      const auto [lo, hi] = reported_enclosure(b, o.digits);
      std::cout << "  passive if b > " << hi << ", not passive if b <= " << lo << " (b* shown only to that enclosure)\n";
    } else
      std::cout << "  passive iff b > " << (exactly.empty() ? b.decimal : "b* (above)") << (b.status == Status::numeric ? " (numeric)" : "")
                << "\n";
  }
  if (o.explain) {
    if (!r.cf) {
      std::cout << "closed form: none of Sec. VI/VII applies; the generic certified result stands alone\n";
    } else {
      std::cout << "closed form: " << r.cf->name << " " << r.cf->equation << "\n  " << r.cf->formula << "\n  = ";
      if (r.cf->infinite) std::cout << "+inf";
      else if (r.cf->value) std::cout << to_decimal(*r.cf->value, o.digits);
      else if (r.cf->approx) std::cout << *r.cf->approx << " (approximation)";
      std::cout << (r.cf->tight ? "" : "  (upper bound / approximation, not tight)") << "\n";
      const std::optional<bool> agree = catalogue::agrees(*r.cf, b);
      std::cout << "  generic: " << (b.infinite ? "+inf" : b.decimal) << " -> "
                << (!agree ? "compare (approximation)" : *agree ? "agrees" : "DISAGREES") << "\n";
      if (r.dirichlet) {
        const auto& [C, D] = *r.dirichlet;
        // the enclosures the JSON prints (dirichlet_C, dirichlet_D), rounded outward: a midpoint
        // rounded to nearest is not a certified digit string
        const auto Cj = cli::enclosure_json(C, o.digits + 3), Dj = cli::enclosure_json(D, o.digits + 3);
        std::cout << "  C = -min sin(y)/y in [" << Cj[0].get<std::string>() << ", " << Cj[1].get<std::string>()
                  << "], D = (1 - C)/2 in [" << Dj[0].get<std::string>() << ", " << Dj[1].get<std::string>() << "]   [certified]\n";
      }
    }
  }
  if (r.damping) {
    const DampingCheck& d = *r.damping;
    // with a friction check the verdict is both conditions' (the coulomb line): b > b* alone is not "passive"
    const bool friction_checked = r.friction && r.friction->coulomb;
    const std::string b_text = to_decimal(d.b, 17);  // as for b*: a rounded b says so
    std::cout << "damping b = " << b_text << (try_parse_rational(b_text) == d.b ? "" : " (rounded; exactly " + d.b.str() + ")") << ": "
              << (!d.passive ? "NOT passive (b <= b*)"
                  : friction_checked ? "b > b* (the damping condition holds; the friction condition below)"
                                     : "passive (b > b*)")
              << "\n";
    if (d.at_max)
      std::cout << "  at w* (paper 001, Sec. III): (14) |rH/(2b + rH)| = " << d.at_max->lhs14
                << (d.at_max->holds14 ? " < 1" : " >= 1") << ";  (15) Re{-rH} = " << d.at_max->rhs15
                << (d.at_max->holds15 ? " < b" : " >= b") << "  -> "
                << (d.at_max->holds14 == d.at_max->holds15 ? "(14) and (15) agree" : "(14) and (15) DISAGREE") << "\n";
  }
  if (r.friction) print_friction(*r.friction);
}

int run_batch(const std::string& file) {
  // a regular file of at most 64 MB (not /dev/zero or a FIFO); the files its lines name (--mat)
  // must lie in its folder, as a scene's files lie in the scene's (docs/security.md)
  std::istringstream in(report::read_input_file(file, "--batch", 64u << 20));
  const std::filesystem::path folder = std::filesystem::path(file).parent_path().empty()
                                           ? std::filesystem::path(".")
                                           : std::filesystem::path(file).parent_path();
  std::string line;
  int worst = 0, lineno = 0;
  while (std::getline(in, line)) {
    ++lineno;
    auto first = line.find_first_not_of(" \t");
    if (first == std::string::npos || line[first] == '#') continue;
    nlohmann::json j;
    try {
      auto toks = cli::split_batch_line(line);
      BoundOpts o;
      CLI::App app{"batch line"};
      add_options(app, o, true);
      app.allow_extras();
      std::vector<std::string> args(toks.rbegin(), toks.rend());
      app.parse(args);
      auto extras = app.remaining();
      if (o.tf.H.empty() && !extras.empty()) {
        o.tf.H = extras.front();
        extras.erase(extras.begin());
      }
      if (!extras.empty()) throw InputError("unexpected '" + extras.front() + "' (one expression per line)");
      if (!o.tf.mat.empty()) o.tf.mat = cli::input_file_in_folder(folder, "mat", o.tf.mat, "--batch line " + std::to_string(lineno) + ": --mat");
      if (!o.max.empty()) {
        const passivity::BoundMax m = compute_max(o);
        j = cli::bound_max_json(m, o.digits);
        worst = std::max(worst, cli::bound_max_exit(m));
      } else {
        j = to_json(compute(o), o.digits);
      }
    } catch (const std::exception& e) {
      const int code = cli::exit_code_for(e).code;
      j = {{"error", std::string(e.what())}, {"exit", code}};
      worst = std::max(worst, code);
    }
    j["line"] = lineno;
    std::cout << j.dump() << std::endl;
  }
  return worst;
}

const cli::Register reg({"bound", "Passivity bound b* of (45)/(54) for a virtual environment H(z) (paper 001)",
                         [](CLI::App& app) {
                           auto o = std::make_shared<BoundOpts>();
                           auto batch = std::make_shared<std::string>();
                           add_options(app, *o, false);
                           app.add_option("--batch", *batch, "FILE with one case per line; prints one JSON line per case");
                           const CLI::App* self = &app;
                           return [o, batch, self]() -> int {
                             if (!batch->empty()) {  // every option comes from FILE's lines: one beside it would be dropped
                               for (const CLI::Option* opt : self->get_options())
                                 if (opt->count() > 0 && opt->get_name() != "--batch")
                                   throw InputError("--batch reads every case's options from FILE's lines: " + opt->get_name() +
                                                    " on the command line would be ignored (put it on each line)");
                               return run_batch(*batch);
                             }
                             if (!o->max.empty()) {
                               const passivity::BoundMax m = compute_max(*o);
                               if (!o->certificate.empty()) {
                                 const nlohmann::json c = cli::bound_max_certificate(o->tf, m, o->digits);
                                 cli::write_certificate(o->certificate, c);
                                 if (!o->json && c["evidence"].contains("witness_theta") && c["claim"].contains("printed_lo"))  // wider than printed
                                   std::cerr << "certificate " << o->certificate << ": " << o->max << "_max in ["
                                             << c["claim"]["printed_lo"].get<std::string>() << ", "
                                             << c["claim"]["printed_hi"].get<std::string>()
                                             << "] by cells (the delay never expanded: an enclosure 10^-12 wider than printed)\n";
                               }
                               if (o->json) cli::print_json(cli::bound_max_json(m, o->digits));
                               else cli::print_bound_max(m, o->digits);
                               return cli::bound_max_exit(m);
                             }
                             Outcome r = compute(*o);
                             if (!o->certificate.empty()) {
                               const nlohmann::json c = cli::bound_certificate(o->tf, r.p, r.b, o->digits);
                               cli::write_certificate(o->certificate, c);
                               if (!o->json && c["evidence"].contains("cells"))  // it claims less than what is printed: say so
                                 std::cerr << "certificate " << o->certificate << ": b* in [" << c["claim"]["printed_lo"].get<std::string>()
                                           << ", " << c["claim"]["printed_hi"].get<std::string>() << "] by "
                                           << c["evidence"]["cells"].size()
                                           << " cells (the delay never expanded: an enclosure, not the exact value)\n";
                             }
                             if (!o->curve.empty()) {
                               std::ofstream f(o->curve);
                               if (!f) throw InputError("--curve: cannot write '" + o->curve + "'");
                               const double T = to_real<double>(r.p.T), pi = 3.14159265358979323846;
                               f << "# omega[rad/s]  Re{T H z^-n e^{-jw t_d}/(1-z)} + eta   (paper 001, (45)/(54))\n";
                               f << "# b* = " << r.b.decimal << " at omega = "
                                 << (r.b.omega ? *r.b.omega : "-") << "\n";
                               f.precision(17);
                               for (int k = 0; k <= 2000; ++k) {
                                 double w = pi / T * k / 2000.0;
                                 if (k == 2000) w *= 1 - 1e-12;
                                 f << w << " " << objective_at(r.p, w) << "\n";
                               }
                             }
                             if (o->json) cli::print_json(to_json(r, o->digits));
                             else print_human(r, *o);
                             return exit_code(r);
                           };
                         }});

}  // namespace
}  // namespace hapstab::cli::cmd_bound
