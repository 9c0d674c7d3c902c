// hapstab/check/scene_model.cpp -- see scene_model.hpp.
#include "hapstab/check/scene_model.hpp"

#include <cctype>
#include <functional>
#include <map>
#include <set>
#include <vector>

#include <toml++/toml.h>

#include "hapstab/check/certificate.hpp"
#include "hapstab/check/loop_model.hpp"
#include "hapstab/lti/parse.hpp"
#include "hapstab/numeric/error.hpp"
#include "hapstab/numeric/scalar.hpp"

namespace hapstab::check::detail {

namespace {

constexpr size_t kMaxDofs = 64;  // DOFs of a scene, written out (a contact scene's N^2 entries each name all N: reading 128 took 7 s)

constexpr size_t kMaxSceneBytes = size_t(1) << 20;    // a one-DOF scene is a few KB
constexpr size_t kMaxExpandedBytes = size_t(1) << 20;  // parameters substituted into one expression
constexpr int kMaxDotsPerLine = 256;  // toml++ recurses per component of a dotted key (report/toml_limits.hpp)

[[noreturn]] void beyond(const std::string& where, const std::string& what) {
  throw InputError("model.scene: " + where + ": " + what + " (beyond this checker; docs/certificates.md lists what it reads of "
                   "a scene)");
}
[[noreturn]] void malformed(const std::string& where, const std::string& what) {
  throw InputError("model.scene: " + where + ": " + what);
}

std::string trimmed(std::string t) {
  t.erase(0, t.find_first_not_of(' '));
  t.erase(t.find_last_not_of(' ') + 1);
  return t;
}

// The scene's [parameters] (model.set replacing definitions), substituted textually.
struct Parameters {
  std::map<std::string, std::string> definition;
  std::string free;  // stays a name (stability-max's K)
  std::map<std::string, std::string> expanded;  // memo
  std::set<std::string> open;                   // on the current chain (a cycle is malformed)
  /// list parameters (docs/scene.md, "Repeated blocks"): NAME[k] is "(v_k)", sum(NAME) "((v_1) + ... + (v_n))"
  std::map<std::string, std::vector<std::string>> lists;
  std::map<std::pair<std::string, long>, std::string> list_expanded;  // memo of (NAME, k), k = 0: the sum
  std::set<std::string> open_lists;                                 // on the current chain

  // NAME's k-th value (k = 0: their sum), expanded once; a list that names itself is a cycle (malformed)
  const std::string& list_value(const std::string& name, long k) {
    if (const auto it = list_expanded.find({name, k}); it != list_expanded.end()) return it->second;
    if (!open_lists.insert(name).second) malformed("parameters." + name, "depends on itself (a cycle)");
    std::string e;
    const auto& values = lists.at(name);
    if (k > 0) e = expand(values[size_t(k - 1)], "parameters." + name);
    else
      for (const auto& v : values) {
        e += (e.empty() ? "(" : " + (") + expand(v, "parameters." + name) + ")";
        if (e.size() > kMaxExpandedBytes) beyond("parameters." + name, "its values expand to more than 1 MB");
      }
    open_lists.erase(name);
    return list_expanded[{name, k}] = e;
  }

  // `text` with every parameter named in it replaced by "(its expansion)": the tokens are the
  // parser's (lti/parse.hpp): numbers with an exponent, identifiers, single characters.
  std::string expand(const std::string& text, const std::string& where) {
    std::string out;
    for (size_t i = 0; i < text.size();) {
      const unsigned char ch = static_cast<unsigned char>(text[i]);
      if (std::isdigit(ch) || ch == '.') {
        size_t j = i;
        while (j < text.size() && (std::isdigit(static_cast<unsigned char>(text[j])) || text[j] == '.')) ++j;
        if (j < text.size() && (text[j] == 'e' || text[j] == 'E')) {
          size_t k = j + 1;
          if (k < text.size() && (text[k] == '+' || text[k] == '-')) ++k;
          if (k < text.size() && std::isdigit(static_cast<unsigned char>(text[k]))) {
            while (k < text.size() && std::isdigit(static_cast<unsigned char>(text[k]))) ++k;
            j = k;
          }
        }
        out.append(text, i, j - i);
        i = j;
      } else if (std::isalpha(ch) || ch == '_') {
        size_t j = i;
        while (j < text.size() && (std::isalnum(static_cast<unsigned char>(text[j])) || text[j] == '_')) ++j;
        const std::string name = text.substr(i, j - i);
        if (name == "sum" && j < text.size() && text[j] == '(') {  // sum(NAME) of a list parameter
          const size_t close = text.find(')', j);
          const std::string inner = close == std::string::npos ? "" : trimmed(text.substr(j + 1, close - j - 1));
          if (lists.count(inner)) {
            out += "(" + list_value(inner, 0) + ")";
            if (out.size() > kMaxExpandedBytes) beyond(where, "its parameters expand to more than 1 MB");
            i = close + 1;
            continue;
          }
        }
        if (const auto it = lists.find(name); it != lists.end()) {  // NAME[k], k from 1
          const size_t close = j < text.size() && text[j] == '[' ? text.find(']', j) : std::string::npos;
          const std::string index = close == std::string::npos ? "" : text.substr(j + 1, close - j - 1);
          const bool digits = !index.empty() && index.size() <= 6 && std::all_of(index.begin(), index.end(), [](char d) {
            return std::isdigit(static_cast<unsigned char>(d));
          });
          const long k = digits ? std::stol(index) : 0;
          if (k < 1 || k > long(it->second.size()))
            malformed(where, "'" + name + (close == std::string::npos ? "" : "[" + index + "]") + "': the list parameter " + name + " has " +
                                 std::to_string(it->second.size()) + " values, " + name + "[1] .. " + name + "[" +
                                 std::to_string(it->second.size()) + "] (or sum(" + name + "))");
          out += "(" + list_value(name, k) + ")";
          if (out.size() > kMaxExpandedBytes) beyond(where, "its parameters expand to more than 1 MB");
          i = close + 1;
          continue;
        }
        out += definition.count(name) && name != free ? "(" + of(name) + ")" : name;
        i = j;
      } else {
        out += text[i++];
      }
      if (out.size() > kMaxExpandedBytes) beyond(where, "its parameters expand to more than 1 MB");
    }
    return out;
  }

  std::string of(const std::string& name) {
    if (const auto it = expanded.find(name); it != expanded.end()) return it->second;
    if (!open.insert(name).second) malformed("parameters." + name, "depends on itself (a cycle)");
    if (open.size() > 200) beyond("parameters." + name, "defined through more than 200 others in a chain");
    const std::string e = expand(definition.at(name), "parameters." + name);
    for (const auto& n : names_in(e))
      if (n == "s" || n == "z") malformed("parameters." + name, "names " + n + ": a parameter is a number, not a transfer function");
    open.erase(name);
    return expanded[name] = e;
  }
};

// A TOML string or integer (an exact number's two forms; TOML floats are binary approximations).
std::string text_of(const toml::node& v, const std::string& where) {
  if (const auto* s = v.as_string()) return s->get();
  if (const auto* i = v.as_integer()) return std::to_string(i->get());
  malformed(where, "expected a string (an exact number or an expression) or an integer");
}

// The rational value of a constant expression (T known when T > 0).
rational constant(const std::string& text, const rational& T, const std::string& where) {
  ParseOptions po;
  po.variable = 's';
  po.T = T;
  try {
    const TransferFunction t = parse_tf(text, po);
    if (t.num().degree() > 0 || t.den().degree() > 0) malformed(where, "not a number");
    return t.num().is_zero() ? rational(0) : rational(t.num().coeff(0) / t.den().coeff(0));
  } catch (const InputError& e) {
    malformed(where, e.what());
  }
}

void only_keys(const toml::table& t, const std::set<std::string>& known, const std::string& where) {
  for (const auto& [k, v] : t)
    if (!known.count(std::string(k.str()))) beyond(where + "." + std::string(k.str()), "a key this checker does not model");
}

const toml::table& one_table(const toml::table& root, const char* key, bool required) {
  static const toml::table none;
  const toml::node* n = root.get(key);
  if (!n) {
    if (required) malformed(std::string("[[") + key + "]]", "missing");
    return none;
  }
  const auto* a = n->as_array();
  if (!a) malformed(key, "expected an array of tables [[" + std::string(key) + "]]");
  if (a->size() != 1) beyond(std::string("[[") + key + "]]", std::to_string(a->size()) + " tables (one DOF: one device, one operator)");
  const auto* t = (*a)[0].as_table();
  if (!t) malformed(std::string("[[") + key + "]]", "not a table");
  return *t;
}

// One SISO transfer function: a string, or a 1 x 1 matrix of strings.
std::string siso(const toml::node& v, const std::string& where) {
  if (const auto* s = v.as_string()) return s->get();
  if (const auto* rows = v.as_array(); rows && rows->size() == 1)
    if (const auto* row = (*rows)[0].as_array(); row && row->size() == 1)
      if (const auto* s = (*row)[0].as_string()) return s->get();
  beyond(where, "not one transfer function (a matrix: more than one DOF)");
}

std::string field(const toml::table& t, const char* key, const std::string& where, Parameters& p, const char* fallback) {
  const toml::node* n = t.get(key);
  if (!n) return fallback;
  return p.expand(text_of(*n, where + "." + key), where + "." + key);
}

// The identifier `var` replaced by "(with)" in `text` (the parser's tokens, as in expand).
std::string substitute(const std::string& text, const std::string& var, const std::string& with) {
  Parameters p;
  p.definition[var] = with;
  p.expanded[var] = with;
  return p.expand(text, "environment.tf");
}

// A list parameter's values: NAME = [v1, ..., vn], or { repeat = [v1, ..., vp], times = n } (the p values n
// times over); at most 4096 values (scene/reader.cpp's limit).
std::vector<std::string> list_values(const toml::node& v, const std::string& where) {
  std::vector<std::string> out;
  const toml::array* a = v.as_array();
  long times = 1;
  if (const auto* t = v.as_table()) {
    only_keys(*t, {"repeat", "times"}, where);
    a = (*t)["repeat"].as_array();
    const auto* n = (*t)["times"].as_integer();
    if (!a || !n || n->get() < 1 || n->get() > 4096) malformed(where, "a repeated list needs repeat = [values] and times = n (1 .. 4096)");
    times = long(n->get());
  }
  if (!a || a->empty() || long(a->size()) * times > 4096) malformed(where, "a list of 1 .. 4096 values");
  for (long k = 0; k < times; ++k)
    for (size_t i = 0; i < a->size(); ++i) out.push_back(text_of(*a->get(i), where + "[" + std::to_string(i + 1) + "]"));
  return out;
}

// Every string in `n` (at any depth) with "[i]" replaced by "[k]" (a copy's number).
void index_strings(toml::node& n, const std::string& k) {
  if (auto* str = n.as_string()) {
    std::string text = str->get();
    for (size_t at = text.find("[i]"); at != std::string::npos; at = text.find("[i]", at + k.size() + 2)) text.replace(at, 3, "[" + k + "]");
    *str = text;
  } else if (auto* a = n.as_array()) {
    for (auto& e : *a) index_strings(e, k);
  } else if (auto* t = n.as_table()) {
    for (auto&& [name, v] : *t) index_strings(v, k);
  }
}

// [[device]] and [[operator]] tables with count = n written out as hapstab's reader does (scene/reader.cpp's
// table_copies): n copies in place, named NAME[k] (or the name's own [i] pattern), "[i]" -> "[k]" in every
// string. At most max_dofs copies (the checkers' DOF limit).
void write_out_copies(toml::table& root, size_t max_dofs) {
  for (const char* key : {"device", "operator"}) {
    auto* arr = root[key].as_array();
    if (!arr) continue;
    toml::array out;
    for (size_t i = 0; i < arr->size(); ++i) {
      const auto* t = arr->get(i)->as_table();
      if (!t || !t->contains("count")) {
        out.push_back(*arr->get(i));
        continue;
      }
      const std::string where = std::string(key) + "[" + std::to_string(i + 1) + "]";
      const auto* n = t->get("count")->as_integer();
      if (!n || n->get() < 1) malformed(where + ".count", "a whole number of copies >= 1");
      if (n->get() > static_cast<int64_t>(max_dofs)) beyond(where + ".count", std::to_string(n->get()) + " copies, more than " + std::to_string(max_dofs));
      const auto* name = (*t)["name"].as_string();
      if (!name) malformed(where + ".name", "a table with count needs a name: its copies are NAME[1] .. NAME[count]");
      const std::string own = name->get(), pattern = own.find("[i]") == std::string::npos ? own + "[i]" : own;
      for (long k = 1; k <= n->get(); ++k) {
        toml::table copy = *t;
        copy.erase("count");
        copy.insert_or_assign("name", pattern);
        for (auto&& [nm, v] : copy) index_strings(v, std::to_string(k));
        out.push_back(std::move(copy));
      }
    }
    root.insert_or_assign(key, std::move(out));
  }
}

toml::table parse_scene(const std::string& text, bool coupling = false, size_t max_dofs = kMaxDofs) {
  if (text.size() > kMaxSceneBytes) beyond("the scene", "more than 1 MB");
  for (size_t at = 0, dots = 0; at <= text.size(); ++at) {
    if (at == text.size() || text[at] == '\n') dots = 0;
    else if (text[at] == '.' && ++dots > size_t(kMaxDotsPerLine)) beyond("the scene", "a line with more than 256 dots");
  }
  toml::table root;
  try {
    root = toml::parse(std::string_view(text), std::string_view("model.scene"));
  } catch (const toml::parse_error& e) {
    throw InputError(std::string("model.scene: not TOML: ") + std::string(e.description()));
  }
  for (const auto& [k, v] : root) {
    const std::string key(k.str());
    static const std::set<std::string> loop{"scene", "parameters", "device", "operator", "environment", "delay"};
    static const std::set<std::string> ignored{"input", "initial", "simulate", "reproduce", "multidof"};
    if (!loop.count(key) && !ignored.count(key) && !(coupling && key == "coupling"))
      beyond("[" + key + "]", "a section this checker does not model");
  }
  if (const auto* m = root["multidof"].as_table(); m && m->contains("perturb_C"))  // it changes E (multidof commands only)
    beyond("multidof.perturb_C", "Sec. VI's perturbed environment, which stability does not model");
  write_out_copies(root, max_dofs);
  return root;
}

// [parameters], each value replaced by model.set's where it gives one; every one expanded once (a
// cycle is malformed, used or not, as for hapstab's loader).
Parameters read_parameters(const toml::table& root, const nlohmann::json& model, const std::string& free) {
  Parameters p;
  p.free = free;
  if (const auto* params = root["parameters"].as_table())
    for (const auto& [k, v] : *params) {
      const std::string name(k.str());
      if (name == "T" || name == "s" || name == "z") beyond("parameters." + name, "a parameter named T, s or z");
      if (v.is_array() || v.is_table()) {
        p.lists[name] = list_values(v, "parameters." + name);
        continue;
      }
      p.definition[name] = text_of(v, "parameters." + name);
    }
  else if (root.contains("parameters")) malformed("[parameters]", "not a table");
  if (model.contains("set")) {
    if (!model.at("set").is_object()) throw InputError("model.set: not an object");
    for (const auto& [name, v] : model.at("set").items()) {
      if (p.lists.count(name)) throw InputError("model.set." + name + ": a list parameter (its values are the scene's)");
      if (!p.definition.count(name)) throw InputError("model.set." + name + ": not a parameter of the scene");
      if (name == free) throw InputError("model.set: gives the parameter model.name = " + free + " a value");
      p.definition[name] = exact_field(model.at("set"), name, "model.set").str();
    }
  }
  for (const auto& [name, definition] : p.definition)
    if (name != p.free) p.of(name);
  return p;
}

// [[device]]: P(s) = 1/(m s^2 + b s) or G(s)/s.
std::string read_plant(const toml::table& device, Parameters& p, const rational& T) {
  only_keys(device, {"name", "m", "b", "tf", "passive"}, "device");
  if (device.contains("tf")) {
    if (device.contains("m") || device.contains("b")) malformed("device", "give either m, b or tf, not both");
    return "(" + p.expand(siso(*device.get("tf"), "device.tf"), "device.tf") + ")/s";
  }
  if (!device.contains("m")) malformed("device.m", "missing (the device mass)");
  const std::string m = field(device, "m", "device", p, "0"), b = field(device, "b", "device", p, "0");
  if (constant(m, T, "device.m") <= 0) malformed("device.m", "must be > 0");
  if (constant(b, T, "device.b") < 0) malformed("device.b", "must be >= 0");
  return "1/((" + m + ")*s^2 + (" + b + ")*s)";
}

// [[operator]] on the one device: Z_op(s) = m s + b + k/s or Z(s) + m_o s.
std::string read_operator(const toml::table& op, const toml::table& device, Parameters& p) {
  only_keys(op, {"name", "dofs", "m", "b", "k", "tf", "mass", "passive"}, "operator");
  if (const toml::node* d = op.get("dofs")) {  // the one device: its name or DOF 0, alone or in a list
    const toml::node* one = d->as_array() && d->as_array()->size() == 1 ? &(*d->as_array())[0] : d;
    const auto* name = one->as_string();
    const auto* index = one->as_integer();
    const auto* dname = device.get("name") ? device.get("name")->as_string() : nullptr;
    if (!((index && index->get() == 0) || (name && dname && name->get() == dname->get())))
      malformed("operator.dofs", "not the scene's one DOF");
  }
  if (!op.contains("tf")) {
    if (op.contains("mass")) malformed("operator.mass", "only with tf");
    return "(" + field(op, "m", "operator", p, "0") + ")*s + (" + field(op, "b", "operator", p, "0") + ") + (" +
           field(op, "k", "operator", p, "0") + ")/s";
  }
  if (op.contains("m") || op.contains("b") || op.contains("k")) malformed("operator", "give either m, b, k or tf, not both");
  std::string Z = "(" + p.expand(siso(*op.get("tf"), "operator.tf"), "operator.tf") + ")";
  if (const toml::node* mass = op.get("mass")) {
    const auto* a = mass->as_array();
    if (!a || a->size() != 1) malformed("operator.mass", "expected a list of one mass");
    Z += " + (" + p.expand(text_of((*a)[0], "operator.mass[1]"), "operator.mass[1]") + ")*s";
  }
  return Z;
}

// [environment]: H(z) = g E(z), E in z or discretised from s.
std::string read_wall(const toml::table* env, Parameters& p) {
  if (!env) malformed("[environment]", "missing (the loop has no controller)");
  only_keys(*env, {"tf", "domain", "method", "gain"}, "environment");
  if (!env->contains("tf")) malformed("environment.tf", "missing");
  std::string E = p.expand(siso(*env->get("tf"), "environment.tf"), "environment.tf");
  for (const char* key : {"domain", "method"})
    if (env->contains(key) && !env->get(key)->is_string()) malformed(std::string("environment.") + key, "not a string");
  const std::string domain = (*env)["domain"].value_or(std::string("z"));
  if (domain == "s") {
    const std::string method = (*env)["method"].value_or(std::string());
    if (method == "backward_euler") E = substitute(E, "s", "(z-1)/(T*z)");
    else if (method == "tustin") E = substitute(E, "s", "2*(z-1)/(T*(z+1))");
    else malformed("environment.method", "an s-domain environment needs \"backward_euler\" or \"tustin\"");
  } else if (domain != "z") {
    malformed("environment.domain", "\"z\" or \"s\"");
  } else if (env->contains("method")) {
    malformed("environment.method", "only with domain = \"s\"");
  }
  return "(" + field(*env, "gain", "environment", p, "1") + ")*(" + E + ")";
}

// [delay]: n = t_d/T, a whole number of samples in [0, 10^5]; 0 without the section.
// [delay] in samples, t_d/T >= 0 (0 without the section); `whole`: a whole number is required.
rational read_delay_samples(const toml::table& root, Parameters& p, const rational& T, bool whole) {
  const auto* delay = root["delay"].as_table();
  if (!delay) {
    if (root.contains("delay")) malformed("[delay]", "not a table");
    return 0;
  }
  only_keys(*delay, {"time", "samples"}, "delay");
  if (delay->size() != 1) malformed("[delay]", "give exactly one of time, samples");
  const bool time = delay->contains("time");
  const std::string key = time ? "time" : "samples";
  rational d = constant(field(*delay, key.c_str(), "delay", p, "0"), T, "delay." + key);
  if (time) d /= T;
  if (d < 0) malformed("delay." + key, "must be >= 0");
  if (whole && bmp::denominator(d) != 1) beyond("delay." + key, "a delay of " + d.str() + " samples, not a whole number");
  return d;
}

long read_delay(const toml::table& root, Parameters& p, const rational& T) {
  const rational d = read_delay_samples(root, p, T, true);
  const std::string key = root["delay"].as_table() && root["delay"].as_table()->contains("time") ? "time" : "samples";
  if (d > 100000) beyond("delay." + key, "more than 100000 samples");
  return static_cast<long>(bmp::numerator(d));
}

// An expression in `var` ('s' or 'z') as a rational function (its parameters already substituted).
RationalFunction<rational> parse_in(const std::string& text, char var, const rational& T, const std::string& where) {
  ParseOptions po;
  po.variable = var;
  po.T = T;
  try {
    const TransferFunction t = parse_tf(text, po);
    if (t.is_discrete() != (var == 'z')) malformed(where, std::string("expected a transfer function in ") + var);
    return t.H;
  } catch (const InputError& e) {
    malformed(where, e.what());
  }
}

bool proper(const RationalFunction<rational>& f) { return f.num().degree() <= f.den().degree(); }

// The DOF a device name or a DOF number names.
int dof_of(const toml::node& n, const std::vector<std::string>& names, const std::string& where) {
  if (const auto* i = n.as_integer()) {
    if (i->get() < 0 || i->get() >= static_cast<int64_t>(names.size())) malformed(where, "no DOF " + std::to_string(i->get()));
    return static_cast<int>(i->get());
  }
  if (const auto* s = n.as_string())
    for (size_t k = 0; k < names.size(); ++k)
      if (names[k] == s->get()) return static_cast<int>(k);
  malformed(where, "not a DOF number or the name of a device");
}

// A matrix of expressions (an array of arrays of strings), rows x cols.
std::vector<std::vector<std::string>> text_matrix(const toml::node& n, size_t rows, const std::string& where) {
  std::vector<std::vector<std::string>> out;
  if (const auto* str = n.as_string()) {
    if (rows != 1) beyond(where, "one transfer function for " + std::to_string(rows) + " DOF (write the matrix)");
    return {{str->get()}};
  }
  const auto* a = n.as_array();
  if (!a || a->size() != rows) malformed(where, "expected a " + std::to_string(rows) + " x " + std::to_string(rows) + " matrix of strings");
  for (const auto& row : *a) {
    const auto* r = row.as_array();
    if (!r || r->size() != rows) malformed(where, "expected a " + std::to_string(rows) + " x " + std::to_string(rows) + " matrix of strings");
    out.emplace_back();
    for (const auto& e : *r) {
      const auto* str = e.as_string();
      if (!str) malformed(where, "an entry that is not a string");
      out.back().push_back(str->get());
    }
  }
  return out;
}

const toml::array& tables(const toml::table& root, const char* key) {
  static const toml::array none;
  const toml::node* n = root.get(key);
  if (!n) return none;
  const auto* a = n->as_array();
  if (!a) malformed(key, "expected an array of tables [[" + std::string(key) + "]]");
  for (const auto& t : *a)
    if (!t.as_table()) malformed(std::string("[[") + key + "]]", "not a table");
  return *a;
}

// ss = { A, B, C, D }: exact numbers (expressions of the parameters), A n x n, B n x N, C N x n, D N x N.
SceneLoop::Matrix ss_matrix(const toml::table& ss, const char* key, size_t rows, size_t cols, const std::string& where,
                            Parameters& p, const rational& T) {
  const std::string at = where + ".ss." + key;
  const toml::node* n = ss.get(key);
  if (!n || !n->as_array()) malformed(at, "missing or not a matrix");
  const toml::array& a = *n->as_array();
  SceneLoop::Matrix M;
  if (rows == 0 || cols == 0) {  // an empty A, B or C: written [] or [[]]
    if (!(a.empty() || (a.size() == 1 && a[0].as_array() && a[0].as_array()->empty()) || (cols == 0 && a.size() == rows)))
      malformed(at, "not of size " + std::to_string(rows) + " x " + std::to_string(cols));
    return SceneLoop::Matrix(rows, std::vector<rational>(cols));
  }
  if (a.size() != rows) malformed(at, "not of size " + std::to_string(rows) + " x " + std::to_string(cols));
  for (const auto& row : a) {
    const auto* r = row.as_array();
    if (!r || r->size() != cols) malformed(at, "not of size " + std::to_string(rows) + " x " + std::to_string(cols));
    M.emplace_back();
    for (const auto& e : *r) M.back().push_back(constant(p.expand(text_of(e, at), at), T, at));
  }
  return M;
}

// t.ss, a table of A, B, C and D only.
const toml::table& ss_table(const toml::table& t, const std::string& where) {
  const auto* ss = t.get("ss")->as_table();
  if (!ss) malformed(where + ".ss", "expected a table { A = ..., B = ..., C = ..., D = ... }");
  for (const auto& [k, v] : *ss)
    if (k.str() != "A" && k.str() != "B" && k.str() != "C" && k.str() != "D") malformed(where + ".ss." + std::string(k.str()), "not A, B, C or D");
  return *ss;
}

// The order n of ss.A (0 when written [] or [[]]).
size_t ss_order(const toml::table& ss) {
  const toml::node* A = ss.get("A");
  return A && A->as_array() && !(A->as_array()->size() == 1 && (*A->as_array())[0].as_array() && (*A->as_array())[0].as_array()->empty())
             ? A->as_array()->size() : 0;
}

void read_loop_operator(const toml::table& op, const std::string& key, const std::vector<std::string>& names, Parameters& p,
                        const rational& T, SceneLoop& out) {
  only_keys(op, {"name", "dofs", "m", "b", "k", "tf", "ss", "mass", "passive"}, key);
  std::vector<int> ports;
  if (const toml::node* d = op.get("dofs")) {
    if (const auto* list = d->as_array())
      for (size_t i = 0; i < list->size(); ++i) ports.push_back(dof_of((*list)[i], names, key + ".dofs"));
    else
      ports.push_back(dof_of(*d, names, key + ".dofs"));
  }
  if (!op.contains("tf") && !op.contains("ss")) {
    if (op.contains("mass")) malformed(key + ".mass", "only with tf or ss");
    if (ports.empty()) ports.push_back(0);
    if (ports.size() != 1) malformed(key + ".dofs", "m, b, k act on one DOF");
    const int j = ports[0];
    out.mass[j] += constant(field(op, "m", key, p, "0"), T, key + ".m");
    out.damping[j] += constant(field(op, "b", key, p, "0"), T, key + ".b");
    out.stiffness[j] += constant(field(op, "k", key, p, "0"), T, key + ".k");
    return;
  }
  if (op.contains("m") || op.contains("b") || op.contains("k")) malformed(key, "give either m, b, k or tf/ss, not both");
  if (op.contains("tf") && op.contains("ss")) malformed(key, "give exactly one of tf, ss");
  SceneLoop::Impedance Z;
  size_t q = 0;
  if (op.contains("ss")) {  // q from D (q x q), else from the ports
    const toml::table& ss = ss_table(op, key);
    const toml::node* D = ss.get("D");
    q = D && D->as_array() ? D->as_array()->size() : ports.size();
    if (ports.empty())
      for (size_t i = 0; i < q && i < names.size(); ++i) ports.push_back(static_cast<int>(i));
    if (q == 0 || ports.size() != q) malformed(key + ".ss", "D is not a square matrix over the operator's DOFs");
    const size_t n = ss_order(ss);
    Z.is_ss = true;
    Z.A = ss_matrix(ss, "A", n, n, key, p, T);
    Z.B = ss_matrix(ss, "B", n, q, key, p, T);
    Z.C = ss_matrix(ss, "C", q, n, key, p, T);
    Z.D = ss_matrix(ss, "D", q, q, key, p, T);
  } else {
    const toml::node& tf = *op.get("tf");
    q = tf.as_string() ? 1 : tf.as_array() ? tf.as_array()->size() : 0;
    if (ports.empty())
      for (size_t i = 0; i < q && i < names.size(); ++i) ports.push_back(static_cast<int>(i));
    if (q == 0 || ports.size() != q) malformed(key + ".tf", "not a square matrix over the operator's DOFs");
    for (const auto& row : text_matrix(tf, q, key + ".tf")) {
      Z.Z.emplace_back();
      for (const auto& e : row) {
        Z.Z.back().push_back(parse_in(p.expand(e, key + ".tf"), 's', T, key + ".tf"));
        if (!proper(Z.Z.back().back())) malformed(key + ".tf", "an improper entry (write a mass by m or mass)");
      }
    }
  }
  Z.ports = ports;
  if (const toml::node* nm = op.get("name"); nm && nm->as_string()) Z.name = nm->as_string()->get();
  if (const toml::node* mass = op.get("mass")) {
    const auto* a = mass->as_array();
    if (!a || a->size() != q) malformed(key + ".mass", "expected a mass per DOF of the operator");
    for (size_t i = 0; i < q; ++i)
      out.mass[ports[i]] += constant(p.expand(text_of((*a)[i], key + ".mass"), key + ".mass"), T, key + ".mass");
  }
  out.operators.push_back(std::move(Z));
}

// [environment] or [coupling]: tf (in z, or in s with a method) or ss (in z), times gain.
// diagonal / off_diagonal [/ blocks] -> the N x N entries as text (docs/scene.md, "Repeated blocks"; hapstab's
// scene/scene.cpp compact_matrix): (i, i) the diagonal with [i] its row's number, (i, j) the off-diagonal with
// [i] the row's and [j] the column's (from 1), 0 between blocks of N/K DOFs.
std::vector<std::vector<std::string>> diagonal_texts(const toml::table& t, const std::string& where, size_t N) {
  const auto place = [](std::string text, const char* index, size_t value) {
    const std::string with = "[" + std::to_string(value) + "]";
    for (size_t at = text.find(index); at != std::string::npos; at = text.find(index, at + with.size())) text.replace(at, 3, with);
    return text;
  };
  const auto* d = t["diagonal"].as_string();
  if (!d) malformed(where + ".diagonal", "not a string");
  const toml::node* o = t.get("off_diagonal");
  if (o && !o->as_string()) malformed(where + ".off_diagonal", "not a string");
  const std::string off = o ? o->as_string()->get() : "0";
  long K = 1;
  if (const toml::node* b = t.get("blocks")) {
    if (!b->as_integer() || b->as_integer()->get() < 1 || N % size_t(b->as_integer()->get()) != 0)
      malformed(where + ".blocks", "a whole number K >= 1 that divides the " + std::to_string(N) + " DOFs");
    K = long(b->as_integer()->get());
  }
  const size_t size = N / size_t(K);
  std::vector<std::vector<std::string>> out(N, std::vector<std::string>(N, "0"));
  for (size_t i = 0; i < N; ++i)
    for (size_t j = 0; j < N; ++j)
      if (i == j) out[i][j] = place(d->get(), "[i]", i + 1);
      else if (i / size == j / size) out[i][j] = place(place(off, "[i]", i + 1), "[j]", j + 1);
  return out;
}

SceneLoop::Discrete read_discrete(const toml::table& t, const std::string& where, size_t N, Parameters& p, const rational& T) {
  only_keys(t, {"tf", "ss", "diagonal", "off_diagonal", "blocks", "domain", "method", "gain"}, where);
  if (t.contains("diagonal") && (t.contains("tf") || t.contains("ss"))) malformed(where, "give one of tf, ss, diagonal");
  if (!t.contains("diagonal") && (t.contains("off_diagonal") || t.contains("blocks"))) malformed(where, "off_diagonal and blocks need diagonal");
  if (!t.contains("diagonal") && t.contains("tf") == t.contains("ss")) malformed(where, "give exactly one of tf, ss");
  const std::string gain_text = field(t, "gain", where, p, "1");
  SceneLoop::Discrete D;
  if (t.contains("ss")) {
    if (t.contains("domain") || t.contains("method")) beyond(where + ".domain", "an ss block in s");
    const toml::table& ss = ss_table(t, where);
    const size_t n = ss_order(ss);
    const rational g = constant(gain_text, T, where + ".gain");
    D.is_ss = true;
    D.A = ss_matrix(ss, "A", n, n, where, p, T);
    D.B = ss_matrix(ss, "B", n, N, where, p, T);
    D.C = ss_matrix(ss, "C", N, n, where, p, T);
    D.D = ss_matrix(ss, "D", N, N, where, p, T);
    for (auto* M : {&D.C, &D.D})
      for (auto& row : *M)
        for (auto& x : row) x *= g;
    return D;
  }
  const RationalFunction<rational> gain = parse_in(gain_text, 'z', T, where + ".gain");
  // each text once, as expanded: a written-out contact scene repeats one N^2 - N times, and identical DOFs (list
  // values equal) give equal texts
  std::map<std::string, RationalFunction<rational>> read;
  for (const auto& row : t.contains("diagonal") ? diagonal_texts(t, where, N) : text_matrix(*t.get("tf"), N, where + ".tf")) {
    D.tf.emplace_back();
    for (const auto& e : row) {
      // read_wall's discretisation, entry by entry
      toml::table one;
      one.insert("tf", e);
      for (const char* key : {"domain", "method"})
        if (t.contains(key)) one.insert(key, *t.get(key));
      const std::string text = read_wall(&one, p);
      auto it = read.find(text);
      if (it == read.end()) {
        const RationalFunction<rational> f = parse_in(text, 'z', T, where + ".tf") * gain;
        if (!proper(f)) malformed(where + ".tf", "an improper entry in z");
        it = read.emplace(text, f).first;
      }
      D.tf.back().push_back(it->second);
    }
  }
  return D;
}

// A device block: ss = { A, B, C, D } (D = 0) or tf (a string or a square matrix), in s, strictly proper.
void read_device_block(const toml::table& d, const std::string& key, Parameters& p, const rational& T, SceneLoop::Device& dev) {
  dev.block = true;
  if (d.contains("tf") && d.contains("ss")) malformed(key, "give exactly one of tf, ss");
  if (d.contains("tf")) {
    const toml::node& tf = *d.get("tf");
    dev.dofs = tf.as_string() ? 1 : tf.as_array() ? tf.as_array()->size() : 0;
    if (dev.dofs == 0) malformed(key + ".tf", "expected a string or a square matrix of strings");
    for (const auto& row : text_matrix(tf, dev.dofs, key + ".tf")) {
      dev.tf.emplace_back();
      for (const auto& e : row) {
        dev.tf.back().push_back(parse_in(p.expand(e, key + ".tf"), 's', T, key + ".tf"));
        if (dev.tf.back().back().num().degree() >= dev.tf.back().back().den().degree() && !dev.tf.back().back().is_zero())
          malformed(key + ".tf", "not strictly proper (a device has no feedthrough)");
      }
    }
    return;
  }
  const auto* ss = d.get("ss")->as_table();
  if (!ss) malformed(key + ".ss", "expected a table { A = ..., B = ..., C = ..., D = ... }");
  for (const auto& [k, v] : *ss)
    if (k.str() != "A" && k.str() != "B" && k.str() != "C" && k.str() != "D") malformed(key + ".ss." + std::string(k.str()), "not A, B, C or D");
  const toml::node* A = ss->get("A");
  const toml::node* D = ss->get("D");
  const size_t n = A && A->as_array() ? A->as_array()->size() : 0;
  dev.dofs = D && D->as_array() ? D->as_array()->size() : 0;
  if (n == 0 || dev.dofs == 0) malformed(key + ".ss", "a device needs states and at least one DOF");
  dev.A = ss_matrix(*ss, "A", n, n, key, p, T);
  dev.B = ss_matrix(*ss, "B", n, dev.dofs, key, p, T);
  dev.C = ss_matrix(*ss, "C", dev.dofs, n, key, p, T);
  for (const auto& row : ss_matrix(*ss, "D", dev.dofs, dev.dofs, key, p, T))
    for (const rational& x : row)
      if (x != 0) malformed(key + ".ss.D", "not 0 (a device has no feedthrough)");
}

}  // namespace

// The one-DOF loop of a `stability` model as written, {plant, H[, operator], set, T, delay} (the
// stability kind's fields): the device G = s P_eff, P_eff = P/(1 + s Z_op P) (force -> velocity), one
// block realised by the checker, its position x' = v; the wall H(z); n whole samples.
SceneLoop read_plant_loop(const nlohmann::json& model) {
  only_fields(model, {"plant", "H", "operator", "set", "T", "delay"}, "model");
  const PeriodDelay pd = read_period_delay(model);
  const std::map<std::string, rational> params = model_parameters(model);
  using RF = RationalFunction<rational>;
  const auto outside = [](const std::string& where, const std::string& what) {
    return InputError(where + ": " + what + " (beyond this checker: docs/certificates.md, `stability-loop`)");
  };
  const RF s(Polynomial<rational>{rational(0), rational(1)});
  RF P = parse_model_field(model, "plant", 's', pd.T, params);
  if (P.is_zero()) throw InputError("model.plant: zero (the device does not move)");
  if (model.contains("operator")) {
    const RF one = RF(rational(1)) + s * parse_model_field(model, "operator", 's', pd.T, params) * P;
    if (one.is_zero()) throw InputError("model.operator: 1 + s Z_op P is zero");
    P = P / one;
  }
  const RF G = s * P;
  if (G.num().degree() >= G.den().degree()) throw outside("model.plant", "a device of relative degree below 2 (s P is not strictly proper)");
  SceneLoop out;
  out.T = pd.T;
  out.delay = pd.n;
  // without a pole at s = 0, G(0) = 0 and x - K xi is constant (K A_G = C_G, K B_G = 0): the
  // quotient by it sets x = K xi, P_eff's own output (stability_loop_check.hpp)
  out.own_conserved = P.den().coeff(0) != 0 ? 1 : 0;
  SceneLoop::Device dev;
  dev.block = true;
  dev.tf = {{G}};
  out.devices = {dev};
  out.mass = out.damping = out.stiffness = {rational(0)};
  out.E.tf = {{parse_model_field(model, "H", 'z', pd.T, params)}};
  if (!proper(out.E.tf[0][0])) throw outside("model.H", "an improper H(z) (z^-n H causal only by the delay)");
  return out;
}

SceneLoop read_scene_loop(const nlohmann::json& model, size_t max_dofs) {
  if (!model.contains("scene") && model.contains("plant")) return read_plant_loop(model);
  only_fields(model, {"scene", "set"}, "model");
  if (!model.contains("scene") || !model.at("scene").is_string()) throw InputError("model.scene: missing or not a string (the scene's TOML text)");
  const toml::table root = parse_scene(model.at("scene").get<std::string>(), true, max_dofs);
  const auto* header = root["scene"].as_table();
  if (!header || !header->contains("T")) malformed("[scene].T", "missing (the sample period)");
  only_keys(*header, {"name", "description", "T"}, "scene");
  SceneLoop out;
  out.T = constant(text_of(*header->get("T"), "scene.T"), rational(0), "scene.T");
  if (out.T <= 0) malformed("scene.T", "must be > 0");
  const rational& T = out.T;
  Parameters p = read_parameters(root, model, "");
  std::vector<std::string> names;
  const toml::array& devices = tables(root, "device");
  if (devices.empty()) malformed("[[device]]", "missing");
  for (size_t i = 0; i < devices.size(); ++i) {
    const toml::table& d = *devices[i].as_table();
    const std::string key = "device[" + std::to_string(i + 1) + "]";
    only_keys(d, {"name", "m", "b", "tf", "ss", "passive"}, key);
    SceneLoop::Device dev;
    dev.first = out.mass.size();
    dev.name = d.get("name") && d.get("name")->as_string() ? d.get("name")->as_string()->get() : "";
    if (d.contains("tf") || d.contains("ss")) {
      if (d.contains("m") || d.contains("b")) malformed(key, "give either m, b or tf/ss, not both");
      read_device_block(d, key, p, T, dev);
    } else {
      if (!d.contains("m")) malformed(key + ".m", "missing (the device mass)");
      out.mass.push_back(constant(field(d, "m", key, p, "0"), T, key + ".m"));
      out.damping.push_back(constant(field(d, "b", key, p, "0"), T, key + ".b"));
      if (out.mass.back() <= 0) malformed(key + ".m", "must be > 0");
      if (out.damping.back() < 0) malformed(key + ".b", "must be >= 0");
      out.stiffness.push_back(0);
    }
    for (size_t j = dev.block ? 0 : 1; j < (dev.block ? dev.dofs : 1); ++j) {
      out.mass.push_back(0);
      out.damping.push_back(0);
      out.stiffness.push_back(0);
    }
    for (size_t j = 0; j < dev.dofs; ++j) names.push_back(dev.dofs == 1 ? dev.name : "");  // a block of several DOFs: by number
    out.devices.push_back(std::move(dev));
  }
  if (names.size() > max_dofs) beyond("[[device]]", std::to_string(names.size()) + " DOFs, more than " + std::to_string(max_dofs));
  const toml::array& ops = tables(root, "operator");
  for (size_t i = 0; i < ops.size(); ++i) read_loop_operator(*ops[i].as_table(), "operator[" + std::to_string(i + 1) + "]", names, p, T, out);
  const auto* env = root["environment"].as_table();
  if (!env) malformed("[environment]", "missing (the loop has no controller)");
  out.E = read_discrete(*env, "environment", names.size(), p, T);
  if (const auto* cpl = root["coupling"].as_table()) out.V = read_discrete(*cpl, "coupling", names.size(), p, T);
  else if (root.contains("coupling")) malformed("[coupling]", "not a table");
  const rational d = read_delay_samples(root, p, T, false);
  if (d > 1000) beyond("[delay]", "more than 1000 samples for the closed-loop matrix");
  out.delay = static_cast<long>(bmp::numerator(d) / bmp::denominator(d));  // floor (d >= 0)
  out.fraction = d - out.delay;
  return out;
}

std::vector<std::vector<std::string>> block_entries(const nlohmann::json& model, const std::string& block, const std::string& free,
                                                    size_t dofs) {
  const toml::table root = parse_scene(model.at("scene").get<std::string>(), true);
  Parameters p = read_parameters(root, model, free);
  const auto* t = root[block].as_table();
  if (!t) malformed("[" + block + "]", "missing or not a table");
  if (!t->contains("tf") && !t->contains("diagonal"))
    beyond(block + ".ss", "the parameter inside an ss block (only a tf entry is proven affine)");
  const std::string gain_text = field(*t, "gain", block, p, "1");
  std::vector<std::vector<std::string>> out;
  for (const auto& row : t->contains("diagonal") ? diagonal_texts(*t, block, dofs) : text_matrix(*t->get("tf"), dofs, block + ".tf")) {
    out.emplace_back();
    for (const auto& e : row) {  // read_discrete's reading, the parameter left a name
      toml::table one;
      one.insert("tf", e);
      for (const char* key : {"domain", "method"})
        if (t->contains(key)) one.insert(key, *t->get(key));
      out.back().push_back("(" + gain_text + ")*(" + read_wall(&one, p) + ")");
    }
  }
  return out;
}

nlohmann::json scene_loop_model(const nlohmann::json& model, bool free) {
  if (!model.is_object() || !model.contains("scene")) return model;
  if (free) only_fields(model, {"scene", "set", "name"}, "model");
  else only_fields(model, {"scene", "set"}, "model");
  if (!model.at("scene").is_string()) throw InputError("model.scene: not a string (the scene's TOML text)");
  const toml::table root = parse_scene(model.at("scene").get<std::string>());
  const auto* header = root["scene"].as_table();
  if (!header || !header->contains("T")) malformed("[scene].T", "missing (the sample period)");
  only_keys(*header, {"name", "description", "T"}, "scene");
  const rational T = constant(text_of(*header->get("T"), "scene.T"), rational(0), "scene.T");
  if (T <= 0) malformed("scene.T", "must be > 0");
  const std::string name = free && model.contains("name") && model.at("name").is_string() ? model.at("name").get<std::string>() : "";
  Parameters p = read_parameters(root, model, name);

  nlohmann::json out{{"T", T.str()}, {"set", nlohmann::json::object()}};
  if (free && model.contains("name")) out["name"] = model.at("name");
  const toml::table& device = one_table(root, "device", true);
  out["plant"] = read_plant(device, p, T);
  if (root.contains("operator")) out["operator"] = read_operator(one_table(root, "operator", false), device, p);
  out["H"] = read_wall(root["environment"].as_table(), p);
  out["delay"] = read_delay(root, p, T);
  return out;
}

}  // namespace hapstab::check::detail
