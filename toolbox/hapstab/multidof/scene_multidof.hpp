// hapstab/multidof/scene_multidof.hpp -- a scene (scene/scene.hpp: devices, operators,
// environment, delay) -> a multidof::Problem, plus the scene's own [multidof] section:
//
//   [multidof]
//   osp = ["1.37", "1.37"]          # device OSP levels (default: the certified level)
//   perturb_C = [["0","1"],["1","0"]]  # optional: C_E := Pi C_E (D_E unchanged), Sec. VI
//   qv_block_diagonal = false       # Remark 3
//   [multidof.coupling]             # Theorem 6 structure (R2)
//   mbar = [1, 1]                   # default: one block per device
//   nbar = [1, 1]                   # default: 1 state per block
//
// The [multidof] values are the schema's typed ones (scene::multidof_values, scene/schema.hpp:
// exact numbers as every other key, expressions of T and the parameters included); this header
// checks them against the scene (sizes, levels, limits), naming the key.
//
// Device OSP levels (Assumption 1(a)) are computed from the device model (assumptions.hpp: b
// of 1/(m s + b) exactly, else a certified lower bound). A declared `osp` is accepted only where
// the device is proven OSP at that level (a lower level is conservative); a level above the
// certified one is an InputError naming both numbers.
//
// [delay]: the computation delay t_d = n T holds the force computed at kT until (k + n)T, so
// the force on the devices is z^-n E x: E is replaced by z^-n E, realised exactly by n*m shift
// states after E's output (perturb_C acts on E before the delay). Theorem 5's conclusion is then
// about the delayed loop. A delay that is not a whole number of periods is an InputError naming
// `hapstab simulate` and `hapstab bound --frac-delay`, which model it.
//
// The operators' DOFs define the structure: operator i acts on m_i consecutive DOFs (in
// device order) and uses the devices on them (case i: one operator on both devices; case ii:
// one operator per device). Inconsistencies (a DOF without operator, a device split between
// operators, non-contiguous operator DOFs) are InputErrors naming the scene entry. Header-only
// so that the multidof library does not depend on scene/.
#pragma once

#include <algorithm>
#include <string>

#include "hapstab/multidof/analysis.hpp"
#include "hapstab/multidof/assumptions.hpp"
#include "hapstab/numeric/decimal.hpp"
#include "hapstab/numeric/limits.hpp"
#include "hapstab/scene/scene.hpp"
#include "hapstab/scene/schema.hpp"
#include "hapstab/sim/hidden_modes.hpp"
#include "hapstab/stability/symmetry.hpp"

namespace hapstab::multidof {

struct SceneProblem {
  Problem problem;
  std::vector<TransferMatrix> operators;  ///< each operator's Z_O(s) (for Assumption 1(b))
  std::vector<std::string> operator_names;
  std::vector<std::string> device_evidence;  ///< per device: where its OSP level comes from
  int delay = 0;                             ///< n of the [delay] z^-n (folded into problem.E)
  sim::LoopHiddenModes hidden;               ///< every block's hidden modes, as written (sim/hidden_modes.hpp)
  /// The scene's loop, its environment the scene's realisation of E with perturb_C applied, not
  /// reduced (E as written; held once: a 1024-device environment's is 2 GB of exact entries): the
  /// loop the verdicts are about.
  sim::LoopSpec loop;
  const StateSpace<rational>& E_written() const { return *loop.environment; }
  /// The split by identical DOFs found when the problem was made (stability/symmetry.hpp), if any.
  bool symmetric = false;
};

/// z^-n E: n shift registers of m states after E's output (exact).
inline StateSpace<rational> delayed(const StateSpace<rational>& E, int n) {
  if (n == 0) return E;
  const Eigen::Index ne = E.states(), m = E.outputs(), p = E.inputs(), N = ne + n * m;
  StateSpace<rational> D{MatQ::Zero(N, N), MatQ::Zero(N, p), MatQ::Zero(m, N), MatQ::Zero(m, p), E.T};
  D.A.topLeftCorner(ne, ne) = E.A;
  D.A.block(ne, 0, m, ne) = E.C;  // w_1(k+1) = C x + D u
  D.B.topRows(ne) = E.B;
  D.B.middleRows(ne, m) = E.D;
  for (int k = 1; k < n; ++k) D.A.block(ne + k * m, ne + (k - 1) * m, m, m) = MatQ::Identity(m, m);
  D.C.rightCols(m) = MatQ::Identity(m, m);  // y = w_n
  return D;
}

/// The whole number n of sample periods in `delay` seconds; InputError otherwise.
inline int delay_in_periods(const rational& delay, const rational& T, const std::string& where) {
  const rational q = delay / T;
  if (bmp::denominator(q) != 1)
    throw InputError(where + "[delay] is " + q.str() + " sample periods, not a whole number: multidof analyze/design "
                     "model an integer delay z^-n only (folded into E); a fractional delay is modelled by "
                     "`hapstab simulate` and `hapstab bound --frac-delay`");
  if (q > limits::multidof_states)
    throw InputError(where + "[delay] of " + q.str() + " periods is more than the " + std::to_string(limits::multidof_states) +
                     " multidof models");
  return static_cast<int>(bmp::numerator(q).convert_to<long>());
}

/// What the caller will do with the problem: analyze (Theorem 5, the loop as written) never
/// builds Theorem 6's coupling, so the coupling's size limits (numeric/limits.hpp
/// coupling_block_states, coupling_states) are design's only; a [multidof.coupling] the scene
/// writes is checked against its DOFs for both.
enum class SceneUse { analyze, design };

// [multidof.coupling] (or its defaults) against the DOFs; design also against its size limits
// (the whole coupling's only with `whole`: a symmetric scene's design builds one block per class,
// design_scene checks the whole's limits when the split does not decide).
inline void check_coupling_structure(CouplingStructure& c, int N, SceneUse use, bool written, const std::string& f,
                                     bool whole = true) {
  long total = 0;
  for (size_t i = 0; use == SceneUse::design && i < c.nbar.size(); ++i) {
    const int n = c.nbar[i];
    if (n > limits::coupling_block_states)
      throw InputError(f + "multidof.coupling.nbar[" + std::to_string(i) + "] = " + std::to_string(n) +
                       " states, more than the limit of " + std::to_string(limits::coupling_block_states) + " per block");
    total += n;
  }
  if (whole && total > limits::coupling_states)
    throw InputError(f + "multidof.coupling.nbar: " + std::to_string(total) + " states in all, more than the limit of " +
                     std::to_string(limits::coupling_states) + " of the coupling `multidof design` builds" +
                     (written ? "" : " (by default one state per device; `multidof analyze` builds none)"));
  if (use == SceneUse::analyze && !written) return;  // the defaults analyze never builds
  try {
    c.validate(N);
  } catch (const InputError& e) {
    throw InputError(f + "multidof.coupling: " + e.what());
  }
}

inline SceneProblem problem_from_scene(const scene::Scene& sc, SceneUse use = SceneUse::design) {
  SceneProblem sp;
  Problem& pb = sp.problem;
  const std::string f = sc.file + ": ";
  if (!sc.loop.environment) throw InputError(f + "the scene has no [environment] (Theorem 5 needs E)");
  const int N = sc.loop.dofs();
  if (sc.loop.environment->inputs() != N || sc.loop.environment->outputs() != N)
    throw InputError(f + "environment is " + std::to_string(sc.loop.environment->outputs()) + "x" +
                     std::to_string(sc.loop.environment->inputs()) + " but the devices have " + std::to_string(N) +
                     " DOF (a square N x N E is required)");
  const scene::MultidofValues md = scene::multidof_values(sc);  // [multidof], typed (scene/schema.hpp)
  sp.loop = sc.loop;
  if (md.perturb_C) {
    const auto& rows = *md.perturb_C;
    const bool square = static_cast<int>(rows.size()) == N &&
                        std::all_of(rows.begin(), rows.end(), [&](const auto& r) { return static_cast<int>(r.size()) == N; });
    if (!square) throw InputError(f + "multidof.perturb_C must be " + std::to_string(N) + "x" + std::to_string(N));
    MatQ Pi(N, N);
    for (int i = 0; i < N; ++i)
      for (int j = 0; j < N; ++j) Pi(i, j) = rows[static_cast<size_t>(i)][static_cast<size_t>(j)];
    StateSpace<rational>& E = *sp.loop.environment;
    E.C = Pi * E.C;  // C_E := Pi C_E: the same transfer matrix on every realisation
  }
  pb.qv_block_diagonal = md.qv_block_diagonal;
  // Hidden modes first, on the realisations as written; then E is reduced (Theorem 5 is about
  // the input-output behaviour, valid once the hidden modes are known: multidof::premises)
  // by the permutations of identical DOFs where the scene has them (their blocks' Kalman
  // decompositions, not the whole's: stability/symmetry.hpp environment_hidden_modes)
  std::string no_split;
  const auto sym = stability::detail::split_by_symmetry(sp.loop, no_split);
  HiddenModes env = sym ? stability::detail::environment_hidden_modes(*sym, sp.E_written()) : hidden_modes(sp.E_written());
  sp.symmetric = sym.has_value();
  sp.hidden = sim::hidden_modes(sp.loop, &env);
  pb.E = std::move(env.minimal);  // P has one row per state of the minimal E
  sp.delay = delay_in_periods(sc.loop.delay, sc.T, f);
  const long folded = static_cast<long>(pb.E.states()) + static_cast<long>(sp.delay) * N;
  // a symmetric scene's analysis and design work on its blocks (multidof/symmetry.hpp), and refuse
  // the whole program beyond the limit only if the split does not decide (analyze_scene_lmis,
  // design_scene)
  if (folded > limits::multidof_states && sp.delay == 0 && !sp.symmetric)
    throw InputError(f + "E has " + std::to_string(folded) + " states (reduced), more than the limit of " +
                     std::to_string(limits::multidof_states) + " that multidof " + (use == SceneUse::design ? "design" : "analyze") +
                     " models");
  if (folded > limits::multidof_states && sp.delay > 0)
    throw InputError(f + "[delay] of " + std::to_string(sp.delay) + " samples folds " + std::to_string(sp.delay * N) +
                     " shift states into E (" + std::to_string(folded) + " states with E's own " +
                     std::to_string(pb.E.states()) + "), more than the limit of " + std::to_string(limits::multidof_states) +
                     " that multidof analyze|design model (`hapstab stability --scene` and `simulate` run longer delays)");
  if (sp.delay > 0) pb.E = minreal(delayed(pb.E, sp.delay));
  // devices: DOF ranges and OSP levels
  std::vector<int> dev_first;
  int off = 0;
  std::vector<MatQ> osp;
  if (md.osp && md.osp->size() != sc.loop.devices.size())
    throw InputError(f + "multidof.osp has " + std::to_string(md.osp->size()) + " levels but the scene has " +
                     std::to_string(sc.loop.devices.size()) + " devices");
  for (size_t d = 0; d < sc.loop.devices.size(); ++d) {
    const auto& dev = sc.loop.devices[d];
    const int k = static_cast<int>(dev.dofs());
    dev_first.push_back(off);
    off += k;
    std::optional<std::pair<rational, rational>> md_mb;  // 1/(m s + b): level b
    if (dev.mass && k == 1 && dev.G.states() == 1) md_mb = std::make_pair(1 / dev.G.B(0, 0), -dev.G.A(0, 0) / dev.G.B(0, 0));
    const TransferMatrix G = ss2tf(dev.G);
    const DeviceLevel level = device_osp_level(G, md_mb);
    const std::string at = f + "multidof.osp[" + std::to_string(d) + "]";
    if (md.osp) {
      const rational declared = (*md.osp)[d];
      if (declared > 0) {
        const bool ok = level.verdict.holds() && (declared <= level.lo || (!level.exact && device_is_osp(G, declared).holds()));
        if (!ok)
          throw InputError(at + " = " + declared.str() + " is above the OSP level of device '" + dev.name +
                           "' computed from its model: " + level.verdict.evidence +
                           ". A declared level may only be lower (conservative); remove osp to use the computed one");
      }
      osp.push_back(declared * MatQ::Identity(k, k));
      sp.device_evidence.push_back(declared == level.lo && level.exact ? level.verdict.evidence
                                   : "declared; at most the level from the model: " + level.verdict.evidence);
    } else {
      if (!level.verdict.holds())
        throw InputError(f + "device '" + dev.name + "': " + level.verdict.evidence +
                         "; Assumption 1(a) needs a positive OSP level, so Theorems 5 and 6 do not apply");
      osp.push_back(level.lo * MatQ::Identity(k, k));
      sp.device_evidence.push_back(level.verdict.evidence);
    }
  }
  // operators: contiguous DOFs, whole devices
  std::vector<int> owner(static_cast<size_t>(N), -1);
  for (size_t i = 0; i < sc.loop.operators.size(); ++i) {
    const auto& op = sc.loop.operators[i];
    for (size_t k = 0; k < op.ports.size(); ++k) {
      const int p = op.ports[k];
      if (owner[static_cast<size_t>(p)] >= 0)
        throw InputError(f + "DOF " + std::to_string(p) + " belongs to two operators");
      owner[static_cast<size_t>(p)] = static_cast<int>(i);
      if (k > 0 && p != op.ports[k - 1] + 1)
        throw InputError(f + "operator '" + op.name + "': its DOFs must be consecutive and in device order");
    }
  }
  for (int p = 0; p < N; ++p)
    if (owner[static_cast<size_t>(p)] < 0)
      throw InputError(f + "block sizes do not add up: DOF " + std::to_string(p) + " has no operator (sum m_i < m = " +
                       std::to_string(N) + ")");
  for (size_t i = 0; i < sc.loop.operators.size(); ++i) {
    const auto& op = sc.loop.operators[i];
    Operator o;
    o.name = op.name;
    o.dof = static_cast<int>(op.ports.size());
    for (size_t d = 0; d < sc.loop.devices.size(); ++d) {
      const int a = dev_first[d], k = static_cast<int>(sc.loop.devices[d].dofs());
      int inside = 0;
      for (int q = a; q < a + k; ++q) inside += owner[static_cast<size_t>(q)] == static_cast<int>(i);
      if (inside == 0) continue;
      if (inside != k)
        throw InputError(f + "device '" + sc.loop.devices[d].name + "' is split between operators");
      o.devices.push_back(Device{sc.loop.devices[d].name, k, osp[d]});
    }
    pb.structure.operators.push_back(o);
    sp.operators.push_back(ss2tf(op.Z));
    sp.operator_names.push_back(op.name);
  }
  // operators must come in DOF order for the block structure
  for (size_t i = 1; i < sc.loop.operators.size(); ++i)
    if (sc.loop.operators[i].ports.front() < sc.loop.operators[i - 1].ports.front())
      throw InputError(f + "operators must be listed in DOF order");
  // coupling structure
  pb.coupling.mbar = md.mbar;
  pb.coupling.nbar = md.nbar;
  if (pb.coupling.mbar.empty())
    for (const auto& d : sc.loop.devices) pb.coupling.mbar.push_back(static_cast<int>(d.dofs()));
  if (pb.coupling.nbar.empty()) pb.coupling.nbar.assign(pb.coupling.mbar.size(), 1);
  // the structure as a whole (sizes first: nothing is allocated yet)
  check_coupling_structure(pb.coupling, N, use, !md.mbar.empty() || !md.nbar.empty(), f, !sp.symmetric);
  return sp;
}

/// The premises the realisations as written must meet, from their hidden modes (an empty list
/// when no block hides a mode): E Schur stable (Theorem 5) for the environment, Assumption 1(a)
/// for a device, 1(b) for an operator. A hidden mode outside the stability region fails the
/// premise by name (exact); Theorem 5's LMIs are posed on the reduced blocks, which is legitimate
/// only when every line here holds. The coupling's hidden modes concern the loop as written only.
inline std::vector<AssumptionCheck> hidden_mode_premises(const SceneProblem& sp) {
  std::vector<AssumptionCheck> out;
  auto premise = [&](const std::string& block) {
    if (block == "environment") return std::string("E Schur stable as written (Theorem 5): the environment's hidden modes");
    if (block.rfind("device", 0) == 0) return "Assumption 1(a): " + block + " as written: its hidden modes";
    return "Assumption 1(b): " + block + " as written: its hidden modes";
  };
  std::vector<std::string> blocks;
  for (const auto& h : sp.hidden.modes)
    if (h.block != "coupling" && std::find(blocks.begin(), blocks.end(), h.block) == blocks.end()) blocks.push_back(h.block);
  for (const auto& b : blocks) {
    std::string bad, good;
    for (const auto& h : sp.hidden.modes)
      if (h.block == b) (h.stable ? good : bad) += (h.stable ? good : bad).empty() ? h.text() : "; " + h.text();
    out.push_back({premise(b), bad.empty() ? Verdict::of(true, Status::exact, "stable hidden modes only (they never move): " + good)
                                           : Verdict::of(false, Status::exact,
                                                         "a hidden mode outside the stability region (no input reaches or "
                                                         "no output shows it, so no coupling or loop moves it): " + bad)});
  }
  if (!sp.hidden.undecided.empty())  // set-aside modes at z = 1 that may chain (sim/hidden_modes.hpp)
    out.push_back({"the modes set aside at z = 1 / s = 0 settle in the loop as written",
                   Verdict{Outcome::undecided, Status::failed, sp.hidden.undecided}});
  return out;
}

}  // namespace hapstab::multidof
