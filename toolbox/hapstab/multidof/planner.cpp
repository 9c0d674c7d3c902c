// hapstab/multidof/planner.cpp -- Theorem 5 by one planner over the paths (planner.hpp): premises
// first, cheapest path first, every candidate point decided by the one exact re-check
// (recheck.cpp), every path's fate recorded in AnalysisResult::plan.
#include "hapstab/multidof/planner.hpp"

#include <chrono>
#include <sstream>

#include "hapstab/numeric/error.hpp"

namespace hapstab::multidof {

using namespace detail;

std::vector<SolvePath> default_paths(AnalysisPath path) {
  switch (path) {
    case AnalysisPath::generic_sdp: return {generic_sdp_path()};
    case AnalysisPath::kyp_riccati: return {kyp_riccati_path(false), generic_sdp_path()};
    case AnalysisPath::automatic: break;
  }
  return {kyp_riccati_path(true), generic_sdp_path()};
}

namespace {

std::string fate_text(const PlanStep& s) { return "the " + s.path + " path: " + s.fate + (s.why.empty() ? "" : " (" + s.why + ")"); }

}  // namespace

AnalysisResult analyze_with(const Problem& pb, const std::vector<SolvePath>& paths, const lmi::Options& opt,
                            AnalysisMode mode) {
  pb.validate(false);
  AnalysisResult res;
  struct Stamp {  // res.seconds on every return
    AnalysisResult& r;
    std::chrono::steady_clock::time_point t0;
    ~Stamp() { r.seconds = since(t0); }
  } stamp{res, std::chrono::steady_clock::now()};
  res.facial = facial_conditions(pb);
  if (!res.facial.symmetric_possible) {
    res.verdict = {Outcome::fails, Status::exact, "exact: " + res.facial.explanation};
    res.path = "facial conditions";
    for (const auto& p : paths) res.plan.push_back({p.name, "not needed", "the facial conditions decided, exactly"});
    return res;
  }
  const EhatSplit sp = ehat_split(pb.E);
  const PathContext ctx{pb, sp, res.facial, opt, mode};
  std::string input_limit;                 // a path skipped only for a size limit
  std::optional<PathResult> fallback;      // the last path that ran with a verdict of its own
  std::string fallback_why;                // ... and its re-check's failure
  std::optional<Pinned> pinned;            // the structure the deciding path used
  std::vector<PlanStep> earlier;           // paths that ran and did not decide
  for (const SolvePath& path : paths) {
    if (!res.path.empty()) {
      res.plan.push_back({path.name, "not needed", "the " + res.path + " path decided"});
      continue;
    }
    const Premises pr = path.premises(ctx);
    if (!pr.hold) {
      res.plan.push_back({path.name, "skipped", pr.why});
      if (pr.input_limit && input_limit.empty()) input_limit = pr.why;
      continue;
    }
    PathResult r = path.search(ctx);
    res.sdp_seconds += r.numeric_seconds;
    auto decide = [&](Verdict v, double margin) {
      res.verdict = std::move(v);
      res.margin = margin;
      res.solver_detail = r.solver_detail;
      res.path = path.name;
      res.plan.push_back({path.name, "decided", ""});
      pinned = r.pinned;
    };
    if (r.proven) {
      decide(*r.proven, r.margin);
      continue;
    }
    std::string why = r.no_point;
    bool tried = false;
    for (const CandidatePoint& c : r.points) {
      tried = true;
      const bool ok = exact_recheck(pb, sp, c.env, c.QV, why);
      if (ok && c.margin > 0) {
        decide({Outcome::holds, Status::exact, why + c.construction}, c.margin);
        store_point(res, pb, c.env.X, c.env.QE, c.QV);
        break;
      }
      if (ok) break;  // passes, but the solver's margin is not positive: its verdict stays numeric
    }
    if (!res.path.empty()) continue;
    PlanStep step{path.name, tried ? "point failed the exact re-check" : "no point", why};
    earlier.push_back(step);
    res.plan.push_back(step);
    if (r.unchecked) {
      fallback = std::move(r);
      fallback_why = tried ? why : "";
    }
  }
  if (!res.path.empty()) {
    // a later path decided after an earlier one ran: the verdict says so
    if (!earlier.empty()) {
      std::string note = " [before it, ";
      for (size_t i = 0; i < earlier.size(); ++i) note += (i ? "; " : "") + fate_text(earlier[i]);
      res.verdict.evidence += note + "; the " + res.path + " path decided]";
    }
    if (mode == AnalysisMode::full && res.verdict.holds()) plan_least_dissipative(pb, sp, opt, pinned, res);
    return res;
  }
  if (!input_limit.empty()) throw InputError(input_limit);
  if (fallback) {  // the path's own verdict, numeric (the solver's, unchecked)
    res.verdict = *fallback->unchecked;
    if (res.verdict.evidence.empty()) res.verdict.evidence = fallback_why;
    res.margin = fallback->margin;
    res.solver_detail = fallback->solver_detail;
    if (fallback->report) store_point(res, pb, fallback->report->env.X, fallback->report->env.QE, fallback->report->QV);
    if (mode == AnalysisMode::full && res.verdict.holds()) plan_least_dissipative(pb, sp, opt, std::nullopt, res);
    return res;
  }
  std::string what = "no path decided: ";
  for (size_t i = 0; i < res.plan.size(); ++i) what += (i ? "; " : "") + fate_text(res.plan[i]);
  res.verdict = {Outcome::undecided, Status::numeric, what};
  return res;
}

AnalysisResult analyze(const Problem& pb, const lmi::Options& opt, AnalysisMode mode, AnalysisPath path) {
  return analyze_with(pb, default_paths(path), opt, mode);
}

}  // namespace hapstab::multidof
