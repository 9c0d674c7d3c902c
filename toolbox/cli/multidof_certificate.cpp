// cli/multidof_certificate.cpp -- see multidof_certificate.hpp.
#include "cli/multidof_certificate.hpp"

#include <algorithm>
#include <optional>
#include <utility>
#include <vector>

#include "cli/certificate.hpp"
#include "hapstab/check/certificate.hpp"
#include "hapstab/check/multidof_model.hpp"
#include "hapstab/lti/parse.hpp"
#include "hapstab/multidof/assumptions.hpp"
#include "hapstab/multidof/components.hpp"
#include "hapstab/multidof/symmetry.hpp"
#include "hapstab/numeric/error.hpp"
#include "hapstab/poly/roots.hpp"
#include "hapstab/scene/schema.hpp"

namespace hapstab::cli {

namespace {

const toml::table* environment_table(const scene::Scene& sc) { return sc.root["environment"].as_table(); }

// A mass-damper 1/(m s + b) (one DOF): (m, b), exactly as the scene reader realised it.
std::optional<std::pair<rational, rational>> mass_damper(const sim::DeviceBlock& dev) {
  if (!dev.mass || dev.dofs() != 1 || dev.G.states() != 1) return std::nullopt;
  return std::make_pair(1 / dev.G.B(0, 0), -dev.G.A(0, 0) / dev.G.B(0, 0));
}

// The environment's gain (a number or a parameter's name), exactly.
rational gain_of(const scene::Scene& sc, const toml::table& env) {
  const toml::node* g = env.get("gain");
  if (!g) return rational(1);
  if (const auto* i = g->as_integer()) return rational(i->get());
  const auto* s = g->as_string();
  if (!s) throw InputError("--certificate: environment.gain is neither an integer nor a string");
  ParseOptions po;
  po.variable = 'z';
  po.T = sc.T;
  po.parameters = sc.parameters;
  const TransferFunction G = parse_tf(s->get(), po);
  if (G.num().degree() > 0 || G.den().degree() > 0) throw InputError("--certificate: environment.gain is not a number");
  return G.num().coeff(0) / G.den().coeff(0);
}

}  // namespace

std::string multidof_certificate_premise(const scene::Scene& sc) {
  const toml::table* env = environment_table(sc);
  if (!env) return "the scene has no [environment]";
  const auto ss = scene::environment_ss_as_written(sc);
  if (!scene::environment_expressions(sc) && !ss) return "the environment is written neither by expressions nor as `ss`";
  if (ss && ss->states() == 0) return "the environment's `ss` has no states (write it as tf: a certificate's ss holds at least one)";
  if (ss && ss->states() > static_cast<long>(check::multidof_model::max_ss_states))
    return "the environment's `ss` has " + std::to_string(ss->states()) + " states, beyond the checkers' limit of " +
           std::to_string(check::multidof_model::max_ss_states) + " (its transfer matrix is taken exactly)";
  long dofs = 0;
  for (const auto& dev : sc.loop.devices) dofs += dev.dofs();
  if (dofs > static_cast<long>(check::multidof_model::max_dofs))
    return std::to_string(dofs) + " DOFs, beyond the checkers' limit of " + std::to_string(check::multidof_model::max_dofs) +
           " (the model holds E's entries written out, m^2 of them)";
  const auto md = scene::multidof_values(sc);
  if (md.qv_block_diagonal)
    return "multidof.qv_block_diagonal = true restricts Q_V, which the certificate kinds take free (Remark 3): a "
           "certificate would claim another program";
  if (!md.osp)
    for (const auto& dev : sc.loop.devices)
      if (!mass_damper(dev))
        return "device '" + dev.name + "' is not a mass-damper and declares no `osp`: its OSP level is a certified "
               "bound, not an exact number a certificate can hold";
  return "";
}

namespace {

nlohmann::json strings(const std::vector<rational>& v) {
  nlohmann::json a = nlohmann::json::array();
  for (const auto& x : v) a.push_back(x.str());
  return a;
}

// The model as the scene writes it (multidof_certificate_premise holds).
nlohmann::json scene_model(const scene::Scene& sc, const multidof::SceneProblem& sp) {
  const toml::table& env = *environment_table(sc);
  nlohmann::json e{{"domain", env["domain"].value_or(std::string("z"))}, {"gain", gain_of(sc, env).str()}};
  if (const auto ss = scene::environment_ss_as_written(sc))  // the realisation as written, its gain apart
    e["ss"] = {{"A", matrix_json(ss->A)}, {"B", matrix_json(ss->B)}, {"C", matrix_json(ss->C)}, {"D", matrix_json(ss->D)}};
  else
    e["E"] = *scene::environment_expressions(sc);  // compact entries written out, lists by value
  if (e["domain"] == "s") e["method"] = env["method"].value_or(std::string());
  nlohmann::json set = nlohmann::json::object();
  for (const auto& [k, v] : sc.parameters) set[k] = v.str();
  const auto md = scene::multidof_values(sc);
  if (md.perturb_C) {  // C_E := Pi C_E, D_E unchanged: the checkers take E' = Pi (E - E(inf)) + E(inf)
    nlohmann::json pi = nlohmann::json::array();
    for (const auto& row : *md.perturb_C) pi.push_back(strings(row));
    e["perturb_C"] = pi;
  }
  nlohmann::json devices = nlohmann::json::array();
  for (size_t d = 0; d < sc.loop.devices.size(); ++d) {
    const auto& dev = sc.loop.devices[d];
    nlohmann::json x{{"dofs", dev.dofs()}};
    if (md.osp) {
      x["osp"] = (*md.osp)[d].str();
    } else {
      const auto mb = *mass_damper(dev);
      x["m"] = mb.first.str();
      x["b"] = mb.second.str();
    }
    devices.push_back(x);
  }
  nlohmann::json operators = nlohmann::json::array();
  int first = 0;
  for (const auto& o : sp.problem.structure.operators) {
    nlohmann::json dofs = nlohmann::json::array();
    for (int k = 0; k < o.dof; ++k) dofs.push_back(first + k);
    first += o.dof;
    operators.push_back(dofs);
  }
  return {{"T", sc.T.str()}, {"delay", sp.delay}, {"environment", e}, {"set", set}, {"devices", devices},
          {"operators", operators}};
}

// The evidence of one point: the realisation of E-hat and (P, X, Q_E, Q_V), exact.
nlohmann::json point_json(const multidof::StoredPoint& sto) {
  const multidof::ExactStorage& st = sto.st;
  return {{"A", matrix_json(st.Ehat.A)}, {"B", matrix_json(st.Ehat.B)}, {"C", matrix_json(st.Ehat.C)},
          {"D", matrix_json(st.Ehat.D)}, {"P", matrix_json(st.P)},       {"X", matrix_json(sto.X)},
          {"Q_E", matrix_json(sto.QE)},  {"Q_V", matrix_json(sto.QV)}};
}

// (16) feasible: the exact point and the realisation of E-hat it is on (multidof::stored_point:
// the whole's, the direct sum of the components' or the lift of the symmetric blocks'; the
// checkers verify it whole)
nlohmann::json feasible_certificate(const scene::Scene& sc, const multidof::SceneAnalysis& a, const multidof::StoredPoint& sto) {
  const multidof::ExactStorage& st = sto.st;
  if (st.Ehat.A.rows() + st.Ehat.B.cols() > 160)  // (16)'s first LMI has order N + m
    throw InputError("--certificate: E-hat's realisation has " + std::to_string(st.Ehat.A.rows()) + " states and " +
                     std::to_string(st.Ehat.B.cols()) + " inputs, beyond the checkers' size limit (order 160): no certificate");
  nlohmann::json j = certificate_header("multidof-feasible");
  j["model"] = scene_model(sc, a.scene);
  j["claim"] = {{"status", "exact"}, {"feasible", true}};
  j["evidence"] = point_json(sto);
  verify_before_writing(j);
  return j;
}

// The independent checker's order limit for a multidof-feasible point (checks/hapstab_check.py,
// MAX_FEASIBLE_ORDER): up to it, a point found by the split is written lifted to the whole, which both
// checkers verify with no theorem about the split; beyond it, block by block (multidof-feasible-symmetric).
constexpr long kWholePointOrder = 40;

// (16) feasible by the split (multidof/symmetry.hpp): each block's exact point and realisation, the
// classes; nullopt when the lifted whole is small enough for both checkers (kWholePointOrder).
std::optional<nlohmann::json> symmetric_certificate(const scene::Scene& sc, const multidof::SceneAnalysis& a) {
  const multidof::SymmetryResult& s = *a.lmis.symmetry;
  std::vector<multidof::StoredPoint> pts;
  long order = a.scene.problem.structure.m();
  for (const auto& b : s.blocks) {
    const auto pt = multidof::stored_point(b.problem, b.result);
    if (!pt) return std::nullopt;
    order += b.copies * pt->st.Ehat.A.rows();
    pts.push_back(*pt);
  }
  if (order <= kWholePointOrder) return std::nullopt;
  for (size_t k = 0; k < s.blocks.size(); ++k)
    if (pts[k].st.Ehat.A.rows() + pts[k].st.Ehat.B.cols() > 160)
      throw InputError("--certificate: " + s.blocks[k].name + "'s E-hat has " + std::to_string(pts[k].st.Ehat.A.rows()) +
                       " states, beyond the checkers' size limit (order 160): no certificate");
  nlohmann::json zero_sum = nlohmann::json::array();
  for (size_t k = 1; k < s.blocks.size(); ++k) zero_sum.push_back({{"class", s.blocks[k].cls}, {"point", point_json(pts[k])}});
  nlohmann::json j = certificate_header("multidof-feasible-symmetric");
  j["model"] = scene_model(sc, a.scene);
  j["claim"] = {{"status", "exact"}, {"feasible", true}};
  j["evidence"] = {{"classes", s.classes}, {"fixed", point_json(pts[0])}, {"zero_sum", zero_sum}};
  verify_before_writing(j);
  return j;
}

// Z's poles on the imaginary axis, s = j w0, as the residue evidence (check/operator_passivity_check.hpp): a
// factor s of an entry's denominator (over Q, exactly) is {pole: 0}; a s^2 + c, c/a > 0, is {pole: w0} where
// w0 = sqrt(c/a) is rational, else {pole_squared: c/a} (w0 irrational, e.g. sqrt(2)).
std::vector<nlohmann::json> axis_poles(const TransferMatrix& Z) {
  std::vector<nlohmann::json> out;
  const auto add = [&out](const nlohmann::json& e) {
    if (std::find(out.begin(), out.end(), e) == out.end()) out.push_back(e);
  };
  const auto square_root = [](const integer& x) -> std::optional<integer> {
    if (x < 0) return std::nullopt;
    const integer r = bmp::sqrt(x);
    return r * r == x ? std::optional<integer>(r) : std::nullopt;
  };
  for (const auto& row : Z.entries)
    for (const auto& e : row)
      for (const auto& f : factor_over_q(e.den())) {
        const auto& p = f.f;
        if (p.degree() == 1 && p.coeff(0).is_zero()) add({{"pole", "0"}});
        if (p.degree() != 2 || !p.coeff(1).is_zero()) continue;
        const rational c = p.coeff(0) / p.coeff(2);  // s^2 + c: the poles +-j sqrt(c)
        if (c <= 0) continue;
        const auto rn = square_root(numerator(c)), rd = square_root(denominator(c));
        if (rn && rd) add({{"pole", (rational(*rn) / rational(*rd)).str()}});
        else add({{"pole_squared", c.str()}});
      }
  return out;
}

}  // namespace

std::optional<nlohmann::json> operator_passivity_certificate(const std::string& scene_path, const std::vector<std::string>& sets,
                                                             const multidof::SceneAnalysis& a) {
  if (!a.feasible || !a.certified || a.premises_hold) return std::nullopt;
  const auto& ops = a.scene.operators;
  for (size_t k = 0; k < ops.size() && k < a.scene.operator_names.size(); ++k) {
    // a negative principal minor of He Z(jw); else Z's residue at an axis pole s = j w0 (a negative
    // spring -k/s, a resonance -k s/(s^2 + w0^2))
    std::vector<nlohmann::json> evidence;
    if (const auto minor = multidof::negative_minor(ops[k])) evidence.push_back({{"w", minor->w.str()}, {"minor", minor->rows}});
    for (const auto& p : axis_poles(ops[k])) evidence.push_back(p);
    for (const auto& e : evidence) {
      nlohmann::json j = certificate_header("operator-passivity");
      j["model"] = scene_model_json(scene_path, sets);
      j["claim"] = {{"quantity", "Assumption 1(b) of paper 000 for the scene's operator `operator`: Z(s) passive (positive real); "
                                 "false: Theorem 5 draws no conclusion for the scene"},
                    {"status", "exact"},
                    {"operator", a.scene.operator_names[k]},
                    {"passive", false}};
      j["evidence"] = e;
      try {
        if (check::check_certificate(j).verified) return j;
      } catch (const InputError&) {  // the checkers do not read this scene or operator (ss, count, ...): the (16) kinds
      }
    }
  }
  return std::nullopt;
}

nlohmann::json multidof_certificate(const scene::Scene& sc, const multidof::SceneAnalysis& a) {
  const auto& r = a.lmis;
  if (const std::string why = multidof_certificate_premise(sc); !why.empty())
    throw InputError("--certificate: " + why + ": no certificate");
  if (a.feasible && a.certified && r.symmetry && r.path == "symmetry")
    if (auto j = symmetric_certificate(sc, a)) return *j;
  if (a.feasible && a.certified)
    if (const auto point = multidof::stored_point(a.scene.problem, r)) return feasible_certificate(sc, a, *point);
  // a symmetric scene decided infeasible by a block: that block's witness or facial condition,
  // lifted to the whole (multidof/symmetry.hpp), for the checkers to verify on the whole scene
  const multidof::SymmetryBlock* block = nullptr;
  if (!a.feasible && a.certified && r.symmetry)
    for (const auto& b : r.symmetry->blocks)
      if (b.analysed && b.result.verdict.fails() && b.result.verdict.proven()) block = &b;
  const multidof::AnalysisResult& decided = block ? block->result : r;
  if (!a.feasible && a.certified && decided.path == "facial conditions") {  // no X makes X E(1) symmetric: the model alone
    nlohmann::json j = certificate_header("multidof-facial");
    j["model"] = scene_model(sc, a.scene);
    j["claim"] = {{"status", "exact"}, {"feasible", false}};
    j["evidence"] = nlohmann::json::object();
    verify_before_writing(j);
    return j;
  }
  if (!decided.witness && !decided.weighted_witness) {
    const std::string what = a.feasible && !r.components.empty() ? "a feasible (16) decided per component (decomposed)"
                             : a.feasible   ? "a feasible (16) without a certified point"
                             : a.certified ? "(16) infeasible by the path '" + r.path + "'"
                                           : "an undecided (16)";
    throw InputError("--certificate: " + what + " has no certificate kind yet (issue 47): no certificate");
  }
  nlohmann::json j = certificate_header("multidof-witness");
  j["model"] = scene_model(sc, a.scene);
  j["claim"] = {{"status", "exact"}, {"feasible", false}};
  const int m = a.scene.problem.structure.m();
  const auto lift = [&](const std::vector<rational>& u) {
    return block ? multidof::lift_direction(*r.symmetry, *block, u, m) : u;
  };
  if (decided.witness) {
    j["evidence"] = {{"z_re", decided.witness->z_re.str()}, {"z_im", decided.witness->z_im.str()},
                     {"u", strings(lift(decided.witness->u))}};
  } else {  // the several-frequency witness: every point with its weight
    nlohmann::json pts = nlohmann::json::array();
    for (const auto& p : decided.weighted_witness->points)
      pts.push_back({{"z_re", p.z_re.str()}, {"z_im", p.z_im.str()}, {"u", strings(lift(p.u.re))},
                     {"u_im", strings(lift(p.u.im))}, {"weight", p.weight.str()}});
    j["evidence"] = {{"points", pts}};
  }
  verify_before_writing(j);
  return j;
}

namespace {

// V-hat's storage for V = blockdiag(V_b) from the blocks' (each in its own V-hat's order: V_b's states,
// then its m_b delay states), placed in vhat(V, K)'s order (V's states, then the m delay states):
// Lemma 1's matrix at it is the blocks' after a permutation (claim 000.thm6.blockwise_lemma1).
MatQ blockwise_storage(const StateSpace<rational>& V, const multidof::CouplingStructure& cs, const std::vector<MatQ>& blocks) {
  const Eigen::Index n = V.states(), m = V.inputs();
  MatQ P = MatQ::Zero(n + m, n + m);
  Eigen::Index s = 0, c = 0;
  for (size_t b = 0; b < cs.mbar.size(); ++b) {
    const Eigen::Index nb = cs.nbar[b], mb = cs.mbar[b];
    std::vector<Eigen::Index> at;  // block index -> whole index
    for (Eigen::Index k = 0; k < nb; ++k) at.push_back(s + k);
    for (Eigen::Index k = 0; k < mb; ++k) at.push_back(n + c + k);
    for (size_t i = 0; i < at.size(); ++i)
      for (size_t j = 0; j < at.size(); ++j)
        P(at[i], at[j]) = blocks[b](static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(j));
    s += nb, c += mb;
  }
  return P;
}

// A design on the split of identical DOFs (design_symmetry.cpp), block by block: the split's points
// at the whole's invariant diagonal (X, Q_E, Q_V), V per DOF and each block's V-hat storage -- the
// evidence the design itself verified, whatever the size (the whole's point is never formed: Theorem
// 4's program on the whole may not find one, and is 27 GB at 128 contacts); nullopt off the split.
std::optional<nlohmann::json> symmetric_design_certificate(const scene::Scene& sc, const multidof::SceneDesign& d) {
  const auto& bw = d.design.blockwise;
  if (d.design.path != "symmetry of identical DOFs (block-wise)" || !bw || bw->split_points.empty()) return std::nullopt;
  const multidof::Problem& pb = d.scene.problem;
  // V per DOF: one block of one channel each, zero elsewhere (checked: the certificate states V so)
  const auto& V = d.design.V;
  const auto& cs = pb.coupling;
  nlohmann::json vblocks = nlohmann::json::array();
  MatQ assembled_A = MatQ::Zero(V.A.rows(), V.A.cols()), assembled_B = MatQ::Zero(V.B.rows(), V.B.cols()),
       assembled_C = MatQ::Zero(V.C.rows(), V.C.cols()), assembled_D = MatQ::Zero(V.D.rows(), V.D.cols());
  Eigen::Index s = 0, c = 0;
  for (size_t b = 0; b < cs.mbar.size(); ++b) {
    const Eigen::Index nb = cs.nbar[b], mb = cs.mbar[b];
    if (mb != 1)
      throw InputError("--certificate: the coupling's block " + std::to_string(b + 1) + " has " + std::to_string(mb) +
                       " channels; the split's certificate kind takes one block per DOF: no certificate");
    const MatQ A = V.A.block(s, s, nb, nb), B = V.B.block(s, c, nb, 1), C = V.C.block(c, s, 1, nb), D = V.D.block(c, c, 1, 1);
    assembled_A.block(s, s, nb, nb) = A, assembled_B.block(s, c, nb, 1) = B, assembled_C.block(c, s, 1, nb) = C, assembled_D(c, c) = D(0, 0);
    vblocks.push_back({{"A", matrix_json(A)}, {"B", matrix_json(B)}, {"C", matrix_json(C)}, {"D", matrix_json(D)}});
    s += nb, c += 1;
  }
  if (!(assembled_A == V.A && assembled_B == V.B && assembled_C == V.C && assembled_D == V.D))
    throw InputError("--certificate: the designed V is not block diagonal by DOF: no certificate");
  nlohmann::json g = nlohmann::json::array(), qe = nlohmann::json::array(), qv = nlohmann::json::array();
  for (const auto& cls : bw->classes) {
    const auto i = static_cast<Eigen::Index>(cls.front());
    g.push_back(bw->X(i, i).str()), qe.push_back(bw->QE(i, i).str()), qv.push_back(bw->QV(i, i).str());
  }
  nlohmann::json zero_sum = nlohmann::json::array();
  for (size_t k = 1; k < bw->split_points.size(); ++k) zero_sum.push_back({{"class", bw->split_class[k]}, {"point", point_json(bw->split_points[k])}});
  nlohmann::json pv = nlohmann::json::array();
  for (const MatQ& P : bw->P_V) pv.push_back(matrix_json(P));
  nlohmann::json model = scene_model(sc, d.scene);
  model["coupling_blocks"] = vblocks;
  nlohmann::json j = certificate_header("multidof-coupling-symmetric");
  j["model"] = model;
  j["claim"] = {{"status", "exact"}, {"theorem4", true}};
  j["evidence"] = {{"classes", bw->classes}, {"g", g}, {"q_E", qe}, {"q_V", qv}, {"fixed", point_json(bw->split_points[0])},
                   {"zero_sum", zero_sum}, {"P_V", pv}};
  verify_before_writing(j);
  return j;
}

}  // namespace

nlohmann::json design_certificate(const scene::Scene& sc, const multidof::SceneDesign& d, const lmi::Options& opt) {
  if (const std::string why = multidof_certificate_premise(sc); !why.empty())
    throw InputError("--certificate: " + why + ": no certificate");
  if (!d.has_v() || !d.design.verdict.holds() || !d.design.verdict.proven())
    throw InputError("--certificate: no coupling V verified exactly (the design's verdict: " +
                     std::string(d.design.verdict.holds() ? "numeric" : "no V") + "): no certificate");
  if (auto j = symmetric_design_certificate(sc, d)) return *j;
  const multidof::Problem& pb = d.scene.problem;
  // the block-wise design's own evidence where it was designed on the whole (its point, V-hat's
  // storage block by block); otherwise Theorem 4's program on the whole (P_E, P_V, X, Q_E, Q_V free)
  // for the designed V
  multidof::ExactPoint point;
  MatQ PV;
  if (const auto& bw = d.design.blockwise; bw && bw->whole) {
    point = *bw->whole;
    PV = blockwise_storage(d.design.V, pb.coupling, bw->P_V);
  } else {
    multidof::CouplingCheck c;
    try {
      c = multidof::check_theorem4(pb, d.design.V, opt);
    } catch (const InputError& e) {
      throw InputError(std::string("--certificate: ") + e.what() + ": no certificate");
    }
    if (!c.verdict.holds() || !c.verdict.proven() || !c.point)
      throw InputError("--certificate: Theorem 4's program on the whole did not certify the designed V with an exact point (" +
                       c.verdict.evidence.substr(0, 300) + "): no certificate");
    point = *c.point;
    PV = c.P_V;
  }
  const multidof::ExactStorage st = multidof::exact_storage(pb, point);
  const long env_order = st.Ehat.A.rows() + st.Ehat.B.cols(), v_order = PV.rows() + d.design.V.inputs();
  if (env_order > 160 || v_order > 160)
    throw InputError("--certificate: E-hat's realisation (order " + std::to_string(env_order) + ") or V-hat's (order " +
                     std::to_string(v_order) + ") is beyond the checkers' size limit (order 160): no certificate");
  nlohmann::json model = scene_model(sc, d.scene);
  const auto& V = d.design.V;
  model["coupling"] = {{"A", matrix_json(V.A)}, {"B", matrix_json(V.B)}, {"C", matrix_json(V.C)}, {"D", matrix_json(V.D)}};
  nlohmann::json j = certificate_header("multidof-coupling");
  j["model"] = model;
  j["claim"] = {{"status", "exact"}, {"theorem4", true}};
  j["evidence"] = point_json({st, point.X, point.QE, point.QV});
  j["evidence"]["P_V"] = matrix_json(PV);
  verify_before_writing(j);
  return j;
}

}  // namespace hapstab::cli
