// hapstab/lmi/ccl.cpp -- cone complementarity linearisation (see ccl.hpp).
#include "hapstab/lmi/ccl.hpp"

#include <cmath>

#include "hapstab/numeric/error.hpp"

namespace hapstab::lmi {

Expr trace(const Expr& E) {
  if (!E.ok()) return E;  // the constraint that receives it names the error
  if (E.rows() != E.cols()) throw InputError("trace: expression is not square");
  Expr t = Expr::scalar(0);
  for (int i = 0; i < E.rows(); ++i) {
    Eigen::MatrixXd ei = Eigen::MatrixXd::Zero(E.rows(), 1);
    ei(i, 0) = 1;
    t += ei.transpose() * E * ei;
  }
  return t;
}

CclResult ccl_solve(const Program& prog0, const std::vector<InversePair>& pairs, const CclOptions& opt) {
  if (pairs.empty()) throw InputError("ccl_solve: no inverse pairs");
  Program prog = prog0;
  CclResult out;
  int ntot = 0;
  for (size_t p = 0; p < pairs.size(); ++p) {
    const auto& pr = pairs[p];
    if (pr.Y.rows != pr.Y.cols || pr.Q.rows != pr.Q.cols || pr.Y.rows != pr.Q.rows)
      throw InputError("ccl_solve: pair " + std::to_string(p + 1) + " (" + pr.Y.name + ", " + pr.Q.name +
                       ") must be square and of equal size");
    const int n = pr.Y.rows;
    ntot += n;
    prog.add_lmi("ccl coupling [[" + pr.Y.name + ", I], [I, " + pr.Q.name + "]] >= 0",
                {{Expr(pr.Y), Expr::identity(n)}, {Expr(), Expr(pr.Q)}}, Strictness::nonstrict);
  }
  out.target = 2.0 * ntot;
  // Starting point: any feasible point of the relaxation (margin objective).
  prog.set_margin_objective();
  SolveResult r = solve(prog, opt.solver);
  if (!r.is_success()) {
    out.reason = std::string("the convex relaxation is not feasible (") + to_string(r.verdict) + ": " + r.detail + ")";
    out.last = r;
    return out;
  }
  std::vector<Eigen::MatrixXd> Yk, Qk;
  for (const auto& pr : pairs) {
    Yk.push_back(r.solution(pr.Y));
    Qk.push_back(r.solution(pr.Q));
  }
  double prev = INFINITY;
  int stalls = 0;
  for (int k = 1; k <= opt.max_iter; ++k) {
    Expr obj = Expr::scalar(0);
    for (size_t p = 0; p < pairs.size(); ++p)
      obj += trace(Yk[p] * Expr(pairs[p].Q)) + trace(Expr(pairs[p].Y) * Qk[p]);
    prog.set_minimize(obj);
    r = solve(prog, opt.solver);
    CclStep step{k, r.objective, 0.0, to_string(r.status)};
    for (size_t p = 0; p < pairs.size(); ++p) {
      Yk[p] = r.solution(pairs[p].Y);
      Qk[p] = r.solution(pairs[p].Q);
      step.trace_yq += (Yk[p] * Qk[p]).trace();
    }
    out.log.push_back(step);
    out.last = r;
    if (!r.is_success()) {
      out.reason = "step " + std::to_string(k) + ": sub-problem " + to_string(r.status) + " (" + r.detail + ")";
      return out;
    }
    if (opt.accept && opt.accept(r)) {
      out.success = true;
      out.reason = "accepted by the independent test at step " + std::to_string(k);
      return out;
    }
    if (r.objective <= out.target * (1 + opt.tol)) {
      out.success = !opt.accept;  // with an acceptance test, reaching the trace alone is not enough
      out.reason = "objective " + std::to_string(r.objective) + " reached 2n = " + std::to_string(out.target) +
                   (opt.accept ? " but the independent test rejected the point" : " within tolerance");
      return out;
    }
    const double dec = (prev - r.objective) / std::max(1.0, std::abs(r.objective));
    stalls = (std::isfinite(prev) && dec < opt.stall_tol) ? stalls + 1 : 0;
    prev = r.objective;
    if (stalls >= opt.stall_iters) {
      out.reason = "stalled at objective " + std::to_string(r.objective) + " > 2n = " + std::to_string(out.target);
      return out;
    }
  }
  out.reason = "no convergence in " + std::to_string(opt.max_iter) + " steps";
  return out;
}

}  // namespace hapstab::lmi
