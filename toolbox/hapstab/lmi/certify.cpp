// hapstab/lmi/certify.cpp -- lmi::solve's result as a hapstab::Verdict (certify.hpp).
#include "hapstab/lmi/certify.hpp"

#include <chrono>
#include <sstream>

namespace hapstab::lmi {

Outcome outcome_of(Feasibility f) {
  switch (f) {
    case Feasibility::feasible: return Outcome::holds;
    case Feasibility::infeasible: return Outcome::fails;
    case Feasibility::undecided: return Outcome::undecided;
  }
  return Outcome::undecided;
}

Feasibility feasibility_of(Outcome o) {
  switch (o) {
    case Outcome::holds: return Feasibility::feasible;
    case Outcome::fails: return Feasibility::infeasible;
    case Outcome::undecided: return Feasibility::undecided;
  }
  return Feasibility::undecided;
}

std::string CertifiedSolve::solver_text() const {
  std::ostringstream o;
  o << result.solver << ": " << to_string(result.verdict) << ", certificate " << to_string(result.certificate)
    << ", margin " << result.margin << ". " << result.detail;
  return o.str();
}

MatQ CertifiedSolve::point(const MatrixVariable& v) const {
  return result.certified() ? result.exact_solution(v) : to_rational(result.solution(v));
}

Verdict CertifiedSolve::recheck(bool passed, std::string why) const {
  if (passed && result.margin > 0) return {Outcome::holds, Status::exact, std::move(why)};
  return {outcome_of(result.verdict), Status::numeric, std::move(why)};
}

CertifiedSolve certify_lmi(const Program& prog, const Options& opt) {
  CertifiedSolve c;
  const auto t0 = std::chrono::steady_clock::now();
  c.result = solve(prog, opt);
  c.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  const Certificate k = c.result.certificate;
  const bool exact = k == Certificate::feasible_exact || k == Certificate::infeasible_exact;
  c.verdict = {outcome_of(c.result.verdict), exact ? Status::exact : Status::numeric, c.solver_text()};
  return c;
}

}  // namespace hapstab::lmi
