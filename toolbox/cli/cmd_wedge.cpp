// `hapstab wedge --H EXPR [--T T] [--set NAME=VALUE ...] [--digits D] [--json]`
// The wedge criterion (25) and Tsypkin's condition (21) of Tsai & Colgate (paper 002), decided
// exactly over all of theta in [0, pi]; margins and largest gains as certified enclosures.
// Exit 0: the wedge criterion holds and its assumptions hold; 1: it does not hold (or does not
// apply); 2: bad input; 3: numerical failure.
#include <iostream>
#include <memory>

#include "cli/certificate.hpp"
#include "cli/command.hpp"
#include "cli/tf_options.hpp"
#include "hapstab/contact/wedge.hpp"
#include "hapstab/numeric/decimal.hpp"
#include "hapstab/numeric/shared_decimal.hpp"
#include "hapstab/numeric/error.hpp"

namespace hapstab::cli::cmd_wedge {  // its own namespace: the commands compile in unity batches
namespace {

// H(z) alone is analysed: --T is needed only when the expression names T.
const TfRules tf_rules{/*period_required=*/false, /*causal=*/true, /*with_delay=*/false};

struct Opts {
  TfOptions tf;
  int digits = 20;
  bool json = false;
  std::string certificate;
};

// Only the digits both ends of the enclosure share (numeric/decimal.hpp, shared_decimal); when the
// enclosure did not narrow to `digits`, how many they are is said.
SharedDecimal shared(const Certified<rational>& r, int digits) {
  if (r.enclosure) return shared_decimal(r.enclosure->lo, r.enclosure->hi, digits);
  return {to_decimal(r.value, digits), r.status == Status::exact ? digits : 0};
}
std::string dec(const Certified<rational>& r, int digits) {
  const SharedDecimal s = shared(r, digits);
  if (s.digits == digits) return s.text;
  if (s.digits == 0) return "(no digit certified)";
  return s.text + " (" + std::to_string(s.digits) + " of " + std::to_string(digits) + " digits certified)";
}

nlohmann::json criterion_json(const contact::CriterionReport& c, int digits) {
  nlohmann::json j;
  j["evaluated"] = c.evaluated();
  if (!c.evaluated()) return j;
  j["holds"] = c.verdict.holds();
  j["margin"] = shared(c.margin, digits).text;
  // the shared names with the value's prefix (docs/json.md): margin_digits_certified as digits_certified
  j["margin_digits_certified"] = shared(c.margin, digits).digits;
  j["margin_digits"] = j["margin_digits_certified"];  // its old name, deprecated: kept for one release
  j["margin_enclosure"] = enclosure_json(*c.margin.enclosure, digits + 5);  // outward (cli/command.hpp)
  if (c.margin.status == Status::exact && c.margin.enclosure->lo == c.margin.enclosure->hi)
    j["margin_exact"] = exact_json(c.margin.enclosure->lo);
  j["margin_status"] = to_string(c.margin.status);
  j["theta_at_min"] = c.theta_at_min;
  j["max_gain"] = c.gain_infinite ? std::string("inf") : shared(c.max_gain, digits).text;
  j["max_gain_digits_certified"] = c.gain_infinite ? digits : shared(c.max_gain, digits).digits;
  j["max_gain_digits"] = j["max_gain_digits_certified"];  // its old name, deprecated: kept for one release
  j["max_gain_status"] = c.gain_infinite ? "exact" : to_string(c.max_gain.status);
  return j;
}

int run(const Opts& o) {
  if (o.digits < 1 || o.digits > 60) throw InputError("--digits must be in [1, 60], got " + std::to_string(o.digits));
  const TransferFunction H = parse_tf_options(o.tf, tf_rules);
  contact::ContactAnalysis a = contact::analyze_contact(H, o.digits);
  if (!o.certificate.empty()) write_certificate(o.certificate, wedge_certificate(o.tf, a, o.digits));
  const bool applies = a.applies();
  const auto& w = a.wedge;
  const auto& ts = a.tsypkin;
  std::string status = "not evaluated";
  if (w.evaluated() || ts.evaluated()) {
    bool all_exact = (!w.evaluated() || w.margin.status == Status::exact) && (!ts.evaluated() || ts.margin.status == Status::exact);
    status = all_exact ? "exact" : "certified";
  }
  std::string verdict;
  if (!w.evaluated())
    verdict = "wedge criterion not evaluated: its branches are unbounded (H has a pole on the unit circle); the "
              "criteria do not apply";
  else if (!applies)
    verdict = "the criteria do not apply: a paper assumption is violated";
  else
    verdict = std::string(w.verdict.holds() ? "wedge criterion holds: no sustained oscillation (paper 002, (25))"
                                  : "wedge criterion fails: oscillations are not excluded") +
              "; Tsypkin " + (ts.verdict.holds() ? "holds" : "fails");
  if (o.json) {
    nlohmann::json j;
    j["H"] = H.to_string();
    j["wedge_holds"] = w.evaluated() && w.verdict.holds();
    j["tsypkin_holds"] = ts.evaluated() && ts.verdict.holds();
    j["wedge_margin"] = w.evaluated() ? nlohmann::json(shared(w.margin, o.digits).text) : nlohmann::json(nullptr);
    j["tsypkin_margin"] = ts.evaluated() ? nlohmann::json(shared(ts.margin, o.digits).text) : nlohmann::json(nullptr);
    j["max_gain_wedge"] = !w.evaluated() ? nlohmann::json(nullptr)
                                       : nlohmann::json(w.gain_infinite ? std::string("inf") : shared(w.max_gain, o.digits).text);
    j["max_gain_tsypkin"] = !ts.evaluated() ? nlohmann::json(nullptr)
                                          : nlohmann::json(ts.gain_infinite ? std::string("inf") : shared(ts.max_gain, o.digits).text);
    j["status"] = status;
    j["assumptions"] = a.assumptions.violated;
    j["applies"] = applies;
    j["verdict"] = verdict;
    j["wedge"] = criterion_json(w, o.digits);
    j["tsypkin"] = criterion_json(ts, o.digits);
    if (a.assumptions.h1) j["H1"] = to_decimal(*a.assumptions.h1, o.digits);
    print_json(j);
  } else {
    std::cout << "H(z) = " << H.to_string() << "\n";
    {
      for (const auto* c : {&w, &ts}) {
        if (!c->evaluated()) {
          std::cout << c->name << ": not evaluated (unbounded on the unit circle)\n";
          continue;
        }
        std::cout << c->name << ": " << (c->verdict.holds() ? "holds" : "fails") << " [exact]; min over theta of left side + 1 = "
                  << dec(c->margin, o.digits) << " [" << to_string(c->margin.status) << "] at theta = " << c->theta_at_min
                  << " rad; max gain k* = " << (c->gain_infinite ? std::string("inf") : dec(c->max_gain, o.digits))
                  << "\n";
        // evaluated with a pole on the circle: the branch stays bounded there (a simple pole at
        // z = -1 for the wedge, at z = +-1 for Tsypkin), so the verdict is about H where it is
        // finite, with the left side extended to the pole by its limit
        if (a.assumptions.pole_on_unit_circle)
          std::cout << "  (H has a pole on the unit circle: checked where H is finite, and at the pole by the"
                       " left side's limit, which is finite there)\n";
      }
    }
    std::cout << "assumptions: " << (a.assumptions.violated.empty() ? "all hold" : "violated:");
    for (const auto& v : a.assumptions.violated) std::cout << "\n  - " << v;
    std::cout << "\n(r_k > 0 is a property of the bias input, not of H)\n" << verdict << "\n";
  }
  return (w.evaluated() && w.verdict.holds() && applies) ? exit_ok : exit_property_fails;
}

const Register reg({"wedge",
                    "Wedge criterion (25) and Tsypkin's condition for H(z) in feedback with a unilateral "
                    "nonlinearity (paper 002), decided over all theta in [0, pi]",
                    [](CLI::App& app) {
                      auto o = std::make_shared<Opts>();
                      add_tf_options(app, o->tf, tf_rules, "H(z) as an exact expression, e.g. \"0.5*(z+1)/(z^2-0.5*z)\"");
                      app.add_option("--digits", o->digits, "Significant digits of the margins (1..60, default 20)");
                      app.add_flag("--json", o->json, "JSON output");
                      app.add_option("--certificate", o->certificate,
                                     "write the certificate of the exact verdicts, margins and gains k* (JSON) to FILE, "
                                     "for `hapstab check FILE` "
                                     "(docs/certificates.md)");
                      return [o]() { return run(*o); };
                    }});

}  // namespace
}  // namespace hapstab::cli::cmd_wedge
