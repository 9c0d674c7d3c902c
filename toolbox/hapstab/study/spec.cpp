// Spec files -> Spec: the TOML is read with toml++, each key checked and named in errors; axes
// are taken in file order (toml++ tables are sorted, so by source position).
#include "hapstab/study/spec.hpp"

#include <algorithm>
#include <cctype>
#include <fstream>
#include <sstream>
#include <toml++/toml.h>

#include "hapstab/numeric/decimal.hpp"
#include "hapstab/numeric/error.hpp"
#include "hapstab/report/paths.hpp"
#include "hapstab/report/toml_limits.hpp"
#include "hapstab/study/sha256.hpp"

namespace hapstab::study {

namespace {

[[noreturn]] void fail(const std::string& file, const std::string& key, const std::string& what) {
  throw InputError(file + ": " + key + ": " + what);
}

bool is_name(const std::string& s) {
  if (s.empty() || s.size() > 64 || !(std::isalpha(static_cast<unsigned char>(s[0])) || s[0] == '_')) return false;
  return std::all_of(s.begin(), s.end(), [](char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; });
}

/// The (key, node) pairs of a table in file order.
std::vector<std::pair<std::string, const toml::node*>> in_file_order(const toml::table& t) {
  std::vector<std::pair<std::string, const toml::node*>> out;
  for (auto&& [k, v] : t) out.emplace_back(std::string(k.str()), &v);
  std::stable_sort(out.begin(), out.end(), [](const auto& a, const auto& b) {
    const auto& sa = a.second->source().begin;
    const auto& sb = b.second->source().begin;
    return sa.line != sb.line ? sa.line < sb.line : sa.column < sb.column;
  });
  return out;
}

/// The bits of q's numerator and denominator together.
size_t bits_of(const rational& q) {
  return mpz_sizeinbase(num(q).backend().data(), 2) + mpz_sizeinbase(den(q).backend().data(), 2);
}

/// An exact number given as a string or an integer (a TOML float is refused: its text is lost),
/// of at most max_value_bits.
std::string number_text(const toml::node& n, const std::string& file, const std::string& key) {
  if (auto s = n.as_string()) {
    const auto q = try_parse_rational(s->get());
    if (!q) fail(file, key, "'" + s->get() + "' is not an exact number");
    if (bits_of(*q) > max_value_bits)
      fail(file, key, "'" + s->get().substr(0, 40) + "' has " + std::to_string(bits_of(*q)) +
                          " bits of numerator and denominator, more than the limit of " + std::to_string(max_value_bits) +
                          " (about 300 digits)");
    return s->get();
  }
  if (auto i = n.as_integer()) return std::to_string(i->get());
  if (n.is_floating_point()) fail(file, key, "write decimals as strings (\"0.1\") so that they stay exact");
  fail(file, key, "expected an exact number as a string, e.g. \"1/2\"");
}

rational number(const toml::table& t, const char* name, const std::string& file, const std::string& key) {
  const toml::node* n = t.get(name);
  if (!n) fail(file, key + "." + name, "missing");
  return parse_rational(number_text(*n, file, key + "." + name));
}

int64_t integer_in(const toml::table& t, const char* name, int64_t lo, int64_t hi, const std::string& file,
                   const std::string& key) {
  const toml::node* n = t.get(name);
  if (!n) fail(file, key + "." + name, "missing");
  auto i = n->as_integer();
  if (!i || i->get() < lo || i->get() > hi)
    fail(file, key + "." + name, "expected an integer in [" + std::to_string(lo) + ", " + std::to_string(hi) + "]");
  return i->get();
}

void only_keys(const toml::table& t, std::initializer_list<const char*> allowed, const std::string& file,
               const std::string& key) {
  for (auto&& entry : t) {
    const std::string_view name = entry.first.str();
    if (std::none_of(allowed.begin(), allowed.end(), [&](const char* a) { return name == a; }))
      fail(file, key + "." + std::string(name), "unknown key");
  }
}

std::vector<std::string> linear_axis(const toml::table& t, const std::string& file, const std::string& key) {
  only_keys(t, {"from", "to", "points", "scale", "digits"}, file, key);
  const rational from = number(t, "from", file, key), to = number(t, "to", file, key);
  const int64_t n = integer_in(t, "points", 1, max_axis_values, file, key);
  std::string scale = "linear";
  if (const toml::node* s = t.get("scale")) {
    if (!s->as_string() || (s->as_string()->get() != "linear" && s->as_string()->get() != "log"))
      fail(file, key + ".scale", "expected \"linear\" or \"log\"");
    scale = s->as_string()->get();
  }
  std::vector<std::string> out;
  out.reserve(static_cast<size_t>(n));
  if (scale == "linear") {
    if (t.get("digits")) fail(file, key + ".digits", "only for scale = \"log\"");
    for (int64_t k = 0; k < n; ++k) out.push_back(exact_text(n == 1 ? from : from + (to - from) * k / (n - 1)));
    return out;
  }
  const int digits = t.get("digits") ? static_cast<int>(integer_in(t, "digits", 1, 30, file, key)) : 6;
  if (from <= 0 || to <= 0) fail(file, key, "a log scale needs from > 0 and to > 0");
  const mp100 lf = log(mp100(from)), lt = log(mp100(to));
  for (int64_t k = 0; k < n; ++k) {
    const mp100 x = n == 1 ? mp100(from) : exp(lf + (lt - lf) * k / (n - 1));
    out.push_back(exact_text(parse_rational(to_decimal(exact_rational(x), digits))));
  }
  return out;
}

std::vector<std::string> random_axis(const toml::table& t, const std::string& file, const std::string& key) {
  only_keys(t, {"random", "from", "to", "seed"}, file, key);
  const int64_t n = integer_in(t, "random", 1, max_axis_values, file, key);
  const rational from = number(t, "from", file, key), to = number(t, "to", file, key);
  const auto seed = static_cast<uint64_t>(integer_in(t, "seed", 0, INT64_MAX, file, key));
  const rational two53 = rational(integer(1) << 53);
  std::vector<std::string> out;
  for (int64_t k = 0; k < n; ++k) {
    const uint64_t u = splitmix64(seed, static_cast<uint64_t>(k)) >> 11;
    out.push_back(exact_text(from + (to - from) * rational(integer(u)) / two53));
  }
  return out;
}

/// The number of values of an axis, from its table alone (nothing generated): values = [...],
/// points or random. 1 for a malformed axis, which read_axis then refuses by name.
uint64_t axis_size(const std::string& name, const toml::node& node, const std::string& file) {
  const toml::table* t = node.as_table();
  if (!t) return 1;
  const std::string key = "axes." + name;
  if (const toml::node* v = t->get("values")) return v->as_array() && !v->as_array()->empty() ? v->as_array()->size() : 1;
  if (t->get("random")) return static_cast<uint64_t>(integer_in(*t, "random", 1, max_axis_values, file, key));
  if (t->get("points")) return static_cast<uint64_t>(integer_in(*t, "points", 1, max_axis_values, file, key));
  return 1;
}

Axis read_axis(const std::string& name, const toml::node& node, const std::string& file) {
  const std::string key = "axes." + name;
  if (!is_name(name) || name == "index" || name == "error" || name == "exit")
    fail(file, key, "an axis is a parameter name (letters, digits, _), not index/error/exit");
  const toml::table* t = node.as_table();
  if (!t) fail(file, key, "expected a table, e.g. { values = [\"1\", \"2\"] }");
  Axis a{name, {}, false, false};
  if (const toml::node* v = t->get("values")) {
    only_keys(*t, {"values"}, file, key);
    const toml::array* arr = v->as_array();
    if (!arr || arr->empty() || arr->size() > max_axis_values) fail(file, key + ".values", "expected a non-empty list");
    for (size_t i = 0; i < arr->size(); ++i)
      a.values.push_back(number_text(*arr->get(i), file, key + ".values[" + std::to_string(i) + "]"));
    a.listed = true;
  } else if (t->get("random")) {
    a.values = random_axis(*t, file, key);
  } else if (t->get("from")) {
    a.values = linear_axis(*t, file, key);
    const toml::node* sc = t->get("scale");
    a.log = sc && sc->as_string() && sc->as_string()->get() == "log";
  } else {
    fail(file, key, "expected values = [...], from/to/points, or random/from/to/seed");
  }
  return a;
}

Arg read_arg(const std::string& name, const toml::node& v, const std::string& file) {
  const std::string key = "args." + name;
  if (name.empty() || name.size() > 64 ||
      !std::all_of(name.begin(), name.end(), [](char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '-' || c == '_'; }) ||
      name[0] == '-')
    fail(file, key, "not an option name");
  if (auto s = v.as_string()) {
    if (s->get().size() > 4096) fail(file, key, "longer than 4096 characters");
    return {name, s->get(), false};
  }
  if (auto i = v.as_integer()) return {name, std::to_string(i->get()), false};
  if (auto b = v.as_boolean()) return {name, "", b->get(), !b->get()};
  if (v.is_floating_point()) fail(file, key, "write decimals as strings (\"0.1\") so that they stay exact");
  fail(file, key, "expected a string, an integer or true/false");
}

std::vector<std::string> split_words(const std::string& s) {
  std::istringstream in(s);
  std::vector<std::string> w;
  for (std::string x; in >> x;) w.push_back(x);
  return w;
}

}  // namespace

std::string exact_text(const rational& q) {
  const integer d = den(q);
  if (d == 1) return num(q).str();
  // d = 2^a 5^b r: found by GMP's valuation functions (the loops `while (r % 5 == 0) r /= 5` and
  // `while (p % d) p *= 10` they replace took time quadratic in the size of d).
  integer r = d;
  const mp_bitcnt_t a = mpz_scan1(d.backend().data(), 0);
  mpz_tdiv_q_2exp(r.backend().data(), r.backend().data(), a);
  const mp_bitcnt_t b = mpz_remove(r.backend().data(), r.backend().data(), integer(5).backend().data());
  if (r != 1) return q.str();
  // A terminating decimal: q = m / 10^k exactly for the smallest such k = max(a, b),
  // m = num(q) 2^(k-a) 5^(k-b).
  const mp_bitcnt_t k = std::max(a, b);
  integer m = num(q), five;
  mpz_mul_2exp(m.backend().data(), m.backend().data(), k - a);
  mpz_ui_pow_ui(five.backend().data(), 5, k - b);
  m *= five;
  const bool neg = m < 0;
  std::string digits = (neg ? integer(-m) : m).str();
  if (digits.size() <= static_cast<size_t>(k)) digits.insert(0, static_cast<size_t>(k) + 1 - digits.size(), '0');
  digits.insert(digits.size() - static_cast<size_t>(k), ".");
  return (neg ? "-" : "") + digits;
}

uint64_t splitmix64(uint64_t seed, uint64_t k) {
  uint64_t z = seed + (k + 1) * 0x9e3779b97f4a7c15ULL;
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  return z ^ (z >> 31);
}

Spec parse_spec(const std::string& text, const std::string& file) {
  if (text.size() > max_spec_bytes) fail(file, "(file)", "larger than 1 MiB");
  report::check_toml_depth(text, file);  // before toml++, which recurses per level
  toml::table root;
  try {
    root = toml::parse(text, file);
  } catch (const toml::parse_error& e) {
    std::ostringstream os;
    os << file << ":" << e.source().begin.line << ":" << e.source().begin.column << ": " << e.description();
    throw InputError(os.str());
  }
  only_keys(root, {"command", "args", "axes", "set", "units"}, file, "(top level)");
  Spec spec;
  spec.sha256 = sha256_hex(text);
  const toml::node* cmd = root.get("command");
  if (!cmd || !cmd->as_string()) fail(file, "command", "missing: the command to run, e.g. command = \"bound\"");
  spec.command = split_words(cmd->as_string()->get());
  if (spec.command.empty() || spec.command.size() > 2) fail(file, "command", "expected one or two words");
  if (const toml::node* a = root.get("args")) {
    if (!a->as_table()) fail(file, "args", "expected a table [args]");
    for (const auto& [k, v] : in_file_order(*a->as_table())) spec.args.push_back(read_arg(k, *v, file));
  }
  const toml::node* axes = root.get("axes");
  if (!axes || !axes->as_table() || axes->as_table()->empty())
    fail(file, "axes", "missing: at least one axis, e.g. [axes] K = { values = [\"1\", \"2\"] }");
  // The number of points from the axes' sizes, before any value is generated.
  const auto axes_in_order = in_file_order(*axes->as_table());
  for (const auto& [k, v] : axes_in_order) {
    const uint64_t n = axis_size(k, *v, file);
    if (spec.points > max_points / n)
      fail(file, "axes." + k, "the axes up to this one make " + std::to_string(spec.points * n) +
                                  " points, more than the limit of 10^9 (nothing was generated)");
    spec.points *= n;
  }
  size_t text_bytes = 0;
  for (const auto& [k, v] : axes_in_order) {
    spec.axes.push_back(read_axis(k, *v, file));
    for (const auto& value : spec.axes.back().values) text_bytes += value.size();
    if (text_bytes > max_values_bytes)
      fail(file, "axes." + k, "the axes' values take " + std::to_string(text_bytes) + " bytes as text, more than the limit of " +
                                  std::to_string(max_values_bytes));
  }
  if (const toml::node* c = root.get("set")) {
    if (!c->as_table()) fail(file, "set", "expected a table [set] of constants, e.g. B = \"1/2\"");
    for (const auto& [k, v] : in_file_order(*c->as_table())) {
      if (!is_name(k) || k == "index" || k == "error" || k == "exit")
        fail(file, "set." + k, "a constant is a parameter name (letters, digits, _), not index/error/exit");
      const std::string& name = k;  // a structured binding cannot be captured in C++17 (clang refuses it)
      if (std::any_of(spec.axes.begin(), spec.axes.end(), [&](const Axis& a) { return a.name == name; }))
        fail(file, "set." + k, "is an axis too: a parameter is either constant or swept");
      spec.constants.push_back({k, number_text(*v, file, "set." + k)});
    }
  }
  if (const toml::node* u = root.get("units")) {
    if (!u->as_table()) fail(file, "units", "expected a table [units], e.g. K = \"N/m\"");
    for (const auto& [k, v] : in_file_order(*u->as_table())) {
      if (!is_name(k)) fail(file, "units." + k, "not a column name (letters, digits, _)");
      const auto* text = v->as_string();
      if (!text || text->get().size() > 64 ||
          !std::all_of(text->get().begin(), text->get().end(), [](char ch) {
            const auto u = static_cast<unsigned char>(ch);
            return u >= 0x20 && u != 0x7f;
          }))
        fail(file, "units." + k, "expected a unit as a string of at most 64 printable characters, e.g. \"N s/m\"");
      spec.units.emplace_back(k, text->get());
    }
  }
  return spec;
}

std::string unit_of(const Spec& spec, const std::string& name) {
  for (const auto& [k, u] : spec.units)
    if (k == name) return u;
  return "";
}

std::string read_spec_file(const std::string& path) {
  return report::read_input_file(path, "the spec file", max_spec_bytes);
}

std::vector<std::string> point_values(const Spec& spec, uint64_t index) {
  std::vector<std::string> out(spec.axes.size());
  for (size_t a = spec.axes.size(); a-- > 0;) {
    const auto& v = spec.axes[a].values;
    out[a] = v[index % v.size()];
    index /= v.size();
  }
  return out;
}

std::vector<std::string> point_args(const Spec& spec, uint64_t index, const std::vector<std::string>& extra) {
  std::vector<std::string> args = spec.command;
  for (const Arg& a : spec.args) {
    if (a.omit) continue;  // key = false
    args.push_back("--" + a.key);
    if (!a.flag) args.push_back(a.value);
  }
  args.insert(args.end(), extra.begin(), extra.end());
  for (const Constant& c : spec.constants) args.insert(args.end(), {"--set", c.name + "=" + c.value});
  const auto values = point_values(spec, index);
  for (size_t a = 0; a < values.size(); ++a) args.insert(args.end(), {"--set", spec.axes[a].name + "=" + values[a]});
  return args;
}

}  // namespace hapstab::study
