// The loop as written split by the permutations of its identical DOFs (see symmetry.hpp).
#include "hapstab/stability/symmetry.hpp"

#include <map>
#include <numeric>
#include <set>

namespace hapstab::stability::detail {

namespace {

using MatQ = Mat<rational>;

bool same(const MatQ& a, const MatQ& b) { return a.rows() == b.rows() && a.cols() == b.cols() && a == b; }
bool same(const StateSpace<rational>& a, const StateSpace<rational>& b) {
  return a.T == b.T && same(a.A, b.A) && same(a.B, b.B) && same(a.C, b.C) && same(a.D, b.D);
}

/// The states of a block's realisation that belong to each input column: the connected
/// components of A's graph fed (B's rows) by exactly one column. A component no input feeds is
/// left out: it is isolated, so the closed loop is block triangular over it and its eigenvalues
/// are the block's uncontrollable modes, which decide_loop's step 1 has proven stable (the
/// caller's premise). nullopt (why) when a component is fed by two columns.
std::optional<std::vector<std::vector<Eigen::Index>>> column_states(const StateSpace<rational>& E, std::string& why) {
  const Eigen::Index n = E.states();
  std::vector<Eigen::Index> parent(static_cast<size_t>(n));
  std::iota(parent.begin(), parent.end(), Eigen::Index(0));
  auto root = [&](Eigen::Index i) {
    while (parent[static_cast<size_t>(i)] != i) i = parent[static_cast<size_t>(i)] = parent[static_cast<size_t>(parent[static_cast<size_t>(i)])];
    return i;
  };
  for (Eigen::Index i = 0; i < n; ++i)
    for (Eigen::Index k = 0; k < n; ++k)
      if (E.A(i, k) != 0) parent[static_cast<size_t>(root(i))] = root(k);
  std::map<Eigen::Index, Eigen::Index> owner;  // component root -> its column
  for (Eigen::Index i = 0; i < n; ++i)
    for (Eigen::Index j = 0; j < E.inputs(); ++j) {
      if (E.B(i, j) == 0) continue;
      const auto [it, fresh] = owner.emplace(root(i), j);
      if (!fresh && it->second != j) {
        why = "mixes the states of its input columns " + std::to_string(it->second + 1) + " and " + std::to_string(j + 1);
        return std::nullopt;
      }
    }
  std::vector<std::vector<Eigen::Index>> cols(static_cast<size_t>(E.inputs()));
  for (Eigen::Index i = 0; i < n; ++i)
    if (const auto it = owner.find(root(i)); it != owner.end()) cols[static_cast<size_t>(it->second)].push_back(i);
  return cols;
}

MatQ rows_cols(const MatQ& M, const std::vector<Eigen::Index>& r, const std::vector<Eigen::Index>& c) {
  MatQ out(static_cast<Eigen::Index>(r.size()), static_cast<Eigen::Index>(c.size()));
  for (size_t i = 0; i < r.size(); ++i)
    for (size_t k = 0; k < c.size(); ++k) out(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(k)) = M(r[i], c[k]);
  return out;
}

/// The operator on each DOF (-1: none); nullopt (why) unless each has one port and each DOF at
/// most one operator, and each device one DOF.
std::optional<std::vector<int>> operators_by_dof(const sim::LoopSpec& spec, std::string& why) {
  for (const auto& d : spec.devices)
    if (d.dofs() != 1) {
      why = "device '" + d.name + "' has " + std::to_string(d.dofs()) + " DOFs";
      return std::nullopt;
    }
  std::vector<int> op_of(static_cast<size_t>(spec.dofs()), -1);
  for (size_t k = 0; k < spec.operators.size(); ++k) {
    const auto& op = spec.operators[k];
    if (op.ports.size() != 1) {
      why = "operator '" + op.name + "' acts on " + std::to_string(op.ports.size()) + " DOFs";
      return std::nullopt;
    }
    int& slot = op_of.at(static_cast<size_t>(op.ports[0]));
    if (slot >= 0) {
      why = "two operators on DOF " + std::to_string(op.ports[0] + 1);
      return std::nullopt;
    }
    slot = static_cast<int>(k);
  }
  return op_of;
}

/// A discrete N x N block of the loop (E, or V) with its states by input column.
struct Block {
  const char* name;
  const StateSpace<rational>* G;
  std::vector<std::vector<Eigen::Index>> cols;
  const std::vector<Eigen::Index>& own(int i) const { return cols[static_cast<size_t>(i)]; }
};
std::vector<Eigen::Index> row(int i) { return {i}; }

/// DOFs i and k alike: device, operator, each block's column and diagonal entry.
bool alike(const sim::LoopSpec& spec, const std::vector<int>& op_of, const std::vector<Block>& blocks, int i, int k) {
  const auto &di = spec.devices[static_cast<size_t>(i)], &dk = spec.devices[static_cast<size_t>(k)];
  if (!same(di.G, dk.G) || di.mass != dk.mass) return false;
  const int oi = op_of[static_cast<size_t>(i)], ok = op_of[static_cast<size_t>(k)];
  if ((oi < 0) != (ok < 0)) return false;
  if (oi >= 0) {
    const auto &a = spec.operators[static_cast<size_t>(oi)], &b = spec.operators[static_cast<size_t>(ok)];
    if (!same(a.Z, b.Z) || a.mass != b.mass) return false;
  }
  for (const Block& b : blocks) {
    const StateSpace<rational>& G = *b.G;
    const auto &ci = b.own(i), &ck = b.own(k);
    if (ci.size() != ck.size() || !same(rows_cols(G.A, ci, ci), rows_cols(G.A, ck, ck)) ||
        !same(rows_cols(G.B, ci, {i}), rows_cols(G.B, ck, {k})) || !same(rows_cols(G.C, row(i), ci), rows_cols(G.C, row(k), ck)) ||
        G.D(i, i) != G.D(k, k))
      return false;
  }
  return true;
}

/// Every off-diagonal entry (row i, column j) of the block equals its class pair's first one;
/// else why names the first that does not.
bool entries_invariant(const Block& b, const std::vector<int>& class_of, size_t r, std::string& why) {
  const StateSpace<rational>& G = *b.G;
  const int N = static_cast<int>(class_of.size());
  std::vector<std::vector<std::optional<std::pair<int, int>>>> first(r, std::vector<std::optional<std::pair<int, int>>>(r));
  for (int i = 0; i < N; ++i)
    for (int j = 0; j < N; ++j) {
      if (i == j) continue;
      auto& f = first[static_cast<size_t>(class_of[static_cast<size_t>(i)])][static_cast<size_t>(class_of[static_cast<size_t>(j)])];
      if (!f) {
        f = std::pair{i, j};
        continue;
      }
      const auto [i0, j0] = *f;
      if (G.D(i, j) != G.D(i0, j0) || !same(rows_cols(G.C, row(i), b.own(j)), rows_cols(G.C, row(i0), b.own(j0)))) {
        why = std::string("the ") + b.name + "'s entry (" + std::to_string(i + 1) + ", " + std::to_string(j + 1) +
              ") differs from (" + std::to_string(i0 + 1) + ", " + std::to_string(j0 + 1) + ") although DOFs " +
              std::to_string(i + 1) + " and " + std::to_string(i0 + 1) + ", " + std::to_string(j + 1) + " and " +
              std::to_string(j0 + 1) + " are alike";
        return false;
      }
    }
  return true;
}

/// The parts of the loop no block couples: i and j in one part when entry (i, j) or (j, i) of
/// some block is not zero (its D entry, or row i of C on column j's states).
std::vector<int> coupled_parts(const std::vector<Block>& blocks, int N) {
  std::vector<int> parent(static_cast<size_t>(N));
  std::iota(parent.begin(), parent.end(), 0);
  auto root = [&](int i) {
    while (parent[static_cast<size_t>(i)] != i) i = parent[static_cast<size_t>(i)] = parent[static_cast<size_t>(parent[static_cast<size_t>(i)])];
    return i;
  };
  for (const Block& b : blocks)
    for (int i = 0; i < N; ++i)
      for (int j = 0; j < N; ++j) {
        if (i == j || root(i) == root(j)) continue;
        bool zero = b.G->D(i, j) == 0;
        for (Eigen::Index k : b.own(j)) zero = zero && b.G->C(i, k) == 0;
        if (!zero) parent[static_cast<size_t>(root(i))] = root(j);
      }
  std::vector<int> part(static_cast<size_t>(N));
  for (int i = 0; i < N; ++i) part[static_cast<size_t>(i)] = root(i);
  return part;
}

/// The block on the fixed space: the states of the classes' first DOFs, its entries summed over
/// each class's columns.
StateSpace<rational> fixed_block(const Block& b, const std::vector<std::vector<int>>& classes) {
  const StateSpace<rational>& G = *b.G;
  const size_t r = classes.size();
  std::vector<Eigen::Index> offset(r + 1, 0);
  for (size_t a = 0; a < r; ++a) offset[a + 1] = offset[a] + static_cast<Eigen::Index>(b.own(classes[a][0]).size());
  const Eigen::Index nf = offset[r], R = static_cast<Eigen::Index>(r);
  StateSpace<rational> F{MatQ::Zero(nf, nf), MatQ::Zero(nf, R), MatQ::Zero(R, nf), MatQ::Zero(R, R), G.T};
  for (size_t a = 0; a < r; ++a) {
    const int i = classes[a][0];
    const Eigen::Index na = offset[a + 1] - offset[a];
    F.A.block(offset[a], offset[a], na, na) = rows_cols(G.A, b.own(i), b.own(i));
    F.B.block(offset[a], static_cast<Eigen::Index>(a), na, 1) = rows_cols(G.B, b.own(i), {i});
    for (size_t c = 0; c < r; ++c)
      for (const int j : classes[c]) {
        F.C.block(static_cast<Eigen::Index>(a), offset[c], 1, offset[c + 1] - offset[c]) += rows_cols(G.C, row(i), b.own(j));
        F.D(static_cast<Eigen::Index>(a), static_cast<Eigen::Index>(c)) += G.D(i, j);
      }
  }
  return F;
}

/// The block on the zero-sum vectors of a class (i != j in it): the column block, the diagonal
/// entry minus the off-diagonal one.
StateSpace<rational> standard_block(const Block& b, int i, int j) {
  const StateSpace<rational>& G = *b.G;
  return StateSpace<rational>{rows_cols(G.A, b.own(i), b.own(i)), rows_cols(G.B, b.own(i), {i}),
                              rows_cols(G.C, row(i), b.own(i)) - rows_cols(G.C, row(i), b.own(j)),
                              MatQ::Constant(1, 1, G.D(i, i) - G.D(i, j)), G.T};
}

/// The devices and operators of these DOFs, renumbered 0.., with the loop's T and delay.
sim::LoopSpec loop_of(const sim::LoopSpec& spec, const std::vector<int>& op_of, const std::vector<int>& dofs) {
  sim::LoopSpec L;
  L.T = spec.T;
  L.delay = spec.delay;
  for (size_t k = 0; k < dofs.size(); ++k) {
    const int i = dofs[k];
    L.devices.push_back(spec.devices[static_cast<size_t>(i)]);
    if (op_of[static_cast<size_t>(i)] < 0) continue;
    sim::OperatorBlock op = spec.operators[static_cast<size_t>(op_of[static_cast<size_t>(i)])];
    op.ports = {static_cast<int>(k)};
    L.operators.push_back(op);
  }
  return L;
}

}  // namespace

std::string LoopSymmetry::group() const {
  std::map<size_t, int> sizes;  // class size -> how many classes
  for (const auto& c : classes)
    if (c.size() >= 2) ++sizes[c.size()];
  std::string g, words;
  for (auto it = sizes.rbegin(); it != sizes.rend(); ++it) {
    g += (g.empty() ? "" : " x ") + ("S_" + std::to_string(it->first)) + (it->second > 1 ? "^" + std::to_string(it->second) : "");
    words += (words.empty() ? "" : ", ") + std::to_string(it->second) + (it->second > 1 ? " classes" : " class") + " of " +
             std::to_string(it->first) + " identical DOFs";
  }
  const size_t singles = classes.size() - static_cast<size_t>(std::accumulate(sizes.begin(), sizes.end(), 0, [](int a, const auto& p) { return a + p.second; }));
  if (singles) words += ", " + std::to_string(singles) + " DOF" + (singles > 1 ? "s" : "") + " alone";
  return g + " (" + words + ")";
}

std::optional<LoopSymmetry> split_by_symmetry(const sim::LoopSpec& spec, std::string& why_not) {
  why_not.clear();
  const int N = spec.dofs();
  if (N < 2 || !spec.environment) return std::nullopt;
  // the reasons below are named only where two devices are alike (an almost symmetric loop)
  bool two_alike = false;
  for (size_t i = 0; i < spec.devices.size() && !two_alike; ++i)
    for (size_t k = i + 1; k < spec.devices.size() && !two_alike; ++k)
      two_alike = same(spec.devices[i].G, spec.devices[k].G) && spec.devices[i].mass == spec.devices[k].mass;
  if (!two_alike) return std::nullopt;
  const auto op_of = operators_by_dof(spec, why_not);
  if (!op_of) return std::nullopt;
  std::vector<Block> blocks{{"environment", &*spec.environment, {}}};
  if (spec.coupling) blocks.push_back({"coupling", &*spec.coupling, {}});
  for (Block& b : blocks) {
    auto cols = column_states(*b.G, why_not);
    if (!cols) {
      why_not = std::string("the ") + b.name + "'s realisation " + why_not;
      return std::nullopt;
    }
    b.cols = std::move(*cols);
  }
  LoopSymmetry s;
  std::vector<int> class_of(static_cast<size_t>(N));
  // classes of alike DOFs; where their entries are not invariant, the same within each part of
  // the loop that no block couples to the rest (separate objects: the classes never mix two)
  std::vector<int> part(static_cast<size_t>(N), 0);
  for (int pass = 0; pass < 2; ++pass) {
    s.classes.clear();
    for (int i = 0; i < N; ++i) {
      size_t a = 0;
      while (a < s.classes.size() && (part[static_cast<size_t>(s.classes[a][0])] != part[static_cast<size_t>(i)] ||
                                      !alike(spec, *op_of, blocks, s.classes[a][0], i)))
        ++a;
      if (a == s.classes.size()) s.classes.emplace_back();
      s.classes[a].push_back(i);
      class_of[static_cast<size_t>(i)] = static_cast<int>(a);
    }
    if (s.classes.size() == static_cast<size_t>(N)) return std::nullopt;  // no two DOFs alike: nothing to name
    bool invariant = true;
    for (const Block& b : blocks) invariant = invariant && entries_invariant(b, class_of, s.classes.size(), why_not);
    if (invariant) break;
    const std::vector<int> parts = coupled_parts(blocks, N);
    if (pass == 1 || parts == part || std::set<int>(parts.begin(), parts.end()).size() == 1) return std::nullopt;
    part = parts;
    why_not.clear();
  }
  std::vector<bool> in_column(static_cast<size_t>(spec.environment->states()), false);
  for (const auto& c : blocks[0].cols)
    for (Eigen::Index k : c) in_column[static_cast<size_t>(k)] = true;
  for (Eigen::Index k = 0; k < spec.environment->states(); ++k)
    if (!in_column[static_cast<size_t>(k)]) s.isolated.push_back(k);
  std::vector<int> firsts;
  for (const auto& c : s.classes) firsts.push_back(c[0]);
  s.fixed = loop_of(spec, *op_of, firsts);
  s.fixed.environment = fixed_block(blocks[0], s.classes);
  if (spec.coupling) s.fixed.coupling = fixed_block(blocks[1], s.classes);
  for (size_t a = 0; a < s.classes.size(); ++a) {
    if (s.classes[a].size() < 2) continue;
    const int i = s.classes[a][0], j = s.classes[a][1];
    sim::LoopSpec L = loop_of(spec, *op_of, {i});
    L.environment = standard_block(blocks[0], i, j);
    if (spec.coupling) L.coupling = standard_block(blocks[1], i, j);
    s.standard.push_back(std::move(L));
    s.standard_class.push_back(static_cast<int>(a));
  }
  return s;
}

namespace {
/// h_j(i) of multidof/symmetry.hpp for class `c` (its DOFs in order): 1 before position j, -j at j.
rational helmert(const std::vector<int>& c, size_t j, int dof) {
  for (size_t l = 0; l <= j; ++l)
    if (c[l] == dof) return l < j ? rational(1) : rational(-static_cast<long>(j));
  return rational(0);
}
}  // namespace

StateSpace<rational> lift_realisation(const std::vector<std::vector<int>>& classes, const StateSpace<rational>& fixed,
                                      const std::vector<const StateSpace<rational>*>& standard, int m) {
  const size_t r = classes.size();
  std::vector<int> class_of(static_cast<size_t>(m), -1);
  for (size_t c = 0; c < r; ++c)
    for (int i : classes[c]) class_of[static_cast<size_t>(i)] = static_cast<int>(c);
  Eigen::Index n = fixed.states();
  for (size_t a = 0; a < r; ++a)
    if (standard[a]) n += standard[a]->states() * static_cast<Eigen::Index>(classes[a].size() - 1);
  StateSpace<rational> E{MatQ::Zero(n, n), MatQ::Zero(n, m), MatQ::Zero(m, n), MatQ::Zero(m, m), fixed.T};
  // the fixed block: its input c is 1_c^T u / k_c, its output c reaches every DOF of class c
  const Eigen::Index nf = fixed.states();
  E.A.topLeftCorner(nf, nf) = fixed.A;
  for (int i = 0; i < m; ++i) {
    const auto c = static_cast<Eigen::Index>(class_of[static_cast<size_t>(i)]);
    E.B.block(0, i, nf, 1) = fixed.B.col(c) / rational(static_cast<long>(classes[static_cast<size_t>(c)].size()));
    E.C.block(i, 0, 1, nf) = fixed.C.row(c);
    for (int k = 0; k < m; ++k) {
      const auto d = static_cast<Eigen::Index>(class_of[static_cast<size_t>(k)]);
      E.D(i, k) = fixed.D(c, d) / rational(static_cast<long>(classes[static_cast<size_t>(d)].size()));
    }
  }
  // each class's zero-sum copies: input h_j^T u / (j (j + 1)), output h_j
  Eigen::Index at = nf;
  for (size_t a = 0; a < r; ++a) {
    if (!standard[a]) continue;
    const StateSpace<rational>& z = *standard[a];
    const auto& cls = classes[a];
    const Eigen::Index na = z.states();
    for (size_t j = 1; j < cls.size(); ++j) {
      const rational jj(static_cast<long>(j * (j + 1)));
      E.A.block(at, at, na, na) = z.A;
      for (size_t l = 0; l <= j; ++l) {
        const int i = cls[l];
        const rational h = helmert(cls, j, i);
        E.B.block(at, i, na, 1) = z.B.col(0) * (h / jj);
        E.C.block(i, at, 1, na) = z.C.row(0) * h;
      }
      at += na;
    }
    // D: d_a sum_j h_j h_j^T / |h_j|^2 = d_a (I - 1 1^T / k_a) on the class
    const rational ka(static_cast<long>(cls.size()));
    for (int i : cls)
      for (int k : cls) E.D(i, k) += z.D(0, 0) * ((i == k ? rational(1) : rational(0)) - 1 / ka);
  }
  return E;
}

HiddenModes environment_hidden_modes(const LoopSymmetry& s, const StateSpace<rational>& E) {
  HiddenModes h;
  const HiddenModes f = hidden_modes(*s.fixed.environment);
  h.uncontrollable = f.uncontrollable;
  h.unobservable = f.unobservable;
  // z = 1 semisimple in the hidden parts (lti/realization.hpp, hidden_marginal_semisimple) iff in each part
  // of the direct sum (multiplicities add; the Kalman subspaces split with it)
  bool semisimple = hidden_marginal_semisimple(*s.fixed.environment);
  std::vector<std::optional<HiddenModes>> by_class(s.classes.size());
  std::vector<const StateSpace<rational>*> minimal(s.classes.size(), nullptr);
  for (size_t k = 0; k < s.standard.size(); ++k) {
    const auto a = static_cast<size_t>(s.standard_class[k]);
    by_class[a] = hidden_modes(*s.standard[k].environment);
    const int copies = static_cast<int>(s.classes[a].size()) - 1;
    h.uncontrollable.multiply(by_class[a]->uncontrollable, copies);
    h.unobservable.multiply(by_class[a]->unobservable, copies);
    semisimple = semisimple && hidden_marginal_semisimple(*s.standard[k].environment);
    minimal[a] = &by_class[a]->minimal;
  }
  if (!s.isolated.empty()) {  // no input reaches them: uncontrollable, all of them
    MatQ Ai(static_cast<Eigen::Index>(s.isolated.size()), static_cast<Eigen::Index>(s.isolated.size()));
    for (size_t i = 0; i < s.isolated.size(); ++i)
      for (size_t k = 0; k < s.isolated.size(); ++k)
        Ai(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(k)) = E.A(s.isolated[i], s.isolated[k]);
    h.uncontrollable.multiply(charpoly(Ai).monic());
    semisimple = semisimple && semisimple_eigenvalue(Ai, rational(1));  // all uncontrollable: the quotient is Ai
  }
  h.marginal_semisimple = semisimple;
  h.minimal = lift_realisation(s.classes, f.minimal, minimal, static_cast<int>(E.inputs()));
  return h;
}

}  // namespace hapstab::stability::detail
