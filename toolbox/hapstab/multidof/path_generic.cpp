// hapstab/multidof/path_generic.cpp -- the generic SDP path of Theorem 5 (planner.hpp): the LMIs
// (16) posed in hapstab::lmi (lmis16.cpp) and solved by lmi::solve, whatever the structure.
//
// Premise: its Schur complement, over all n(n+1)/2 entries of P11 plus X, Q_E, Q_V, fits
// limits::generic_sdp_bytes (checked before anything is posed; beyond it the problem is refused
// by name if no cheaper path decides). The search:
//   full            (16) with margin in (P11, X, Q_E, Q_V): the solver's point, scaled to
//                   min g_i = 1, is the candidate;
//   stability_only  Q_E and Q_V eliminated (analysis.hpp): the first LMI with Q_E = Delta_D X
//                   and margin mu; the candidates Q_E = Delta_D X - eps I,
//                   Q_V = Q_E + Q_E^2/eps + eps I (eps = mu/2, then mu/16). Not for
//                   Problem::qv_block_diagonal (a constructed Q_V is not block diagonal): full.
// An infeasible verdict with lmi::solve's exact Farkas certificate is proven here without a
// point; otherwise the solver's verdict is the path's own, numeric, until the planner's exact
// re-check (recheck.cpp) passes a point.
//
// Implements: paper 000 (16) (Theorem 5) as an SDP.
#include <cmath>

#include "hapstab/multidof/planner.hpp"
#include "hapstab/numeric/exact_matrix.hpp"
#include "hapstab/numeric/limits.hpp"

namespace hapstab::multidof {

using namespace detail;

namespace {

// The solver's verdict before any point is re-checked: infeasible with solve()'s exact Farkas
// certificate (evidence `farkas`: proven) or numerically ("numeric only"); otherwise the solver's
// outcome, numeric, no evidence yet.
void solver_verdict(const lmi::CertifiedSolve& cs, const std::string& farkas, PathResult& r) {
  r.numeric_seconds = cs.seconds;
  r.margin = cs.margin();
  r.solver_detail = cs.solver_text();
  if (cs.verdict.fails() && cs.verdict.proven()) {
    r.proven = Verdict{Outcome::fails, cs.verdict.status, farkas};
    return;
  }
  if (cs.verdict.fails()) r.unchecked = Verdict{Outcome::fails, cs.verdict.status, "numeric only"};
  else r.unchecked = Verdict{cs.verdict.outcome, Status::numeric, ""};
}

PathResult stability_only(const PathContext& c) {
  PathResult r;
  const Problem& pb = c.pb;
  const int m = pb.structure.m();
  lmi::Program prog;
  const EnvVars ev = add_environment(prog, pb, c.split, c.facial, true);
  prog.set_margin_objective(1.0);
  const lmi::CertifiedSolve cs = lmi::certify_lmi(prog, c.opt);
  solver_verdict(cs, "exact Farkas certificate of the posed (reduced) LMI with Q_E = Delta_D X "
                     "(infeasible there implies (16) infeasible)", r);
  if (cs.verdict.fails() || !cs.has_point()) return r;
  // mu: smallest eigenvalue of the reduced first LMI at the solver's point (original scale)
  double mu = INFINITY;
  for (size_t i = 0; i < prog.lmis().size(); ++i)
    if (prog.lmis()[i].name.rfind("(16) first LMI", 0) == 0) mu = std::min(mu, cs.result.min_eigenvalue[i]);
  ExactEnv x = exact_env(cs, ev);
  const rational s = normaliser(x.X);
  x.X *= s;
  x.P11 *= s;
  const MatQ DX = exact_product(pb.structure.delta_D(), x.X);
  for (double f : {0.5, 0.0625}) {
    if (!(mu > 0)) break;
    const rational eps = lmi::round_dyadic(f * mu * to_real<double>(s), 20);
    if (!(eps > 0)) break;
    CandidatePoint cp;
    cp.env = x;
    cp.env.QE = DX - eps * MatQ::Identity(m, m);
    cp.QV = cp.env.QE + exact_product(cp.env.QE, cp.env.QE) / eps + eps * MatQ::Identity(m, m);
    cp.margin = cs.margin();
    cp.construction = "; Q_E = Delta_D X - eps I and Q_V = Q_E + Q_E^2/eps + eps I constructed exactly "
                      "(stability-only mode)";
    r.points.push_back(std::move(cp));
  }
  if (r.points.empty()) {
    r.no_point = "the first LMI with Q_E = Delta_D X has no margin at the solver's point";
    r.unchecked->evidence = r.no_point;
  }
  return r;
}

PathResult margin_program(const PathContext& c) {
  PathResult r;
  lmi::Program prog;
  EnvVars ev;
  lmi::MatrixVariable QV;
  pose_16(prog, c.pb, c.split, c.facial, ev, QV);
  prog.set_margin_objective(1.0);
  const lmi::CertifiedSolve cs = lmi::certify_lmi(prog, c.opt);
  solver_verdict(cs, "exact Farkas certificate of the posed (reduced) LMIs", r);
  if (cs.verdict.fails() || !cs.has_point()) return r;
  const ScaledPoint p = scaled_point(cs, ev, QV);
  CandidatePoint cp{p.env, p.QV, cs.margin(), ""};
  r.points.push_back(cp);
  r.report = cp;  // the solver's point is reported even when it fails the re-check
  return r;
}

}  // namespace

SolvePath generic_sdp_path() {
  SolvePath p;
  p.name = "generic SDP";
  p.premises = [](const PathContext& c) {
    const int m = c.pb.structure.m();
    const std::string why = generic_size_exceeded(c.pb, static_cast<long>(m) * (m + 1), "Theorem 5's generic SDP (16)");
    if (!why.empty()) return Premises::unmet(why, true);
    const double n = static_cast<double>(c.pb.E.states());
    const double unknowns = n * (n + 1) / 2 + static_cast<double>(m) * (m + 1);
    if (unknowns > limits::generic_sdp_unknowns)  // bounded work: minutes of interior-point iterations
      return Premises::unmet("its program has about " + std::to_string(static_cast<long>(unknowns)) +
                                 " scalar unknowns (E-hat of order " + std::to_string(static_cast<long>(n)) + "), more than the " +
                                 std::to_string(static_cast<long>(limits::generic_sdp_unknowns)) +
                                 " of numeric/limits.hpp generic_sdp_unknowns (minutes of interior-point work)",
                             false);
    return Premises::met();
  };
  p.search = [](const PathContext& c) {
    if (c.mode == AnalysisMode::stability_only && !c.pb.qv_block_diagonal) return stability_only(c);
    return margin_program(c);
  };
  return p;
}

}  // namespace hapstab::multidof
