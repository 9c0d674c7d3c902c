// hapstab/multidof/design_symmetry.cpp -- Theorem 6 for a scene of identical DOFs, by the split
// of symmetry.hpp (design_by_symmetry; issue 48: N = 1024 devices).
//
// The block-wise design (design.hpp) needs one certified point of (16) with X and Q_V diagonal;
// it then designs each block of V against its own square of X and Q_V. For a symmetric scene the
// whole's (16) is never posed: the blocks of the split share one structured bisection
// (least_dissipative.cpp, least_dissipative_points) along Q_E = s Delta_D X, and every block's
// point is (X_b, s Delta_b X_b, c(s) Delta_b X_b), c(s) = max(s/(1 - s), 0) + eps -- each
// re-checked exactly on its block. Those points are the images of ONE invariant point of the
// whole, X = diag(g) (g_c on class c), Q_E = s Delta_D X, Q_V = c(s) Delta_D X:
//   under S (symmetry.hpp) S^T X S = diag(k_c g_c, j (j + 1) g_a), and Q_E, Q_V are Delta_D X
//   times s and c(s), Delta_D constant on each class; so the fixed block's point is the whole's
//   image divided by sigma (X_f(c, c) = k_c g_c / sigma) and class a's block the image of copy j
//   divided by j (j + 1) g_a / X_a. (16) being homogeneous in (P, X, Q_E, Q_V), the blocks'
//   storages scaled alike give the whole's P (lift_point's construction with these scalings;
//   with every Q invariant, its closed form reduces to Q = Q_b's value on each class).
// The scalings are checked exactly here (each block's X, Q_E, Q_V against the whole's), not
// assumed. The point then satisfies every condition of the whole's (16) exactly, which is what
// the block-wise Theorem 4 certificate needs from the environment side; the coupling side
// (Lemma 1 for each distinct block of V) and V's stability are checked as always.
// Infeasible, exactly, without any program: the fixed space's facial conditions admit no X > 0
// (no_invariant_x below: then no X of the whole is admissible either, by averaging over the group).
// Infeasible, exactly, where no shared point is found and Theorem 5's (16) split the same way
// (analyze_by_symmetry) is proven infeasible by a block's witness or facial conditions: (19) is
// (16) with Q_V restricted to V's blocks, so it has no point either.
// The fixed space of several independent objects keeps one scale of X per object: its components
// (components.hpp: its (16) holds iff each component's does) then take its place in the bisection.
// Not attempted (why_not, the whole design decides or the size limit refuses it): a part whose
// X is not pinned to one direction or whose Delta_D X is not diagonal, no shared Riccati point,
// a point that fails its exact re-check, a chosen back-end or path (--backend, --path generic).
//
// Implements: paper 000 (16), (19)-(24), Theorem 6, on the split of Theorem 5 (symmetry.hpp).
#include <sstream>

#include "hapstab/multidof/components.hpp"
#include "hapstab/multidof/detail.hpp"
#include "hapstab/multidof/symmetry.hpp"

namespace hapstab::multidof {

namespace {

// The fixed space's facial conditions admit no X > 0: then no X > 0 of the whole does either,
// so (16) -- and (19), which is (16) with Q_V structured -- has no solution. Why: X E(1) symmetric
// and g > 0 are kept by every permutation of the group (E(1) is invariant) and by averaging, so
// a whole's admissible X averages to an invariant one, X = diag(g_c on class c); its image on the
// fixed space, diag(k_c g_c), is admissible there (the fixed space's E_f(1) is E(1)'s row sums by
// class: X E(1) symmetric on the invariant X iff diag(k_c g_c) E_f(1) is). "" when some X > 0 may
// be admissible (a standard block has one DOF: any g is admissible there).
std::optional<std::string> no_invariant_x(const SymmetryResult& split, size_t b, const FacialConditions& fc) {
  if (split.blocks[b].cls >= 0) return std::nullopt;
  if (!fc.symmetric_possible) return "no X makes X E_f(1) symmetric";
  if (fc.gamma_basis.size() != 1) return std::nullopt;
  bool pos = false, nonpos = false;
  for (const rational& g : fc.gamma_basis[0]) (g > 0 ? pos : nonpos) = true;
  if (pos && !nonpos) return std::nullopt;
  bool neg_only = !pos;
  for (const rational& g : fc.gamma_basis[0]) neg_only = neg_only && g < 0;
  if (neg_only) return std::nullopt;  // -X_1 > 0 is admissible
  return std::string("the one direction the facial conditions leave has entries of both signs (or a zero): no X > 0");
}

DesignResult infeasible_by_facial(const SymmetryResult& split, size_t b, const FacialConditions& fc, const std::string& why) {
  DesignResult res;
  res.facial = fc;
  res.verdict = {Outcome::fails, Status::exact,
                 "no solution: the convex part (19) is infeasible (exact): by the symmetry " + split.group + ", " +
                     split.blocks[b].name + ": " + why + " (" + fc.explanation +
                     "); an admissible X > 0 of the whole would average over the group to an invariant one, whose image "
                     "there would be admissible (multidof/design_symmetry.cpp)"};
  res.path = "symmetry of identical DOFs (facial conditions)";
  res.plan.push_back({res.path, "decided", split.group + ": " + split.blocks[b].name + "'s facial conditions"});
  for (const char* p : {"block-wise (structured KYP/Riccati)", "generic SDP"}) res.plan.push_back({p, "not needed", "the split decided, exactly"});
  return res;
}

// One part of the shared bisection (design_at_shared_point): a block of the split, or one of the
// fixed space's independent components.
struct Part {
  size_t block;
  std::vector<int> dofs;  // the block's DOFs this part covers, in the part's order
  std::string name;
};

// The evidence of `multidof design --certificate` (DesignResult::BlockwiseEvidence): the classes and
// each block's exact point, in block order (part k is block of[k].block's, or one of the fixed space's
// components, whose points are assembled into the fixed space's).
void keep_split_evidence(DesignResult::BlockwiseEvidence& ev, const SymmetryResult& split,
                         const std::vector<detail::KypMinPoint>& part_pts, const std::vector<Part>& of,
                         const std::vector<Component>& fixed_components) {
  ev.classes = split.classes;
  std::vector<ExactPoint> fixed_parts;  // the fixed space's components' points, when it went by them
  for (size_t k = 0; k < part_pts.size(); ++k) {
    const detail::KypMinPoint& p = part_pts[k];
    const SymmetryBlock& blk = split.blocks[of[k].block];
    const ExactPoint x{p.env.P11, p.env.X, p.env.QE, p.QV};
    if (of[k].block == 0 && fixed_components.size() > 1) {
      fixed_parts.push_back(x);
      if (fixed_parts.size() < fixed_components.size()) continue;
      ev.split_points.push_back(assemble_components(blk.problem, fixed_components, fixed_parts));
    } else {
      ev.split_points.push_back({exact_storage(blk.problem, x), p.env.X, p.env.QE, p.QV});
    }
    ev.split_class.push_back(blk.cls);
  }
}

// The design at one shared structured point (the header); nullopt with why_not when a part's
// premise fails or no point is found.
std::optional<DesignResult> design_at_shared_point(const SceneProblem& sp, const SymmetryResult& split,
                                                   const DesignOptions& opt, std::string& why_not) {
  using detail::KypMinPoint;
  using detail::KypPart;
  using detail::Pinned;
  if (opt.path == DesignPath::generic_sdp) return why_not = "the generic design was asked for", std::nullopt;
  if (opt.lmi.backend != lmi::Backend::automatic)
    return why_not = "an SDP back-end was chosen (--backend): that is the generic design", std::nullopt;
  // every block's structured data: facial conditions, X pinned to one direction
  const size_t B = split.blocks.size();
  std::vector<FacialConditions> fc(B);
  std::vector<EhatSplit> es(B);
  std::vector<KypPart> parts;
  for (size_t b = 0; b < B; ++b) {
    const SymmetryBlock& blk = split.blocks[b];
    fc[b] = facial_conditions(blk.problem);
    if (const auto none = no_invariant_x(split, b, fc[b])) return infeasible_by_facial(split, b, fc[b], *none);
    if (!fc[b].symmetric_possible) return why_not = blk.name + ": " + fc[b].explanation, std::nullopt;
    es[b] = ehat_split(blk.problem.E);
  }
  // the parts of the shared bisection: each block, or -- where the facial conditions leave the fixed
  // space's X more than one direction -- its independent components (components.hpp: its (16)
  // holds iff each component's does; each component's X keeps its own scale)
  std::vector<Part> of;
  std::vector<Component> fixed_components;
  if (fc[0].gamma_basis.size() > 1) fixed_components = components(split.blocks[0].problem);
  std::vector<const Problem*> problems;
  for (size_t b = 0; b < B; ++b) {
    if (b == 0 && fixed_components.size() > 1) {
      for (const Component& c : fixed_components) {
        problems.push_back(&c.problem);
        of.push_back({0, c.dofs, split.blocks[0].name + ", component " + component_name(split.blocks[0].problem, c)});
      }
      continue;
    }
    std::vector<int> all(static_cast<size_t>(split.blocks[b].problem.structure.m()));
    for (size_t i = 0; i < all.size(); ++i) all[i] = static_cast<int>(i);
    problems.push_back(&split.blocks[b].problem);
    of.push_back({b, all, split.blocks[b].name});
  }
  const size_t np = problems.size();
  std::vector<FacialConditions> pfc(np);
  std::vector<EhatSplit> pes(np);
  for (size_t k = 0; k < np; ++k) {
    const bool own = of[k].block != 0 || fixed_components.size() <= 1;
    pfc[k] = own ? fc[of[k].block] : facial_conditions(*problems[k]);
    pes[k] = own ? std::move(es[of[k].block]) : ehat_split(problems[k]->E);
  }
  for (size_t k = 0; k < np; ++k) {
    std::string why;
    std::optional<Pinned> px = detail::pinned_x(*problems[k], pes[k], pfc[k], &why);
    if (!px) return why_not = of[k].name + ": " + why, std::nullopt;
    parts.push_back({problems[k], &pes[k], std::move(*px)});
  }
  const auto part_pts = np > 1 ? detail::least_dissipative_points(parts) : std::nullopt;
  if (!part_pts) return why_not = "no Riccati point shared by the blocks along Q_E = s Delta_D X", std::nullopt;
  for (size_t k = 0; k < np; ++k) {
    const KypMinPoint& p = (*part_pts)[k];
    if (!p.certified)
      return why_not = of[k].name + ": the shared point failed the exact re-check (" + p.why + ")", std::nullopt;
    if (!(p.env.X.isDiagonal(0) && p.env.QE.isDiagonal(0) && p.QV.isDiagonal(0)))
      return why_not = of[k].name + ": its point is not diagonal", std::nullopt;
  }
  // each block's point: its part's, or the direct sum of its components' (diagonal)
  std::vector<KypMinPoint> block_pts(B);
  for (size_t b = 0; b < B; ++b) {
    const auto mb = static_cast<Eigen::Index>(split.blocks[b].problem.structure.m());
    block_pts[b].env.X = block_pts[b].env.QE = block_pts[b].QV = MatQ::Zero(mb, mb);
    block_pts[b].r = (*part_pts)[0].r;
    block_pts[b].why = "";
  }
  for (size_t k = 0; k < np; ++k) {
    const KypMinPoint& p = (*part_pts)[k];
    KypMinPoint& q = block_pts[of[k].block];
    for (size_t i = 0; i < of[k].dofs.size(); ++i) {
      const auto I = static_cast<Eigen::Index>(i), D = static_cast<Eigen::Index>(of[k].dofs[i]);
      q.env.X(D, D) = p.env.X(I, I), q.env.QE(D, D) = p.env.QE(I, I), q.QV(D, D) = p.QV(I, I);
    }
    if (of[k].block == 0 && q.why.empty()) q.why = p.why;
  }
  if (fixed_components.size() > 1)
    block_pts[0].why = "by its " + std::to_string(fixed_components.size()) + " independent components (" +
                       "multidof/components.hpp), each re-checked exactly; the first: " + block_pts[0].why;
  // the whole's invariant point, from the fixed block's X (symmetry.hpp's sigma: g_c >= 1)
  const int m = sp.problem.structure.m();
  const size_t r = split.classes.size();
  const KypMinPoint& f = block_pts[0];
  const MatQ delta_f = split.blocks[0].problem.structure.delta_D();
  const auto k_of = [&](size_t c) { return rational(static_cast<long>(split.classes[c].size())); };
  rational sigma(1);
  for (size_t c = 0; c < r; ++c) {
    const auto C = static_cast<Eigen::Index>(c);
    if (k_of(c) / f.env.X(C, C) > sigma) sigma = k_of(c) / f.env.X(C, C);
  }
  const rational s = f.r;
  std::vector<rational> g(r), qe(r), qv(r);
  for (size_t c = 0; c < r; ++c) {
    const auto C = static_cast<Eigen::Index>(c);
    g[c] = sigma * f.env.X(C, C) / k_of(c);
    qe[c] = f.env.QE(C, C) * sigma / k_of(c);
    qv[c] = f.QV(C, C) * sigma / k_of(c);
    if (!(qe[c] == s * delta_f(C, C) * g[c]))
      return why_not = split.blocks[0].name + ": its Q_E is not s Delta_D X on class " + std::to_string(c + 1), std::nullopt;
  }
  // each block's point is the whole's image, scaled (the header): checked exactly, not assumed
  for (size_t b = 0; b < B; ++b) {
    const KypMinPoint& p = block_pts[b];
    const SymmetryBlock& blk = split.blocks[b];
    const auto n = p.env.X.rows();
    for (Eigen::Index i = 0; i < n; ++i) {
      const size_t c = blk.cls < 0 ? static_cast<size_t>(i) : static_cast<size_t>(blk.cls);
      const rational t = p.env.X(i, i) / g[c];  // the block's scale against the whole on class c
      bool ok = p.env.X.isDiagonal(0) && p.QV.isDiagonal(0) && p.env.QE.isDiagonal(0) && p.env.QE(i, i) == t * qe[c] &&
                p.QV(i, i) == t * qv[c] && p.r == s;
      ok = ok && t > 0 && (blk.cls >= 0 || t == k_of(c) / sigma);
      if (!ok) return why_not = blk.name + ": its point is not the image of one invariant point of the whole", std::nullopt;
    }
  }
  KypMinPoint whole;
  whole.r = s;
  whole.certified = true;
  whole.env.X = whole.env.QE = whole.QV = MatQ::Zero(m, m);
  for (size_t c = 0; c < r; ++c)
    for (int i : split.classes[c]) whole.env.X(i, i) = g[c], whole.env.QE(i, i) = qe[c], whole.QV(i, i) = qv[c];
  std::ostringstream why;
  why << "by the symmetry " << split.group << ": one point of the whole's (16) (X = diag(g), Q_E = s Delta_D X, Q_V "
      << "diagonal, s = " << to_real<double>(s) << "), whose images on the " << B << " blocks were each re-checked "
      << "exactly (multidof/design_symmetry.cpp); " << split.blocks[0].name << ": " << f.why;
  whole.why = why.str();
  std::string why_blockwise;
  std::optional<DesignResult> res = detail::design_blockwise_at(sp.problem, whole, opt, why_blockwise);
  if (!res) return why_not = why_blockwise, std::nullopt;
  if (res->blockwise) {  // the whole's point is the split's blocks', not a storage of the whole
    res->blockwise->whole.reset();
    keep_split_evidence(*res->blockwise, split, *part_pts, of, fixed_components);
  }
  res->facial = fc[0];
  res->facial.explanation = "facial reduction per block (" + split.blocks[0].name + ": " + fc[0].explanation + ")";
  res->path = "symmetry of identical DOFs (block-wise)";
  std::string blocks = split.group + ": " + std::to_string(B) + " blocks share one structured point (" +
                       split.blocks[0].name + (fixed_components.size() > 1 ? ", by its " + std::to_string(fixed_components.size()) + " components" : "");
  for (size_t b = 1; b < B && b < 9; ++b) blocks += "; " + split.blocks[b].name;
  blocks += B > 9 ? "; .. " + std::to_string(B - 9) + " more zero-sum spaces)" : ")";
  res->plan.push_back({"symmetry of identical DOFs (block-wise)", "decided", blocks});
  res->plan.push_back({"block-wise (structured KYP/Riccati)", "not needed", "the split decided"});
  res->plan.push_back({"generic SDP", "not needed", "the split decided"});
  return res;
}

}  // namespace

std::optional<DesignResult> design_by_symmetry(const SceneProblem& sp, const SymmetryResult& split,
                                               const DesignOptions& opt, std::string& why_not) {
  if (auto r = design_at_shared_point(sp, split, opt, why_not)) return r;
  if (opt.path == DesignPath::generic_sdp || opt.lmi.backend != lmi::Backend::automatic) return std::nullopt;
  // No shared point: Theorem 5's (16) by the same split (symmetry.hpp). Its infeasibility, proven
  // (a block's witness or facial conditions, which hold for the whole), proves (19) infeasible:
  // (19) is (16) with Q_V restricted to V's block structure, so every point of (19) is one of (16).
  std::string why16;
  const std::optional<AnalysisResult> a = analyze_by_symmetry(sp, split, opt.lmi, why16);
  if (!(a && a->verdict.fails() && a->verdict.proven())) {
    why_not += "; Theorem 5's (16) by the split: " + (a ? "feasible, or not proven infeasible" : why16);
    return std::nullopt;
  }
  DesignResult res;
  res.facial = a->facial;
  res.verdict = {Outcome::fails, Status::exact,
                 "no solution: the convex part (19) is infeasible (exact): Theorem 5's (16) is (" + a->verdict.evidence +
                     "), and (19) is (16) with Q_V restricted to V's blocks"};
  res.path = "symmetry of identical DOFs (Theorem 5's (16))";
  res.plan.push_back({"symmetry of identical DOFs (block-wise)", "no point", why_not});
  res.plan.push_back({res.path, "decided", split.group + ": (16) proven infeasible by its blocks"});
  for (const char* p : {"block-wise (structured KYP/Riccati)", "generic SDP"}) res.plan.push_back({p, "not needed", "the split decided, exactly"});
  return res;
}

}  // namespace hapstab::multidof
