// The scene schema and the command x part declarations (see schema.hpp).
#include "hapstab/scene/schema.hpp"

#include <algorithm>
#include <sstream>
#include <stdexcept>

#include "hapstab/numeric/error.hpp"
#include "hapstab/report/escape.hpp"
#include "hapstab/scene/reader.hpp"
#include "hapstab/scene/scene.hpp"

namespace hapstab::scene {

namespace {

using T = Type;

Key k(std::string name, Type type, std::string unit, std::string doc) {
  return Key{std::move(name), type, std::move(unit), std::move(doc), "", ""};
}
Key for_input(std::string name, Type type, std::string unit, std::string doc, std::string only_for) {
  return Key{std::move(name), type, std::move(unit), std::move(doc), std::move(only_for), ""};
}
Key sub(std::string name, std::string table, std::string doc) {
  return Key{std::move(name), T::table, "", std::move(doc), "", std::move(table)};
}

std::vector<Key> expectations(std::vector<std::pair<std::string, std::string>> keys) {
  std::vector<Key> out;
  for (auto& [name, doc] : keys) out.push_back(k(name, T::expectation, "", doc));
  return out;
}

// What a block's tf/ss mean, shared by device, operator, environment and coupling.
const char* kSs = "a state-space realisation instead of tf: { A = [[..]], B = .., C = .., D = .. }";

Section scene_section() {
  return {"scene", true, false, true, false, "Required: what the scene is and its sample period.",
          {k("name", T::text, "", "title of plots and reports (free text, at most 256 bytes)"),
           k("description", T::text, "", "free text, may hold newlines (at most 8192 bytes)"),
           k("T", T::exact, "s", "sample period, > 0 (a number, not an expression)")}};
}

Section parameters_section() {
  return {"parameters", true, false, false, true,
          "Named exact values usable in every expression below; each may refer to T and to other parameters, "
          "in any order (`bstar = \"K*T/2 + B\"`). Names are identifiers (letters, digits and _, not starting "
          "with a digit, at most 64). `--set NAME=VALUE` overrides one exactly. A *list parameter* `kc = [\"500\", "
          "\"600\"]` holds one value per copy: `kc[2]` is its second value, `sum(kc)` their sum (see Repeated blocks).",
          {}};
}

Section device_section() {
  return {"device", true, true, true, false,
          "One table per haptic device (force -> velocity); the DOFs are numbered in device order from 0. Either "
          "a mass-damper 1/(m s + b) or a strictly proper block tf/ss.",
          {k("name", T::text, "", "the device's name; later sections use it as a DOF name"),
           k("count", T::integer, "", "this table stands for count identical copies, named name[1] .. name[count] (see Repeated blocks)"),
           k("m", T::exact, "kg", "mass of the mass-damper 1/(m s + b)"),
           k("b", T::exact, "N s/m", "damping of the mass-damper (default 0)"),
           k("tf", T::tf, "m/(N s)", "or a strictly proper force -> velocity block: \"1/(m*s + b)\" or a matrix of strings"),
           sub("ss", "ss", kSs),
           k("passive", T::boolean, "", "claims the block passive (default true): checked, no pole with Re s > 0"),
           k("quantum", T::exact, "m", "(mass-damper only) encoder resolution Delta > 0: the controller sees a quantised position"),
           k("quantizer", T::text, "", "(with quantum) \"floor\" (default): Delta floor(x/Delta); \"round\": Delta floor(x/Delta + 1/2)"),
           k("coulomb", T::exact, "N", "(mass-damper only) Coulomb friction f_c >= 0 with stiction (docs/friction.md)")}};
}

Section operator_section() {
  return {"operator", true, true, false, false,
          "Human operator impedance Z_O(s), velocity -> force; the force on the device is -Z_O v. Either m, b, k "
          "on one DOF or a proper block tf/ss (plus optional masses).",
          {k("name", T::text, "", "the operator's name"),
           k("count", T::integer, "", "this table stands for count copies, named name[1] .. name[count] (see Repeated blocks)"),
           k("dofs", T::dofs, "", "device names or DOF numbers it acts on (default: the first |Z_O| DOFs)"),
           k("m", T::exact, "kg", "Z_O = m s + b + k/s: mass moving with the device"),
           k("b", T::exact, "N s/m", "damper of Z_O = m s + b + k/s"),
           k("k", T::exact, "N/m", "spring of Z_O = m s + b + k/s"),
           k("tf", T::tf, "N s/m", "or a proper square impedance in s, |dofs| x |dofs|"),
           sub("ss", "ss", kSs),
           k("mass", T::exact_list, "kg", "with tf/ss: a mass per DOF moving with the device"),
           k("passive", T::boolean, "", "claims the block passive (default true): checked, no pole with Re s > 0")}};
}

// The keys of a discrete block: environment and coupling.
std::vector<Key> discrete_keys() {
  return {k("tf", T::tf, "", "a SISO string or an N x N matrix of strings, in z (or in s with domain = \"s\")"),
          sub("ss", "ss", kSs),
          k("diagonal", T::text, "", "instead of tf: entry (i, i) of the N x N matrix, one expression in which [i] is the row "
                                     "(see Repeated blocks)"),
          k("off_diagonal", T::text, "", "with diagonal: entry (i, j), i != j, [i] the row and [j] the column (default \"0\")"),
          k("blocks", T::integer, "", "with diagonal: the matrix is block diagonal, K blocks of N/K DOFs in order (one object "
                                      "each); entries between blocks are 0 (default 1)"),
          k("domain", T::text, "", "\"z\" (default) or \"s\": a continuous model discretised exactly"),
          k("method", T::text, "", "(domain = \"s\") \"backward_euler\" (s = (z-1)/(Tz)) or \"tustin\"; s-improper is fine"),
          k("gain", T::exact, "", "a scale g of the block (default 1): g times its outputs (C and D), its states unchanged; "
                                  "a parameter here is one `stability --max` can maximise")};
}

Section environment_section() {
  return {"environment", true, false, false, false,
          "The virtual environment E(z), displacement [m] -> force [N], N x N (paper 001's H(z)).", discrete_keys()};
}

Section coupling_section() {
  return {"coupling", true, false, false, false,
          "A coupling V(z), force [N] -> displacement [m], in parallel with the device (paper 000 (11)): "
          "x_e = xi(x) + V u, u = -E x_e; det(I + D_E D_V) = 0 is an error. Needs [environment].",
          discrete_keys()};
}

Section contact_section() {
  return {"contact", true, false, false, false,
          "The unilateral wall at x = 0, occupying x > 0 (paper 002's xi): the environment sees max(0, x_j(kT)).",
          {k("dofs", T::dofs, "", "the DOFs in contact (default: every DOF)")}};
}

Section passivity_controller_section() {
  return {"passivity_controller", true, false, false, false,
          "Hannaford-Ryu's passivity observer/controller at the actuator (docs/friction.md): E_obs -= T u_k v_k; "
          "while E_obs < 0 a damper alpha v_k with alpha = -E_obs/(T v_k^2). Needs [environment].",
          {k("dofs", T::dofs, "", "the DOFs whose actuator it controls (required)")}};
}

Section delay_section() {
  return {"delay", true, false, false, false,
          "Computation delay: u_k is applied from kT + t_d on. Give exactly one key (an empty [delay] is refused).",
          {k("time", T::exact, "s", "t_d >= 0 (integer and fractional parts of t_d/T both exact)"),
           k("samples", T::exact, "T", "t_d / T >= 0, e.g. \"3/2\" (at most 1e7)")}};
}

Section input_section() {
  return {"input", true, true, false, false,
          "Exogenous forces on the devices (beside the operator); the keys a table takes depend on its type.",
          {k("type", T::text, "", "\"impulse\", \"bias\" or \"profile\""),
           k("dof", T::dof, "", "the DOF it acts on (default 0)"),
           for_input("time", T::exact, "s", "state jump at the sample instant nearest time, in [0, 4e12 T] (default 0)", "impulse"),
           for_input("magnitude", T::exact, "N s", "the impulse", "impulse"),
           for_input("force", T::exact, "N", "constant force from the first sample >= start", "bias"),
           for_input("start", T::exact, "s", "when the bias starts, in [0, 4e12 T] (default 0)", "bias"),
           for_input("values", T::real_list, "N", "force at t = kT, held (floats allowed; finite)", "profile"),
           for_input("file", T::text, "", "or a file in the scene's folder, one finite force (or t,force with t = kT) per line", "profile")}};
}

Section initial_section() {
  return {"initial", true, false, false, false, "The initial state, one value per DOF (default 0).",
          {k("x", T::exact_list, "m", "positions"), k("v", T::exact_list, "m/s", "velocities")}};
}

Section simulate_section() {
  return {"simulate", true, false, false, false,
          "How `hapstab simulate` runs the scene (exactly one of duration and steps).",
          {k("duration", T::exact, "s", "run length > 0 (rounded up to whole periods)"),
           k("steps", T::integer, "", "or the number of periods > 0"),
           k("record_every", T::integer, "", "write every n-th sample (0: summary only; default 1)"),
           k("substeps", T::integer, "", "exact intersample output every T/substeps (fine.csv; 1..10000)"),
           k("window", T::real_list, "s", "[from, to], finite, from <= to: the intersample output only in this window"),
           k("max_velocity", T::real, "m/s", "|v| above this (finite, > 0) stops the run: diverged (default 1e4)"),
           k("watch_dof", T::dof, "", "whose sampled position the limit-cycle detector watches"),
           k("energy", T::boolean, "", "exact port energies and the passivity observer (default true)"),
           k("plots", T::text_list, "", "what plot.gp draws: position, velocity, force, energy, intersample")}};
}

Section multidof_section() {
  return {"multidof", true, false, false, false,
          "Paper 000's Theorems 5 and 6 (`hapstab multidof analyze|design`, multidof/scene_multidof.hpp).",
          {k("osp", T::exact_list, "N s/m", "device OSP levels, one per device (default: b of a 1-DOF mass-damper)"),
           k("perturb_C", T::matrix, "", "N x N: C_E := Pi C_E with D_E unchanged (Sec. VI's perturbed environment)"),
           k("qv_block_diagonal", T::boolean, "", "Remark 3: Q_V block diagonal (default false)"),
           sub("coupling", "multidof.coupling", "Theorem 6's coupling structure (R2)")}};
}

Section multidof_coupling_section() {
  return {"multidof.coupling", false, false, false, false, "Theorem 6's coupling structure (R2), [multidof.coupling].",
          {k("mbar", T::integer_list, "", "DOFs per coupling block (default: one block per device)"),
           k("nbar", T::integer_list, "", "states per block (default 1 each)")}};
}

Section reproduce_section() {
  return {"reproduce", true, false, false, false,
          "What `hapstab reproduce` checks when it runs the scene (toolbox/cli/scenes.hpp). Every command the "
          "scene runs needs its expectation table: [simulate] -> simulate; [multidof] -> analyze and design.",
          {k("paper", T::text, "", "the report section: \"000\", \"001\", \"002\" (default: the toolbox's)"),
           k("claim", T::text, "", "the claim the scene shows, one line"),
           sub("simulate", "reproduce.simulate", "expectations on `hapstab simulate --json`"),
           sub("analyze", "reproduce.analyze", "expectations on `hapstab multidof analyze --json`"),
           sub("design", "reproduce.design", "expectations on `hapstab multidof design --json`")}};
}

Section ss_section() {
  return {"ss", false, false, false, false, "A state-space block { A = .., B = .., C = .., D = .. }: all four required.",
          {k("A", T::matrix, "", "state matrix"), k("B", T::matrix, "", "input matrix"),
           k("C", T::matrix, "", "output matrix"), k("D", T::matrix, "", "feedthrough")}};
}

Section reproduce_simulate_section() {
  return {"reproduce.simulate", false, false, false, false,
          "`hapstab simulate --json` keys (summary.json). A value is true/false (the key must be a boolean), a "
          "string compared for equality, \"> x\", \">= x\", \"< x\", \"<= x\", \"== x\" on a number, or "
          "\"!= null\" / \"== null\" (limit_cycle).",
          expectations({{"diverged", "|v| passed max_velocity (boolean)"},
                        {"max_velocity", "largest |v| [m/s]"},
                        {"energy_generated", "max over t of -sum_j int f_h v dt [J]"},
                        {"limit_cycle", "{period, amplitude} or null"},
                        {"trend", "\"growing\", \"decaying\", \"steady\", \"rest\", ..."},
                        {"step_matrix_radius", "proven error of the ZOH matrices"},
                        {"steps_run", "periods simulated"},
                        {"min_port_energy", "least human-port energy [J]"},
                        {"port_energy", "port energy per DOF [J]"},
                        {"actuator_energy", "actuator energy per DOF [J]"},
                        {"passivity_observer", "passivity observer per DOF [J]"},
                        {"status", "\"numeric\""},
                        {"method", "how the run was computed"},
                        {"friction_events", "(with coulomb) stick/slip events"},
                        {"pc_dissipated", "(with [passivity_controller]) energy it dissipated [J]"},
                        {"pc_active_samples", "(with [passivity_controller]) samples it acted"},
                        {"quantum", "(with quantum) the encoder resolution"},
                        {"scene", "the scene file"},
                        {"T", "the sample period"},
                        {"seconds", "run time"}})};
}

Section reproduce_analyze_section() {
  return {"reproduce.analyze", false, false, false, false, "`hapstab multidof analyze --json` keys (values as for simulate).",
          expectations({{"feasible", "LMIs (16) feasible"},
                        {"stability_concluded", "Theorem 5 concludes stability (all premises checked)"},
                        {"loop_as_written", "the scene's own loop: {stable, coupling, why}"},
                        {"certified", "the verdict is proven"},
                        {"verdict", "feasible / infeasible / ..."},
                        {"certificate", "the certificate's description"},
                        {"gamma", "gamma_i of Gamma"},
                        {"x", "the g_i of X"},
                        {"q_v", "Q_V"},
                        {"delta_v_required", "Gamma^-1 Q_V Gamma^-1"},
                        {"margin", "the LMIs' margin"},
                        {"facial_reduction", "what facial reduction did"},
                        {"solver", "the SDP solver's report"},
                        {"assumptions", "Assumption 1's checks"},
                        {"least_dissipative", "the least dissipative point"},
                        {"seconds", "run times"}})};
}

Section reproduce_design_section() {
  return {"reproduce.design", false, false, false, false, "`hapstab multidof design --json` keys (values as for simulate).",
          expectations({{"feasible", "a stabilising V found and verified"},
                        {"certified", "the design's verdict is proven"},
                        {"converged", "CCL converged"},
                        {"iterations", "CCL iterations"},
                        {"trace_gap", "CCL's trace gap"},
                        {"convex_infeasible", "the convex relaxation is infeasible"},
                        {"convex_certified", "... and that is proven"},
                        {"A_V", "the coupling V"},
                        {"B_V", "the coupling V"},
                        {"C_V", "the coupling V"},
                        {"D_V", "the coupling V"},
                        {"gamma", "gamma_i of Gamma"},
                        {"q_v", "Q_V"},
                        {"verification", "the independent checks of V"},
                        {"message", "the design's evidence"},
                        {"assumptions", "Assumption 1's checks"}})};
}

// The whole schema, one function per section above (the order is the order docs/scene.md lists them).
std::vector<Section> make_schema() {
  return {scene_section(),        parameters_section(),         device_section(),
          operator_section(),     environment_section(),        coupling_section(),
          contact_section(),      passivity_controller_section(), delay_section(),
          input_section(),        initial_section(),            simulate_section(),
          multidof_section(),     multidof_coupling_section(),  reproduce_section(),
          ss_section(),           reproduce_simulate_section(), reproduce_analyze_section(),
          reproduce_design_section()};
}

const Section* find_section(const std::string& path) {
  for (const auto& s : schema())
    if (s.path == path) return &s;
  return nullptr;
}

const Key* find_key(const Section& s, const std::string& name) {
  for (const auto& key : s.keys)
    if (key.name == name) return &key;
  return nullptr;
}

// "FILE:LINE: " (LINE when toml++ knows the node's source).
std::string where(const std::string& file, const toml::node& n) {
  const auto line = n.source().begin.line;
  return line > 0 ? file + ":" + std::to_string(line) + ": " : file + ": ";
}

// The nearest of `names` to `name` when it is close enough (edit distance at most 2, or half
// the name's length), else ""; of two as near, the one sharing the longer prefix (coupl ->
// coupling, not osp).
std::string nearest(const std::string& name, const std::vector<std::string>& names) {
  const auto prefix = [&](const std::string& n) {
    size_t i = 0;
    while (i < n.size() && i < name.size() && n[i] == name[i]) ++i;
    return i;
  };
  std::string best;
  size_t d = std::string::npos;
  for (const auto& n : names) {
    const size_t e = edit_distance(name, n);
    if (e < d || (e == d && prefix(n) > prefix(best))) d = e, best = n;
  }
  return !best.empty() && d <= std::max<size_t>(2, (name.size() + 1) / 2) ? best : "";
}

// "; did you mean PREFIX.X?" (in brackets for a section), or the list of valid names.
std::string suggestion(const std::string& name, const std::vector<std::string>& names, const std::string& prefix,
                       bool section) {
  const std::string best = nearest(name, names);
  if (!best.empty()) return "; did you mean " + std::string(section ? "[" : "") + prefix + best + (section ? "]" : "") + "?";
  std::string list;
  for (const auto& n : names) list += (list.empty() ? "" : ", ") + n;
  return " (expected one of: " + list + ")";
}

std::string described(Type t) {
  switch (t) {
    case T::text: return "a string";
    case T::exact: return "an exact number (a string like \"1/1000\" or an integer)";
    case T::integer: return "an integer";
    case T::boolean: return "true or false";
    case T::real: return "a number";
    case T::exact_list: return "a list of exact numbers ([\"1/10\", \"2\"])";
    case T::real_list: return "a list of numbers";
    case T::text_list: return "a list of strings";
    case T::integer_list: return "a list of integers";
    case T::matrix: return "a matrix: a list of rows of exact numbers";
    case T::tf: return "a transfer function: a string or a matrix of strings";
    case T::dof: return "a DOF number or a device name";
    case T::dofs: return "a DOF number, a device name or a list of them";
    case T::table: return "a table";
    case T::expectation: return "true/false, a string or a number";
  }
  return "?";
}

std::string kind_of(const toml::node& n) {
  if (n.is_string()) return "a string";
  if (n.is_integer()) return "an integer";
  if (n.is_floating_point()) return "a float";
  if (n.is_boolean()) return "a boolean";
  if (n.is_array()) return "a list";
  if (n.is_table()) return "a table";
  return "a date or time";
}

bool all_of(const toml::node& n, bool (*each)(const toml::node&)) {
  const auto* a = n.as_array();
  if (!a) return false;
  for (const auto& e : *a)
    if (!each(e)) return false;
  return true;
}

bool is_exact(const toml::node& n) { return n.is_string() || n.is_integer(); }
bool is_real(const toml::node& n) { return n.is_string() || n.is_integer() || n.is_floating_point(); }
bool is_text(const toml::node& n) { return n.is_string(); }
bool is_int(const toml::node& n) { return n.is_integer(); }
bool is_exact_row(const toml::node& n) { return all_of(n, is_exact); }
bool is_text_row(const toml::node& n) { return all_of(n, is_text); }

bool has_type(const toml::node& n, Type t) {
  switch (t) {
    case T::text: return n.is_string();
    case T::exact: return is_exact(n);
    case T::integer: return n.is_integer();
    case T::boolean: return n.is_boolean();
    case T::real: return is_real(n);
    case T::exact_list: return all_of(n, is_exact);
    case T::real_list: return all_of(n, is_real);
    case T::text_list: return all_of(n, is_text);
    case T::integer_list: return all_of(n, is_int);
    case T::matrix: return all_of(n, is_exact_row);
    case T::tf: return n.is_string() || all_of(n, is_text_row);
    case T::dof: return is_exact(n);
    case T::dofs: return is_exact(n) || all_of(n, is_exact);
    case T::table: return n.is_table();
    case T::expectation: return n.is_boolean() || is_real(n);
  }
  return false;
}

struct Checker {
  const std::string& file;
  bool types;  ///< also the values' TOML forms (else only the names)

  [[noreturn]] void fail(const toml::node& n, const std::string& what) const { throw InputError(where(file, n) + what); }

  // One table of section s, named `key` in messages ("device[0]", "multidof.coupling").
  void table(const toml::table& t, const Section& s, const std::string& key) const {
    const std::string variant = s.path == "input" ? t["type"].value_or(std::string()) : std::string();
    for (const auto& [name_, v] : t) {
      const std::string name(name_.str());
      const std::string path = key + "." + name;
      if (s.open) {
        const auto* rep = v.as_table();  // { repeat = [values], times = n }: its keys and values checked where it is read
        const bool repeated = rep && rep->get("repeat") && all_of(*rep->get("repeat"), is_exact);
        if (types && !is_exact(v) && !all_of(v, is_exact) && !repeated)
          fail(v, path + ": expected " + described(T::exact) + ", a list of them or { repeat = [list], times = n }, got " +
                      kind_of(v));
        continue;
      }
      const Key* kd = find_key(s, name);
      if (!kd) {
        std::vector<std::string> names;
        for (const auto& x : s.keys) names.push_back(x.name);
        const auto* sub = v.as_table();
        if (sub && !sub->is_inline())
          fail(v, "unknown section [" + report::text(path) + "]" + suggestion(name, names, key + ".", true));
        fail(v, "unknown key " + report::text(path) + suggestion(name, names, key + ".", false));
      }
      if (!kd->only_for.empty() && !variant.empty()) {
        bool known = false, takes = false;
        for (const auto& x : s.keys) known = known || x.only_for == variant;
        takes = kd->only_for == variant;
        if (known && !takes) {
          std::vector<std::string> names;
          for (const auto& x : s.keys)
            if (x.only_for.empty() || x.only_for == variant) names.push_back(x.name);
          fail(v, "unknown key " + path + " for type = \"" + report::text(variant) + "\"" +
                      suggestion(name, names, key + ".", false));
        }
      }
      if (types && !has_type(v, kd->type)) fail(v, path + ": expected " + described(kd->type) + ", got " + kind_of(v));
      if (kd->type == T::table && v.is_table()) table(*v.as_table(), *find_section(kd->table), path);
    }
  }

  void root(const toml::table& r) const {
    std::vector<std::string> tops;
    for (const auto& s : schema())
      if (s.top) tops.push_back(s.path);
    for (const auto& [name_, v] : r) {
      const std::string name(name_.str());
      const Section* s = find_section(name);
      if (!s || !s->top) {
        if (!v.is_table() && !v.is_array_of_tables()) {
          std::string owners;
          for (const auto& x : schema())
            if (x.top && find_key(x, name)) owners += (owners.empty() ? "[" : ", [") + x.path + "]";
          fail(v, "unknown top-level key " + report::text(name) + "; keys belong in a section" +
                      (owners.empty() ? "" : " (" + report::text(name) + " is a key of " + owners + ")"));
        }
        const bool arr = v.is_array();
        std::string msg = "unknown section " + std::string(arr ? "[[" : "[") + report::text(name) + (arr ? "]]" : "]");
        const std::string best = nearest(name, tops);
        if (!best.empty()) {
          const bool barr = find_section(best)->array;
          msg += "; did you mean " + std::string(barr ? "[[" : "[") + best + (barr ? "]]" : "]") + "?";
        } else {
          msg += suggestion(name, tops, "", false);
        }
        fail(v, msg);
      }
      if (const auto* t = v.as_table()) {
        table(*t, *s, s->array ? name + "[0]" : name);
        continue;
      }
      const auto* a = v.as_array();
      if (!s->array || !a) {
        if (!types) continue;  // the section's reader says what it expected
        fail(v, name + ": expected a table [" + name + "]");
      }
      for (size_t i = 0; i < a->size(); ++i) {
        const auto* t = (*a)[i].as_table();
        if (!t && !types) continue;
        if (!t) fail((*a)[i], name + "[" + std::to_string(i) + "]: expected a table");
        table(*t, *s, name + "[" + std::to_string(i) + "]");
      }
    }
  }
};

// ---- which command models which part of a scene

const std::string kSim = "simulate", kAnalyze = "multidof analyze", kDesign = "multidof design", kStab = "stability";

std::vector<Part> make_uses() {
  using U = Use;
  const auto all = [](std::string name, std::string what, std::string section) {
    return Part{std::move(name), std::move(what), std::move(section), {},
                {{kSim, U::models, ""}, {kAnalyze, U::models, ""}, {kDesign, U::models, ""}, {kStab, U::models, ""}}};
  };
  // Parts only the simulator models: why Theorems 5 and 6 do not, and why the Schur test of the
  // linear loop (`stability --scene`) does not.
  const auto sim_only = [](std::string name, std::string what, std::string section, std::vector<std::string> keys,
                           std::string why, std::string why_stab) {
    return Part{std::move(name), std::move(what), std::move(section), std::move(keys),
                {{kSim, U::models, ""}, {kAnalyze, U::refuses, why}, {kDesign, U::refuses, why}, {kStab, U::refuses, why_stab}}};
  };
  const std::string nonlinear = "Theorems 5 and 6 are about the linear loop";
  const std::string schur = "the Schur test decides the linear loop";
  std::vector<Part> p;
  p.push_back(all("[scene]", "the sample period", "scene"));
  p.push_back(all("[parameters]", "named exact values", "parameters"));
  p.push_back(all("[[device]] m, b, tf, ss", "the devices", "device"));
  p.push_back(sim_only("[[device]] quantum, quantizer", "encoder quantization", "device", {"quantum", "quantizer"},
                       nonlinear + "; a quantizer is not in it", schur + "; a quantizer is not in it"));
  p.push_back(sim_only("[[device]] coulomb", "Coulomb friction", "device", {"coulomb"}, nonlinear + "; friction is not in it",
                       schur + "; friction is not in it"));
  p.push_back(all("[[operator]]", "the human operators", "operator"));
  p.push_back(all("[environment]", "the virtual environment E(z)", "environment"));
  p.push_back({"[coupling]", "the coupling V(z)", "coupling", {},
               {{kSim, U::models, ""},
                {kAnalyze, U::models, "checked against Theorem 5's requirement on Delta_V (the loop as written)"},
                {kDesign, U::outside, "design computes the coupling; the scene's own is not used"},
                {kStab, U::models, ""}}});
  p.push_back(sim_only("[contact]", "a unilateral wall", "contact", {}, "Theorems 5 and 6 model a two-sided linear wall",
                       "the Schur test models a two-sided linear wall"));
  p.push_back(sim_only("[passivity_controller]", "Hannaford-Ryu's passivity controller", "passivity_controller", {},
                       nonlinear + "; the controller is a time-varying damper", schur + "; the controller is a time-varying damper"));
  p.push_back({"[delay]", "a computation delay", "delay", {},
               {{kSim, U::models, ""},
                {kAnalyze, U::models, "an integer delay z^-n in the environment's realisation; a fractional one is refused"},
                {kDesign, U::models, "as analyze"},
                {kStab, U::models, "integer and fractional: the forces still to act are states of the closed loop"}}});
  p.push_back({"[[input]]", "exogenous forces", "input", {},
               {{kSim, U::models, ""},
                {kAnalyze, U::outside, "an excitation: the stability of the linear loop does not depend on it"},
                {kDesign, U::models, "drives the simulated verification of the designed V"},
                {kStab, U::outside, "an excitation: the stability of the linear loop does not depend on it"}}});
  p.push_back({"[initial]", "the initial state", "initial", {},
               {{kSim, U::models, ""},
                {kAnalyze, U::outside, "the stability of the linear loop does not depend on it"},
                {kDesign, U::models, "the initial state of the simulated verification"},
                {kStab, U::outside, "the stability of the linear loop does not depend on it"}}});
  p.push_back({"[simulate]", "how simulate runs the scene", "simulate", {},
               {{kSim, U::models, ""},
                {kAnalyze, U::outside, "configures `hapstab simulate`"},
                {kDesign, U::outside, "configures `hapstab simulate` (design's run length is --duration)"},
                {kStab, U::outside, "configures `hapstab simulate`"}}});
  p.push_back({"[multidof] osp, qv_block_diagonal, [multidof.coupling]", "Theorems 5 and 6's premises and structure",
               "multidof", {"osp", "qv_block_diagonal", "coupling"},
               {{kSim, U::outside, "configures `hapstab multidof`"}, {kAnalyze, U::models, ""}, {kDesign, U::models, ""},
                {kStab, U::outside, "configures `hapstab multidof`"}}});
  p.push_back({"multidof.perturb_C", "Sec. VI's perturbed environment C_E := Pi C_E", "multidof", {"perturb_C"},
               {{kSim, U::refuses, "the simulator reads [environment] as written"},
                {kAnalyze, U::models, ""},
                {kDesign, U::models, ""},
                {kStab, U::refuses, "the Schur test reads [environment] as written"}}});
  p.push_back({"[reproduce]", "what `hapstab reproduce` expects", "reproduce", {},
               {{kSim, U::outside, "configures `hapstab reproduce`"},
                {kAnalyze, U::outside, "configures `hapstab reproduce`"},
                {kDesign, U::outside, "configures `hapstab reproduce`"},
                {kStab, U::outside, "configures `hapstab reproduce`"}}});
  return p;
}

// The node that makes `p` present in `root` (for its line), or nullptr.
const toml::node* present(const toml::table& root, const Part& p) {
  const toml::node* s = root.get(p.section);
  if (!s) return nullptr;
  if (p.keys.empty()) return s;
  std::vector<const toml::table*> tables;
  if (const auto* t = s->as_table()) tables.push_back(t);
  if (const auto* a = s->as_array())
    for (const auto& e : *a)
      if (const auto* t = e.as_table()) tables.push_back(t);
  for (const auto* t : tables)
    for (const auto& key : p.keys)
      if (const toml::node* n = t->get(key)) return n;
  return nullptr;
}

std::string type_name(Type t) {
  switch (t) {
    case T::text: return "string";
    case T::exact: return "exact number";
    case T::integer: return "integer";
    case T::boolean: return "boolean";
    case T::real: return "number";
    case T::exact_list: return "list of exact numbers";
    case T::real_list: return "list of numbers";
    case T::text_list: return "list of strings";
    case T::integer_list: return "list of integers";
    case T::matrix: return "matrix";
    case T::tf: return "transfer function";
    case T::dof: return "DOF";
    case T::dofs: return "DOFs";
    case T::table: return "table";
    case T::expectation: return "expectation";
  }
  return "?";
}

std::string cell(std::string s) {  // a Markdown table cell
  for (size_t i = 0; (i = s.find('|', i)) != std::string::npos; i += 2) s.replace(i, 1, "\\|");
  return s;
}

}  // namespace

const std::vector<Section>& schema() {
  static const std::vector<Section> s = make_schema();
  return s;
}

void check_names(const toml::table& root, const std::string& file) { Checker{file, false}.root(root); }

void check_schema(const toml::table& root, const std::string& file) { Checker{file, true}.root(root); }

const std::vector<std::string>& scene_commands() {
  static const std::vector<std::string> c = {kSim, kAnalyze, kDesign, kStab};
  return c;
}

const std::vector<Part>& command_uses() {
  static const std::vector<Part> p = make_uses();
  return p;
}

void check_command(const toml::table& root, const std::string& file, const std::string& command) {
  if (std::find(scene_commands().begin(), scene_commands().end(), command) == scene_commands().end())
    throw std::logic_error("check_command: no command '" + command + "' in scene/schema.cpp");
  for (const auto& p : command_uses()) {
    const toml::node* n = present(root, p);
    if (!n) continue;
    for (const auto& f : p.uses) {
      if (f.command != command || f.use != Use::refuses) continue;
      std::string other;
      for (const auto& g : p.uses)
        if (g.use == Use::models) other += (other.empty() ? "`hapstab " : " and `hapstab ") + g.command + "`";
      throw InputError(where(file, *n) + command + " does not model " + p.name + " (" + p.what + "; " + f.why + "); " +
                       other + (other.find(" and ") == std::string::npos ? " does" : " do"));
    }
  }
}

const std::vector<Key>& expectation_keys(const std::string& command) {
  const std::string c = command.substr(command.rfind(' ') + 1);  // "multidof analyze" -> analyze
  const Section* s = find_section("reproduce." + c);
  if (!s) throw std::logic_error("expectation_keys: no command '" + command + "'");
  return s->keys;
}

MultidofValues multidof_values(const Scene& sc) {
  MultidofValues v;
  const toml::table* md = sc.root["multidof"].as_table();
  if (!md) return v;
  Reader c;  // the scene's T and parameters, for exact numbers written as expressions
  c.file = sc.file;
  c.T = sc.T;
  c.params = sc.parameters;
  if (const toml::array* osp = (*md)["osp"].as_array()) {
    v.osp.emplace();
    for (size_t d = 0; d < osp->size(); ++d) v.osp->push_back(c.number((*osp)[d], "multidof.osp[" + std::to_string(d) + "]"));
  }
  if (const toml::array* pc = (*md)["perturb_C"].as_array()) {
    v.perturb_C.emplace();
    for (size_t i = 0; i < pc->size(); ++i) {
      const toml::array* row = (*pc)[i].as_array();
      if (!row) c.fail("multidof.perturb_C[" + std::to_string(i) + "]", "expected a row (an array of exact numbers)");
      auto& out = v.perturb_C->emplace_back();
      for (size_t j = 0; j < row->size(); ++j)
        out.push_back(c.number((*row)[j], "multidof.perturb_C[" + std::to_string(i) + "][" + std::to_string(j) + "]"));
    }
  }
  if (auto b = (*md)["qv_block_diagonal"].value<bool>()) v.qv_block_diagonal = *b;
  if (const toml::table* cp = (*md)["coupling"].as_table())
    for (auto [key, out] : {std::pair{"mbar", &v.mbar}, std::pair{"nbar", &v.nbar}}) {
      const toml::array* a = (*cp)[key].as_array();
      for (size_t i = 0; a && i < a->size(); ++i) {
        const std::string at = std::string("multidof.coupling.") + key + "[" + std::to_string(i) + "]";
        const auto n = (*a)[i].value<int64_t>();
        if (!n) c.fail(at, "expected an integer");
        if (*n < -1000000 || *n > 1000000) c.fail(at, std::to_string(*n) + " is out of range");
        out->push_back(static_cast<int>(*n));
      }
    }
  return v;
}

size_t edit_distance(const std::string& a, const std::string& b) {
  std::vector<std::vector<size_t>> d(a.size() + 1, std::vector<size_t>(b.size() + 1));
  for (size_t i = 0; i <= a.size(); ++i) d[i][0] = i;
  for (size_t j = 0; j <= b.size(); ++j) d[0][j] = j;
  for (size_t i = 1; i <= a.size(); ++i)
    for (size_t j = 1; j <= b.size(); ++j) {
      const size_t cost = a[i - 1] == b[j - 1] ? 0 : 1;
      d[i][j] = std::min({d[i - 1][j] + 1, d[i][j - 1] + 1, d[i - 1][j - 1] + cost});
      if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1]) d[i][j] = std::min(d[i][j], d[i - 2][j - 2] + 1);
    }
  return d[a.size()][b.size()];
}

// docs/scene.md's "Repeated blocks": count, list parameters, diagonal/off_diagonal (scene/reader.hpp
// table_copies and Reader::expand, scene.cpp expand_matrix). Its example is parsed by tests/scene.
static std::string repeated_blocks_markdown() {
  return "## Repeated blocks\n\n"
         "Arrays of identical actuators (pin displays, ultrasound arrays, exoskeleton fingers) are written once with a\n"
         "count. The reader expands them; every command then sees the same scene as if it were written out.\n\n"
         "- `count = n` in a `[[device]]` or `[[operator]]` table stands for n copies of it, 1 <= n <= 4096. A count\n"
         "  that is 0, negative, a float, a string or above 4096 is refused naming the key (`device[0].count: 0\n"
         "  copies: a repeated table needs count >= 1`). The table needs a `name`: the copies are `NAME[1]` ..\n"
         "  `NAME[n]` (a name holding `[i]`, e.g. `\"finger[i].pad\"`, is the pattern instead). The copies take the\n"
         "  table's place: the DOFs of `d[1]` .. `d[n]` follow the devices before the table, in copy order.\n"
         "- In every string of a repeated table, `[i]` is the copy's number: `dofs = \"d[i]\"` puts `H[k]` on\n"
         "  `d[k]`, `m = \"mass[i]\"` gives copy k the k-th value of the list parameter `mass`. Messages about a\n"
         "  copy name it `device[0](copy k)`.\n"
         "- A *list parameter* `kc = [\"500\", \"600\", ...]` in `[parameters]` holds exact values (numbers or\n"
         "  expressions, as any parameter); in any expression `kc[k]` is its k-th value (from 1) and `sum(kc)` the\n"
         "  exact sum of all of them. A list indexed by `[i]` in a table with count n must hold n values; `kc[k]`\n"
         "  beyond its length, `kc` without an index, `[i]` outside a repeated table and `--set kc=...` are refused\n"
         "  by name. `kc = { repeat = [\"500\", \"600\"], times = 512 }` is the two values over and over, 1024 in\n"
         "  all: an array of identical devices in a few kinds, said once.\n"
         "- `[environment]` and `[coupling]` may give their N x N matrix (N the number of DOFs) by two entries instead\n"
         "  of `tf`: `diagonal`, entry (i, i) with `[i]` its row, and `off_diagonal`, entry (i, j), i != j, with `[i]`\n"
         "  the row and `[j]` the column (default `\"0\"`). A list they index by `[i]` or `[j]` must hold N values, and the\n"
         "  matrix is never written out: entries whose `[i]` and `[j]` lists take the same values are parsed and\n"
         "  realised once, so a matrix over a few classes of DOFs costs a few entries, and its realisation (column by\n"
         "  column) may have at most 4096 states and inputs together. `blocks = K` makes it block diagonal: K\n"
         "  blocks of N/K DOFs in order (K separate objects), entries between two blocks 0, [i] and [j] still the\n"
         "  DOF numbers (`bench/contact_scene.py 1024 --objects 16 --compact`: 16 objects of 64 devices, 769 bytes).\n\n"
         "N devices in contact with one virtual mass M (paper 000's Fig. 5 environment generalised; `bench/contact_scene.py\n"
         "N --compact` writes it for any N, 3.2 KB at N = 128 where the written-out scene is 18 MB):\n\n"
         "```toml\n"
         "[scene]\n"
         "name = \"4 contact points on one mass\"\n"
         "T = \"0.01\"\n\n"
         "[parameters]\n"
         "M = \"0.3\"\n"
         "k = \"1000\"\n"
         "B = \"5\"\n"
         "kc = [\"500\", \"600\", \"700\", \"800\"]   # contact i: kc[i] + Bc[i] s\n"
         "Bc = [\"1\", \"2\", \"3/2\", \"5/2\"]\n"
         "g = [\"0.1\", \"0.05\", \"0.08\", \"0.06\"]   # operator gains\n\n"
         "[[device]]\n"
         "count = 4          # d[1] .. d[4]: DOFs 0 .. 3\n"
         "name = \"d\"\n"
         "m = \"1/10\"\n"
         "b = \"1.37\"\n\n"
         "[[operator]]\n"
         "count = 4          # H[k] holds d[k]\n"
         "name = \"H\"\n"
         "dofs = \"d[i]\"\n"
         "tf = \"g[i]*(s^2+5*s+10)/(s^2+s+1)\"\n\n"
         "[environment]      # E = diag(c_i) - c c^T / (M s^2 + (B + sum Bc) s + k + sum kc), c_i = kc[i] + Bc[i] s\n"
         "domain = \"s\"\n"
         "method = \"backward_euler\"\n"
         "diagonal = \"kc[i] + Bc[i]*s - (kc[i] + Bc[i]*s)^2/(M*s^2 + (B + sum(Bc))*s + k + sum(kc))\"\n"
         "off_diagonal = \"-(kc[i] + Bc[i]*s)*(kc[j] + Bc[j]*s)/(M*s^2 + (B + sum(Bc))*s + k + sum(kc))\"\n"
         "```\n\n"
         "`bench/contact_scene.py 4` writes the same scene out (devices d1 .. d4, 16 entries of E); `multidof analyze`\n"
         "and `stability --scene` give the same output on both forms (ctest `scene_compact_vs_written`, N = 4 and 8).\n"
         "The compact form saves the work as well as the file: the 1024-device scene (712 bytes) is read and realised\n"
         "in about 1.5 s, where the written-out scene would be over a gigabyte (multidof analyze: docs/multidof.md).\n\n";
}

std::string schema_markdown() {
  std::ostringstream o;
  o << "# Scene files\n\n"
       "<!-- Generated from toolbox/hapstab/scene/schema.cpp by scene::schema_markdown(); do not edit. Regenerate:\n"
       "     HAPSTAB_WRITE_DOCS=1 build/tests/test_scene --gtest_filter=SceneSchema.DocsSceneMdIsGenerated -->\n\n"
       "A scene is a TOML file that names only the blocks a study needs (examples in\n"
       "[examples/](../examples/README.md)). This page lists every section and key a scene may hold;\n"
       "the loader checks a scene against the same declaration. **Any other section or key, at any\n"
       "depth, is refused** (exit 2), naming the file, the line and the nearest valid name:\n\n"
       "```\n"
       "$ hapstab simulate --scene tests/scene/data/bias_wall_contacts.toml --out /tmp/w\n"
       "hapstab: error: tests/scene/data/bias_wall_contacts.toml:41: unknown section [contacts]; did you mean [contact]?\n"
       "[rc=2]\n"
       "```\n\n"
       "Types: an *exact number* is a string holding a decimal, a fraction or a constant expression of `T`\n"
       "and the `[parameters]` (`\"0.001\"`, `\"1/1000\"`, `\"K*T/2 + B\"`), or a TOML integer; TOML floats\n"
       "are refused there (they are binary approximations). A *number* may also be a float. A *DOF* is\n"
       "a DOF number (from 0, in device order) or the name of a one-DOF device; *DOFs* is one or a list\n"
       "(a device name stands for all its DOFs). Units are SI.\n\n";
  for (const auto& s : schema()) {
    const std::string head = s.top ? (s.array ? "[[" + s.path + "]]" : "[" + s.path + "]")
                                   : (s.path == "ss" ? "ss = { ... }" : s.path.find("reproduce.") == 0
                                                                             ? "[reproduce] " + s.path.substr(10) + " = { ... }"
                                                                             : "[" + s.path + "]");
    o << "## `" << head << "`" << (s.required ? " (required)" : "") << "\n\n" << s.doc << "\n\n";
    if (s.open) {
      o << "Keys: any parameter name; values: exact numbers.\n\n";
      continue;
    }
    o << "| key | type | unit | meaning |\n|---|---|---|---|\n";
    for (const auto& key : s.keys) {
      std::string doc = key.doc;
      if (!key.only_for.empty()) doc = "(type = \"" + key.only_for + "\") " + doc;
      if (key.type == T::table) doc += " (see `" + key.table + "`)";
      o << "| `" << key.name << "` | " << type_name(key.type) << " | " << cell(key.unit) << " | " << cell(doc) << " |\n";
    }
    o << "\n";
  }
  o << repeated_blocks_markdown();
  o << "## What each command models\n\n"
       "A command reads every part of a scene it models. A part it does not model but that would change the\n"
       "model is **refused** (exit 2), naming the command that models it, e.g. \"multidof analyze does not model\n"
       "[contact] (a unilateral wall; ...); `hapstab simulate` does\". A part that configures another command, or\n"
       "cannot change the command's result, is *not part of the model* and is allowed.\n\n"
       "| part of the scene |";
  for (const auto& c : scene_commands()) o << " `" << c << "` |";
  o << "\n|---|";
  for (size_t i = 0; i < scene_commands().size(); ++i) o << "---|";
  o << "\n";
  for (const auto& p : command_uses()) {
    o << "| `" << p.name << "`: " << cell(p.what) << " |";
    for (const auto& c : scene_commands())
      for (const auto& f : p.uses)
        if (f.command == c) {
          const char* w = f.use == Use::models ? "modelled" : f.use == Use::refuses ? "**refused**" : "not part of the model";
          o << " " << w << (f.why.empty() ? "" : ": " + cell(f.why)) << " |";
        }
    o << "\n";
  }
  o << "\n`hapstab reproduce` runs each scene with the commands its sections call for; the Python module\n"
       "runs the same code (`hapstab.simulate`: `scene::prepare_run`, the preparation `hapstab simulate`\n"
       "uses; `hapstab.multidof.analyze|design`: the commands), so the same table holds.\n";
  return o.str();
}

}  // namespace hapstab::scene
