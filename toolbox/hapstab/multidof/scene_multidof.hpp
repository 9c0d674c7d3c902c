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

#include <string>

#include "hapstab/multidof/analysis.hpp"
#include "hapstab/multidof/assumptions.hpp"
#include "hapstab/numeric/decimal.hpp"
#include "hapstab/scene/scene.hpp"

namespace hapstab::multidof {

struct SceneProblem {
  Problem problem;
  std::vector<TransferMatrix> operators;  ///< each operator's Z_O(s) (for Assumption 1(b))
  std::vector<std::string> operator_names;
  std::vector<std::string> device_evidence;  ///< per device: where its OSP level comes from
  int delay = 0;                             ///< n of the [delay] z^-n (folded into problem.E)
  StateSpace<rational> E_undelayed;          ///< E as analysed before the delay (perturb_C applied)
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
  if (q > 1000) throw InputError(where + "[delay] of " + q.str() + " periods is more than the 1000 multidof models");
  return static_cast<int>(bmp::numerator(q).convert_to<long>());
}

inline rational scene_rational(const toml::node& n, const std::string& where) {
  if (auto s = n.value<std::string>()) return parse_rational(*s, where);
  if (auto i = n.value<int64_t>()) return rational(*i);
  throw InputError(where + ": expected an exact number (string like \"1.37\" or an integer)");
}

inline SceneProblem problem_from_scene(const scene::Scene& sc) {
  SceneProblem sp;
  Problem& pb = sp.problem;
  const std::string f = sc.file + ": ";
  if (!sc.loop.environment) throw InputError(f + "the scene has no [environment] (Theorem 5 needs E)");
  pb.E = minreal(*sc.loop.environment);  // Theorem 5 is realisation-independent; P has one row per state
  const toml::table* md = sc.root["multidof"].as_table();
  const int N = sc.loop.dofs();
  if (pb.E.inputs() != N || pb.E.outputs() != N)
    throw InputError(f + "environment is " + std::to_string(pb.E.outputs()) + "x" + std::to_string(pb.E.inputs()) +
                     " but the devices have " + std::to_string(N) + " DOF (a square N x N E is required)");
  if (md) {
    if (auto* pc = (*md)["perturb_C"].as_array()) {
      MatQ Pi(static_cast<Eigen::Index>(pc->size()), N);
      for (size_t i = 0; i < pc->size(); ++i) {
        auto* row = (*pc)[i].as_array();
        if (!row || static_cast<int>(row->size()) != N)
          throw InputError(f + "multidof.perturb_C must be " + std::to_string(N) + "x" + std::to_string(N));
        for (int j = 0; j < N; ++j)
          Pi(static_cast<Eigen::Index>(i), j) = scene_rational((*row)[static_cast<size_t>(j)], f + "multidof.perturb_C");
      }
      if (Pi.rows() != N) throw InputError(f + "multidof.perturb_C must be " + std::to_string(N) + "x" + std::to_string(N));
      pb.E.C = Pi * pb.E.C;
    }
    if (auto b = (*md)["qv_block_diagonal"].value<bool>()) pb.qv_block_diagonal = *b;
  }
  sp.E_undelayed = pb.E;
  sp.delay = delay_in_periods(sc.loop.delay, sc.T, f);
  if (sp.delay > 0) pb.E = minreal(delayed(pb.E, sp.delay));
  // devices: DOF ranges and OSP levels
  std::vector<int> dev_first;
  int off = 0;
  std::vector<MatQ> osp;
  const toml::array* ospa = md ? (*md)["osp"].as_array() : nullptr;
  if (ospa && ospa->size() != sc.loop.devices.size())
    throw InputError(f + "multidof.osp has " + std::to_string(ospa->size()) + " levels but the scene has " +
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
    if (ospa) {
      const rational declared = scene_rational((*ospa)[d], at);
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
  pb.coupling.mbar.clear();
  pb.coupling.nbar.clear();
  const toml::table* cp = md ? (*md)["coupling"].as_table() : nullptr;
  auto ints = [&](const char* key, std::vector<int>& out) {
    if (!cp) return;
    if (auto* a = (*cp)[key].as_array()) {
      for (const auto& e : *a) {
        auto v = e.value<int64_t>();
        if (!v) throw InputError(f + "multidof.coupling." + key + " must be a list of integers");
        out.push_back(static_cast<int>(*v));
      }
    }
  };
  ints("mbar", pb.coupling.mbar);
  ints("nbar", pb.coupling.nbar);
  if (pb.coupling.mbar.empty())
    for (const auto& d : sc.loop.devices) pb.coupling.mbar.push_back(static_cast<int>(d.dofs()));
  if (pb.coupling.nbar.empty()) pb.coupling.nbar.assign(pb.coupling.mbar.size(), 1);
  return sp;
}

}  // namespace hapstab::multidof
