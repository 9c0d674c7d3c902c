// cli/bound_max.cpp -- see bound_max.hpp.
#include "cli/bound_max.hpp"

#include <iostream>

#include "cli/command.hpp"
#include "hapstab/numeric/decimal.hpp"

namespace hapstab::cli {

using passivity::BoundMax;
using passivity::MaxGain;

namespace {

nlohmann::json outward(const Enclosure<rational>& e, int digits) {
  return {decimal_outward(e.lo, digits, -1), decimal_outward(e.hi, digits, +1)};
}

nlohmann::json bound_json(const passivity::Bound& b, int digits) {
  nlohmann::json j;
  j["bound"] = b.decimal;
  const auto [lo, hi] = passivity::reported_enclosure(b, digits);
  j["enclosure"] = {lo, hi};
  j["status"] = to_string(b.status);
  return j;
}

}  // namespace

nlohmann::json bound_max_json(const BoundMax& r, int digits) {
  const MaxGain& m = r.max;
  nlohmann::json j;
  j["name"] = r.problem.name;
  j["max"] = m.decimal;
  const bool finite = !m.infinite && m.enclosure.has_value();
  j["digits_certified"] = finite ? nlohmann::json(m.digits) : nlohmann::json(nullptr);
  j["max_digits"] = j["digits_certified"];  // its old name, deprecated: kept for one release (docs/json.md)
  j["enclosure"] = finite ? outward(*m.enclosure, digits + 3) : nlohmann::json(nullptr);
  j["status"] = to_string(m.status);
  if (m.status == Status::exact && finite) j["exact"] = m.value.str();
  j["damping"] = to_decimal(r.problem.b, 17);
  j["b_at_zero"] = bound_json(m.at_zero, digits);
  // the crossing frequency's enclosure under the shared suffix (docs/json.md): `bound`'s `omega`
  // is a decimal, so an enclosure is `omega_enclosure`; `omega` is its old name, kept for one release
  j["omega_enclosure"] = m.omega ? outward(*m.omega, 17) : nlohmann::json(nullptr);
  j["omega"] = j["omega_enclosure"];
  j["where"] = m.where;
  const auto& cf = r.closed_form;
  j["closed_form"] = cf ? nlohmann::json(cf->name) : nlohmann::json(nullptr);
  if (cf) {
    j["closed_form_equation"] = cf->equation;
    j["closed_form_formula"] = cf->formula;
    j["closed_form_value"] = passivity::closed_form_decimal(*cf, digits);
    j["closed_form_tight"] = cf->tight;
    j["closed_form_agrees"] = passivity::agrees(*cf, m);
  }
  j["jump"] = m.jump;
  if (m.jump) j["b_at_sup"] = bound_json(*m.at_sup, digits);
  j["method"] = m.method;
  j["path"] = to_string(m.path);
  j["note"] = m.note;
  j["digits"] = digits;
  if (r.check)
    j["check"] = {{"holds", r.check->holds},
                  {"bound_at_lo", bound_json(r.check->at_lo, digits)},
                  {"bound_at_hi", bound_json(r.check->at_hi, digits)}};
  return j;
}

void print_bound_max(const BoundMax& r, int digits) {
  const MaxGain& m = r.max;
  const std::string& K = r.problem.name;
  const std::string b = to_decimal(r.problem.b, 17);
  std::cout << "sup " << K << " = " << (m.digits > 0 || m.infinite ? m.decimal : "(no digit certified)") << "   ["
            << to_string(m.status);
  // a point enclosure (K_max = 0 by b*(0) = +inf shown in balls) is the value itself: no digits, no enclosure
  const bool point = !m.infinite && m.enclosure && m.enclosure->lo == m.enclosure->hi;
  if (!m.infinite && !point && m.status != Status::exact && m.digits < digits)
    std::cout << ", " << m.digits << " of " << digits << " digits";
  std::cout << "]\n";
  const bool finite = !m.infinite && m.enclosure.has_value();
  if (finite && !point && m.status != Status::exact) {
    const nlohmann::json e = outward(*m.enclosure, digits + 3);
    std::cout << "  enclosure [" << e[0].get<std::string>() << ", " << e[1].get<std::string>() << "]\n";
  }
  std::cout << "  b*(0) = " << (m.at_zero.infinite ? "inf" : m.at_zero.decimal) << " [" << to_string(m.at_zero.status) << "], b = " << b
            << "\n";
  if (m.outcome == Outcome::holds && m.infinite)
    std::cout << "  passive (b > b*) for every " << K << " >= 0\n";
  else if (m.outcome == Outcome::holds && m.jump)
    std::cout << "  passive (b > b*) for 0 <= " << K << " < sup; b*(sup) = " << (m.at_sup->infinite ? "inf" : m.at_sup->decimal) << " ["
              << to_string(m.at_sup->status) << "] <= b, and b* = +inf for every " << K
              << " > sup: H's pole at z = -1 under the fractional delay (its term T rho sin((nu + 1) wT)/(2 sin wT) "
                 "tends to +inf at wT = pi once rho(" << K << ") sin(nu pi) < 0)\n";
  else if (m.outcome == Outcome::holds)
    std::cout << "  passive (b > b*) for 0 <= " << K << " < sup; b* = b at the sup"
              << (m.omega ? ", attained at w = " + outward(*m.omega, 17)[0].get<std::string>() + " rad/s (" + m.where + ")"
                          : m.where.empty() ? std::string() : ", " + m.where)
              << "\n";
  if (!m.note.empty()) std::cout << "  note: " << m.note << "\n";
  if (const auto& cf = r.closed_form) {
    std::cout << "  closed form: " << cf->name << " " << cf->equation << ": " << cf->formula << "\n    = "
              << passivity::closed_form_decimal(*cf, digits) << (cf->tight ? "" : " (a lower bound of the sup)") << " -> "
              << (passivity::agrees(*cf, m) ? "agrees" : "DISAGREES") << "\n";
  }
  std::cout << "  method: " << m.method << "\n";
  if (const auto& c = r.check) {
    auto show = [](const passivity::Bound& x) { return x.infinite ? std::string("inf") : x.decimal; };
    if (m.status == Status::exact)
      std::cout << "  check: b*(" << K << " = " << m.decimal << ") = " << show(c->at_lo) << " [" << to_string(c->at_lo.status) << "]";
    else
      std::cout << "  check: b* = " << show(c->at_lo) << " at the lower end, " << show(c->at_hi) << " at the upper end";
    if (m.jump)
      std::cout << (c->holds ? ": b* <= b at the sup, +inf above (the pole at z = -1)" : ": b* > b at the sup: INCONSISTENT") << "\n";
    else
      std::cout << (c->holds ? ": b* = b within the enclosure" : ": b* != b: INCONSISTENT") << "\n";
  }
}

int bound_max_exit(const BoundMax& r) { return r.max.outcome == Outcome::holds ? exit_ok : exit_property_fails; }

}  // namespace hapstab::cli
