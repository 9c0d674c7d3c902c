// fuzz-modules: check
// fuzz-seeds: examples/certificates tests/check/fixtures
// fuzz-dict: tests/fuzz/certificate.dict
// libFuzzer target: `hapstab check` (check/certificate.hpp, issue 47), the reader of a format that
// anybody may hand-edit. Any text must end in a Verdict (verified or refuted, with a reason), an
// InputError naming the field (malformed), or a NumericalError (the checker undecided); never a
// crash, another exception (a JSON type error escaping a checker would be exit 4, not 2) or a hang.
// Work budget: a checker's work grows with the model by design (the delay's degree, exponents in
// an expression, the numbers' digits; docs/certificates.md "Sizes and times" measures real ones),
// so inputs beyond this budget are passed over, never checked: a delay above 64 samples, an
// exponent above 64, a number of more than 300 digits, a fractional delay t_d/T whose denominator
// is above 16, a scene whose loop model (check/scene_model.hpp) is beyond these or above 16 KB, a
// stability-loop P of order above 24.
// Within it every input must finish in
// libFuzzer's 10 s.
#include <cstdint>
#include <string>

#include <nlohmann/json.hpp>

#include "hapstab/check/certificate.hpp"
#include "hapstab/check/scene_model.hpp"
#include "hapstab/numeric/error.hpp"

namespace {

/// A run of decimal digits in `s` whose value exceeds `limit` (longer than 9 digits counts).
bool digits_above(const std::string& s, size_t from, long limit) {
  size_t i = from;
  while (i < s.size() && (s[i] == ' ' || s[i] == '(' || s[i] == '+' || s[i] == '-')) ++i;
  size_t j = i;
  while (j < s.size() && s[j] >= '0' && s[j] <= '9') ++j;
  if (j == i) return false;
  return j - i > 9 || std::stol(s.substr(i, j - i)) > limit;
}

bool over_budget(const nlohmann::json& v, const std::string& key) {
  if (v.is_object()) {
    for (auto it = v.begin(); it != v.end(); ++it)
      if (over_budget(it.value(), it.key())) return true;
    return false;
  }
  if (v.is_array()) {
    for (const auto& e : v)
      if (over_budget(e, key)) return true;
    return false;
  }
  std::string s;
  if (v.is_string()) s = v.get<std::string>();
  else if (v.is_number()) s = v.dump();
  else return false;
  if (key == "delay" || key == "free_steps" || key == "period" || key == "dofs") {
    if (digits_above(s, 0, 64)) return true;
  }
  size_t run = 0;
  for (size_t i = 0; i < s.size(); ++i) {
    run = (s[i] >= '0' && s[i] <= '9') ? run + 1 : 0;
    if (run > 300) return true;
    if ((s[i] == '^' || (s[i] == '*' && i + 1 < s.size() && s[i + 1] == '*')) && digits_above(s, i + 1 + (s[i] == '*'), 64))
      return true;
    if ((s[i] == 'e' || s[i] == 'E') && digits_above(s, i + 1, 64)) return true;
  }
  return false;
}

/// A fractional delay t_d/T = P/q expands the objective to degree ~q (deg H + 1): q above 16.
bool fraction_over_budget(const nlohmann::json& c) {
  if (!c.is_object() || !c.contains("model") || !c.at("model").is_object()) return false;
  const auto& m = c.at("model");
  if (!m.contains("frac_delay") || !m.contains("T")) return false;
  try {
    const hapstab::rational td = hapstab::check::detail::exact_string(m.at("frac_delay"), "frac_delay");
    const hapstab::rational T = hapstab::check::detail::exact_string(m.at("T"), "T");
    return T != 0 && denominator(hapstab::rational(td / T)) > 16;
  } catch (const hapstab::InputError&) {
    return false;  // the checker reports it
  }
}

/// A stability-loop certificate's work grows with P's order (the closed loop's): above 24, passed over.
bool loop_over_budget(const nlohmann::json& c) {
  if (!c.is_object() || !c.contains("evidence") || !c.at("evidence").is_object()) return false;
  const auto& e = c.at("evidence");
  return e.contains("P") && e.at("P").is_array() && e.at("P").size() > 24;
}

/// A scene (check/scene_model.hpp) is checked as the loop model it is read into, within the same
/// budget; its parameters, substituted, may make that model larger than the input: above 16 KB it is
/// passed over.
bool scene_over_budget(const nlohmann::json& c) {
  if (!c.is_object() || !c.contains("model") || !c.at("model").is_object() || !c.at("model").contains("scene")) return false;
  try {
    const nlohmann::json m = hapstab::check::detail::scene_loop_model(c.at("model"), c.at("model").contains("name"));
    return m.dump().size() > 16384 || over_budget(m, "");
  } catch (const hapstab::InputError&) {
    return false;  // the checker reports it
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  nlohmann::json c;
  try {
    c = nlohmann::json::parse(text);
  } catch (const nlohmann::json::exception&) {
    return 0;  // `hapstab check` reports it as "not JSON" before any checker runs
  }
  if (over_budget(c, "") || fraction_over_budget(c) || scene_over_budget(c) || loop_over_budget(c)) return -1;  // not added to the corpus
  try {
    const hapstab::check::Verdict v = hapstab::check::check_certificate(c);
    if (v.reason.empty()) std::abort();  // every verdict says what was shown or what failed
  } catch (const hapstab::InputError& e) {
    if (std::string(e.what()).empty()) std::abort();
  } catch (const hapstab::NumericalError&) {
  }
  return 0;
}
