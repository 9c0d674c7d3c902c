// hapstab/check/certificate.cpp -- see certificate.hpp.
#include "hapstab/check/certificate.hpp"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstring>
#include <fstream>
#include <sstream>
#include <sys/stat.h>

#include "hapstab/check/bound_check.hpp"
#include "hapstab/check/bound_max_check.hpp"
#include "hapstab/check/limit_cycle_check.hpp"
#include "hapstab/check/multidof_feasible_check.hpp"
#include "hapstab/check/multidof_coupling_check.hpp"
#include "hapstab/check/multidof_coupling_symmetric_check.hpp"
#include "hapstab/check/multidof_facial_check.hpp"
#include "hapstab/check/multidof_symmetric_check.hpp"
#include "hapstab/check/multidof_witness_check.hpp"
#include "hapstab/check/operator_passivity_check.hpp"
#include "hapstab/check/passivity_level_check.hpp"
#include "hapstab/check/passivity_level_mimo_check.hpp"
#include "hapstab/check/r_check.hpp"
#include "hapstab/check/stability_check.hpp"
#include "hapstab/check/stability_loop_check.hpp"
#include "hapstab/check/stability_loop_max_check.hpp"
#include "hapstab/check/stability_loop_max_symmetric_check.hpp"
#include "hapstab/check/stability_loop_symmetric_check.hpp"
#include "hapstab/check/stability_loop_verdicts_check.hpp"
#include "hapstab/check/stability_max_check.hpp"
#include "hapstab/check/wedge_check.hpp"
#include "hapstab/lti/parse.hpp"
#include "hapstab/numeric/decimal.hpp"
#include "hapstab/numeric/error.hpp"
#include "hapstab/numeric/limits.hpp"
#include "hapstab/poly/stability.hpp"

namespace hapstab::check {

namespace detail {

rational exact_string(const nlohmann::json& v, const std::string& what) {
  if (!v.is_string()) throw InputError(what + ": expected a string \"p/q\" (an exact rational)");
  const std::string s = v.get<std::string>();
  if (s.size() > 1000000) throw InputError(what + ": more than 10^6 characters");
  // -?[0-9]+(/[0-9]+)?  and nothing else
  size_t i = 0;
  if (i < s.size() && s[i] == '-') ++i;
  const size_t d0 = i;
  while (i < s.size() && s[i] >= '0' && s[i] <= '9') ++i;
  bool ok = i > d0;
  size_t slash = std::string::npos;
  if (ok && i < s.size() && s[i] == '/') {
    slash = i++;
    const size_t e0 = i;
    while (i < s.size() && s[i] >= '0' && s[i] <= '9') ++i;
    ok = i > e0;
  }
  if (!ok || i != s.size()) throw InputError(what + ": '" + s.substr(0, 60) + "' is not \"p/q\" or \"p\" (integers)");
  // decimal whatever the leading zeros ("010" is ten, as the expression parser and the independent
  // checker read it; GMP's base 0, which Boost's string constructor uses, would read octal eight)
  const auto decimal = [](std::string digits) {
    const bool negative = !digits.empty() && digits[0] == '-';
    if (negative) digits.erase(0, 1);
    digits.erase(0, std::min(digits.find_first_not_of('0'), digits.size() - 1));
    const integer v(digits);
    return negative ? integer(-v) : v;
  };
  const integer p = decimal(s.substr(0, slash));
  const integer q = slash == std::string::npos ? integer(1) : decimal(s.substr(slash + 1));
  if (q == 0) throw InputError(what + ": '" + s.substr(0, 60) + "' divides by zero");
  return rational(p, q);
}

long integer_field(const nlohmann::json& obj, const std::string& key, const std::string& where, long lo, long hi) {
  const std::string at = where + "." + key;
  if (!obj.contains(key) || !obj.at(key).is_number_integer()) throw InputError(at + ": missing or not an integer");
  const auto& v = obj.at(key);
  const bool above = v.is_number_unsigned() && v.get<unsigned long>() > static_cast<unsigned long>(hi);
  const long x = above ? hi : v.get<long>();
  if (above || x < lo || x > hi)
    throw InputError(at + ": " + v.dump() + " is outside [" + std::to_string(lo) + ", " + std::to_string(hi) + "]");
  return x;
}

rational exact_field(const nlohmann::json& obj, const std::string& key, const std::string& where) {
  if (!obj.contains(key)) throw InputError(where + "." + key + ": missing");
  return exact_string(obj.at(key), where + "." + key);
}

const nlohmann::json& object_field(const nlohmann::json& obj, const std::string& key, const std::string& where) {
  if (!obj.contains(key)) throw InputError(key + ": missing (" + where + ")");
  const auto& v = obj.at(key);
  if (!v.is_object()) throw InputError(key + ": not an object (" + where + ")");
  return v;
}

void only_fields(const nlohmann::json& obj, std::initializer_list<const char*> known, const std::string& where) {
  for (auto it = obj.begin(); it != obj.end(); ++it) {
    bool ok = false;
    for (const char* k : known) ok = ok || it.key() == k;
    if (!ok) throw InputError(where + "." + it.key() + ": a field this checker does not know (it would not be checked)");
  }
}

Parts certificate_parts(const nlohmann::json& cert) {
  only_fields(cert, {"certificate", "version", "kind", "model", "claim", "evidence", "produced_by"}, "certificate");
  return {object_field(cert, "model", "certificate"), object_field(cert, "claim", "certificate"),
          object_field(cert, "evidence", "certificate")};
}

ClaimRange upper_bound_claim(const nlohmann::json& claim) {
  only_fields(claim, {"quantity", "status", "hi", "printed_hi"}, "claim");
  ClaimRange r;
  r.status = "upper_bound";
  r.hi = exact_field(claim, "hi", "claim");
  if (claim.contains("printed_hi")) {
    const auto& v = claim.at("printed_hi");
    const auto q = v.is_string() ? try_parse_rational(v.get<std::string>()) : std::nullopt;
    if (!q) throw InputError("claim.printed_hi: not a number string");
    if (*q != r.hi) r.refuted = "claim.printed_hi = " + v.get<std::string>() + " is not the claimed " + r.hi.str();
  }
  return r;
}

ClaimRange lower_bound_claim(const nlohmann::json& claim, bool& has_hi) {
  ClaimRange r;
  r.status = claim.at("status").get<std::string>();
  has_hi = r.status == "bounds";
  if (has_hi) only_fields(claim, {"quantity", "status", "lo", "hi", "printed_lo", "printed_hi"}, "claim");
  else only_fields(claim, {"quantity", "status", "lo", "printed_lo"}, "claim");
  r.lo = exact_field(claim, "lo", "claim");
  if (has_hi) r.hi = exact_field(claim, "hi", "claim");
  const auto printed = [&](const char* key, const rational& x) {
    if (!claim.contains(key)) return;
    const auto& v = claim.at(key);
    const auto q = v.is_string() ? try_parse_rational(v.get<std::string>()) : std::nullopt;
    if (!q) throw InputError(std::string("claim.") + key + ": not a number string");
    if (*q != x && !r.refuted) r.refuted = std::string("claim.") + key + " = " + v.get<std::string>() + " is not the claimed " + x.str();
  };
  printed("printed_lo", r.lo);
  if (has_hi) printed("printed_hi", r.hi);
  if (has_hi && r.lo > r.hi && !r.refuted) r.refuted = "claim: lo = " + r.lo.str() + " > hi = " + r.hi.str();
  return r;
}

ClaimRange claim_range(const nlohmann::json& claim, bool may_be_infinite) {
  ClaimRange r;
  if (!claim.contains("status") || !claim.at("status").is_string())
    throw InputError("claim.status: missing or not a string (\"exact\" or \"certified\")");
  r.status = claim.at("status").get<std::string>();
  if (r.status != "exact" && r.status != "certified")
    throw InputError("claim.status: \"" + r.status + "\" is neither \"exact\" nor \"certified\"");
  if (may_be_infinite && claim.contains("infinite")) {
    if (!claim.at("infinite").is_boolean()) throw InputError("claim.infinite: not true/false");
    r.infinite = claim.at("infinite").get<bool>();
  }
  if (r.infinite) {
    for (const char* key : {"value", "lo", "hi", "printed", "printed_lo", "printed_hi"})
      if (claim.contains(key)) throw InputError(std::string("claim.infinite: true beside claim.") + key);
    return r;
  }
  if (r.status == "exact") {
    r.lo = r.hi = exact_field(claim, "value", "claim");
  } else {
    r.lo = exact_field(claim, "lo", "claim");
    r.hi = exact_field(claim, "hi", "claim");
    if (r.lo > r.hi) {
      r.refuted = "claim: lo = " + r.lo.str() + " > hi = " + r.hi.str();
      return r;
    }
  }
  for (const char* key : {"printed_lo", "printed_hi", "printed"}) {
    if (!claim.contains(key)) continue;
    const auto& v = claim.at(key);
    if (!v.is_string()) throw InputError(std::string("claim.") + key + ": not a string");
    const auto q = try_parse_rational(v.get<std::string>());
    if (!q) throw InputError(std::string("claim.") + key + ": '" + v.get<std::string>() + "' is not a number");
    const rational& want = std::string(key) == "printed_hi" ? r.hi : r.lo;
    if (*q != want) {
      r.refuted = std::string("claim.") + key + " = " + v.get<std::string>() + " is not the claimed " + want.str();
      return r;
    }
  }
  return r;
}

std::string decimal(const rational& x) { return to_decimal(x, 12); }

std::optional<bool> rounds_to(const std::string& s, const rational& x) {
  size_t i = s.size() > 0 && s[0] == '-' ? 1 : 0;
  const size_t d0 = i;
  while (i < s.size() && std::isdigit(static_cast<unsigned char>(s[i]))) ++i;
  if (i == d0) return std::nullopt;
  long frac = 0;
  if (i < s.size() && s[i] == '.') {
    const size_t f0 = ++i;
    while (i < s.size() && std::isdigit(static_cast<unsigned char>(s[i]))) ++i;
    frac = static_cast<long>(i - f0);
    if (frac == 0) return std::nullopt;
  }
  long e = 0;
  if (i < s.size() && (s[i] == 'e' || s[i] == 'E')) {
    ++i;
    const bool neg = i < s.size() && s[i] == '-';
    if (i < s.size() && (s[i] == '-' || s[i] == '+')) ++i;
    const size_t e0 = i;
    while (i < s.size() && std::isdigit(static_cast<unsigned char>(s[i]))) ++i;
    if (i == e0 || i - e0 > 4) return std::nullopt;  // |e| < 10^4
    e = std::stol(s.substr(e0, i - e0)) * (neg ? -1 : 1);
  }
  if (i != s.size()) return std::nullopt;
  const auto q = try_parse_rational(s);
  if (!q) return std::nullopt;
  rational unit = 1;  // 10^(e - frac), the last digit's unit
  for (long p = e - frac; p > 0; --p) unit *= 10;
  for (long p = e - frac; p < 0; ++p) unit /= 10;
  return 2 * abs(rational(*q - x)) <= unit;
}


std::vector<std::vector<rational>> exact_matrix(const nlohmann::json& obj, const std::string& key, const std::string& where,
                                                size_t max_dim) {
  const std::string at = where + "." + key;
  if (!obj.contains(key) || !obj.at(key).is_array())
    throw InputError(at + ": missing or not an array of rows of \"p/q\" strings");
  const auto& rows = obj.at(key);
  std::vector<std::vector<rational>> M;
  for (size_t i = 0; i < rows.size(); ++i) {
    if (!rows[i].is_array()) throw InputError(at + "[" + std::to_string(i) + "]: not an array (a row)");
    if (rows.size() > max_dim || rows[i].size() > max_dim)
      throw InputError(at + ": more than " + std::to_string(max_dim) + " rows or columns (this checker's limit)");
    std::vector<rational> r;
    for (size_t j = 0; j < rows[i].size(); ++j)
      r.push_back(exact_string(rows[i][j], at + "[" + std::to_string(i) + "][" + std::to_string(j) + "]"));
    if (!M.empty() && r.size() != M[0].size()) throw InputError(at + ": rows of different lengths");
    M.push_back(std::move(r));
  }
  return M;
}

PeriodDelay read_period_delay(const nlohmann::json& model) {
  PeriodDelay m;
  m.T = exact_field(model, "T", "model");
  if (m.T <= 0) throw InputError("model.T: the sample period must be > 0, got " + m.T.str());
  m.n = integer_field(model, "delay", "model", 0, 100000);  // n in z^-n
  return m;
}

std::map<std::string, rational> model_parameters(const nlohmann::json& model) {
  std::map<std::string, rational> params;
  if (!model.contains("set")) return params;
  const auto& sets = model.at("set");
  if (!sets.is_object()) throw InputError("model.set: must be an object {NAME: \"p/q\"}");
  for (auto it = sets.begin(); it != sets.end(); ++it) params[it.key()] = exact_string(it.value(), "model.set." + it.key());
  return params;
}

namespace {

// model.num or model.den: the coefficients as written, descending powers of z, each "p/q".
std::vector<rational> coefficients_field(const nlohmann::json& model, const char* key) {
  const std::string where = std::string("model.") + key;
  if (!model.contains(key) || !model.at(key).is_array() || model.at(key).empty())
    throw InputError(where + ": missing or not a non-empty array of \"p/q\" (descending powers of z)");
  const auto& a = model.at(key);
  if (a.size() > static_cast<size_t>(limits::model_degree) + 1)
    throw InputError(where + ": more than " + std::to_string(limits::model_degree + 1) + " coefficients");
  std::vector<rational> c;
  for (size_t i = 0; i < a.size(); ++i) c.push_back(exact_string(a[i], where + "[" + std::to_string(i) + "]"));
  return c;
}

}  // namespace

TransferFunction model_tf(const nlohmann::json& model, const rational& T, HiddenPoles hidden_poles) {
  if (model.contains("num") || model.contains("den")) {  // `--num/--den` (or a .mat's num, den): numbers, no expression
    if (model.contains("H")) throw InputError("model: H and num/den both given (one model, written one way)");
    if (model.contains("set")) throw InputError("model.set: num/den hold numbers, not parameters");
    const std::vector<rational> num = coefficients_field(model, "num"), den = coefficients_field(model, "den");
    if (den.front() == 0) throw InputError("model.den: the leading coefficient is 0");
    const Polynomial<rational> written(std::vector<rational>(den.rbegin(), den.rend()));
    TransferFunction H = tf(Polynomial<rational>(std::vector<rational>(num.rbegin(), num.rend())), written, T);
    if (!H.num().is_zero() && !unstable_cancelled_factor(written, H.den(), Domain::z).is_zero() &&
        (hidden_poles == HiddenPoles::refuse || !marginally_stable(written)))
      throw InputError("model.num/den: they share a factor with a root on or outside the unit circle: realised as "
                       "written, a hidden mode");
    return H;
  }
  if (!model.contains("H") || !model.at("H").is_string())
    throw InputError("model.H: missing or not a string (the expression of H(z); or num and den, its coefficients)");
  ParseOptions po;
  po.variable = 'z';
  po.T = T;
  po.parameters = model_parameters(model);
  po.hidden_poles = hidden_poles;
  TransferFunction H;
  try {
    H = parse_tf(model.at("H").get<std::string>(), po);
  } catch (const InputError& e) {
    throw InputError(std::string("model.H: ") + e.what());
  }
  if (!H.is_discrete()) throw InputError("model.H: expected a transfer function in z");
  return H;
}

}  // namespace detail

Verdict check_certificate(const nlohmann::json& c) {
  if (!c.is_object()) throw InputError("certificate: not a JSON object");
  if (!c.contains("certificate") || c.at("certificate") != "hapstab")
    throw InputError("certificate: missing or not \"hapstab\" (not a hapstab certificate)");
  if (!c.contains("version") || c.at("version") != 1) throw InputError("version: missing or not 1");
  if (!c.contains("kind") || !c.at("kind").is_string()) throw InputError("kind: missing or not a string");
  const std::string kind = c.at("kind").get<std::string>();
  if (kind == "bound") return check_bound(c);
  if (kind == "bound-max") return check_bound_max(c);
  if (kind == "limit-cycle") return check_limit_cycle(c);
  if (kind == "multidof-coupling") return check_multidof_coupling(c);
  if (kind == "multidof-coupling-symmetric") return check_multidof_coupling_symmetric(c);
  if (kind == "multidof-feasible") return check_multidof_feasible(c);
  if (kind == "multidof-feasible-symmetric") return check_multidof_feasible_symmetric(c);
  if (kind == "multidof-facial") return check_multidof_facial(c);
  if (kind == "multidof-witness") return check_multidof_witness(c);
  if (kind == "operator-passivity") return check_operator_passivity(c);
  if (kind == "passivity-level") return check_passivity_level(c);
  if (kind == "passivity-level-mimo") return check_passivity_level_mimo(c);
  if (kind == "r") return check_r(c);
  if (kind == "stability") return check_stability(c);
  if (kind == "stability-max") return check_stability_max(c);
  if (kind == "stability-loop") return check_stability_loop(c);
  if (kind == "stability-loop-max") return check_stability_loop_max(c);
  if (kind == "stability-loop-max-symmetric") return check_stability_loop_max_symmetric(c);
  if (kind == "stability-loop-symmetric") return check_stability_loop_symmetric(c);
  if (kind == "stability-loop-verdicts") return check_stability_loop_verdicts(c);
  if (kind == "wedge") return check_wedge(c);
  throw InputError("kind: '" + kind + "' has no checker (known: bound, bound-max, limit-cycle, multidof-coupling, multidof-coupling-symmetric, multidof-facial, multidof-feasible, multidof-feasible-symmetric, multidof-witness, operator-passivity, passivity-level, passivity-level-mimo, r, stability, stability-loop, stability-loop-max, stability-loop-max-symmetric, stability-loop-symmetric, stability-loop-verdicts, stability-max, wedge)");
}

Verdict check_file(const std::string& path) {
  struct stat st {};
  if (::stat(path.c_str(), &st) != 0) throw InputError(path + ": cannot read (" + std::strerror(errno) + ")");
  if (!S_ISREG(st.st_mode)) throw InputError(path + ": not a regular file");
  if (st.st_size > (64 << 20)) throw InputError(path + ": larger than 64 MB");
  std::ifstream f(path);
  if (!f) throw InputError(path + ": cannot read");
  std::stringstream ss;
  ss << f.rdbuf();
  nlohmann::json j;
  try {
    j = nlohmann::json::parse(ss.str());
  } catch (const nlohmann::json::exception& e) {
    throw InputError(path + ": not JSON (" + e.what() + ")");
  }
  return check_certificate(j);
}

}  // namespace hapstab::check
