#include "hapstab/numeric/decimal.hpp"
#include "hapstab/numeric/shared_decimal.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <vector>

#include "hapstab/numeric/error.hpp"

namespace hapstab {

namespace {
// 10^k as an integer; the powers up to 10^400 computed once (formatting and parsing every
// number asked for three or four of them, each allocating).
const integer& ten_to(unsigned k) {
  static const std::vector<integer> table = [] {
    std::vector<integer> t(401);
    t[0] = 1;
    for (size_t i = 1; i < t.size(); ++i) t[i] = t[i - 1] * 10;
    return t;
  }();
  if (k < table.size()) return table[k];
  thread_local integer big;
  big = bmp::pow(integer(10), k);
  return big;
}
}  // namespace

rational pow10(long e) {
  const integer& p = ten_to(static_cast<unsigned>(e < 0 ? -e : e));
  return e >= 0 ? rational(p) : rational(integer(1), p);
}

namespace {

// One decimal: [+-] digits [. digits] [(e|E) [+-] digits], at least one mantissa digit.
std::optional<rational> parse_decimal(std::string_view s) {
  size_t i = 0;
  bool neg = false;
  if (i < s.size() && (s[i] == '+' || s[i] == '-')) neg = s[i++] == '-';
  std::string digits;  // the mantissa's digits without the point: one GMP conversion, not one per digit
  long scale = 0;
  while (i < s.size() && std::isdigit(static_cast<unsigned char>(s[i]))) digits += s[i++];
  if (i < s.size() && s[i] == '.') {
    ++i;
    while (i < s.size() && std::isdigit(static_cast<unsigned char>(s[i]))) {
      digits += s[i++];
      --scale;
    }
  }
  if (digits.empty()) return std::nullopt;
  if (i < s.size() && (s[i] == 'e' || s[i] == 'E')) {
    ++i;
    bool eneg = false;
    if (i < s.size() && (s[i] == '+' || s[i] == '-')) eneg = s[i++] == '-';
    long ex = 0;
    int edigits = 0;
    while (i < s.size() && std::isdigit(static_cast<unsigned char>(s[i]))) {
      ex = ex * 10 + (s[i++] - '0');
      if (++edigits > 6) return std::nullopt;  // |exponent| < 1e6: beyond is a typo, not a number
    }
    if (edigits == 0) return std::nullopt;
    scale += eneg ? -ex : ex;
  }
  if (i != s.size()) return std::nullopt;
  digits.erase(0, std::min(digits.find_first_not_of('0'), digits.size() - 1));  // "007" would be octal to GMP
  integer mant(digits.c_str());
  if (neg) mant = -mant;
  return scale == 0 ? rational(mant) : rational(mant) * pow10(scale);
}

std::string_view trim(std::string_view s) {
  while (!s.empty() && std::isspace(static_cast<unsigned char>(s.front()))) s.remove_prefix(1);
  while (!s.empty() && std::isspace(static_cast<unsigned char>(s.back()))) s.remove_suffix(1);
  return s;
}

}  // namespace

std::optional<rational> try_parse_rational(std::string_view text) {
  text = trim(text);
  auto slash = text.find('/');
  if (slash == std::string_view::npos) return parse_decimal(text);
  auto a = parse_decimal(trim(text.substr(0, slash)));
  auto b = parse_decimal(trim(text.substr(slash + 1)));
  if (!a || !b || *b == 0) return std::nullopt;
  return *a / *b;
}

rational parse_rational(std::string_view text, std::string_view what) {
  auto q = try_parse_rational(text);
  if (!q) {
    std::string msg = std::string(what) + ": '" + std::string(text) + "' is not a number";
    auto slash = text.find('/');
    if (slash != std::string_view::npos) {
      auto b = try_parse_rational(text.substr(slash + 1));
      if (b && *b == 0) msg = std::string(what) + ": '" + std::string(text) + "' divides by zero";
    }
    msg += " (expected a decimal such as 0.001, 1e-3, or a fraction such as 1/1000)";
    throw InputError(msg);
  }
  return *q;
}

namespace {

enum class Rounding { nearest_even, down, up };  // down: toward -inf; up: toward +inf

// x with `digits` significant digits, rounded as `mode` says: the one formatter behind
// to_decimal and decimal_outward.
std::string format_decimal(const rational& x, int digits, Rounding mode) {
  if (digits < 1) digits = 1;
  if (x == 0) return "0";
  const bool neg = x < 0;
  // all in integers (no rational canonicalisation): |x| = P/Q, and |x| 10^k = N/M
  const integer P = abs(num(x)), Q = den(x);
  if (Q == 1) {  // an integer of at most `digits` digits is itself
    std::string s = P.str();
    if (static_cast<long>(s.size()) <= digits) return neg ? "-" + s : s;
  }
  auto scaled = [&](long k, integer& N, integer& M) {
    N = P;
    M = Q;
    if (k >= 0) N *= ten_to(static_cast<unsigned>(k));
    else M *= ten_to(static_cast<unsigned>(-k));
  };
  // e = floor(log10 |x|), estimated from the binary exponents and then fixed exactly
  long ep = 0, eq = 0;
  const double mp = mpz_get_d_2exp(&ep, P.backend().data()), mq = mpz_get_d_2exp(&eq, Q.backend().data());
  long e = static_cast<long>(std::floor(std::log10(mp / mq) + static_cast<double>(ep - eq) * std::log10(2.0)));
  // |x| 10^(digits-1-e) = N/M truncated to n: 10^e <= |x| < 10^(e+1) iff 10^(digits-1) <= n <
  // 10^digits (n = floor(N/M) and the ends are integers), so one division checks the estimate
  integer N, M, n, r;
  for (;;) {
    scaled(digits - 1 - e, N, M);
    n = N / M;
    if (n < ten_to(static_cast<unsigned>(digits - 1))) { --e; continue; }  // |x| < 10^e
    if (n >= ten_to(static_cast<unsigned>(digits))) { ++e; continue; }     // |x| >= 10^(e+1)
    break;
  }
  r = N - n * M;  // n is the magnitude, truncated; then rounded as asked
  const bool away = mode == Rounding::nearest_even ? 2 * r > M || (2 * r == M && (n % 2) != 0)
                                                   : r != 0 && neg == (mode == Rounding::down);
  if (away) n += 1;
  if (n == ten_to(static_cast<unsigned>(digits))) {
    n /= 10;
    ++e;
  }
  std::string s = n.str();  // exactly `digits` characters
  // strip trailing zeros: they are exact and carry no information
  while (s.size() > 1 && s.back() == '0') s.pop_back();
  std::string out = neg ? "-" : "";
  if (e >= -5 && e < digits) {
    if (e >= 0) {
      if (static_cast<long>(s.size()) <= e + 1) {
        out += s + std::string(e + 1 - s.size(), '0');
      } else {
        out += s.substr(0, e + 1) + "." + s.substr(e + 1);
      }
    } else {
      out += "0." + std::string(-e - 1, '0') + s;
    }
  } else {
    out += s.substr(0, 1);
    if (s.size() > 1) out += "." + s.substr(1);
    out += (e < 0 ? "e-" : "e+");
    std::string es = std::to_string(e < 0 ? -e : e);
    if (es.size() < 2) es = "0" + es;
    out += es;
  }
  return out;
}

}  // namespace

std::string to_decimal(const rational& x, int digits) { return format_decimal(x, digits, Rounding::nearest_even); }

std::string decimal_outward(const rational& q, int digits, int dir) {
  return format_decimal(q, digits, dir < 0 ? Rounding::down : Rounding::up);
}

std::optional<std::string> common_decimal(const rational& lo, const rational& hi, int digits) {
  std::string a = to_decimal(lo, digits), b = to_decimal(hi, digits);
  if (a == b) return a;
  return std::nullopt;
}

SharedDecimal shared_decimal(const rational& lo, const rational& hi, int digits) {
  if (lo == hi) return {to_decimal(lo, digits), digits};
  for (int d = digits; d >= 1; --d)
    if (auto s = common_decimal(lo, hi, d)) return {*s, d};
  return {};
}

rational exact_rational(double x) {
  if (!std::isfinite(x)) throw InputError("exact_rational: value is not finite");
  rational q;
  mpq_set_d(q.backend().data(), x);  // exact: a double is m 2^e (GMP: "no rounding")
  return q;
}

double double_outward(const rational& q, int dir) {
  const mpfr_rnd_t rnd = dir < 0 ? MPFR_RNDD : dir > 0 ? MPFR_RNDU : MPFR_RNDN;
  mpfr_t x;
  mpfr_init2(x, 53);
  // both steps round the same way: a 53-bit MPFR number is a double unless it is subnormal there,
  // where mpfr_get_d rounds once more in the same direction (still on the outward side)
  mpfr_set_q(x, q.backend().data(), rnd);
  const double d = mpfr_get_d(x, rnd);
  mpfr_clear(x);
  return d;
}

}  // namespace hapstab
