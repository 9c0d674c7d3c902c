// hapstab/multidof/planner.cpp -- Theorem 5 by one planner over the paths (planner.hpp): premises
// first, cheapest path first, every candidate point decided by the one exact re-check
// (recheck.cpp), every path's fate recorded in AnalysisResult::plan.
#include "hapstab/multidof/planner.hpp"

#include <algorithm>
#include <chrono>
#include <map>
#include <sstream>

#include "hapstab/multidof/components.hpp"
#include "hapstab/numeric/error.hpp"
#include "hapstab/study/run.hpp"
#include "hapstab/study/threads.hpp"

namespace hapstab::multidof {

using namespace detail;

std::vector<SolvePath> default_paths(AnalysisPath path) {
  switch (path) {
    case AnalysisPath::generic_sdp: return {generic_sdp_path()};
    case AnalysisPath::kyp_riccati:
      return {kyp_riccati_path(false), kyp_search_path(false), frequency_witness_path(), generic_sdp_path()};
    case AnalysisPath::automatic: break;
  }
  return {kyp_riccati_path(true), kyp_search_path(true), frequency_witness_path(), generic_sdp_path()};
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
  std::vector<PlanStep> earlier;           // paths whose points failed the exact re-check
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
      res.witness = r.witness;
      res.weighted_witness = r.weighted_witness;
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
        res.exact_point = ExactPoint{c.env.P11, c.env.X, c.env.QE, c.QV};
        break;
      }
      if (ok) break;  // passes, but the solver's margin is not positive: its verdict stays numeric
    }
    if (!res.path.empty()) continue;
    PlanStep step{path.name, tried ? "point failed the exact re-check" : "no point", why};
    if (tried) earlier.push_back(step);  // the verdict names a point that failed (issue 40)
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

namespace {

// A component's weighted witness on the whole's DOFs (zero outside the component: E is a direct sum,
// and each direction X_k of the component is the whole's X_k restricted to it).
WeightedWitness on_whole(WeightedWitness w, const std::vector<int>& dofs, int m) {
  auto lift = [&](const std::vector<rational>& v) {
    std::vector<rational> out(static_cast<size_t>(m), rational(0));
    for (size_t i = 0; i < dofs.size(); ++i) out[static_cast<size_t>(dofs[i])] = v[i];
    return out;
  };
  for (auto& pt : w.points) pt.u = {lift(pt.u.re), lift(pt.u.im)};
  for (auto& d : w.directions) d = lift(d);
  return w;
}

// The components' results assembled (components.hpp: the whole is feasible iff every component
// is; the block-diagonal assembly of their points is the whole's point).
AnalysisResult assemble(const Problem& pb, const std::vector<Component>& comps, std::vector<AnalysisResult>& parts,
                        unsigned threads) {
  AnalysisResult res;
  res.facial = facial_conditions(pb);
  res.path = "decomposed";
  const int m = pb.structure.m();
  const size_t K = comps.size();
  const std::string how = "by decomposition into " + std::to_string(K) +
                          " independent components (multidof/components.hpp: E's realisation is their direct sum "
                          "exactly and no operator spans two, so (16) holds for the whole iff it holds for each)";
  std::map<std::string, int> count;
  bool all_proven_hold = true, all_hold = true, all_points = true, all_min = true, all_min_cert = true;
  std::optional<size_t> proven_fail, numeric_fail, open;
  res.margin = INFINITY;
  for (size_t k = 0; k < K; ++k) {
    const AnalysisResult& r = parts[k];
    res.components.push_back({component_name(pb, comps[k]), comps[k].dofs, r.path, r.verdict, r.seconds, r.exact_point});
    for (const PlanStep& st : r.plan) res.plan.push_back({"component " + std::to_string(k + 1) + ": " + st.path, st.fate, st.why});
    ++count[r.path.empty() ? "none" : r.path];
    res.sdp_seconds += r.sdp_seconds;
    res.margin = std::min(res.margin, r.margin);
    all_proven_hold = all_proven_hold && r.verdict.holds() && r.verdict.proven();
    all_hold = all_hold && r.verdict.holds();
    all_points = all_points && r.X.rows() == static_cast<Eigen::Index>(comps[k].dofs.size());
    all_min = all_min && r.min_found;
    all_min_cert = all_min_cert && r.min_point_certified;
    if (r.verdict.fails() && r.verdict.proven() && !proven_fail) proven_fail = k;
    if (r.verdict.fails() && !r.verdict.proven() && !numeric_fail) numeric_fail = k;
    if (!r.verdict.holds() && !r.verdict.fails() && !open) open = k;
    if (r.verdict.holds() && !r.verdict.proven() && !open) open = k;
  }
  auto named = [&](size_t k) { return "component " + std::to_string(k + 1) + " " + res.components[k].name; };
  if (all_proven_hold) {
    res.verdict = {Outcome::holds, Status::exact,
                   "exact, " + how + ": each component's point passed the exact re-check (" + named(0) + ": " +
                       parts[0].verdict.evidence + "); the whole's point is their block-diagonal assembly"};
  } else if (proven_fail) {
    res.verdict = {Outcome::fails, parts[*proven_fail].verdict.status,
                   "exact, " + how + ": " + named(*proven_fail) + " is infeasible: " + parts[*proven_fail].verdict.evidence};
    if (const auto& w = parts[*proven_fail].witness) {  // its direction on the whole's DOFs (E is a direct sum)
      res.witness = *w;
      res.witness->u.assign(static_cast<size_t>(m), rational(0));
      for (size_t i = 0; i < comps[*proven_fail].dofs.size(); ++i)
        res.witness->u[static_cast<size_t>(comps[*proven_fail].dofs[i])] = w->u[i];
    }
    if (const auto& w = parts[*proven_fail].weighted_witness)
      res.weighted_witness = on_whole(*w, comps[*proven_fail].dofs, m);
  } else if (numeric_fail) {
    res.verdict = {Outcome::fails, Status::numeric,
                   "numeric, " + how + ": " + named(*numeric_fail) + ": " + parts[*numeric_fail].verdict.evidence};
  } else {
    res.verdict = {all_hold ? Outcome::holds : Outcome::undecided, Status::numeric,
                   "not certified, " + how + ": " + named(*open) + ": " + parts[*open].verdict.evidence};
  }
  std::ostringstream o;
  o << "decomposed into " << K << " independent components on " << threads << " thread(s); decided by";
  for (const auto& [path, n] : count) o << " " << path << " x" << n;
  o << "; component 1: " << parts[0].solver_detail;  // times: AnalysisResult::components, ::seconds
  res.solver_detail = o.str();
  if (!all_points) return res;
  // the block-diagonal assembly of the points
  res.X = res.Q_E = res.Q_V = res.delta_V = Eigen::MatrixXd::Zero(m, m);
  if (all_min) res.Q_V_min = res.delta_V_min = Eigen::MatrixXd::Zero(m, m);
  res.gamma.assign(pb.structure.operators.size(), 0.0);
  res.gamma_sqrt = res.gamma;
  if (all_min) res.gamma_sqrt_min = res.gamma;
  for (size_t k = 0; k < K; ++k) {
    const AnalysisResult& r = parts[k];
    const auto& d = comps[k].dofs;
    for (size_t i = 0; i < d.size(); ++i)
      for (size_t j = 0; j < d.size(); ++j) {
        const auto I = static_cast<Eigen::Index>(i), J = static_cast<Eigen::Index>(j);
        res.X(d[i], d[j]) = r.X(I, J);
        res.Q_E(d[i], d[j]) = r.Q_E(I, J);
        res.Q_V(d[i], d[j]) = r.Q_V(I, J);
        res.delta_V(d[i], d[j]) = r.delta_V(I, J);
        if (all_min) {
          res.Q_V_min(d[i], d[j]) = r.Q_V_min(I, J);
          res.delta_V_min(d[i], d[j]) = r.delta_V_min(I, J);
        }
      }
    for (size_t i = 0; i < comps[k].operators.size(); ++i) {
      const auto o = static_cast<size_t>(comps[k].operators[i]);
      res.gamma[o] = r.gamma[i];
      res.gamma_sqrt[o] = r.gamma_sqrt[i];
      if (all_min) res.gamma_sqrt_min[o] = r.gamma_sqrt_min[i];
    }
    if (all_min) res.Q_V_min_norm = std::max(res.Q_V_min_norm, r.Q_V_min_norm);
  }
  res.min_found = all_min;
  res.min_point_certified = all_min && all_min_cert;
  return res;
}

}  // namespace

AnalysisResult analyze(const Problem& pb, const lmi::Options& opt, AnalysisMode mode, AnalysisPath path) {
  const std::vector<SolvePath> paths = default_paths(path);
  if (path != AnalysisPath::automatic) return analyze_with(pb, paths, opt, mode);  // the whole, as asked
  pb.validate(false);
  const auto t0 = std::chrono::steady_clock::now();
  const std::vector<Component> comps = components(pb);
  if (comps.size() == 1) return analyze_with(pb, paths, opt, mode);
  // independent problems: one per thread (the SDP libraries' calls are serialised by lmi)
  std::vector<AnalysisResult> parts(comps.size());
  const unsigned threads = std::min<unsigned>(study::available_cpus(), static_cast<unsigned>(comps.size()));
  study::run_threads(comps.size(), threads, [&](uint64_t k) { parts[k] = analyze_with(comps[k].problem, paths, opt, mode); });
  AnalysisResult res = assemble(pb, comps, parts, threads);
  res.seconds = since(t0);
  // the components ran side by side: their numeric searches' share of the wall time
  double busy = 0;
  for (const auto& r : parts) busy += r.seconds;
  if (busy > 0) res.sdp_seconds *= std::min(1.0, res.seconds / busy);
  return res;
}

}  // namespace hapstab::multidof
