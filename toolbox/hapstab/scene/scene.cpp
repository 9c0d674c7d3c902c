// Scene files -> models (see scene.hpp; the schema is documented in examples/README.md).
#include "hapstab/scene/scene.hpp"

#include <Eigen/Eigenvalues>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <functional>
#include <fstream>
#include <set>
#include <sstream>

#include "hapstab/lti/discretize.hpp"
#include "hapstab/lti/parse.hpp"
#include "hapstab/lti/realization.hpp"
#include "hapstab/numeric/decimal.hpp"
#include "hapstab/numeric/error.hpp"
#include "hapstab/report/escape.hpp"
#include "hapstab/report/paths.hpp"

namespace hapstab::scene {

namespace {

using Q = rational;

struct Ctx {
  std::string file;
  std::string base_dir;
  Q T = 0;
  std::map<std::string, Q> params;
  std::map<std::string, std::pair<int, int>> device_dofs;  // name -> [first, count]
  int N = 0;

  [[noreturn]] void fail(const std::string& key, const std::string& what) const {
    throw InputError(file + ": " + key + ": " + what);
  }

  // Names and descriptions are free text (examples/README.md, "Names"): any Unicode, at most
  // `max` bytes, no control characters (a description may hold newlines) and well-formed UTF-8.
  // Everything they reach -- gnuplot, CSV, LaTeX, HTML, a terminal -- escapes them
  // (report/escape.hpp); they never name a file.
  std::string free_text(const toml::table& t, const char* k, const std::string& key, const std::string& fallback,
                        size_t max, bool newlines = false) const {
    const toml::node* n = t.get(k);
    if (!n) return fallback;
    const auto* v = n->as_string();
    if (!v) fail(key + "." + k, "expected a string");
    const std::string& text = v->get();
    if (text.size() > max) fail(key + "." + k, "longer than " + std::to_string(max) + " bytes");
    if (report::text(text, newlines) != text)
      fail(key + "." + k, "'" + report::text(text) + "' holds control characters or malformed UTF-8 (each shown "
                              "as U+FFFD); write plain text");
    return text;
  }

  // An exact number: integer, or string holding a decimal/fraction/expression of T and parameters.
  Q number(const toml::node& n, const std::string& key, bool allow_names = true) const {
    if (auto i = n.as_integer()) return Q(i->get());
    if (n.is_floating_point())
      fail(key, "write the value as a string (\"0.001\") so that it is exact; TOML floats are binary approximations");
    auto s = n.as_string();
    if (!s) fail(key, "expected a number (a string like \"1/1000\" or an integer)");
    const std::string text = s->get();
    if (auto q = try_parse_rational(text)) return *q;
    if (!allow_names) fail(key, "'" + text + "' is not a number");
    ParseOptions po;
    po.variable = 's';
    po.T = T;
    po.parameters = params;
    TransferFunction tf;
    try {
      tf = parse_tf(text, po);
    } catch (const InputError& e) {
      fail(key, e.what());
    }
    if (tf.num().degree() > 0 || tf.den().degree() > 0) fail(key, "'" + text + "' must be a constant");
    return tf.num().is_zero() ? Q(0) : Q(tf.num().coeff(0) / tf.den().coeff(0));
  }
  Q number(const toml::table& t, const std::string& k, const std::string& key) const {
    auto n = t.get(k);
    if (!n) fail(key + "." + k, "missing");
    return number(*n, key + "." + k);
  }
  double real(const toml::node& n, const std::string& key) const {
    if (auto f = n.as_floating_point()) return f->get();
    return to_real<double>(number(n, key));
  }

  void only_keys(const toml::table& t, const std::string& key, std::set<std::string> allowed) const {
    for (const auto& [k, v] : t) {
      (void)v;
      if (!allowed.count(std::string(k.str()))) {
        std::string list;
        for (const auto& a : allowed) list += (list.empty() ? "" : ", ") + a;
        fail(key + "." + std::string(k.str()), "unknown key (expected one of: " + list + ")");
      }
    }
  }

  Mat<Q> matrix(const toml::node& n, const std::string& key) const {
    auto a = n.as_array();
    if (!a) fail(key, "expected a matrix: an array of rows, e.g. [[\"0\", \"1\"], [\"-1\", \"0\"]]");
    const Eigen::Index r = Eigen::Index(a->size());
    if (r == 0) return Mat<Q>(0, 0);
    Eigen::Index c = -1;
    Mat<Q> M;
    for (Eigen::Index i = 0; i < r; ++i) {
      auto row = (*a)[size_t(i)].as_array();
      if (!row) fail(key, "row " + std::to_string(i) + " is not an array");
      if (c < 0) {
        c = Eigen::Index(row->size());
        M = Mat<Q>::Zero(r, c);
      }
      if (Eigen::Index(row->size()) != c) fail(key, "rows have different lengths");
      for (Eigen::Index j = 0; j < c; ++j)
        M(i, j) = number((*row)[size_t(j)], key + "[" + std::to_string(i) + "][" + std::to_string(j) + "]");
    }
    return M;
  }

  TransferFunction tf_of(const std::string& text, const std::string& key, char var) const {
    ParseOptions po;
    po.variable = var;
    po.T = T;
    po.parameters = params;
    try {
      return parse_tf(text, po);
    } catch (const InputError& e) {
      fail(key, std::string("'") + text + "': " + e.what());
    }
  }

  // A block given as tf (string or matrix of strings) or ss = {A,B,C,D}. `var`: 's' or 'z'
  // (0: infer, then the result's domain tells).
  StateSpace<Q> block(const toml::table& t, const std::string& key, char var,
                      const std::function<TransferFunction(const TransferFunction&)>& to_z = {}) const {
    const bool has_tf = t.contains("tf"), has_ss = t.contains("ss");
    if (has_tf == has_ss) fail(key, "give exactly one of tf = \"...\" or ss = { A = ..., B = ..., C = ..., D = ... }");
    if (has_ss) {
      auto s = t["ss"].as_table();
      if (!s) fail(key + ".ss", "expected a table { A = ..., B = ..., C = ..., D = ... }");
      only_keys(*s, key + ".ss", {"A", "B", "C", "D"});
      StateSpace<Q> G;
      for (const char* k : {"A", "B", "C", "D"})
        if (!s->contains(k)) fail(key + ".ss." + k, "missing");
      G.A = matrix(*s->get("A"), key + ".ss.A");
      G.B = matrix(*s->get("B"), key + ".ss.B");
      G.C = matrix(*s->get("C"), key + ".ss.C");
      G.D = matrix(*s->get("D"), key + ".ss.D");
      // empty A with inputs/outputs: shape it
      if (G.A.size() == 0) {
        G.A = Mat<Q>(0, 0);
        G.B = Mat<Q>(0, G.D.cols());
        G.C = Mat<Q>(G.D.rows(), 0);
      }
      G.T = var == 'z' ? T : Q(0);
      try {
        G.validate(key + ".ss");
      } catch (const InputError& e) {
        fail(key + ".ss", e.what());
      }
      return G;
    }
    const toml::node& n = *t.get("tf");
    try {
      if (auto s = n.as_string()) {
        auto tf = tf_of(s->get(), key + ".tf", var);
        if (to_z) tf = to_z(tf);
        if (!tf.is_proper()) fail(key + ".tf", "'" + s->get() + "' is improper (more zeros than poles); not realisable");
        return tf2ss(tf);
      }
      auto a = n.as_array();
      if (!a) fail(key + ".tf", "expected a string or a matrix of strings");
      TransferMatrix M;
      M.domain = (var == 's' && !to_z) ? Domain::s : Domain::z;
      M.T = (var == 's' && !to_z) ? Q(0) : T;
      for (size_t i = 0; i < a->size(); ++i) {
        auto row = (*a)[i].as_array();
        if (!row) fail(key + ".tf", "row " + std::to_string(i) + " is not an array");
        M.entries.emplace_back();
        for (size_t j = 0; j < row->size(); ++j) {
          auto s = (*row)[j].as_string();
          const std::string k2 = key + ".tf[" + std::to_string(i) + "][" + std::to_string(j) + "]";
          if (!s) fail(k2, "expected a string expression");
          auto tf = tf_of(s->get(), k2, var);
          if (to_z) tf = to_z(tf);
          if (!tf.is_proper()) fail(k2, "improper transfer function");
          M.entries.back().push_back(tf);
        }
        if (M.entries.back().size() != M.entries.front().size()) fail(key + ".tf", "rows have different lengths");
      }
      return tf2ss(M);
    } catch (const InputError& e) {
      const std::string w = e.what();
      if (w.rfind(file, 0) == 0) throw;
      fail(key + ".tf", w);
    }
  }

  // Stability of a continuous block claimed passive: no pole with Re s > 0 (numeric eigenvalues,
  // tolerance 1e-9 relative to the pole's size; poles on the axis -- springs, integrators -- pass).
  void check_passive_claim(const StateSpace<Q>& G, const std::string& key) const {
    if (G.states() == 0) {
      // static: passive iff D + D^T >= 0 (checked on the eigenvalues of the symmetric part)
      Mat<double> D(G.D.rows(), G.D.cols());
      for (Eigen::Index i = 0; i < D.size(); ++i) D.data()[i] = to_real<double>(G.D.data()[i]);
      if (D.rows() == D.cols() && D.rows() > 0) {
        Eigen::SelfAdjointEigenSolver<Mat<double>> es(D + D.transpose());
        if (es.eigenvalues().minCoeff() < -1e-12 * (1 + D.norm()))
          fail(key, "claimed passive but D + D^T is not positive semidefinite");
      }
      return;
    }
    Mat<double> A(G.A.rows(), G.A.cols());
    for (Eigen::Index i = 0; i < A.size(); ++i) A.data()[i] = to_real<double>(G.A.data()[i]);
    Eigen::EigenSolver<Mat<double>> es(A, false);
    for (Eigen::Index i = 0; i < es.eigenvalues().size(); ++i) {
      auto l = es.eigenvalues()(i);
      if (l.real() > 1e-9 * (1 + std::abs(l))) {
        std::ostringstream os;
        os << "unstable continuous block claimed passive (pole at s = " << l.real()
           << (l.imag() >= 0 ? " + " : " - ") << std::abs(l.imag()) << "j); a passive impedance has no pole with Re s > 0";
        fail(key, os.str());
      }
    }
  }

  int dof_of(const toml::node& n, const std::string& key) const {
    if (auto i = n.as_integer()) {
      if (i->get() < 0 || i->get() >= N)
        fail(key, "DOF " + std::to_string(i->get()) + " does not exist (the devices give " + std::to_string(N) +
                      " DOF(s), numbered from 0)");
      return int(i->get());
    }
    if (auto s = n.as_string()) {
      auto it = device_dofs.find(s->get());
      if (it == device_dofs.end()) fail(key, "names the block '" + s->get() + "', which the scene does not define");
      if (it->second.second != 1)
        fail(key, "device '" + s->get() + "' has " + std::to_string(it->second.second) + " DOFs; give DOF numbers");
      return it->second.first;
    }
    fail(key, "expected a DOF number or a device name");
  }
  std::vector<int> dofs_of(const toml::node& n, const std::string& key) const {
    std::vector<int> out;
    if (auto a = n.as_array()) {
      for (size_t i = 0; i < a->size(); ++i) {
        const auto& e = (*a)[i];
        if (auto s = e.as_string()) {
          auto it = device_dofs.find(s->get());
          if (it == device_dofs.end())
            fail(key, "names the block '" + s->get() + "', which the scene does not define");
          for (int j = 0; j < it->second.second; ++j) out.push_back(it->second.first + j);
        } else {
          out.push_back(dof_of(e, key + "[" + std::to_string(i) + "]"));
        }
      }
      return out;
    }
    if (auto s = n.as_string()) {
      auto it = device_dofs.find(s->get());
      if (it == device_dofs.end()) fail(key, "names the block '" + s->get() + "', which the scene does not define");
      for (int j = 0; j < it->second.second; ++j) out.push_back(it->second.first + j);
      return out;
    }
    return {dof_of(n, key)};
  }
};

const toml::table* section(const toml::table& root, const char* k, const Ctx& c) {
  auto n = root.get(k);
  if (!n) return nullptr;
  auto t = n->as_table();
  if (!t) c.fail(k, "expected a table [" + std::string(k) + "]");
  return t;
}

template <class F>
void each_table(const toml::table& root, const char* k, const Ctx& c, F f) {
  auto n = root.get(k);
  if (!n) return;
  if (auto t = n->as_table()) {
    f(*t, std::string(k) + "[0]", 0);
    return;
  }
  auto a = n->as_array();
  if (!a) c.fail(k, "expected [[" + std::string(k) + "]] tables");
  for (size_t i = 0; i < a->size(); ++i) {
    auto t = (*a)[i].as_table();
    if (!t) c.fail(std::string(k) + "[" + std::to_string(i) + "]", "expected a table");
    f(*t, std::string(k) + "[" + std::to_string(i) + "]", int(i));
  }
}

}  // namespace

Scene parse_scene(const std::string& text, const std::string& file, const std::map<std::string, rational>& overrides,
                  const std::string& base_dir) {
  Scene sc;
  sc.file = file;
  Ctx c;
  c.file = file;
  c.base_dir = base_dir;
  try {
    sc.root = toml::parse(text, file);
  } catch (const toml::parse_error& e) {
    std::ostringstream os;
    os << file << ":" << e.source().begin.line << ":" << e.source().begin.column << ": " << e.description();
    throw InputError(os.str());
  }
  const toml::table& root = sc.root;
  // ---- [scene]
  auto s = section(root, "scene", c);
  if (!s) c.fail("scene", "missing: every scene starts with [scene] and its sample period T = \"1/1000\"");
  c.only_keys(*s, "scene", {"name", "description", "T"});
  sc.name = c.free_text(*s, "name", "scene", "", 256);
  sc.description = c.free_text(*s, "description", "scene", "", 8192, true);
  if (!s->contains("T")) c.fail("scene.T", "missing: the sample period, e.g. T = \"1/1000\"");
  c.T = c.number(*s->get("T"), "scene.T", false);
  if (c.T <= 0) c.fail("scene.T", "the sample period must be > 0, got " + c.T.str());
  sc.T = c.T;
  sc.loop.T = c.T;
  // ---- [parameters]: literals or constant expressions of T and other parameters (any order)
  if (auto p = section(root, "parameters", c)) {
    std::map<std::string, const toml::node*> todo;
    for (const auto& [k, v] : *p) {
      const std::string name(k.str());  // parameters are read in expressions: identifiers only
      bool ok = !name.empty() && name.size() <= 64 && (std::isalpha(static_cast<unsigned char>(name[0])) || name[0] == '_');
      for (char ch : name) ok = ok && (std::isalnum(static_cast<unsigned char>(ch)) || ch == '_');
      if (!ok)
        c.fail("parameters", "'" + report::text(name) + "' is not a parameter name (letters, digits and _, " +
                                 "starting with a letter or _, at most 64)");
      todo[name] = &v;
    }
    for (const auto& [k, v] : overrides) {
      if (!todo.count(k)) c.fail("parameters." + k, "--set names a parameter the scene does not define");
      todo.erase(k);
      c.params[k] = v;
    }
    while (!todo.empty()) {
      bool progress = false;
      std::string last_err;
      for (auto it = todo.begin(); it != todo.end();) {
        try {
          c.params[it->first] = c.number(*it->second, "parameters." + it->first);
          it = todo.erase(it);
          progress = true;
        } catch (const InputError& e) {
          last_err = e.what();
          ++it;
        }
      }
      if (!progress) throw InputError(last_err);
    }
  } else if (!overrides.empty()) {
    c.fail("parameters", "--set given but the scene has no [parameters]");
  }
  sc.parameters = c.params;
  // ---- devices
  each_table(root, "device", c, [&](const toml::table& t, const std::string& key, int) {
    c.only_keys(t, key, {"name", "m", "b", "tf", "ss", "passive"});
    const std::string name = c.free_text(t, "name", key, key, 256);
    sim::DeviceBlock d;
    if (t.contains("m") || t.contains("b")) {
      if (t.contains("tf") || t.contains("ss")) c.fail(key, "give either m, b (a mass-damper) or tf/ss, not both");
      if (!t.contains("m")) c.fail(key + ".m", "missing (the device mass)");
      const Q m = c.number(t, "m", key), b = t.contains("b") ? c.number(t, "b", key) : Q(0);
      if (m <= 0) c.fail(key + ".m", "must be > 0, got " + m.str());
      if (b < 0) c.fail(key + ".b", "must be >= 0, got " + b.str());
      d = sim::mass_damper(name, m, b);
    } else {
      d.name = name;
      d.G = c.block(t, key, 's');
      if (d.G.is_discrete()) c.fail(key + ".tf", "a device is continuous: write it in s");
      if (d.G.inputs() != d.G.outputs()) c.fail(key, "a device maps forces to velocities: it must be square");
      if (!d.G.D.isZero()) c.fail(key, "a device must be strictly proper (force -> velocity has no feedthrough)");
      if (t["passive"].value_or(true)) c.check_passive_claim(d.G, key);
    }
    if (c.device_dofs.count(name)) c.fail(key + ".name", "'" + name + "' is defined twice");
    c.device_dofs[name] = {c.N, int(d.dofs())};
    c.N += int(d.dofs());
    sc.loop.devices.push_back(std::move(d));
  });
  if (sc.loop.devices.empty()) c.fail("device", "missing: the scene needs at least one [[device]]");
  // ---- operators
  each_table(root, "operator", c, [&](const toml::table& t, const std::string& key, int) {
    c.only_keys(t, key, {"name", "dofs", "m", "b", "k", "tf", "ss", "mass", "passive"});
    const std::string name = c.free_text(t, "name", key, key, 256);
    std::vector<int> dofs = t.contains("dofs") ? c.dofs_of(*t.get("dofs"), key + ".dofs") : std::vector<int>{};
    sim::OperatorBlock o;
    if (t.contains("tf") || t.contains("ss")) {
      if (t.contains("m") || t.contains("b") || t.contains("k")) c.fail(key, "give either m, b, k or tf/ss, not both");
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
    } else {
      if (dofs.empty()) dofs = {0};
      if (dofs.size() != 1) c.fail(key + ".dofs", "a mass-spring-damper operator acts on one DOF");
      auto get = [&](const char* k) { return t.contains(k) ? c.number(t, k, key) : Q(0); };
      const Q m = get("m"), b = get("b"), k = get("k");
      if (m < 0 || b < 0 || k < 0)
        c.fail(key, "operator m, b, k must be >= 0 (negative values are not a passive operator)");
      o = sim::mass_spring_damper_operator(name, dofs[0], m, b, k);
    }
    for (int j : o.ports)
      if (j < 0 || j >= c.N) c.fail(key + ".dofs", "DOF " + std::to_string(j) + " does not exist");
    sc.loop.operators.push_back(std::move(o));
  });
  // ---- environment / coupling (discrete N x N; an s-domain tf is discretised by `method`)
  auto discrete_block = [&](const char* k) -> std::optional<StateSpace<Q>> {
    auto t = section(root, k, c);
    if (!t) return std::nullopt;
    const std::string key = k;
    c.only_keys(*t, key, {"tf", "ss", "method", "domain"});
    const std::string domain = (*t)["domain"].value_or(std::string("z"));
    if (domain != "z" && domain != "s") c.fail(key + ".domain", "expected \"z\" or \"s\"");
    StateSpace<Q> G;
    if (domain == "s") {
      const std::string method = (*t)["method"].value_or(std::string());
      if (method.empty()) c.fail(key + ".method", "an s-domain block needs method = \"backward_euler\" or \"tustin\"");
      C2dMethod cm = parse_c2d_method(method, file + ": " + key + ".method");
      if (cm == C2dMethod::zoh)
        c.fail(key + ".method", "zoh of a virtual environment is not rational; use backward_euler or tustin");
      if (t->contains("tf")) {
        // Substitute s = (z-1)/(T z) or (2/T)(z-1)/(z+1) exactly in num and den: also right for
        // s-improper environments (springs with dampers), whose discretisation is proper.
        const Polynomial<Q> sn = cm == C2dMethod::tustin ? Polynomial<Q>(std::vector<Q>{Q(-2), Q(2)}) : Polynomial<Q>(std::vector<Q>{Q(-1), Q(1)});
        const Polynomial<Q> sd = cm == C2dMethod::tustin ? Polynomial<Q>(std::vector<Q>{c.T, c.T}) : Polynomial<Q>(std::vector<Q>{Q(0), c.T});
        auto to_z = [&](const TransferFunction& H) {
          const int d = std::max(H.num().degree(), H.den().degree());
          auto sub = [&](const Polynomial<Q>& p) {  // p(sn/sd) * sd^d
            Polynomial<Q> acc;
            for (int i = 0; i <= p.degree(); ++i) acc += p.coeff(i) * sn.pow(unsigned(i)) * sd.pow(unsigned(d - i));
            return acc;
          };
          return tf(sub(H.num()), sub(H.den()), c.T);
        };
        G = c.block(*t, key, 's', to_z);
        G.T = c.T;
      } else {
        G = c2d<Q>(c.block(*t, key, 's'), c.T, cm);
      }
    } else {
      if (t->contains("method")) c.fail(key + ".method", "only for domain = \"s\"");
      G = c.block(*t, key, 'z');
    }
    if (G.inputs() != c.N || G.outputs() != c.N)
      c.fail(key, "incompatible dimensions: must be " + std::to_string(c.N) + "x" + std::to_string(c.N) +
                      " (one row and column per DOF), got " + std::to_string(G.outputs()) + "x" +
                      std::to_string(G.inputs()));
    return G;
  };
  sc.loop.environment = discrete_block("environment");
  sc.loop.coupling = discrete_block("coupling");
  if (sc.loop.coupling && !sc.loop.environment) c.fail("coupling", "a coupling needs an [environment]");
  // ---- contact
  if (auto t = section(root, "contact", c)) {
    c.only_keys(*t, "contact", {"dofs"});
    if (!sc.loop.environment) c.fail("contact", "a wall needs an [environment] (the wall's E(z))");
    if (t->contains("dofs")) sc.loop.contact = c.dofs_of(*t->get("dofs"), "contact.dofs");
    else
      for (int j = 0; j < c.N; ++j) sc.loop.contact.push_back(j);
  }
  // ---- delay
  if (auto t = section(root, "delay", c)) {
    c.only_keys(*t, "delay", {"time", "samples"});
    if (t->contains("time") == t->contains("samples")) c.fail("delay", "give exactly one of time or samples");
    sc.loop.delay = t->contains("time") ? c.number(*t, std::string("time"), std::string("delay")) : c.number(*t, std::string("samples"), std::string("delay")) * c.T;
    if (sc.loop.delay < 0) c.fail("delay", "must be >= 0");
  }
  // ---- inputs
  each_table(root, "input", c, [&](const toml::table& t, const std::string& key, int) {
    const std::string type = t["type"].value_or(std::string());
    const int dof = t.contains("dof") ? c.dof_of(*t.get("dof"), key + ".dof") : 0;
    if (type == "impulse") {
      c.only_keys(t, key, {"type", "dof", "time", "magnitude"});
      sim::Impulse im;
      im.dof = dof;
      im.time = t.contains("time") ? c.number(t, "time", key) : Q(0);
      im.magnitude = c.number(t, "magnitude", key);
      if (im.time < 0) c.fail(key + ".time", "must be >= 0");
      sc.loop.impulses.push_back(im);
    } else if (type == "bias") {
      c.only_keys(t, key, {"type", "dof", "force", "start"});
      sim::Bias b;
      b.dof = dof;
      b.force = c.number(t, "force", key);
      b.start = t.contains("start") ? c.number(t, "start", key) : Q(0);
      sc.loop.biases.push_back(b);
    } else if (type == "profile") {
      c.only_keys(t, key, {"type", "dof", "values", "file"});
      sim::Profile p;
      p.dof = dof;
      if (t.contains("values") == t.contains("file")) c.fail(key, "give exactly one of values = [...] or file = \"...\"");
      if (auto a = t["values"].as_array()) {
        for (size_t i = 0; i < a->size(); ++i) p.samples.push_back(c.real((*a)[i], key + ".values"));
      } else {
        const auto* f = t["file"].as_string();
        if (!f) c.fail(key + ".file", "expected a file name (a string)");
        // A scene reads only regular files in its own folder, at most 64 MB (docs/security.md).
        const auto path = report::input_file_inside(c.base_dir, f->get(), c.file + ": " + key + ".file", 64u << 20);
        std::ifstream in(path);
        if (!in) c.fail(key + ".file", "cannot read '" + report::text(f->get()) + "'");
        std::string line;
        while (std::getline(in, line)) {
          if (line.empty() || line[0] == '#') continue;
          auto comma = line.find(',');
          std::string cell = comma == std::string::npos ? line : line.substr(comma + 1);  // t,f or f
          try {
            p.samples.push_back(std::stod(cell));
          } catch (...) {
            c.fail(key + ".file", "'" + report::text(line.substr(0, 80)) + "' is not a number (one force per line, or t,force)");
          }
        }
      }
      sc.loop.profiles.push_back(std::move(p));
    } else {
      c.fail(key + ".type", "expected \"impulse\", \"bias\" or \"profile\", got '" + type + "'");
    }
  });
  // ---- initial
  if (auto t = section(root, "initial", c)) {
    c.only_keys(*t, "initial", {"x", "v"});
    for (const char* k : {"x", "v"}) {
      if (!t->contains(k)) continue;
      auto a = (*t)[k].as_array();
      if (!a || int(a->size()) != c.N) c.fail(std::string("initial.") + k, "expected one value per DOF (" + std::to_string(c.N) + ")");
      auto& dst = std::string(k) == "x" ? sc.loop.x0 : sc.loop.v0;
      for (size_t i = 0; i < a->size(); ++i) dst.push_back(c.number((*a)[i], std::string("initial.") + k));
    }
  }
  // ---- [simulate]
  if (auto t = section(root, "simulate", c)) {
    auto& S = sc.simulate;
    S.present = true;
    c.only_keys(*t, "simulate", {"duration", "steps", "record_every", "substeps", "window", "max_velocity", "watch_dof",
                                 "energy", "plots"});
    if (t->contains("duration") == t->contains("steps")) c.fail("simulate", "give exactly one of duration or steps");
    if (t->contains("steps")) {
      auto n = (*t)["steps"].as_integer();
      if (!n) c.fail("simulate.steps", "expected an integer");
      if (n->get() <= 0) c.fail("simulate.steps", "the step count must be > 0, got " + std::to_string(n->get()));
      S.steps = long(n->get());
    } else {
      const Q d = c.number(*t, std::string("duration"), std::string("simulate"));
      if (d <= 0) c.fail("simulate.duration", "must be > 0, got " + d.str());
      const Q q = d / c.T;
      integer k = bmp::numerator(q) / bmp::denominator(q);
      if (Q(k) < q) k += 1;
      if (k > integer(4000000000000LL)) c.fail("simulate.duration", "more than 4e12 steps");
      S.steps = k.convert_to<long>();
    }
    if (auto n = t->get("record_every")) {
      auto i = n->as_integer();
      if (!i || i->get() < 0) c.fail("simulate.record_every", "expected an integer >= 0");
      S.record_every = long(i->get());
    }
    if (auto n = t->get("substeps")) {
      auto i = n->as_integer();
      if (!i || i->get() < 1 || i->get() > 10000) c.fail("simulate.substeps", "expected an integer in [1, 10000]");
      S.substeps = int(i->get());
    }
    if (auto n = t->get("window")) {
      auto a = n->as_array();
      if (!a || a->size() != 2) c.fail("simulate.window", "expected [from, to] in seconds");
      S.window_from = c.real((*a)[0], "simulate.window");
      S.window_to = c.real((*a)[1], "simulate.window");
    } else if (S.substeps > 1) {
      S.window_from = 0;
      S.window_to = 1e300;
    }
    if (auto n = t->get("max_velocity")) {
      S.max_velocity = c.real(*n, "simulate.max_velocity");
      if (!(S.max_velocity > 0)) c.fail("simulate.max_velocity", "must be > 0");
    }
    if (auto n = t->get("watch_dof")) S.watch_dof = c.dof_of(*n, "simulate.watch_dof");
    if (auto n = t->get("energy")) S.energy = n->value_or(true);
    if (auto n = t->get("plots")) {
      auto a = n->as_array();
      if (!a) c.fail("simulate.plots", "expected a list, e.g. [\"position\", \"velocity\", \"energy\"]");
      S.plots.clear();
      for (size_t i = 0; i < a->size(); ++i) {
        std::string p = (*a)[i].value_or(std::string());
        if (p != "position" && p != "velocity" && p != "force" && p != "energy" && p != "intersample")
          c.fail("simulate.plots", "unknown plot '" + p + "' (position, velocity, force, energy, intersample)");
        S.plots.push_back(p);
      }
    }
  }
  return sc;
}

Scene load_scene(const std::string& path, const std::map<std::string, rational>& overrides) {
  std::ifstream in(path);
  if (!in) throw InputError(path + ": cannot read the scene file");
  std::stringstream ss;
  ss << in.rdbuf();
  auto dir = std::filesystem::path(path).parent_path();
  return parse_scene(ss.str(), path, overrides, dir.empty() ? "." : dir.string());
}

}  // namespace hapstab::scene
