// Typed values out of a scene's TOML (see reader.hpp).
#include "hapstab/scene/reader.hpp"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cctype>
#include <cmath>
#include <map>
#include <sstream>

#include "hapstab/lti/parse.hpp"
#include "hapstab/lti/realization.hpp"
#include "hapstab/numeric/decimal.hpp"
#include "hapstab/numeric/error.hpp"
#include "hapstab/numeric/limits.hpp"
#include "hapstab/report/escape.hpp"

namespace hapstab::scene {

using Q = rational;

void Reader::fail(const std::string& key, const std::string& what) const {
  throw InputError(file + ": " + key + ": " + what);
}

std::string Reader::free_text(const toml::table& t, const char* k, const std::string& key, const std::string& fallback,
                              size_t max, bool newlines) const {
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

Q Reader::number(const toml::node& n, const std::string& key, bool allow_names) const {
  if (auto i = n.as_integer()) return Q(i->get());
  if (n.is_floating_point())
    fail(key, "write the value as a string (\"0.001\") so that it is exact; TOML floats are binary approximations");
  auto s = n.as_string();
  if (!s) fail(key, "expected a number (a string like \"1/1000\" or an integer)");
  const std::string& written = s->get();
  if (auto q = try_parse_rational(written)) return *q;
  if (!allow_names) fail(key, "'" + written + "' is not a number");
  const std::string text = expand(written, key);
  ParseOptions po;
  po.variable = 's';
  po.T = T;
  po.shared_parameters = &params;  // not copied (lti/parse.hpp)
  TransferFunction tf;
  try {
    tf = parse_tf(text, po);
  } catch (const InputError& e) {
    fail(key, e.what());
  }
  if (tf.num().degree() > 0 || tf.den().degree() > 0) fail(key, "'" + written + "' must be a constant");
  return tf.num().is_zero() ? Q(0) : Q(tf.num().coeff(0) / tf.den().coeff(0));
}

Q Reader::number(const toml::table& t, const std::string& k, const std::string& key) const {
  auto n = t.get(k);
  if (!n) fail(key + "." + k, "missing");
  return number(*n, key + "." + k);
}

double Reader::real(const toml::node& n, const std::string& key) const {
  // TOML writes nan and inf as floats, and an exact number may be beyond the range of double:
  // neither is a force, a time or a velocity
  const double v = n.as_floating_point() ? n.as_floating_point()->get() : to_real<double>(number(n, key));
  if (!std::isfinite(v)) {
    std::ostringstream os;
    os << "must be a finite number, got " << v;
    fail(key, os.str());
  }
  return v;
}

Mat<Q> Reader::matrix(const toml::node& n, const std::string& key) const {
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

TransferFunction Reader::tf_of(const std::string& written, const std::string& key, char var) const {
  const std::string text = expand(written, key);
  ParseOptions po;
  po.variable = var;
  po.T = T;
  po.shared_parameters = &params;  // not copied: copying the ones each entry names was 40% of reading a large scene
  po.memo = &memo;
  try {
    return parse_tf(text, po);
  } catch (const InputError& e) {
    fail(key, std::string("'") + written + "': " + e.what());
  }
}

// `var`: 's' or 'z' (0: infer, then the result's domain tells).
StateSpace<Q> Reader::block(const toml::table& t, const std::string& key, char var,
                            const std::function<TransferFunction(const TransferFunction&)>& to_z) const {
  const bool has_tf = t.contains("tf"), has_ss = t.contains("ss");
  if (has_tf == has_ss) fail(key, "give exactly one of tf = \"...\" or ss = { A = ..., B = ..., C = ..., D = ... }");
  if (has_ss) return ss_block(t, key, var);
  try {
    return tf_block(*t.get("tf"), key, var, to_z);
  } catch (const InputError& e) {
    // The realisation's own errors do not name the key yet.
    const std::string w = e.what();
    if (w.rfind(file, 0) == 0) throw;
    fail(key + ".tf", w);
  }
}

StateSpace<Q> Reader::ss_block(const toml::table& t, const std::string& key, char var) const {
  auto s = t["ss"].as_table();
  if (!s) fail(key + ".ss", "expected a table { A = ..., B = ..., C = ..., D = ... }");
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

StateSpace<Q> Reader::tf_block(const toml::node& n, const std::string& key, char var,
                               const std::function<TransferFunction(const TransferFunction&)>& to_z) const {
  if (auto s = n.as_string()) {
    auto tf = tf_of(s->get(), key + ".tf", var);
    if (to_z) tf = to_z(tf);
    if (!tf.is_proper()) fail(key + ".tf", "'" + s->get() + "' is improper (more zeros than poles); not realisable");
    return tf2ss(tf);
  }
  auto a = n.as_array();
  if (!a) fail(key + ".tf", "expected a string or a matrix of strings");
  // entries whose text is the same once the lists are in are parsed and discretised once
  std::vector<TransferFunction> distinct;
  std::map<std::string, int> seen;
  std::vector<int> index;
  size_t cols = 0;
  for (size_t i = 0; i < a->size(); ++i) {
    auto row = (*a)[i].as_array();
    if (!row) fail(key + ".tf", "row " + std::to_string(i) + " is not an array");
    if (i == 0) cols = row->size();
    if (row->size() != cols) fail(key + ".tf", "rows have different lengths");
    for (size_t j = 0; j < row->size(); ++j) {
      auto s = (*row)[j].as_string();
      const std::string k2 = key + ".tf[" + std::to_string(i) + "][" + std::to_string(j) + "]";
      if (!s) fail(k2, "expected a string expression");
      auto [hit, fresh] = seen.try_emplace(expand(s->get(), k2), static_cast<int>(distinct.size()));
      if (fresh) distinct.push_back(realisable(tf_of(s->get(), k2, var), k2, to_z));
      index.push_back(hit->second);
    }
  }
  const bool to_discrete = var != 's' || to_z;
  return tf2ss(distinct, index, a->size(), cols, to_discrete ? T : Q(0));  // empty: tf2ss's error
}

TransferFunction Reader::realisable(TransferFunction tf, const std::string& key,
                                    const std::function<TransferFunction(const TransferFunction&)>& to_z) const {
  if (to_z) tf = to_z(tf);
  if (!tf.is_proper()) fail(key, "improper transfer function");
  return tf;
}

StateSpace<Q> Reader::compact_block(const CompactMatrix& m, char var,
                                    const std::function<TransferFunction(const TransferFunction&)>& to_z) const {
  std::vector<TransferFunction> distinct;
  for (size_t k = 0; k < m.texts.size(); ++k) distinct.push_back(realisable(tf_of(m.texts[k], m.keys[k], var), m.keys[k], to_z));
  // the states tf2ss will make (each column's common denominator), before it allocates them
  const auto n = static_cast<size_t>(m.n);
  std::map<std::vector<int>, long> degree;
  long states = 0;
  for (size_t j = 0; j < n; ++j) {
    std::vector<int> ids;
    for (size_t i = 0; i < n; ++i) ids.push_back(m.index[i * n + j]);
    std::sort(ids.begin(), ids.end());
    ids.erase(std::unique(ids.begin(), ids.end()), ids.end());
    auto [it, fresh] = degree.try_emplace(ids, 0);
    if (fresh) {
      Polynomial<Q> d(Q(1));
      for (int id : ids) d = divmod(d * distinct[size_t(id)].den(), gcd(d, distinct[size_t(id)].den())).first;
      it->second = d.degree();
    }
    states += it->second;
  }
  const std::string key = m.keys.front().substr(0, m.keys.front().find(' '));
  if (states + m.n > limits::scene_block_order)
    fail(key, "realised column by column, the " + std::to_string(m.n) + " x " + std::to_string(m.n) + " matrix has " +
                  std::to_string(states) + " states and " + std::to_string(m.n) + " inputs, more than the limit of " +
                  std::to_string(limits::scene_block_order) + " states and inputs together (its exact entries grow as the square)");
  const bool to_discrete = var != 's' || to_z;
  return tf2ss(distinct, m.index, n, n, to_discrete ? T : Q(0));
}

// Numeric eigenvalues, tolerance 1e-9 relative to the pole's size; poles on the axis --
// springs, integrators -- pass.
void Reader::check_passive_claim(const StateSpace<Q>& G, const std::string& key) const {
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

const std::pair<int, int>& Reader::device(const std::string& name, const std::string& key) const {
  auto it = device_dofs.find(name);
  if (it == device_dofs.end()) fail(key, "names the block '" + name + "', which the scene does not define");
  return it->second;
}

int Reader::dof_of(const toml::node& n, const std::string& key) const {
  if (auto i = n.as_integer()) {
    if (i->get() < 0 || i->get() >= N)
      fail(key, "DOF " + std::to_string(i->get()) + " does not exist (the devices give " + std::to_string(N) +
                    " DOF(s), numbered from 0)");
    return int(i->get());
  }
  if (auto s = n.as_string()) {
    const auto& [first, count] = device(s->get(), key);
    if (count != 1) fail(key, "device '" + s->get() + "' has " + std::to_string(count) + " DOFs; give DOF numbers");
    return first;
  }
  fail(key, "expected a DOF number or a device name");
}

std::vector<int> Reader::dofs_of(const toml::node& n, const std::string& key) const {
  std::vector<int> out;
  const auto all_of = [&](const std::string& name) {
    const auto& [first, count] = device(name, key);
    for (int j = 0; j < count; ++j) out.push_back(first + j);
  };
  if (auto a = n.as_array()) {
    for (size_t i = 0; i < a->size(); ++i) {
      const auto& e = (*a)[i];
      if (auto s = e.as_string()) all_of(s->get());
      else out.push_back(dof_of(e, key + "[" + std::to_string(i) + "]"));
    }
    return out;
  }
  if (auto s = n.as_string()) {
    all_of(s->get());
    return out;
  }
  return {dof_of(n, key)};
}

namespace {

bool name_char(char ch) { return std::isalnum(static_cast<unsigned char>(ch)) || ch == '_'; }

// The name starting at i (a letter or _ not after a name character, a digit or '.'), or "".
std::string name_at(const std::string& s, size_t i) {
  if (!(std::isalpha(static_cast<unsigned char>(s[i])) || s[i] == '_')) return "";
  if (i > 0 && (name_char(s[i - 1]) || s[i - 1] == '.')) return "";
  size_t j = i;
  while (j < s.size() && name_char(s[j])) ++j;
  return s.substr(i, j - i);
}

}  // namespace

// NAME[k] -> "(v_k)", sum(NAME) -> "(v_1 + ... + v_n)" as one exact value; scans once.
std::string Reader::expand(const std::string& text, const std::string& key) const {
  if (lists.empty() && text.find('[') == std::string::npos) return text;
  std::string out;
  out.reserve(text.size());
  for (size_t i = 0; i < text.size();) {
    const std::string name = name_at(text, i);
    if (name.empty()) {
      out += text[i++];
      continue;
    }
    size_t j = i + name.size();
    if (name == "sum" && j < text.size() && text[j] == '(') {
      const size_t close = text.find(')', j);
      std::string inner = close == std::string::npos ? "" : text.substr(j + 1, close - j - 1);
      inner.erase(0, inner.find_first_not_of(' '));
      inner.erase(inner.find_last_not_of(' ') + 1);
      if (auto it = lists.find(inner); it != lists.end()) {
        auto [sum, fresh] = list_sums.try_emplace(inner);  // once per list: a compact matrix names it N^2 times
        if (fresh) {
          rational total = 0;
          for (const auto& v : it->second) total += v;
          sum->second = "(" + total.str() + ")";
        }
        out += sum->second;
        i = close + 1;
        continue;
      }
    }
    if (j < text.size() && text[j] == '[') {
      const size_t close = text.find(']', j);
      const std::string index = close == std::string::npos ? "" : text.substr(j + 1, close - j - 1);
      const std::string used = name + "[" + index + "]";
      if (index == "i" || index == "j")
        fail(key, "'" + used + "': [" + index + "] is a copy's number, meaningful only in a table with count = n" +
                      (index == "j" ? " (or, as [j], in an environment's or coupling's off_diagonal)" : ""));
      auto it = lists.find(name);
      if (it == lists.end())
        fail(key, "'" + used + "': " + name + " is not a list parameter ([parameters] " + name + " = [values])");
      const bool digits = !index.empty() && index.size() <= 6 &&
                          std::all_of(index.begin(), index.end(), [](char ch) { return std::isdigit(static_cast<unsigned char>(ch)); });
      const long k = digits ? std::stol(index) : 0;
      if (k < 1 || k > long(it->second.size()))
        fail(key, "'" + used + "': the list parameter " + name + " has " + std::to_string(it->second.size()) +
                      " values, numbered " + name + "[1] .. " + name + "[" + std::to_string(it->second.size()) + "]");
      out += "(" + it->second[size_t(k - 1)].str() + ")";
      i = close + 1;
      continue;
    }
    if (lists.count(name))
      fail(key, "'" + name + "' is a list parameter: write " + name + "[k] for its k-th value (from 1) or sum(" + name + ")");
    out += name;
    i = j;
  }
  return out;
}

std::vector<std::string> lists_indexed_by(const std::string& text, const std::string& index, const Reader& c) {
  std::vector<std::string> out;
  const std::string tail = "[" + index + "]";
  for (size_t i = 0; i < text.size(); ++i) {
    const std::string name = name_at(text, i);
    if (name.empty()) continue;
    if (text.compare(i + name.size(), tail.size(), tail) == 0 && c.lists.count(name)) out.push_back(name);
    i += name.size() - 1;
  }
  return out;
}

namespace {

// Every string in `n` (at any depth) with "[i]" replaced by "[k]"; calls seen(text) on each original.
template <class Seen>
void index_strings(toml::node& n, const std::string& k, Seen& seen) {
  if (auto* s = n.as_string()) {
    std::string text = s->get();
    seen(text);
    for (size_t at = text.find("[i]"); at != std::string::npos; at = text.find("[i]", at + k.size() + 2))
      text.replace(at, 3, "[" + k + "]");
    *s = text;
  } else if (auto* a = n.as_array()) {
    for (auto& e : *a) index_strings(e, k, seen);
  } else if (auto* t = n.as_table()) {
    for (auto&& [name, v] : *t) index_strings(v, k, seen);
  }
}

}  // namespace

std::vector<toml::table> table_copies(const toml::table& t, const std::string& key, const Reader& c) {
  const toml::node* cn = t.get("count");
  if (!cn) return {t};
  const auto* count = cn->as_integer();
  if (!count)
    c.fail(key + ".count", "expected a whole number of copies (a TOML integer such as 128), got " +
                               std::string(cn->is_floating_point() ? "a float" : cn->is_string() ? "a string" : "another type"));
  const long n = long(count->get());
  if (n < 1) c.fail(key + ".count", std::to_string(n) + " copies: a repeated table needs count >= 1");
  if (n > limits::scene_copies)
    c.fail(key + ".count", std::to_string(n) + " copies, more than the limit of " + std::to_string(limits::scene_copies));
  const auto* name = t["name"].as_string();
  if (!name) c.fail(key + ".name", "a table with count needs a name: its copies are named NAME[1] .. NAME[count]");
  std::vector<toml::table> out;
  out.reserve(size_t(n));
  for (long k = 1; k <= n; ++k) {
    toml::table copy = t;
    copy.erase("count");
    const std::string own = name->get();
    const std::string named = own.find("[i]") == std::string::npos ? own + "[i]" : own;
    copy.insert_or_assign("name", named);
    std::vector<std::string> texts;
    auto seen = [&](const std::string& text) {
      if (k == 1) texts.push_back(text);
    };
    for (auto&& [nm, v] : copy) index_strings(v, std::to_string(k), seen);
    for (const auto& text : texts)  // the lists it indexes by copy: one value per copy
      for (const auto& list : lists_indexed_by(text, "i", c))
        if (long(c.lists.at(list).size()) != n)
          c.fail(key, "'" + list + "[i]' indexes the list parameter " + list + " of " +
                          std::to_string(c.lists.at(list).size()) + " values by a copy number, but count = " +
                          std::to_string(n) + " (give one value per copy)");
    out.push_back(std::move(copy));
  }
  return out;
}

const toml::table* section(const toml::table& root, const char* k, const Reader& c) {
  auto n = root.get(k);
  if (!n) return nullptr;
  auto t = n->as_table();
  if (!t) c.fail(k, "expected a table [" + std::string(k) + "]");
  return t;
}

}  // namespace hapstab::scene
