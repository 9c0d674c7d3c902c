// hapstab/scene/reader.hpp -- typed values out of a scene's TOML, for the section readers of
// scene.cpp (internal to the scene module). Every error is an InputError
// "FILE: KEY: what is wrong", KEY the dotted path of the value (docs/scene.md). A scene is
// untrusted input (docs/security.md): these are the checks that keep it so (sizes of names,
// exact numbers only, DOF indices in range, blocks realisable and, when claimed, passive).
#pragma once

#include <functional>
#include <map>
#include <string>
#include <toml++/toml.h>
#include <utility>
#include <vector>

#include "hapstab/lti/parse.hpp"
#include "hapstab/lti/state_space.hpp"
#include "hapstab/lti/tf.hpp"
#include "hapstab/numeric/scalar.hpp"

namespace hapstab::scene {

/// A matrix given by diagonal / off_diagonal (docs/scene.md, "Repeated blocks"), kept compact: its
/// distinct entries and, per entry, which one it is. Entries (i, j) and (k, l) are the same when
/// the list values that [i] and [j] name in them are equal (rows i and k, columns j and l), so an
/// N x N matrix over a few classes of DOFs is parsed and realised a few times, not N^2.
struct CompactMatrix {
  int n = 0;
  std::vector<std::string> texts;  ///< the distinct entries, [i] and [j] placed (list values not yet in)
  std::vector<std::string> keys;   ///< where each was first met: "environment.off_diagonal (row 3, column 7)"
  std::vector<int> index;          ///< n x n, row-major: entry (i, j) is texts[index[i n + j]]
};

/// What a section reader knows of the scene so far: the file (for messages), its folder (for
/// files a scene reads), T and the parameters (for expressions) and the devices' DOFs (for
/// DOF names).
struct Reader {
  std::string file;
  std::string base_dir;
  rational T = 0;
  std::map<std::string, rational> params;
  /// List parameters ([parameters] NAME = [v1, ..., vn]): NAME[k] is v_k (from 1), sum(NAME) their
  /// sum; expressions see them through expand().
  std::map<std::string, std::vector<rational>> lists;
  std::map<std::string, std::pair<int, int>> device_dofs;  ///< name -> [first, count]
  int N = 0;                                               ///< DOFs given by the devices so far
  /// The long parenthesised groups tf_of has parsed (lti/parse.hpp, ParseMemo: used only where
  /// the names in them still have the values they were parsed with).
  mutable ParseMemo memo;
  /// sum(NAME) of each list parameter as expand() writes it, computed once (the lists do not
  /// change once the parameters are read).
  mutable std::map<std::string, std::string> list_sums;

  /// Throws InputError("file: key: what").
  [[noreturn]] void fail(const std::string& key, const std::string& what) const;

  /// Free text (names, descriptions; examples/README.md, "Names"): any Unicode, at most `max`
  /// bytes, no control characters (a description may hold newlines), well-formed UTF-8.
  /// Everything they reach escapes them (report/escape.hpp); they never name a file.
  std::string free_text(const toml::table& t, const char* k, const std::string& key, const std::string& fallback,
                        size_t max, bool newlines = false) const;
  /// An exact number: integer, or a string holding a decimal/fraction, or (allow_names) a
  /// constant expression of T and the parameters. TOML floats are refused.
  rational number(const toml::node& n, const std::string& key, bool allow_names = true) const;
  /// The number t[k], which must be present (key names the table).
  rational number(const toml::table& t, const std::string& k, const std::string& key) const;
  /// A plotting/profile value: a TOML float, or an exact number rounded to double; refused unless
  /// finite (nan, inf, or an exact number beyond the range of double).
  double real(const toml::node& n, const std::string& key) const;
  /// A matrix of exact numbers: an array of rows of equal length.
  Mat<rational> matrix(const toml::node& n, const std::string& key) const;
  /// A transfer function in `var` ('s' or 'z') of T and the parameters.
  TransferFunction tf_of(const std::string& text, const std::string& key, char var) const;
  /// A block given as tf (string or matrix of strings) or ss = {A,B,C,D}; `to_z` maps each
  /// s-domain entry to z (environment discretisation) before realisation.
  StateSpace<rational> block(const toml::table& t, const std::string& key, char var,
                             const std::function<TransferFunction(const TransferFunction&)>& to_z = {}) const;
  /// The block a CompactMatrix describes (each distinct entry parsed once, mapped by `to_z`,
  /// realised as tf2ss realises the matrix written out); refused beyond limits::scene_block_order.
  StateSpace<rational> compact_block(const CompactMatrix& m, char var,
                                     const std::function<TransferFunction(const TransferFunction&)>& to_z = {}) const;
  /// A continuous block claimed passive: no pole with Re s > 0 (static: D + D^T >= 0).
  void check_passive_claim(const StateSpace<rational>& G, const std::string& key) const;
  /// `text` with every NAME[k] of a list parameter replaced by its exact value "(p/q)" and every
  /// sum(NAME) by the sum of its values (the expression parser sees only scalars). A list used
  /// without an index, an index out of range, or a copy index [i]/[j] left outside a repeated
  /// table is an InputError naming `key`. Text without lists is returned as it is.
  std::string expand(const std::string& text, const std::string& key) const;
  /// One DOF: a number in [0, N) or the name of a one-DOF device.
  int dof_of(const toml::node& n, const std::string& key) const;
  /// A list of DOFs (numbers and device names; a name stands for all its DOFs), or one.
  std::vector<int> dofs_of(const toml::node& n, const std::string& key) const;

 private:
  StateSpace<rational> ss_block(const toml::table& t, const std::string& key, char var) const;
  StateSpace<rational> tf_block(const toml::node& n, const std::string& key, char var,
                                const std::function<TransferFunction(const TransferFunction&)>& to_z) const;
  const std::pair<int, int>& device(const std::string& name, const std::string& key) const;
  /// tf mapped by to_z (when given), refused at `key` when improper.
  TransferFunction realisable(TransferFunction tf, const std::string& key,
                              const std::function<TransferFunction(const TransferFunction&)>& to_z) const;
};

/// The table root[k], or nullptr when absent; an error when it is not a table.
const toml::table* section(const toml::table& root, const char* k, const Reader& c);

/// The copies a table with `count = n` stands for (docs/scene.md, "Repeated blocks"): copy k (1..n)
/// is the table without `count`, with every "[i]" in its strings replaced by "[k]" and its name
/// NAME made NAME[k] (or, when the name holds "[i]", that replaced). A wrong count (not an
/// integer, < 1, above limits::scene_copies), a count without a name, or a list parameter used
/// as LIST[i] whose length is not n is an InputError naming `key`. A table without count is
/// returned as its only copy.
std::vector<toml::table> table_copies(const toml::table& t, const std::string& key, const Reader& c);

/// The lists `text` indexes as LIST[<index>] (index "i" or "j"), for the length checks.
std::vector<std::string> lists_indexed_by(const std::string& text, const std::string& index, const Reader& c);

/// Calls f(table, "k[i]", i) for each [[k]] table (a single [k] table counts as k[0]); a table
/// with `count` is called once per copy (table_copies), named "k[i](copy c)".
template <class F>
void each_table(const toml::table& root, const char* k, const Reader& c, F f) {
  auto n = root.get(k);
  if (!n) return;
  const auto each_copy = [&](const toml::table& t, const std::string& key, int i) {
    if (!t.contains("count")) return f(t, key, i);
    const auto copies = table_copies(t, key, c);
    for (size_t j = 0; j < copies.size(); ++j) f(copies[j], key + "(copy " + std::to_string(j + 1) + ")", i);
  };
  if (auto t = n->as_table()) {
    each_copy(*t, std::string(k) + "[0]", 0);
    return;
  }
  auto a = n->as_array();
  if (!a) c.fail(k, "expected [[" + std::string(k) + "]] tables");
  for (size_t i = 0; i < a->size(); ++i) {
    auto t = (*a)[i].as_table();
    if (!t) c.fail(std::string(k) + "[" + std::to_string(i) + "]", "expected a table");
    each_copy(*t, std::string(k) + "[" + std::to_string(i) + "]", int(i));
  }
}

}  // namespace hapstab::scene
