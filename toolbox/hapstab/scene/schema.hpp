// hapstab/scene/schema.hpp -- the one declaration of what a scene may hold: every section and
// key, with its TOML type, unit and meaning (schema()), and which command models which part of
// a scene (command_uses()). parse_scene checks a scene against it before reading anything:
// an unknown section or key, at any depth, is an InputError "FILE:LINE: unknown key
// multidof.ops; did you mean multidof.osp?" (exit 2), never ignored. Each command calls
// check_command() with its name: a part of the scene it cannot model is refused by name,
// naming the command that does ("multidof analyze does not model [contact] (a unilateral
// wall); `hapstab simulate` does"). docs/scene.md is schema_markdown() (tests/scene checks
// the committed file).
#pragma once

#include <optional>
#include <string>
#include <toml++/toml.h>
#include <vector>

#include "hapstab/numeric/scalar.hpp"

namespace hapstab::scene {

struct Scene;  // scene.hpp

/// The TOML form a key's value must have (the section readers then check its content).
enum class Type {
  text,          ///< a string
  exact,         ///< an exact number: a string ("1/1000", "0.001", an expression of T and the parameters) or an integer
  integer,       ///< a TOML integer
  boolean,       ///< true or false
  real,          ///< a TOML float, integer or exact-number string (plotting and run options)
  exact_list,    ///< a list of exact numbers
  real_list,     ///< a list of floats or exact numbers
  text_list,     ///< a list of strings
  integer_list,  ///< a list of integers
  matrix,        ///< a list of rows of exact numbers
  tf,            ///< a transfer function: a string, or a matrix (rows) of strings
  dof,           ///< a DOF number or the name of a one-DOF device
  dofs,          ///< a DOF, a device name (all its DOFs) or a list of them
  table,         ///< a table with keys of its own (Key::table names its schema)
  expectation,   ///< true/false, a string ("growing", "> 1", "!= null") or a number
};

struct Key {
  std::string name;
  Type type;
  std::string unit;      ///< SI unit of the value ("" when none)
  std::string doc;       ///< what it means, one line
  std::string only_for;  ///< [[input]]: the input types that take it ("" = every table)
  std::string table;     ///< Type::table: the path of its schema ("ss", "multidof.coupling", ...)
};

struct Section {
  std::string path;       ///< "device", "multidof.coupling", or a value table ("ss")
  bool top = true;        ///< a top-level section (else reached through a Key of Type::table)
  bool array = false;     ///< [[path]] (a single [path] counts as one)
  bool required = false;  ///< the loader refuses a scene without it
  bool open = false;      ///< any key (parameters: identifiers holding exact numbers)
  std::string doc;
  std::vector<Key> keys;
};

/// Every section a scene may hold, top-level ones first, in the order the loader reads them.
const std::vector<Section>& schema();

/// Refuses any section or key the schema does not declare, at any depth: InputError
/// "FILE:LINE: unknown section [contacts]; did you mean [contact]?".
void check_names(const toml::table& root, const std::string& file);
/// check_names, and refuses any value whose TOML form is not its key's Type ("FILE:LINE:
/// simulate.energy: expected true or false, got a string"). parse_scene calls check_names
/// before its section readers and this after them (their messages say more about a value).
void check_schema(const toml::table& root, const std::string& file);

/// How a command treats one part of a scene.
enum class Use {
  models,   ///< part of the command's model
  refuses,  ///< present -> refused (exit 2), naming a command that models it
  outside,  ///< not part of the command's model (configures another command, or does not change it)
};

/// One part of a scene a command may or may not model: a section, or keys of one.
struct Part {
  std::string name;  ///< "[contact]", "[[device]] coulomb", "multidof.perturb_C"
  std::string what;  ///< "a unilateral wall"
  std::string section;            ///< top-level section it lives in
  std::vector<std::string> keys;  ///< keys of that section that make it present (empty: the section)
  struct For {
    std::string command;
    Use use;
    std::string why;  ///< for outside (and refuses): why, shown in docs/scene.md
  };
  std::vector<For> uses;
};

/// The commands that read scenes and, per part of a scene, what each does with it.
const std::vector<std::string>& scene_commands();
const std::vector<Part>& command_uses();

/// Refuses the first part present in `root` that `command` ("simulate", "multidof analyze",
/// "multidof design") does not model: InputError "FILE:LINE: multidof analyze does not model
/// [contact] (a unilateral wall); `hapstab simulate` does".
void check_command(const toml::table& root, const std::string& file, const std::string& command);

/// The keys `hapstab reproduce` may state for a command ([reproduce] simulate/analyze/design).
const std::vector<Key>& expectation_keys(const std::string& command);

/// [multidof] and [multidof.coupling] (the schema's `multidof` sections) as typed values, read by
/// the commands that model them (multidof analyze|design: multidof/scene_multidof.hpp) rather
/// than by parse_scene, so that a scene another command runs is not refused for them. Their TOML
/// forms were checked by parse_scene (check_schema); these readers give the values their
/// meaning, as every other key of that type: `osp` and `perturb_C` entries are exact numbers
/// (decimals, fractions, or constant expressions of T and the [parameters]), `mbar`/`nbar`
/// integers in [-10^6, 10^6] (their meaning, and the limits of numeric/limits.hpp, are checked
/// by the caller). Sizes against the scene's devices and DOFs are the caller's too: it names
/// what they must match. Errors are InputErrors "FILE: multidof.osp[1]: 'x' is not ...", naming
/// the key and the entry.
struct MultidofValues {
  std::optional<std::vector<rational>> osp;                     ///< one OSP level per device, as written
  std::optional<std::vector<std::vector<rational>>> perturb_C;  ///< Pi's rows, as written (not yet N x N)
  bool qv_block_diagonal = false;                               ///< Remark 3 (default false)
  std::vector<int> mbar, nbar;  ///< [multidof.coupling]; empty when absent (the caller's defaults)
};
MultidofValues multidof_values(const Scene& sc);

/// docs/scene.md: the schema and the command x part table, as Markdown.
std::string schema_markdown();

/// Optimal string alignment distance (Levenshtein plus adjacent transpositions), for "did you mean".
size_t edit_distance(const std::string& a, const std::string& b);

}  // namespace hapstab::scene
