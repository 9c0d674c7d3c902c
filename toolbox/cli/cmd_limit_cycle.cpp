// `hapstab limit-cycle --H EXPR --gain K [--rho RHO] [--steps N] [--exact [--certificate FILE]] [--json]`
// Simulates the autonomous loop of Fig. 5 of paper 002, y_k = -k H(z) (xi(y_k + rho) - rho),
// in double from several initial states and reports a sustained oscillation (period in
// samples, amplitude of y). With --exact the periodic orbit is solved and replayed in rational
// arithmetic: an exactly repeated state proves the periodic solution.
// Growth is decided whatever --steps is (contact/limit_cycle.hpp, detect): in contact by the exact
// stability of the linear loop (1 + kH)^-1, out of contact by the envelope (diverged when it grows
// beyond 1e6 rho). JSON: oscillates, growing, diverged, period, amplitude, note, exact {...}.
// Exit 0: no sustained oscillation; 1: an oscillation (or growth, or divergence) was found; 2: bad input.
#include <iostream>
#include <memory>

#include "cli/certificate.hpp"
#include "cli/command.hpp"
#include "cli/tf_options.hpp"
#include "hapstab/contact/limit_cycle.hpp"
#include "hapstab/numeric/decimal.hpp"
#include "hapstab/numeric/error.hpp"

namespace hapstab::cli::cmd_limit_cycle {  // its own namespace: the commands compile in unity batches
namespace {

// The loop is H(z) alone: --T is needed only when the expression names T.
const TfRules tf_rules{/*period_required=*/false, /*causal=*/true, /*with_delay=*/false};

struct Opts {
  TfOptions tf;
  std::string gain, rho = "1";
  long steps = 200000;
  bool exact = false, json = false;
  std::string certificate;
};

std::string attraction(const contact::ExactOrbit& e) {
  if (!e.stability_decided) return "attraction not decided (a sample on y = -rho)";
  return std::string(e.stable ? "attracting" : "not attracting") + " (exact)";
}

int run(const Opts& o) {
  const rational k = option_rational(o.gain, "--gain");
  const rational rho = option_rational(o.rho, "--rho");
  if (o.steps < 1000 || o.steps > 2000000000L)
    throw InputError("--steps must be in [1000, 2e9], got " + std::to_string(o.steps));
  if (!o.certificate.empty() && !o.exact)
    throw InputError("--certificate: the certificate is of the orbit that --exact proves; add --exact");
  const TransferFunction H = parse_tf_options(o.tf, tf_rules);
  contact::LureLoop L = contact::make_lure_loop(H, k, rho);
  contact::Oscillation osc = contact::find_oscillation(L, o.steps, std::min<long>(8192, o.steps / 4));
  std::optional<contact::ExactOrbit> ex;
  if (o.exact && osc.period) ex = contact::certify_orbit(L, osc.state, *osc.period);
  const bool oscillates = osc.oscillates || osc.diverged;
  if (!o.certificate.empty()) {
    if (!ex || !ex->found)
      throw InputError(std::string("--certificate: no periodic orbit was proven (") +
                       (ex ? ex->note : std::string("no period found")) + "): no claim to certify");
    write_certificate(o.certificate, limit_cycle_certificate(o.tf, k, rho, *ex, L.order()));
  }
  if (o.json) {
    nlohmann::json j;
    j["H"] = H.to_string();
    j["gain"] = to_decimal(k, 17);
    j["rho"] = to_decimal(rho, 17);
    j["oscillates"] = oscillates;
    j["growing"] = osc.growing;
    j["diverged"] = osc.diverged;
    j["period"] = osc.period ? nlohmann::json(*osc.period) : nlohmann::json(nullptr);
    j["amplitude"] = osc.amplitude;
    j["amplitude_status"] = "numeric";
    j["note"] = osc.note;
    if (ex) {
      j["exact"] = {{"orbit_found", ex->found},
                    {"period", ex->period},
                    {"amplitude", ex->found ? to_decimal(ex->amplitude, 20) : std::string()},
                    {"amplitude_fraction", ex->found ? exact_json(ex->amplitude) : nlohmann::json(nullptr)},  // exactly
                    {"stable", ex->stable},
                    {"stability_decided", ex->stability_decided},
                    {"free_steps_per_period", ex->free_steps},
                    {"note", ex->note}};
      if (ex->found) j["amplitude_exact"] = to_decimal(ex->amplitude, 20);
    }
    print_json(j);
  } else {
    std::cout << "H(z) = " << H.to_string() << ", k = " << to_decimal(k, 17) << ", rho = " << to_decimal(rho, 17)
              << "\n"
              << (osc.diverged ? "diverged" : osc.growing ? "growing" : oscillates ? "sustained oscillation" : "no sustained oscillation")
              << ": " << osc.note
              << "; amplitude of y = " << osc.amplitude << " [numeric]\n";
    if (ex) {
      if (ex->found)
        std::cout << "exact: periodic orbit of period " << ex->period << " proven (state repeats exactly), amplitude "
                  << to_decimal(ex->amplitude, 20) << ", " << ex->free_steps << " samples per period out of contact, "
                  << attraction(*ex) << "\n";
      else
        std::cout << "exact: no orbit certified: " << ex->note << "\n";
    }
  }
  return oscillates ? exit_property_fails : exit_ok;
}

const Register reg({"limit-cycle",
                    "Simulate the unilateral-contact loop of paper 002 (Fig. 5) and detect sustained oscillations",
                    [](CLI::App& app) {
                      auto o = std::make_shared<Opts>();
                      add_tf_options(app, o->tf, tf_rules, "H(z) as an exact expression");
                      app.add_option("--gain", o->gain, "Loop gain k >= 0 (the loop is k*H)")->required();
                      app.add_option("--rho", o->rho, "rho > 0 of Fig. 4 (default 1; amplitudes scale with it)");
                      app.add_option("--steps", o->steps, "Samples simulated per initial state (default 200000)");
                      app.add_flag("--exact", o->exact, "Certify the periodic orbit in rational arithmetic");
                      app.add_flag("--json", o->json, "JSON output");
                      app.add_option("--certificate", o->certificate,
                                     "with --exact: write the proven orbit's certificate (JSON) to FILE, for `hapstab "
                                     "check FILE` (docs/certificates.md)");
                      return [o]() { return run(*o); };
                    }});

}  // namespace
}  // namespace hapstab::cli::cmd_limit_cycle
