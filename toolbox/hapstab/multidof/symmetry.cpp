// hapstab/multidof/symmetry.cpp -- see symmetry.hpp.
#include "hapstab/multidof/symmetry.hpp"

#include <chrono>
#include <cmath>
#include <sstream>

#include "hapstab/lmi/certify.hpp"
#include "hapstab/numeric/result.hpp"
#include "hapstab/numeric/error.hpp"
#include "hapstab/stability/symmetry.hpp"

namespace hapstab::multidof {

namespace {

/// The one-DOF operator of each DOF (the structure's operator index); nullopt (why) when an
/// operator has more than one DOF.
std::optional<std::vector<int>> operator_of_dof(const Structure& st, std::string& why) {
  std::vector<int> of;
  for (size_t k = 0; k < st.operators.size(); ++k) {
    if (st.operators[k].dof != 1) {
      why = "operator '" + st.operators[k].name + "' has " + std::to_string(st.operators[k].dof) +
            " DOFs (X = g I over them: the split needs one multiplier per DOF)";
      return std::nullopt;
    }
    of.push_back(static_cast<int>(k));
  }
  return of;
}

/// A block's problem: these DOFs' operators (one per class: its first DOF), E reduced and delayed
/// as the whole's is (scene_multidof.hpp).
Problem block_problem(const SceneProblem& sp, const std::vector<int>& op_of, const std::vector<int>& dofs,
                      const StateSpace<rational>& E) {
  Problem pb;
  for (int i : dofs) pb.structure.operators.push_back(sp.problem.structure.operators[static_cast<size_t>(op_of[static_cast<size_t>(i)])]);
  pb.E = minreal(E);
  if (sp.delay > 0) pb.E = minreal(delayed(pb.E, sp.delay));
  return pb;
}

rational osp_of(const Operator& op) { return op.devices.at(0).osp(0, 0); }

}  // namespace

std::optional<SymmetryResult> split_problem(const SceneProblem& sp, std::string& why_not) {
  why_not.clear();
  if (sp.problem.qv_block_diagonal) {
    why_not = "Q_V block diagonal (Remark 3): a lifted Q_V is not diagonal";
    return std::nullopt;
  }
  const auto op_of = operator_of_dof(sp.problem.structure, why_not);
  if (!op_of) return std::nullopt;
  const auto loop = stability::detail::split_by_symmetry(sp.loop, why_not);
  if (!loop) return std::nullopt;
  SymmetryResult s;
  s.classes = loop->classes;
  s.group = loop->group();
  const auto& ops = sp.problem.structure.operators;
  for (const auto& c : s.classes)
    for (int i : c)
      if (osp_of(ops[static_cast<size_t>((*op_of)[static_cast<size_t>(i)])]) !=
          osp_of(ops[static_cast<size_t>((*op_of)[static_cast<size_t>(c[0])])])) {
        why_not = "the OSP levels of DOFs " + std::to_string(c[0] + 1) + " and " + std::to_string(i + 1) +
                  " differ although their devices are alike (multidof.osp)";
        return std::nullopt;
      }
  std::vector<int> firsts;
  for (const auto& c : s.classes) firsts.push_back(c[0]);
  SymmetryBlock f;
  f.name = "the fixed space (" + std::to_string(firsts.size()) + " DOF, one per class)";
  f.problem = block_problem(sp, *op_of, firsts, *loop->fixed.environment);
  s.blocks.push_back(std::move(f));
  for (size_t k = 0; k < loop->standard.size(); ++k) {
    const int a = loop->standard_class[k];
    SymmetryBlock b;
    b.cls = a;
    b.copies = static_cast<int>(s.classes[static_cast<size_t>(a)].size()) - 1;
    b.name = "class " + std::to_string(a + 1) + "'s zero-sum space (1 DOF, " + std::to_string(b.copies) +
             (b.copies == 1 ? " copy)" : " copies)");
    b.problem = block_problem(sp, *op_of, {s.classes[static_cast<size_t>(a)][0]}, *loop->standard[k].environment);
    s.blocks.push_back(std::move(b));
  }
  return s;
}

namespace {

/// A block's infeasibility that holds for the whole (symmetry.hpp): a witness (one frequency or
/// several) or the facial conditions -- each a statement about E-hat's transfer matrix, not
/// about a realisation. A Farkas vector is about the block's realisation only: not lifted.
bool lifts_infeasibility(const AnalysisResult& r) {
  return r.verdict.fails() && r.verdict.proven() && (r.witness || r.weighted_witness || r.path == "facial conditions");
}

}  // namespace

std::vector<rational> lift_direction(const SymmetryResult& s, const SymmetryBlock& b, const std::vector<rational>& u, int m) {
  std::vector<rational> out(static_cast<size_t>(m), rational(0));
  if (b.cls < 0) {  // the fixed space: u's entry of class c on every DOF of c
    for (size_t c = 0; c < s.classes.size(); ++c)
      for (int i : s.classes[c]) out[static_cast<size_t>(i)] = u.at(c);
  } else {  // a class's zero-sum space: u (e_i - e_j), i, j its first two DOFs
    const auto& cls = s.classes[static_cast<size_t>(b.cls)];
    out[static_cast<size_t>(cls[0])] = u.at(0);
    out[static_cast<size_t>(cls[1])] = -u.at(0);
  }
  return out;
}

std::optional<AnalysisResult> analyze_by_symmetry(const SceneProblem& sp, SymmetryResult split, const lmi::Options& opt,
                                                  std::string& why_not) {
  const auto t0 = std::chrono::steady_clock::now();
  double sdp = 0;
  const SymmetryBlock* infeasible = nullptr;
  for (SymmetryBlock& b : split.blocks) {
    try {
      b.result = analyze(b.problem, opt);
    } catch (const InputError& e) {  // the block's own premise (its size, E's stability): the whole decides
      why_not = b.name + ": " + e.what();
      return std::nullopt;
    }
    b.analysed = true;
    sdp += b.result.sdp_seconds;
    if (lifts_infeasibility(b.result)) {
      infeasible = &b;
      break;
    }
    if (!(b.result.verdict.holds() && b.result.verdict.proven() && stored_point(b.problem, b.result))) {
      why_not = b.name + ": " + lmi::to_string(lmi::feasibility_of(b.result.verdict.outcome)) + " [" +
                to_string(b.result.verdict.status) + "] (" + b.result.verdict.evidence.substr(0, 160) +
                "...); the split decides a feasible (16), or an infeasible one by a witness or the facial conditions";
      return std::nullopt;
    }
  }
  const int m = sp.problem.structure.m();
  AnalysisResult res;
  res.path = "symmetry";
  res.plan.push_back({"symmetry of identical DOFs", "decided", ""});
  res.facial.symmetric_possible = !infeasible || infeasible->result.path != "facial conditions";
  if (infeasible) {
    // whole feasible => for every X = diag(g) of it, phi(z, u) > 0 at every lifted u (symmetry.hpp):
    // E-hat maps the lifted u as the block does, so the whole's phi is a positive multiple of the
    // block's at an X the block admits -- which the block's witness makes <= 0
    res.verdict = {Outcome::fails, Status::exact,
                   "infeasible by the symmetry " + split.group + ": " + infeasible->name + " is infeasible (" +
                       infeasible->result.verdict.evidence + "), and a block's witness or facial condition holds for "
                       "the whole (multidof/symmetry.hpp)"};
    res.facial.explanation = infeasible->name + ": " + infeasible->result.facial.explanation;
    res.solver_detail = "split by " + split.group + "; " + infeasible->name + ": " + infeasible->result.solver_detail;
  } else {
    const StoredPoint lifted = lift_point(split, m, true);  // the whole realisation and P: for --certificate only
    std::ostringstream ev;
    ev << "feasible by the symmetry " << split.group << ": the program splits into " << split.blocks.size()
       << " blocks whose points lift to one point of the whole (multidof/symmetry.hpp), each re-checked exactly:";
    for (const auto& b : split.blocks)
      ev << " " << b.name << " by the " << b.result.path << " path" << (&b == &split.blocks.back() ? "" : ";");
    res.verdict = {Outcome::holds, Status::exact, ev.str()};
    res.solver_detail = "split by " + split.group + "; " + split.blocks[0].name + ": " + split.blocks[0].result.solver_detail;
    res.facial.explanation = "facial reduction per block (the fixed space: " + split.blocks[0].result.facial.explanation + ")";
    res.X = to_double(lifted.X);
    res.Q_E = to_double(lifted.QE);
    res.Q_V = to_double(lifted.QV);
    res.gamma.resize(static_cast<size_t>(m));
    res.gamma_sqrt.resize(static_cast<size_t>(m));
    Eigen::MatrixXd Gi = Eigen::MatrixXd::Zero(m, m);
    for (int i = 0; i < m; ++i) {
      res.gamma[static_cast<size_t>(i)] = res.X(i, i);
      res.gamma_sqrt[static_cast<size_t>(i)] = std::sqrt(res.X(i, i));
      Gi(i, i) = 1 / res.gamma_sqrt[static_cast<size_t>(i)];
    }
    res.delta_V = Gi * res.Q_V * Gi;
    res.margin = split.blocks[0].result.margin;
    for (const auto& b : split.blocks) res.margin = std::min(res.margin, b.result.margin);
  }
  res.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  res.sdp_seconds = sdp;
  res.symmetry = std::make_shared<const SymmetryResult>(std::move(split));
  return res;
}

StoredPoint lift_point(const SymmetryResult& s, int m, bool multipliers_only) {
  const size_t r = s.classes.size();
  std::vector<int> class_of(static_cast<size_t>(m), -1);
  for (size_t c = 0; c < r; ++c)
    for (int i : s.classes[c]) class_of[static_cast<size_t>(i)] = static_cast<int>(c);
  const SymmetryBlock& fb = s.blocks.at(0);
  const StoredPoint f = *stored_point(fb.problem, fb.result);
  // sigma = max(1, max_c k_c / gamma_c): g_c = sigma gamma_c / k_c >= 1
  rational sigma(1);
  std::vector<rational> g(r);
  const auto k_of = [&](size_t c) { return rational(static_cast<long>(s.classes[c].size())); };
  for (size_t c = 0; c < r; ++c) {
    const rational gc = f.X(static_cast<Eigen::Index>(c), static_cast<Eigen::Index>(c));
    if (k_of(c) / gc > sigma) sigma = k_of(c) / gc;
  }
  for (size_t c = 0; c < r; ++c) g[c] = sigma * f.X(static_cast<Eigen::Index>(c), static_cast<Eigen::Index>(c)) / k_of(c);
  // the standard blocks' points; E-hat's realisation: the blocks' put back together
  std::vector<std::optional<StoredPoint>> std_pt(r);
  std::vector<const StateSpace<rational>*> ehat(r, nullptr);
  for (size_t k = 1; k < s.blocks.size(); ++k) {
    const auto& b = s.blocks[k];
    std_pt[static_cast<size_t>(b.cls)] = *stored_point(b.problem, b.result);
    ehat[static_cast<size_t>(b.cls)] = &std_pt[static_cast<size_t>(b.cls)]->st.Ehat;
  }
  StoredPoint out;
  const Eigen::Index nf = f.st.Ehat.A.rows();
  if (!multipliers_only) {
    out.st.Ehat = stability::detail::lift_realisation(s.classes, f.st.Ehat, ehat, m);
    const Eigen::Index n = out.st.Ehat.A.rows();
    out.st.P = MatQ::Zero(n, n);
    // the fixed block's point scaled by sigma
    out.st.P.topLeftCorner(nf, nf) = sigma * f.st.P;
  }
  out.X = out.QE = out.QV = MatQ::Zero(m, m);
  // Q = S^-T Q_b S^-1 on the fixed space: Q_f(c, d) / (k_c k_d)
  for (int i = 0; i < m; ++i) {
    const auto c = static_cast<size_t>(class_of[static_cast<size_t>(i)]);
    out.X(i, i) = g[c];
    for (int k = 0; k < m; ++k) {
      const auto d = static_cast<size_t>(class_of[static_cast<size_t>(k)]);
      const auto C = static_cast<Eigen::Index>(c), Dd = static_cast<Eigen::Index>(d);
      out.QE(i, k) = sigma * f.QE(C, Dd) / (k_of(c) * k_of(d));
      out.QV(i, k) = sigma * f.QV(C, Dd) / (k_of(c) * k_of(d));
    }
  }
  // each class's copies (in lift_realisation's order), scaled by t_aj = g_a j (j + 1) / gamma_a;
  // their Q summed over the copies in closed form: (g_a / gamma_a) q_a (delta_ik - 1/k_a)
  Eigen::Index at = nf;
  for (size_t a = 0; a < r; ++a) {
    if (!std_pt[a]) continue;
    const StoredPoint& p = *std_pt[a];
    const auto& cls = s.classes[a];
    const Eigen::Index na = p.st.Ehat.A.rows();
    const rational ratio = g[a] / p.X(0, 0);
    for (size_t j = 1; j < cls.size() && !multipliers_only; ++j, at += na)
      out.st.P.block(at, at, na, na) = (ratio * rational(static_cast<long>(j * (j + 1)))) * p.st.P;
    for (int i : cls)
      for (int k : cls) {
        const rational w = (i == k ? rational(1) : rational(0)) - 1 / k_of(a);
        out.QE(i, k) += ratio * p.QE(0, 0) * w;
        out.QV(i, k) += ratio * p.QV(0, 0) * w;
      }
  }
  return out;
}

nlohmann::json symmetry_json(const AnalysisResult& r) {
  if (!r.symmetry) return nullptr;
  nlohmann::json blocks = nlohmann::json::array();
  for (const auto& b : r.symmetry->blocks)
    blocks.push_back({{"name", b.name}, {"copies", b.copies}, {"dofs", b.problem.structure.m()},
                      {"states", b.problem.E.states()}, {"path", b.result.path},
                      {"verdict", b.analysed ? lmi::to_string(lmi::feasibility_of(b.result.verdict.outcome)) : "not needed"},
                      {"certified", b.analysed && b.result.verdict.proven()},
                      {"seconds", b.result.seconds}});
  nlohmann::json classes = nlohmann::json::array();
  for (const auto& c : r.symmetry->classes) classes.push_back(c);
  return {{"group", r.symmetry->group}, {"classes", classes}, {"blocks", blocks}};
}

}  // namespace hapstab::multidof
