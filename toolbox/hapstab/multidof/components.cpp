// hapstab/multidof/components.cpp -- see components.hpp.
#include "hapstab/multidof/components.hpp"

#include <numeric>

#include "hapstab/multidof/symmetry.hpp"
#include "hapstab/numeric/error.hpp"

namespace hapstab::multidof {

namespace {

struct UnionFind {
  std::vector<int> parent;
  explicit UnionFind(int n) : parent(static_cast<size_t>(n)) { std::iota(parent.begin(), parent.end(), 0); }
  int find(int a) {
    while (parent[static_cast<size_t>(a)] != a) a = parent[static_cast<size_t>(a)] = parent[static_cast<size_t>(parent[static_cast<size_t>(a)])];
    return a;
  }
  void join(int a, int b) { parent[static_cast<size_t>(find(a))] = find(b); }
};

MatQ sub(const MatQ& M, const std::vector<int>& rows, const std::vector<int>& cols) {
  MatQ S(static_cast<Eigen::Index>(rows.size()), static_cast<Eigen::Index>(cols.size()));
  for (size_t i = 0; i < rows.size(); ++i)
    for (size_t j = 0; j < cols.size(); ++j) S(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(j)) = M(rows[i], cols[j]);
  return S;
}

}  // namespace

std::vector<Component> components(const Problem& pb) {
  const StateSpace<rational>& E = pb.E;
  const int m = static_cast<int>(E.inputs()), n = static_cast<int>(E.states());
  // nodes: DOF k -> k, state i -> m + i
  UnionFind uf(m + n);
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j)
      if (E.A(i, j) != 0) uf.join(m + i, m + j);
  for (int i = 0; i < n; ++i)
    for (int k = 0; k < m; ++k) {
      if (E.B(i, k) != 0) uf.join(m + i, k);
      if (E.C(k, i) != 0) uf.join(k, m + i);
    }
  for (int k = 0; k < m; ++k)
    for (int l = 0; l < m; ++l)
      if (E.D(k, l) != 0) uf.join(k, l);
  const auto sizes = pb.structure.operator_sizes();
  std::vector<int> op_of(static_cast<size_t>(m));
  for (int o = 0, off = 0; o < static_cast<int>(sizes.size()); off += sizes[static_cast<size_t>(o)], ++o)
    for (int k = off; k < off + sizes[static_cast<size_t>(o)]; ++k) {
      op_of[static_cast<size_t>(k)] = o;
      if (k > off) uf.join(k, off);
    }
  // components in the order of their first DOF
  std::vector<int> index(static_cast<size_t>(m + n), -1);
  std::vector<Component> out;
  for (int k = 0; k < m; ++k) {
    const int r = uf.find(k);
    if (index[static_cast<size_t>(r)] < 0) {
      index[static_cast<size_t>(r)] = static_cast<int>(out.size());
      out.emplace_back();
    }
    Component& c = out[static_cast<size_t>(index[static_cast<size_t>(r)])];
    c.dofs.push_back(k);
    if (c.operators.empty() || c.operators.back() != op_of[static_cast<size_t>(k)]) c.operators.push_back(op_of[static_cast<size_t>(k)]);
  }
  for (int i = 0; i < n; ++i) {
    const int r = uf.find(m + i);
    if (index[static_cast<size_t>(r)] < 0) {  // a state no DOF reaches (not minimal): do not split
      out.clear();
      break;
    }
    out[static_cast<size_t>(index[static_cast<size_t>(r)])].states.push_back(i);
  }
  if (out.size() <= 1) {
    Component whole;
    whole.dofs.resize(static_cast<size_t>(m));
    std::iota(whole.dofs.begin(), whole.dofs.end(), 0);
    whole.states.resize(static_cast<size_t>(n));
    std::iota(whole.states.begin(), whole.states.end(), 0);
    whole.operators.resize(sizes.size());
    std::iota(whole.operators.begin(), whole.operators.end(), 0);
    whole.problem = pb;
    return {whole};
  }
  for (Component& c : out) {
    Problem& p = c.problem;
    p.qv_block_diagonal = pb.qv_block_diagonal;
    p.E.T = E.T;
    p.E.A = sub(E.A, c.states, c.states);
    p.E.B = sub(E.B, c.states, c.dofs);
    p.E.C = sub(E.C, c.dofs, c.states);
    p.E.D = sub(E.D, c.dofs, c.dofs);
    for (int o : c.operators) p.structure.operators.push_back(pb.structure.operators[static_cast<size_t>(o)]);
  }
  return out;
}

Problem direct_sum(const Problem& a, const Problem& b) {
  if (a.E.T != b.E.T) throw InputError("direct_sum: the two environments have different sample periods");
  const StateSpace<rational>&Ea = a.E, &Eb = b.E;
  const Eigen::Index na = Ea.states(), nb = Eb.states(), ma = Ea.inputs(), mb = Eb.inputs();
  Problem p;
  p.qv_block_diagonal = a.qv_block_diagonal;
  p.E.T = Ea.T;
  p.E.A = MatQ::Zero(na + nb, na + nb);
  p.E.B = MatQ::Zero(na + nb, ma + mb);
  p.E.C = MatQ::Zero(Ea.outputs() + Eb.outputs(), na + nb);
  p.E.D = MatQ::Zero(Ea.outputs() + Eb.outputs(), ma + mb);
  p.E.A.topLeftCorner(na, na) = Ea.A;
  p.E.A.bottomRightCorner(nb, nb) = Eb.A;
  p.E.B.topLeftCorner(na, ma) = Ea.B;
  p.E.B.bottomRightCorner(nb, mb) = Eb.B;
  p.E.C.topLeftCorner(Ea.outputs(), na) = Ea.C;
  p.E.C.bottomRightCorner(Eb.outputs(), nb) = Eb.C;
  p.E.D.topLeftCorner(Ea.outputs(), ma) = Ea.D;
  p.E.D.bottomRightCorner(Eb.outputs(), mb) = Eb.D;
  p.structure.operators = a.structure.operators;
  for (const auto& o : b.structure.operators) p.structure.operators.push_back(o);
  return p;
}

std::string component_name(const Problem& whole, const Component& c) {
  std::string s = "{";
  for (size_t i = 0; i < c.operators.size(); ++i) {
    if (i == 3 && c.operators.size() > 4) {
      s += ", ..., " + whole.structure.operators[static_cast<size_t>(c.operators.back())].name;
      break;
    }
    s += (i ? ", " : "") + whole.structure.operators[static_cast<size_t>(c.operators[i])].name;
  }
  return s + "} (" + std::to_string(c.dofs.size()) + " DOF, " + std::to_string(c.states.size()) + " states)";
}

StoredPoint assemble_components(const Problem& pb, const std::vector<Component>& comps, const std::vector<ExactPoint>& points) {
  const Eigen::Index m = pb.structure.m();
  std::vector<ExactStorage> parts;
  Eigen::Index N = 0;
  for (size_t k = 0; k < comps.size(); ++k) {
    parts.push_back(exact_storage(comps[k].problem, points[k]));
    N += parts.back().Ehat.A.rows();
  }
  StoredPoint out;
  auto& E = out.st.Ehat;
  E.T = pb.E.T;
  E.A = MatQ::Zero(N, N), E.B = MatQ::Zero(N, m), E.C = MatQ::Zero(m, N), E.D = MatQ::Zero(m, m), out.st.P = MatQ::Zero(N, N);
  out.X = out.QE = out.QV = MatQ::Zero(m, m);
  Eigen::Index at = 0;
  for (size_t k = 0; k < comps.size(); ++k) {
    const auto& s = parts[k];
    const auto& x = points[k];
    const auto& d = comps[k].dofs;
    const Eigen::Index n = s.Ehat.A.rows();
    E.A.block(at, at, n, n) = s.Ehat.A;
    out.st.P.block(at, at, n, n) = s.P;
    for (size_t i = 0; i < d.size(); ++i) {
      const auto I = static_cast<Eigen::Index>(i);
      E.B.block(at, d[i], n, 1) = s.Ehat.B.col(I);
      E.C.block(d[i], at, 1, n) = s.Ehat.C.row(I);
      for (size_t j = 0; j < d.size(); ++j) {
        const auto J = static_cast<Eigen::Index>(j);
        E.D(d[i], d[j]) = s.Ehat.D(I, J);
        out.X(d[i], d[j]) = x.X(I, J);
        out.QE(d[i], d[j]) = x.QE(I, J);
        out.QV(d[i], d[j]) = x.QV(I, J);
      }
    }
    at += n;
  }
  return out;
}

std::optional<StoredPoint> stored_point(const Problem& pb, const AnalysisResult& r) {
  if (r.exact_point) return StoredPoint{exact_storage(pb, *r.exact_point), r.exact_point->X, r.exact_point->QE, r.exact_point->QV};
  if (r.symmetry) return lift_point(*r.symmetry, pb.structure.m());
  if (r.components.empty()) return std::nullopt;
  const std::vector<Component> comps = components(pb);
  std::vector<ExactPoint> points;
  for (size_t k = 0; k < comps.size(); ++k) {
    if (k >= r.components.size() || r.components[k].dofs != comps[k].dofs || !r.components[k].exact_point)
      return std::nullopt;  // (the analysis split another way, or a component holds no point)
    points.push_back(*r.components[k].exact_point);
  }
  return assemble_components(pb, comps, points);
}

}  // namespace hapstab::multidof
