// Scene files -> models (see scene.hpp; the schema is scene/schema.cpp, docs/scene.md). One
// reader per section, in the order parse_scene calls them: a section may use what the earlier
// ones defined (T and the parameters in expressions, the devices' DOFs in DOF lists). The
// typed values and their checks are in reader.hpp.
#include "hapstab/scene/scene.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <optional>
#include <set>
#include <sstream>

#include "hapstab/lti/discretize.hpp"
#include "hapstab/lti/parse.hpp"
#include "hapstab/numeric/decimal.hpp"
#include "hapstab/numeric/error.hpp"
#include "hapstab/numeric/limits.hpp"
#include "hapstab/report/escape.hpp"
#include "hapstab/report/paths.hpp"
#include "hapstab/report/toml_limits.hpp"
#include "hapstab/scene/reader.hpp"
#include "hapstab/scene/schema.hpp"

namespace hapstab::scene {

namespace {

using Q = rational;

constexpr size_t kSceneBytes = 64u << 20;  ///< the largest scene file load_scene reads (docs/security.md)

toml::table parse_toml(const std::string& text, const std::string& file) {
  report::check_toml_depth(text, file);  // before toml++, which recurses per level
  try {
    return toml::parse(text, file);
  } catch (const toml::parse_error& e) {
    std::ostringstream os;
    os << file << ":" << e.source().begin.line << ":" << e.source().begin.column << ": " << e.description();
    throw InputError(os.str());
  }
}

// ---- [scene]: name, description and the sample period T
void read_scene_header(const toml::table& root, Reader& c, Scene& sc) {
  auto s = section(root, "scene", c);
  if (!s) c.fail("scene", "missing: every scene starts with [scene] and its sample period T = \"1/1000\"");
  sc.name = c.free_text(*s, "name", "scene", "", 256);
  sc.description = c.free_text(*s, "description", "scene", "", 8192, true);
  if (!s->contains("T")) c.fail("scene.T", "missing: the sample period, e.g. T = \"1/1000\"");
  c.T = c.number(*s->get("T"), "scene.T", false);
  if (c.T <= 0) c.fail("scene.T", "the sample period must be > 0, got " + c.T.str());
  sc.T = c.T;
  sc.loop.T = c.T;
}

// ---- [parameters]: literals or constant expressions of T and other parameters (any order)
std::map<std::string, const toml::node*> parameter_nodes(const toml::table& p, const Reader& c) {
  std::map<std::string, const toml::node*> todo;
  for (const auto& [k, v] : p) {
    const std::string name(k.str());  // parameters are read in expressions: identifiers only
    bool ok = !name.empty() && name.size() <= 64 && (std::isalpha(static_cast<unsigned char>(name[0])) || name[0] == '_');
    for (char ch : name) ok = ok && (std::isalnum(static_cast<unsigned char>(ch)) || ch == '_');
    if (!ok)
      c.fail("parameters", "'" + report::text(name) + "' is not a parameter name (letters, digits and _, " +
                               "starting with a letter or _, at most 64)");
    todo[name] = &v;
  }
  return todo;
}

// A list parameter NAME = [v1, ..., vn] (1 <= n <= limits::scene_copies): its values, named
// NAME[1] .. NAME[n] in messages as in expressions.
std::vector<Q> list_values(const toml::array& a, const std::string& key, const Reader& c) {
  if (a.empty()) c.fail(key, "an empty list: a list parameter holds one value per copy (at least one)");
  if (a.size() > size_t(limits::scene_copies))
    c.fail(key, std::to_string(a.size()) + " values, more than the limit of " + std::to_string(limits::scene_copies));
  std::vector<Q> out;
  for (size_t k = 0; k < a.size(); ++k) out.push_back(c.number(a[k], key + "[" + std::to_string(k + 1) + "]"));
  return out;
}

// NAME = { repeat = [v1, ..., vp], times = n }: the values v1 .. vp over and over, n times (p n
// values: an array of identical devices in p kinds, said once).
std::vector<Q> repeated_list(const toml::table& t, const std::string& key, const Reader& c) {
  for (const auto& [k, v] : t)
    if (k.str() != "repeat" && k.str() != "times")
      c.fail(key + "." + std::string(k.str()), "not a key of a repeated list (repeat = [values], times = n)");
  const auto* values = t["repeat"].as_array();
  if (!values) c.fail(key + ".repeat", "missing or not an array: the values to repeat");
  const auto times = t["times"].value<int64_t>();
  if (!times || *times < 1) c.fail(key + ".times", "missing or not a whole number >= 1");
  const std::vector<Q> once = list_values(*values, key + ".repeat", c);
  if (double(once.size()) * double(*times) > double(limits::scene_copies))
    c.fail(key + ".times", std::to_string(once.size()) + " values " + std::to_string(*times) +
                               " times is more than the limit of " + std::to_string(limits::scene_copies) + " values");
  std::vector<Q> out;
  for (int64_t k = 0; k < *times; ++k) out.insert(out.end(), once.begin(), once.end());
  return out;
}

// Evaluates the parameters in dependency order (Kahn's topological sort over the names each
// expression refers to, lti/parse.hpp names_in): each is parsed once, after the parameters it
// names. (Passes over all of them until none was left took cubic time: 1000 chained
// parameters, 20 s.) A parameter on a cycle is refused naming the cycle's members.
void resolve_parameters(const std::map<std::string, const toml::node*>& todo, Reader& c) {
  if (todo.size() > size_t(limits::scene_parameters))
    c.fail("parameters", std::to_string(todo.size()) + " parameters, more than the limit of " +
                             std::to_string(limits::scene_parameters));
  std::map<std::string, std::vector<std::string>> users;  // name -> the parameters that name it
  std::map<std::string, size_t> waiting;                  // name -> its unresolved dependencies
  for (const auto& [name, node] : todo) {
    std::set<std::string> deps;  // a list depends on what any of its values names
    const auto named = [&](const toml::node& v) {
      if (const auto* text = v.as_string())
        for (const auto& dep : names_in(text->get()))
          if (todo.count(dep)) deps.insert(dep);
    };
    const toml::node* values = node->is_table() ? node->as_table()->get("repeat") : node;
    if (const auto* list = values ? values->as_array() : nullptr) for (const auto& v : *list) named(v);
    else if (values) named(*values);
    for (const auto& dep : deps) users[dep].push_back(name);
    waiting[name] = deps.size();
  }
  std::vector<std::string> ready;
  for (const auto& [name, n] : waiting)
    if (n == 0) ready.push_back(name);
  size_t done = 0;
  while (!ready.empty()) {
    const std::string name = ready.back();
    ready.pop_back();
    if (const auto* list = todo.at(name)->as_array()) c.lists[name] = list_values(*list, "parameters." + name, c);
    else if (const auto* rep = todo.at(name)->as_table()) c.lists[name] = repeated_list(*rep, "parameters." + name, c);
    else c.params[name] = c.number(*todo.at(name), "parameters." + name);
    ++done;
    for (const auto& user : users[name])
      if (--waiting[user] == 0) ready.push_back(user);
  }
  if (done < todo.size()) {
    std::string cycle;
    for (const auto& [name, n] : waiting)
      if (n > 0 && cycle.size() < 200) cycle += (cycle.empty() ? "" : ", ") + name;
    c.fail("parameters", "these parameters depend on each other in a cycle (or on one that does): " + cycle);
  }
}

void read_parameters(const toml::table& root, const std::map<std::string, Q>& overrides, Reader& c) {
  auto p = section(root, "parameters", c);
  if (!p) {
    if (!overrides.empty()) c.fail("parameters", "--set given but the scene has no [parameters]");
    return;
  }
  auto todo = parameter_nodes(*p, c);
  for (const auto& [k, v] : overrides) {
    if (!todo.count(k)) c.fail("parameters." + k, "--set names a parameter the scene does not define");
    if (todo.at(k)->is_array() || todo.at(k)->is_table()) c.fail("parameters." + k, "--set gives one value, but " + k + " is a list parameter");
    todo.erase(k);
    c.params[k] = v;
  }
  resolve_parameters(todo, c);
}

// ---- [[device]]: a mass-damper (m, b) or a strictly proper force -> velocity block
sim::DeviceBlock read_device(const toml::table& t, const std::string& key, const Reader& c) {
  if ((t.contains("quantum") || t.contains("quantizer") || t.contains("coulomb")) && !t.contains("m"))
    c.fail(key, "quantum, quantizer and coulomb need a mass-damper device (m, b)");
  const std::string name = c.free_text(t, "name", key, key, 256);
  sim::DeviceBlock d;
  if (t.contains("m") || t.contains("b")) {
    if (t.contains("tf") || t.contains("ss")) c.fail(key, "give either m, b (a mass-damper) or tf/ss, not both");
    if (!t.contains("m")) c.fail(key + ".m", "missing (the device mass)");
    const Q m = c.number(t, "m", key), b = t.contains("b") ? c.number(t, "b", key) : Q(0);
    if (m <= 0) c.fail(key + ".m", "must be > 0, got " + m.str());
    if (b < 0) c.fail(key + ".b", "must be >= 0, got " + b.str());
    return sim::mass_damper(name, m, b);
  }
  d.name = name;
  d.G = c.block(t, key, 's');
  if (d.G.is_discrete()) c.fail(key + ".tf", "a device is continuous: write it in s");
  if (d.G.inputs() != d.G.outputs()) c.fail(key, "a device maps forces to velocities: it must be square");
  if (!d.G.D.isZero()) c.fail(key, "a device must be strictly proper (force -> velocity has no feedthrough)");
  if (t["passive"].value_or(true)) c.check_passive_claim(d.G, key);
  return d;
}

// [[device]] quantum = Delta (> 0), quantizer = "floor" (default) | "round", coulomb = f_c (>= 0).
void read_encoder_and_friction(const toml::table& t, const std::string& key, const Reader& c, int dof,
                               sim::LoopSpec& loop) {
  if (t.contains("quantizer") && !t.contains("quantum")) c.fail(key + ".quantizer", "needs quantum (the encoder resolution)");
  if (t.contains("quantum")) {
    sim::Quantizer q;
    q.dof = dof;
    q.step = c.number(t, "quantum", key);
    if (q.step <= 0) c.fail(key + ".quantum", "must be > 0, got " + q.step.str());
    if (t.contains("quantizer")) {
      const auto kind = t["quantizer"].value<std::string>();
      if (!kind || (*kind != "floor" && *kind != "round")) c.fail(key + ".quantizer", "must be \"floor\" or \"round\"");
      q.round = *kind == "round";
    }
    loop.quantizers.push_back(q);
  }
  if (t.contains("coulomb")) {
    sim::Coulomb f;
    f.dof = dof;
    f.force = c.number(t, "coulomb", key);
    if (f.force < 0) c.fail(key + ".coulomb", "must be >= 0, got " + f.force.str());
    loop.coulomb.push_back(f);
  }
}

// Devices number the DOFs in their order; the names become DOF names for later sections.
void read_devices(const toml::table& root, Reader& c, sim::LoopSpec& loop) {
  each_table(root, "device", c, [&](const toml::table& t, const std::string& key, int) {
    sim::DeviceBlock d = read_device(t, key, c);
    const std::string& name = d.name;
    if (c.device_dofs.count(name)) c.fail(key + ".name", "'" + name + "' is defined twice");
    c.device_dofs[name] = {c.N, int(d.dofs())};
    read_encoder_and_friction(t, key, c, c.N, loop);
    c.N += int(d.dofs());
    loop.devices.push_back(std::move(d));
  });
  if (loop.devices.empty()) c.fail("device", "missing: the scene needs at least one [[device]]");
}

// ---- [[operator]]: an impedance given as tf/ss (plus optional inertia) on its DOFs
sim::OperatorBlock read_operator_block(const toml::table& t, const std::string& key, const std::string& name,
                                       std::vector<int> dofs, const Reader& c) {
  if (t.contains("m") || t.contains("b") || t.contains("k")) c.fail(key, "give either m, b, k or tf/ss, not both");
  sim::OperatorBlock o;
  o.name = name;
  o.Z = c.block(t, key, 's');
  if (o.Z.is_discrete()) c.fail(key + ".tf", "an operator is continuous: write it in s");
  if (dofs.empty())
    for (int j = 0; j < int(o.Z.inputs()); ++j) dofs.push_back(j);
  if (o.Z.inputs() != Eigen::Index(dofs.size()) || o.Z.outputs() != Eigen::Index(dofs.size()))
    c.fail(key, "incompatible dimensions: the impedance is " + std::to_string(o.Z.outputs()) + "x" +
                    std::to_string(o.Z.inputs()) + " but it acts on " + std::to_string(dofs.size()) + " DOF(s)");
  if (auto m = t.get("mass")) {
    auto a = m->as_array();
    if (!a || a->size() != dofs.size()) c.fail(key + ".mass", "expected one mass per DOF");
    for (size_t i = 0; i < a->size(); ++i) o.mass.push_back(c.number((*a)[i], key + ".mass"));
  }
  o.ports = dofs;
  if (t["passive"].value_or(true)) c.check_passive_claim(o.Z, key);
  return o;
}

// ... or Z_O = m s + b + k/s on one DOF.
sim::OperatorBlock read_operator_msd(const toml::table& t, const std::string& key, const std::string& name,
                                     std::vector<int> dofs, const Reader& c) {
  if (dofs.empty()) dofs = {0};
  if (dofs.size() != 1) c.fail(key + ".dofs", "a mass-spring-damper operator acts on one DOF");
  auto get = [&](const char* k) { return t.contains(k) ? c.number(t, k, key) : Q(0); };
  const Q m = get("m"), b = get("b"), k = get("k");
  if (m < 0 || b < 0 || k < 0) c.fail(key, "operator m, b, k must be >= 0 (negative values are not a passive operator)");
  return sim::mass_spring_damper_operator(name, dofs[0], m, b, k);
}

void read_operators(const toml::table& root, const Reader& c, sim::LoopSpec& loop) {
  each_table(root, "operator", c, [&](const toml::table& t, const std::string& key, int) {
    const std::string name = c.free_text(t, "name", key, key, 256);
    std::vector<int> dofs = t.contains("dofs") ? c.dofs_of(*t.get("dofs"), key + ".dofs") : std::vector<int>{};
    sim::OperatorBlock o = t.contains("tf") || t.contains("ss") ? read_operator_block(t, key, name, dofs, c)
                                                                : read_operator_msd(t, key, name, dofs, c);
    for (int j : o.ports)
      if (j < 0 || j >= c.N) c.fail(key + ".dofs", "DOF " + std::to_string(j) + " does not exist");
    loop.operators.push_back(std::move(o));
  });
}

// ---- [environment] / [coupling]: discrete N x N; an s-domain block is discretised by `method`

// Substitutes s = (z-1)/(T z) (backward Euler) or (2/T)(z-1)/(z+1) (Tustin) exactly in num and
// den: also right for s-improper environments (springs with dampers), whose discretisation is
// proper.
std::function<TransferFunction(const TransferFunction&)> s_to_z(C2dMethod cm, const Q& T) {
  const Polynomial<Q> sn = cm == C2dMethod::tustin ? Polynomial<Q>(std::vector<Q>{Q(-2), Q(2)}) : Polynomial<Q>(std::vector<Q>{Q(-1), Q(1)});
  const Polynomial<Q> sd = cm == C2dMethod::tustin ? Polynomial<Q>(std::vector<Q>{T, T}) : Polynomial<Q>(std::vector<Q>{Q(0), T});
  return [sn, sd, T](const TransferFunction& H) {
    const int d = std::max(H.num().degree(), H.den().degree());
    auto sub = [&](const Polynomial<Q>& p) {  // p(sn/sd) * sd^d
      Polynomial<Q> acc;
      for (int i = 0; i <= p.degree(); ++i) acc += p.coeff(i) * sn.pow(unsigned(i)) * sd.pow(unsigned(d - i));
      return acc;
    };
    return tf(sub(H.num()), sub(H.den()), T);
  };
}

StateSpace<Q> read_s_domain_block(const toml::table& t, const std::string& key, const Reader& c,
                                  const CompactMatrix* compact) {
  const std::string method = t["method"].value_or(std::string());
  if (method.empty()) c.fail(key + ".method", "an s-domain block needs method = \"backward_euler\" or \"tustin\"");
  C2dMethod cm = parse_c2d_method(method, c.file + ": " + key + ".method");
  if (cm == C2dMethod::zoh) c.fail(key + ".method", "zoh of a virtual environment is not rational; use backward_euler or tustin");
  if (!t.contains("tf") && !compact) return c2d<Q>(c.block(t, key, 's'), c.T, cm);
  StateSpace<Q> G = compact ? c.compact_block(*compact, 's', s_to_z(cm, c.T)) : c.block(t, key, 's', s_to_z(cm, c.T));
  G.T = c.T;
  return G;
}

// "[index]" replaced by "[value]" throughout text.
std::string place(std::string text, const char* index, int value) {
  const std::string from = std::string("[") + index + "]", to = "[" + std::to_string(value) + "]";
  for (size_t at = text.find(from); at != std::string::npos; at = text.find(from, at + to.size())) text.replace(at, 3, to);
  return text;
}

// diagonal / off_diagonal -> the N x N tf matrix they describe (docs/scene.md, "Repeated
// blocks"): entry (i, j) is the diagonal's text (i = j) or the off-diagonal's with [i] the row's
// number and [j] the column's (from 1). A list indexed by [i] or [j] must hold N values. Kept
// compact (reader.hpp): an entry is the values its [i] and [j] lists take, so rows i and k with
// the same values there give the same entries.
CompactMatrix compact_matrix(const toml::table& t, const std::string& key, const Reader& c) {
  if (t.contains("blocks") && !t.contains("diagonal")) c.fail(key + ".blocks", "only with diagonal (and off_diagonal)");
  if (t.contains("tf") || t.contains("ss")) c.fail(key + ".diagonal", "give either diagonal (and off_diagonal) or tf/ss, not both");
  const auto* d = t["diagonal"].as_string();
  if (!d) c.fail(key + ".diagonal", t.contains("diagonal") ? "expected a string expression" : "off_diagonal needs diagonal");
  const auto* o = t["off_diagonal"].as_string();
  if (t.contains("off_diagonal") && !o) c.fail(key + ".off_diagonal", "expected a string expression");
  const std::string diag = d->get(), off = o ? o->get() : std::string("0");
  for (const auto& [text, k] : {std::pair{diag, "diagonal"}, std::pair{off, "off_diagonal"}})
    for (const char* index : {"i", "j"})
      for (const auto& list : lists_indexed_by(text, index, c))
        if (long(c.lists.at(list).size()) != c.N)
          c.fail(key + "." + k, "'" + list + "[" + index + "]' indexes the list parameter " + list + " of " +
                                    std::to_string(c.lists.at(list).size()) + " values by a row or column, but the matrix is " +
                                    std::to_string(c.N) + " x " + std::to_string(c.N) + " (one value per DOF)");
  if (diag.find("[j]") != std::string::npos) c.fail(key + ".diagonal", "[j] (the column) is [i] on the diagonal: write [i]");
  int blocks = 1;  // blocks = K: K diagonal blocks of N/K DOFs, entries between them 0
  if (t.contains("blocks")) {
    const auto k = t["blocks"].value<int64_t>();
    if (!t["blocks"].is_integer() || !k || *k < 1 || *k > c.N || c.N % *k != 0)
      c.fail(key + ".blocks", "expected a whole number K >= 1 that divides the " + std::to_string(c.N) +
                                  " DOFs (K diagonal blocks of N/K DOFs each)");
    blocks = int(*k);
  }
  const int per_block = c.N / blocks;
  // the values a text's [index] lists take at k (1..N), numbered in order of first appearance
  const auto classes = [&](const std::string& text, const char* index) {
    const auto names = lists_indexed_by(text, index, c);
    std::map<std::vector<rational>, int> seen;
    std::vector<int> out;
    for (int k = 1; k <= c.N; ++k) {
      std::vector<rational> values;
      for (const auto& name : names) values.push_back(c.lists.at(name)[size_t(k - 1)]);
      out.push_back(seen.try_emplace(std::move(values), int(seen.size())).first->second);
    }
    return out;
  };
  const std::vector<int> diag_class = classes(diag, "i"), row_class = classes(off, "i"), col_class = classes(off, "j");
  CompactMatrix m;
  m.n = c.N;
  m.index.resize(size_t(c.N) * size_t(c.N));
  std::map<std::pair<int, int>, int> seen;  // (row class, column class) of an off-diagonal entry; (-1, class) on the diagonal
  for (int i = 1; i <= c.N; ++i)
    for (int j = 1; j <= c.N; ++j) {
      const bool apart = (i - 1) / per_block != (j - 1) / per_block;  // in two blocks: 0
      const std::pair<int, int> kind = apart    ? std::pair{-2, 0}
                                       : i == j ? std::pair{-1, diag_class[size_t(i - 1)]}
                                                : std::pair{row_class[size_t(i - 1)], col_class[size_t(j - 1)]};
      auto [it, fresh] = seen.try_emplace(kind, int(m.texts.size()));
      if (fresh) {
        m.texts.push_back(apart ? std::string("0") : i == j ? place(diag, "i", i) : place(place(off, "i", i), "j", j));
        m.keys.push_back(key + (i == j ? ".diagonal" : ".off_diagonal") + " (row " + std::to_string(i) + ", column " +
                         std::to_string(j) + ")");
      }
      m.index[size_t(i - 1) * size_t(c.N) + size_t(j - 1)] = it->second;
    }
  return m;
}

std::optional<StateSpace<Q>> read_discrete_block(const toml::table& root, const char* k, const Reader& c) {
  auto written = section(root, k, c);
  if (!written) return std::nullopt;
  const std::string key = k;
  std::optional<CompactMatrix> compact;
  if (written->contains("diagonal") || written->contains("off_diagonal") || written->contains("blocks")) compact = compact_matrix(*written, key, c);
  const toml::table* t = written;
  const std::string domain = (*t)["domain"].value_or(std::string("z"));
  if (domain != "z" && domain != "s") c.fail(key + ".domain", "expected \"z\" or \"s\"");
  StateSpace<Q> G;
  if (domain == "s") {
    G = read_s_domain_block(*t, key, c, compact ? &*compact : nullptr);
  } else {
    if (t->contains("method")) c.fail(key + ".method", "only for domain = \"s\"");
    G = compact ? c.compact_block(*compact, 'z') : c.block(*t, key, 'z');
  }
  if (t->contains("gain")) {  // g E: the outputs scaled, the realisation's states as they are
    const Q g = c.number(*t, "gain", key);
    G.C *= g;
    G.D *= g;
  }
  if (G.inputs() != c.N || G.outputs() != c.N)
    c.fail(key, "incompatible dimensions: must be " + std::to_string(c.N) + "x" + std::to_string(c.N) +
                    " (one row and column per DOF), got " + std::to_string(G.outputs()) + "x" +
                    std::to_string(G.inputs()));
  return G;
}

// ---- [contact]: the DOFs with the unilateral wall (default: all)
// [passivity_controller] dofs = [...]: Hannaford-Ryu's PO/PC at the actuator of those DOFs.
void read_passivity_controller(const toml::table& root, const Reader& c, sim::LoopSpec& loop) {
  auto t = section(root, "passivity_controller", c);
  if (!t) return;
  if (!loop.environment) c.fail("passivity_controller", "it acts on the wall's force: the scene needs an [environment]");
  if (!t->contains("dofs")) c.fail("passivity_controller.dofs", "missing (the DOFs whose actuator it controls)");
  loop.passivity_controller = c.dofs_of(*t->get("dofs"), "passivity_controller.dofs");
}

void read_contact(const toml::table& root, const Reader& c, sim::LoopSpec& loop) {
  auto t = section(root, "contact", c);
  if (!t) return;
  if (!loop.environment) c.fail("contact", "a wall needs an [environment] (the wall's E(z))");
  if (t->contains("dofs")) loop.contact = c.dofs_of(*t->get("dofs"), "contact.dofs");
  else
    for (int j = 0; j < c.N; ++j) loop.contact.push_back(j);
}

// A time in seconds that the simulator turns into a sample index (t / T): in [0, run_steps T]
// (limits.hpp), checked here so that the message names the key.
Q sample_time(const toml::table& t, const std::string& k, const std::string& key, const Reader& c) {
  const Q v = c.number(t, k, key);
  if (v < 0) c.fail(key + "." + k, "must be >= 0, got " + v.str());
  if (v > c.T * limits::run_steps)
    c.fail(key + "." + k, decimal_outward(v, 6, -1) + " s is " + decimal_outward(v / c.T, 3, -1) +
                              " sample periods, beyond the longest run of " + std::to_string(limits::run_steps));
  return v;
}

// ---- [delay]: time (seconds) or samples (periods)
void read_delay(const toml::table& root, const Reader& c, sim::LoopSpec& loop) {
  auto t = section(root, "delay", c);
  if (!t) return;
  if (t->contains("time") == t->contains("samples"))
    c.fail("delay", t->empty() ? "empty: give exactly one of time or samples (or leave [delay] out: no delay)"
                               : "give exactly one of time or samples");
  const std::string k = t->contains("time") ? "time" : "samples";
  const Q v = c.number(*t, k, std::string("delay"));
  loop.delay = k == "time" ? v : v * c.T;
  if (loop.delay < 0) c.fail("delay." + k, "must be >= 0, got " + v.str());
  if (loop.delay > c.T * limits::delay_samples)  // before anything converts t_d / T to an integer
    c.fail("delay." + k, decimal_outward(loop.delay / c.T, 6, -1) + " sample periods, more than the limit of " +
                             std::to_string(limits::delay_samples));
}

// ---- [[input]]: impulses, biases and force profiles
sim::Impulse read_impulse(const toml::table& t, const std::string& key, int dof, const Reader& c) {
  sim::Impulse im;
  im.dof = dof;
  im.time = t.contains("time") ? sample_time(t, "time", key, c) : Q(0);
  im.magnitude = c.number(t, "magnitude", key);
  return im;
}

sim::Bias read_bias(const toml::table& t, const std::string& key, int dof, const Reader& c) {
  sim::Bias b;
  b.dof = dof;
  b.force = c.number(t, "force", key);
  b.start = t.contains("start") ? sample_time(t, "start", key, c) : Q(0);
  return b;
}

// A profile file: one force per line, or t,force; '#' starts a comment line. The forces are
// sampled at the scene's T from t = 0: a line's t, when given, must be that line's instant kT
// (to half a period) -- a file sampled at another rate is refused, not replayed at T. Every force
// must be finite.
std::vector<double> read_profile_file(const toml::table& t, const std::string& key, const Reader& c) {
  const auto* f = t["file"].as_string();
  if (!f) c.fail(key + ".file", "expected a file name (a string)");
  // A scene reads only regular files in its own folder, at most 64 MB (docs/security.md).
  const auto path = report::input_file_inside(c.base_dir, f->get(), c.file + ": " + key + ".file", 64u << 20);
  std::ifstream in(path);
  if (!in) c.fail(key + ".file", "cannot read '" + report::text(f->get()) + "'");
  std::vector<double> samples;
  std::string line;
  long number = 0;
  while (std::getline(in, line)) {
    ++number;
    if (line.empty() || line[0] == '#') continue;
    const std::string where = key + ".file", at = "line " + std::to_string(number) + ": ";
    auto comma = line.find(',');
    std::string cell = comma == std::string::npos ? line : line.substr(comma + 1);  // t,f or f
    if (comma != std::string::npos) {
      const auto tk = try_parse_rational(line.substr(0, comma));
      if (!tk) c.fail(where, at + "t = '" + report::text(line.substr(0, std::min<size_t>(comma, 80))) + "' is not a number");
      const Q k = *tk / c.T - Q(static_cast<long>(samples.size()));  // t/T - (this line's sample)
      if (abs(k) >= Q(1, 2))
        c.fail(where, at + "t = " + decimal_outward(*tk, 8, -1) + " s is not this line's instant " +
                          to_decimal(Q(static_cast<long>(samples.size())) * c.T, 8) +
                          " s: the profile is one force per sample period T from t = 0");
    }
    double f = 0;
    try {
      size_t used = 0;
      f = std::stod(cell, &used);
      if (cell.find_first_not_of(" \t\r", used) != std::string::npos) throw std::invalid_argument(cell);
    } catch (...) {
      c.fail(where, at + "'" + report::text(line.substr(0, 80)) + "' is not a number (one force per line, or t,force)");
    }
    if (!std::isfinite(f)) c.fail(where, at + "the force " + report::text(cell.substr(0, 40)) + " is not finite");
    samples.push_back(f);
  }
  return samples;
}

sim::Profile read_profile(const toml::table& t, const std::string& key, int dof, const Reader& c) {
  sim::Profile p;
  p.dof = dof;
  if (t.contains("values") == t.contains("file")) c.fail(key, "give exactly one of values = [...] or file = \"...\"");
  if (auto a = t["values"].as_array()) {
    for (size_t i = 0; i < a->size(); ++i) p.samples.push_back(c.real((*a)[i], key + ".values[" + std::to_string(i) + "]"));
  } else {
    p.samples = read_profile_file(t, key, c);
  }
  return p;
}

void read_inputs(const toml::table& root, const Reader& c, sim::LoopSpec& loop) {
  each_table(root, "input", c, [&](const toml::table& t, const std::string& key, int) {
    const std::string type = t["type"].value_or(std::string());
    const int dof = t.contains("dof") ? c.dof_of(*t.get("dof"), key + ".dof") : 0;
    if (type == "impulse") loop.impulses.push_back(read_impulse(t, key, dof, c));
    else if (type == "bias") loop.biases.push_back(read_bias(t, key, dof, c));
    else if (type == "profile") loop.profiles.push_back(read_profile(t, key, dof, c));
    else c.fail(key + ".type", "expected \"impulse\", \"bias\" or \"profile\", got '" + type + "'");
  });
}

// ---- [initial]: positions x and velocities v, one per DOF
void read_initial(const toml::table& root, const Reader& c, sim::LoopSpec& loop) {
  auto t = section(root, "initial", c);
  if (!t) return;
  for (const char* k : {"x", "v"}) {
    if (!t->contains(k)) continue;
    auto a = (*t)[k].as_array();
    if (!a || int(a->size()) != c.N) c.fail(std::string("initial.") + k, "expected one value per DOF (" + std::to_string(c.N) + ")");
    auto& dst = std::string(k) == "x" ? loop.x0 : loop.v0;
    for (size_t i = 0; i < a->size(); ++i) dst.push_back(c.number((*a)[i], std::string("initial.") + k));
  }
}

// ---- [simulate]
// The run length: steps, or duration / T rounded up (at most 4e12 steps).
long simulate_steps(const toml::table& t, const Reader& c) {
  if (t.contains("duration") == t.contains("steps")) c.fail("simulate", "give exactly one of duration or steps");
  if (t.contains("steps")) {
    auto n = t["steps"].as_integer();
    if (!n) c.fail("simulate.steps", "expected an integer");
    if (n->get() <= 0) c.fail("simulate.steps", "the step count must be > 0, got " + std::to_string(n->get()));
    if (n->get() > limits::run_steps) c.fail("simulate.steps", "more than " + std::to_string(limits::run_steps) + " steps");
    return long(n->get());
  }
  const Q d = c.number(t, std::string("duration"), std::string("simulate"));
  if (d <= 0) c.fail("simulate.duration", "must be > 0, got " + d.str());
  const Q q = d / c.T;
  integer k = bmp::numerator(q) / bmp::denominator(q);
  if (Q(k) < q) k += 1;
  if (k > integer(limits::run_steps)) c.fail("simulate.duration", "more than " + std::to_string(limits::run_steps) + " steps");
  return k.convert_to<long>();
}

std::vector<std::string> simulate_plots(const toml::node& n, const Reader& c) {
  auto a = n.as_array();
  if (!a) c.fail("simulate.plots", "expected a list, e.g. [\"position\", \"velocity\", \"energy\"]");
  std::vector<std::string> plots;
  for (size_t i = 0; i < a->size(); ++i) {
    std::string p = (*a)[i].value_or(std::string());
    if (p != "position" && p != "velocity" && p != "force" && p != "energy" && p != "intersample")
      c.fail("simulate.plots", "unknown plot '" + p + "' (position, velocity, force, energy, intersample)");
    plots.push_back(p);
  }
  return plots;
}

SimulateSection read_simulate(const toml::table& t, const Reader& c) {
  SimulateSection S;
  S.present = true;
  S.steps = simulate_steps(t, c);
  if (auto n = t.get("record_every")) {
    auto i = n->as_integer();
    if (!i || i->get() < 0) c.fail("simulate.record_every", "expected an integer >= 0");
    S.record_every = long(i->get());
  }
  if (auto n = t.get("substeps")) {
    auto i = n->as_integer();
    if (!i || i->get() < 1 || i->get() > 10000) c.fail("simulate.substeps", "expected an integer in [1, 10000]");
    S.substeps = int(i->get());
  }
  if (auto n = t.get("window")) {
    auto a = n->as_array();
    if (!a || a->size() != 2) c.fail("simulate.window", "expected [from, to] in seconds");
    S.window_from = c.real((*a)[0], "simulate.window");  // finite (Reader::real)
    S.window_to = c.real((*a)[1], "simulate.window");
    if (S.window_from > S.window_to) {
      std::ostringstream os;
      os << "reversed: from = " << S.window_from << " s is after to = " << S.window_to << " s (expected [from, to])";
      c.fail("simulate.window", os.str());
    }
  } else if (S.substeps > 1) {
    S.window_from = 0;
    S.window_to = 1e300;
  }
  if (auto n = t.get("max_velocity")) {
    S.max_velocity = c.real(*n, "simulate.max_velocity");
    if (!(S.max_velocity > 0)) c.fail("simulate.max_velocity", "must be > 0");
  }
  if (auto n = t.get("watch_dof")) S.watch_dof = c.dof_of(*n, "simulate.watch_dof");
  if (auto n = t.get("energy")) S.energy = n->value_or(true);
  if (auto n = t.get("plots")) S.plots = simulate_plots(*n, c);
  return S;
}

}  // namespace

Scene parse_scene(const std::string& text, const std::string& file, const std::map<std::string, rational>& overrides,
                  const std::string& base_dir) {
  Scene sc;
  sc.file = file;
  Reader c;
  c.file = file;
  c.base_dir = base_dir;
  sc.root = parse_toml(text, file);
  const toml::table& root = sc.root;
  check_names(root, file);  // every section and key is one the schema declares (schema.hpp)
  read_scene_header(root, c, sc);
  read_parameters(root, overrides, c);
  sc.parameters = c.params;
  sc.lists = c.lists;
  read_devices(root, c, sc.loop);
  read_operators(root, c, sc.loop);
  sc.loop.environment = read_discrete_block(root, "environment", c);
  sc.loop.coupling = read_discrete_block(root, "coupling", c);
  if (sc.loop.coupling && !sc.loop.environment) c.fail("coupling", "a coupling needs an [environment]");
  read_contact(root, c, sc.loop);
  read_passivity_controller(root, c, sc.loop);
  read_delay(root, c, sc.loop);
  read_inputs(root, c, sc.loop);
  read_initial(root, c, sc.loop);
  if (auto t = section(root, "simulate", c)) sc.simulate = read_simulate(*t, c);
  check_schema(root, file);  // the values the readers above leave to other modules, or default
  return sc;
}

Scene load_scene(const std::string& path, const std::map<std::string, rational>& overrides) {
  // a regular file of bounded size (not a FIFO, /dev/zero or a folder: docs/security.md), as
  // reproduce reads its scenes
  const std::string text = report::read_input_file(path, "the scene file", kSceneBytes);
  auto dir = std::filesystem::path(path).parent_path();
  return parse_scene(text, path, overrides, dir.empty() ? "." : dir.string());
}

namespace {

// The reader of the scene's own values (its file, T, parameters and lists, its DOFs).
Reader reader_of(const Scene& sc) {
  Reader c;
  c.file = sc.file;
  c.T = sc.T;
  c.params = sc.parameters;
  c.lists = sc.lists;
  c.N = sc.loop.dofs();
  return c;
}

}  // namespace

std::optional<StateSpace<rational>> environment_ss_as_written(const Scene& sc) {
  const toml::table* env = sc.root["environment"].as_table();
  if (!env || !env->contains("ss") || env->contains("diagonal") || env->contains("off_diagonal") || env->contains("blocks"))
    return std::nullopt;
  const bool s_domain = (*env)["domain"].value_or(std::string("z")) == "s";
  return reader_of(sc).block(*env, "environment", s_domain ? 's' : 'z');
}

std::optional<std::vector<std::vector<std::string>>> environment_expressions(const Scene& sc) {
  const toml::table* env = sc.root["environment"].as_table();
  if (!env) return std::nullopt;
  Reader c = reader_of(sc);
  std::vector<std::vector<std::string>> E;
  if (env->contains("diagonal") || env->contains("off_diagonal") || env->contains("blocks")) {  // written out, [i] and [j] placed, lists by value
    const CompactMatrix m = compact_matrix(*env, "environment", c);
    for (int i = 0; i < m.n; ++i) {
      E.emplace_back();
      for (int j = 0; j < m.n; ++j) E.back().push_back(c.expand(m.texts[size_t(m.index[size_t(i * m.n + j)])], "environment"));
    }
    return E;
  }
  const toml::node* tf = env->get("tf");
  if (!tf) return std::nullopt;  // an `ss` environment
  if (const auto* one = tf->as_string()) return std::vector<std::vector<std::string>>{{c.expand(one->get(), "environment.tf")}};
  for (const auto& r : *tf->as_array()) {
    E.emplace_back();
    for (const auto& e : *r.as_array()) E.back().push_back(c.expand(*e.value<std::string>(), "environment.tf"));
  }
  return E;
}

}  // namespace hapstab::scene
