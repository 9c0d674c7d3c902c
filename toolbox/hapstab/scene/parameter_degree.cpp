// How a scene parameter enters the loop, proven from the scene's text (parameter_degree.hpp).
#include "hapstab/scene/parameter_degree.hpp"

#include <functional>
#include <vector>

#include "hapstab/lti/parse.hpp"
#include "hapstab/numeric/error.hpp"
#include "hapstab/scene/schema.hpp"

namespace hapstab::scene {

namespace {

struct Found {
  std::string key, text;
};

// Every string leaf of `n` that names `name`, with its key path ("environment.ss.D[0][1]").
void strings(const toml::node& n, const std::string& key, const std::string& name, std::vector<Found>& out) {
  if (auto s = n.as_string()) {
    if (names_in(s->get()).count(name)) out.push_back({key, s->get()});
  } else if (auto a = n.as_array()) {
    for (size_t i = 0; i < a->size(); ++i) strings((*a)[i], key + "[" + std::to_string(i) + "]", name, out);
  } else if (auto t = n.as_table()) {
    for (const auto& [k, v] : *t) strings(v, key + "." + std::string(k.str()), name, out);
  }
}

const Section* section_of(const std::string& path) {
  for (const Section& s : schema())
    if (s.path == path) return &s;
  return nullptr;
}

// The values of table `t` (schema section `sec`) that are expressions and name `name`: a key the
// schema types as a name or free text (text, dof, dofs) is not an expression; a key it does not
// know is taken as one (the scene was checked against the schema before).
void expressions(const toml::table& t, const Section* sec, const std::string& prefix, const std::string& name, std::vector<Found>& out) {
  for (const auto& [k, v] : t) {
    const std::string key = prefix + "." + std::string(k.str());
    const Key* spec = nullptr;
    if (sec)
      for (const Key& x : sec->keys)
        if (x.name == k.str()) spec = &x;
    if (spec && (spec->type == Type::text || spec->type == Type::text_list || spec->type == Type::dof || spec->type == Type::dofs)) continue;
    if (spec && spec->type == Type::table && v.as_table()) {
      expressions(*v.as_table(), section_of(spec->table), key, name, out);
      continue;
    }
    strings(v, key, name, out);
  }
}

void collect(const toml::table& root, const std::string& name, std::vector<Found>& out) {
  for (const auto& [k, v] : root) {
    const std::string key(k.str());
    const Section* sec = section_of(key);
    if (auto t = v.as_table()) {
      expressions(*t, sec, key, name, out);
    } else if (auto a = v.as_array()) {
      for (size_t i = 0; i < a->size(); ++i) {
        const std::string ki = key + "[" + std::to_string(i) + "]";
        if (auto e = (*a)[i].as_table()) expressions(*e, sec, ki, name, out);
        else strings((*a)[i], ki, name, out);
      }
    } else {
      strings(v, key, name, out);
    }
  }
}

/// Degree <= 1 in `name` with a denominator of degree 0 (the parse's bound): a + b name.
bool polynomial_of_degree_one(const std::string& text, const ParseOptions& po, const std::string& name) {
  ParseOptions q = po;
  q.parameters.erase(name);
  const auto [dn, dd] = ParsedExpression(text, q, {name}).degree_bound();
  return dn <= 1 && dd == 0;
}

struct BlockUse {
  bool gain = false, A = false, B = false, C = false, D = false;
};

}  // namespace

ParameterDegree parameter_degree(const Scene& sc, const std::string& name) {
  std::vector<Found> uses;
  collect(sc.root, name, uses);
  ParameterDegree out;
  out.name = name;
  ParseOptions po;
  po.T = sc.T;
  po.parameters = sc.parameters;
  BlockUse env, cpl;
  auto fail = [&](const std::string& key, const std::string& why) {
    throw InputError(name + " is not proven to enter the loop affinely: " + key + " " + why);
  };
  for (const Found& u : uses) {
    const std::string section = u.key.substr(0, u.key.find_first_of(".["));
    if (section == "input" || section == "simulate") continue;  // not the loop
    if (section == "parameters") {
      if (u.key == "parameters." + name) continue;
      fail(u.key, "is defined from " + name + " (write " + name + " into the block itself)");
    }
    if (section != "environment" && section != "coupling")
      fail(u.key, "names " + name + ": only [environment] and [coupling] may (the plant, the delay and T must not move)");
    const toml::table& block = *sc.root[section].as_table();
    const bool s_domain = block["domain"].value_or(std::string("z")) == "s";
    BlockUse& b = section == "environment" ? env : cpl;
    (section == "environment" ? out.environment : out.coupling) = true;
    out.where += (out.where.empty() ? "" : ", ") + u.key;
    po.variable = s_domain ? 's' : 'z';
    const std::string field = u.key.substr(section.size() + 1);
    if (field == "gain") {
      if (!polynomial_of_degree_one(u.text, po, name)) fail(u.key, "'" + u.text + "' is not a polynomial of degree <= 1 in " + name);
      b.gain = true;
    } else if (field.rfind("ss.", 0) == 0 && field.size() > 4) {
      const char m = field[3];
      if (!polynomial_of_degree_one(u.text, po, name)) fail(u.key, "'" + u.text + "' is not a polynomial of degree <= 1 in " + name);
      if (s_domain && m != 'D') fail(u.key, "moves the dynamics of an s-domain block (its discretisation is not affine in " + name + ")");
      (m == 'A' ? b.A : m == 'B' ? b.B : m == 'C' ? b.C : b.D) = true;
    } else if (field.rfind("tf", 0) == 0) {
      ParseOptions q = po;
      q.parameters.erase(name);
      AffineSplit sp;
      try {
        sp = split_affine(u.text, q, name);  // proven H0 + name H1, or InputError
      } catch (const InputError& e) {
        fail(u.key, "'" + u.text + "': " + e.what());
      }
      b.D = true;
      if (sp.H1.num().degree() > 0 || sp.H1.den().degree() > 0) {  // the one-DOF H is still proven affine
        b.C = true;
        out.tf_dynamics = u.key + " '" + u.text + "' moves the block's dynamics (H1 = " + sp.H1.to_string() +
                          " is not a constant): write " + name + " as the block's gain or in an ss's D";
      }
    } else {
      fail(u.key, "names " + name);
    }
  }
  for (const auto* b : {&env, &cpl}) {
    if (b->gain && (b->C || b->D))
      throw InputError(name + " is not proven to enter the loop affinely: a block's gain and its C or D both name " + name +
                       " (their product is of degree 2)");
    out.dynamics_move = out.dynamics_move || b->A || b->B;
    out.feedthrough_moves = out.feedthrough_moves || b->D || b->gain;
  }
  out.has_coupling = sc.loop.coupling.has_value();
  out.dofs = sc.loop.dofs();
  if (sc.loop.environment) out.environment_states = static_cast<long>(sc.loop.environment->states());
  return out;
}

long points_needed(const ParameterDegree& d) {
  if (!d.tf_dynamics.empty()) throw InputError(d.name + " is not proven to enter the loop's matrix affinely: " + d.tf_dynamics);
  if (!d.has_coupling) return 2;
  if (!d.feedthrough_moves) return 5;
  return 2 * d.dofs + 3;
}

long points_needed_one_dof(const ParameterDegree& d) { return d.dynamics_move ? d.environment_states + 3 : 2; }

}  // namespace hapstab::scene
