// hapstab/check/stability_loop_symmetric_check.cpp -- see stability_loop_symmetric_check.hpp.
#include "hapstab/check/stability_loop_symmetric_check.hpp"

#include <algorithm>
#include <cstdint>
#include <string>
#include <vector>

#include "hapstab/check/stability_loop_check.hpp"
#include "hapstab/numeric/error.hpp"

namespace hapstab::check {

namespace {

using P = Polynomial<rational>;
using RF = RationalFunction<rational>;
using SL = detail::SceneLoop;

const std::string kKind = "beyond stability-loop-symmetric";

// What the split takes: one-DOF devices and operators, a tf environment, no coupling (header).
void require_split_loop(const SL& L) {
  if (L.E.is_ss) throw InputError("model.scene: environment.ss: " + kKind + " (the split compares E's entries, a tf)");
  if (L.V && L.V->is_ss) throw InputError("model.scene: coupling.ss: " + kKind + " (the split compares V's entries, a tf)");
  for (const auto& d : L.devices)
    if (d.dofs != 1) throw InputError("model.scene: device '" + d.name + "' on " + std::to_string(d.dofs) + " DOFs: " + kKind + " (one DOF each)");
  for (const auto& o : L.operators)
    if (o.ports.size() != 1)
      throw InputError("model.scene: operator '" + o.name + "' on " + std::to_string(o.ports.size()) + " DOFs: " + kKind + " (one-port operators)");
}

std::vector<const SL::Impedance*> operators_on(const SL& L, int i) {
  std::vector<const SL::Impedance*> out;
  for (const auto& o : L.operators)
    if (o.ports[0] == i) out.push_back(&o);
  return out;
}

// DOFs i and j carry the same device and the same operators, in order (exactly). With one-DOF devices, device i
// is DOF i.
bool same_dof(const SL& L, int i, int j) {
  if (L.mass[size_t(i)] != L.mass[size_t(j)] || L.damping[size_t(i)] != L.damping[size_t(j)] ||
      L.stiffness[size_t(i)] != L.stiffness[size_t(j)])
    return false;
  const SL::Device &a = L.devices[size_t(i)], &b = L.devices[size_t(j)];
  if (a.block != b.block || a.A != b.A || a.B != b.B || a.C != b.C || a.tf != b.tf) return false;
  const auto oa = operators_on(L, i), ob = operators_on(L, j);
  if (oa.size() != ob.size()) return false;
  for (size_t k = 0; k < oa.size(); ++k)
    if (oa[k]->is_ss != ob[k]->is_ss || oa[k]->A != ob[k]->A || oa[k]->B != ob[k]->B || oa[k]->C != ob[k]->C || oa[k]->D != ob[k]->D ||
        oa[k]->Z != ob[k]->Z)
      return false;
  return true;
}

// A block's environment or coupling: its tf matrix, column j to be realised over over[j].
struct BlockTf {
  std::vector<std::vector<RF>> tf;
  std::vector<P> over;
};

// The loop of the DOFs `reps` (their devices and operators, in the whole's order) under E (and V: the scene's
// coupling, split the same way).
SL block_loop(const SL& L, const std::vector<int>& reps, const BlockTf& E, const std::optional<BlockTf>& V) {
  SL B;
  B.T = L.T;
  B.delay = L.delay;
  B.fraction = L.fraction;
  for (size_t a = 0; a < reps.size(); ++a) {
    SL::Device d = L.devices[size_t(reps[a])];
    d.first = a;
    B.devices.push_back(std::move(d));
    B.mass.push_back(L.mass[size_t(reps[a])]);
    B.damping.push_back(L.damping[size_t(reps[a])]);
    B.stiffness.push_back(L.stiffness[size_t(reps[a])]);
  }
  for (const auto& o : L.operators)
    if (const auto it = std::find(reps.begin(), reps.end(), o.ports[0]); it != reps.end()) {
      SL::Impedance c = o;
      c.ports = {static_cast<int>(it - reps.begin())};
      B.operators.push_back(std::move(c));
    }
  B.E = detail::column_realisation(E.tf, E.over);
  if (V) B.V = detail::column_realisation(V->tf, V->over);
  return B;
}

std::string dof_pair(const char* M, int i, int j) { return std::string(M) + "[" + std::to_string(i + 1) + "][" + std::to_string(j + 1) + "]"; }

}  // namespace

std::optional<detail::SymmetricSplit> detail::split_loop(const SceneLoop& L, const std::vector<std::vector<int>>& classes,
                                                         std::string& why) {
  require_split_loop(L);
  const size_t N = L.dofs();
  std::vector<int> class_of(N, -1);
  for (size_t a = 0; a < classes.size(); ++a) {
    if (classes[a].empty()) throw InputError("evidence.classes[" + std::to_string(a + 1) + "]: empty");
    for (int i : classes[a]) {
      if (i < 0 || size_t(i) >= N) throw InputError("evidence.classes: DOF " + std::to_string(i) + " is not one of the scene's 0 .. " + std::to_string(N - 1));
      if (class_of[size_t(i)] >= 0) throw InputError("evidence.classes: DOF " + std::to_string(i) + " in two classes");
      class_of[size_t(i)] = static_cast<int>(a);
    }
  }
  if (std::count(class_of.begin(), class_of.end(), -1) > 0) throw InputError("evidence.classes: not every DOF is in a class (a partition of the DOFs)");
  const size_t r = classes.size();
  std::vector<int> f(r), s(r, -1);
  for (size_t a = 0; a < r; ++a) {
    f[a] = classes[a][0];
    if (classes[a].size() > 1) s[a] = classes[a][1];
    for (int i : classes[a])
      if (!same_dof(L, f[a], i)) {
        why = "DOF " + std::to_string(i) + " is not identical to DOF " + std::to_string(f[a]) + " of its class (device or operators)";
        return std::nullopt;
      }
  }
  // E (and V) invariant: every entry its class pattern's representative
  const auto invariant = [&](const std::vector<std::vector<RF>>& G, const char* name) {
    for (size_t i = 0; i < N; ++i)
      for (size_t j = 0; j < N; ++j) {
        const int a = class_of[i], b = class_of[j];
        const int ri = f[size_t(a)], rj = i == j ? ri : a == b ? s[size_t(a)] : f[size_t(b)];
        if (!(G[i][j] == G[size_t(ri)][size_t(rj)])) {
          why = std::string("the ") + (name[0] == 'E' ? "environment" : "coupling") + " is not invariant under the classes: " +
                dof_pair(name, int(i), int(j)) + " != " + dof_pair(name, ri, rj);
          return false;
        }
      }
    return true;
  };
  if (!invariant(L.E.tf, "E") || (L.V && !invariant(L.V->tf, "V"))) return std::nullopt;
  // per matrix G (E, V): column b's lcm -- its entries are G_{f_b f_b}, G_{f_b s_b} (a class of two or more) and
  // G_{f_a f_b} (a != b) --, the fixed space's G_F[a][a] = G_{f_a f_a} + (k_a - 1) G_{f_a s_a}, G_F[a][b] = k_b
  // G_{f_a f_b}, and class a's zero-sum G_{f_a f_a} - G_{f_a s_a}
  const auto split = [&](const std::vector<std::vector<RF>>& G) {
    std::vector<BlockTf> out(r + 1);  // [0]: the fixed space; [a + 1]: class a's zero-sum space
    std::vector<P> over(r);
    for (size_t b = 0; b < r; ++b) {
      std::vector<std::vector<RF>> column;
      for (size_t a = 0; a < r; ++a) column.push_back({G[size_t(f[a])][size_t(f[b])]});
      if (s[b] >= 0) column.push_back({G[size_t(f[b])][size_t(s[b])]});
      over[b] = column_lcms(column)[0];
    }
    out[0].tf.assign(r, std::vector<RF>(r, RF(0)));
    out[0].over = over;
    for (size_t a = 0; a < r; ++a)
      for (size_t b = 0; b < r; ++b)
        out[0].tf[a][b] = a == b ? G[size_t(f[a])][size_t(f[a])] + (s[a] >= 0 ? RF(rational(classes[a].size() - 1)) * G[size_t(f[a])][size_t(s[a])] : RF(0))
                                 : RF(rational(classes[b].size())) * G[size_t(f[a])][size_t(f[b])];
    for (size_t a = 0; a < r; ++a)
      if (s[a] >= 0) out[a + 1] = {{{G[size_t(f[a])][size_t(f[a])] - G[size_t(f[a])][size_t(s[a])]}}, {over[a]}};
    return out;
  };
  const std::vector<BlockTf> E = split(L.E.tf);
  const std::optional<std::vector<BlockTf>> V = L.V ? std::optional<std::vector<BlockTf>>(split(L.V->tf)) : std::nullopt;
  const auto v_of = [&](size_t k) { return V ? std::optional<BlockTf>((*V)[k]) : std::nullopt; };
  SymmetricSplit out;
  out.fixed = block_loop(L, f, E[0], v_of(0));
  for (size_t a = 0; a < r; ++a) {
    out.sizes.push_back(classes[a].size());
    out.zero_sum.push_back(s[a] < 0 ? SceneLoop{} : block_loop(L, {f[a]}, E[a + 1], v_of(a + 1)));
  }
  return out;
}

std::vector<std::vector<int>> detail::identical_dofs(const SceneLoop& L) {
  require_split_loop(L);
  std::vector<std::vector<int>> classes;
  for (size_t i = 0; i < L.dofs(); ++i) {
    const int d = static_cast<int>(i);
    auto it = std::find_if(classes.begin(), classes.end(), [&](const std::vector<int>& c) {
      return same_dof(L, c[0], d) && L.E.tf[size_t(c[0])][size_t(c[0])] == L.E.tf[i][i] &&
             (!L.V || L.V->tf[size_t(c[0])][size_t(c[0])] == L.V->tf[i][i]);
    });
    if (it == classes.end())
      classes.push_back({d});
    else
      it->push_back(d);
  }
  return classes;
}

std::vector<std::vector<int>> detail::read_classes(const nlohmann::json& evidence, size_t dofs) {
  if (!evidence.contains("classes") || !evidence.at("classes").is_array()) throw InputError("evidence.classes: missing or not an array");
  std::vector<std::vector<int>> classes;
  for (const auto& c : evidence.at("classes")) {
    if (!c.is_array()) throw InputError("evidence.classes: each class an array of DOF indices (0-based)");
    classes.emplace_back();
    for (const auto& i : c) {
      // range-checked before it is narrowed (2^32 + 1 must not read as DOF 1)
      if (!i.is_number_integer() || (i.is_number_unsigned() ? i.get<uint64_t>() >= dofs : i.get<int64_t>() < 0 || i.get<int64_t>() >= static_cast<int64_t>(dofs)))
        throw InputError("evidence.classes: " + i.dump() + " is not a DOF index of the scene's 0 .. " + std::to_string(dofs - 1));
      classes.back().push_back(static_cast<int>(i.get<int64_t>()));
    }
  }
  return classes;
}

detail::BlockSlot detail::block_slot(const nlohmann::json& blk, const SymmetricSplit& split, const std::string& where) {
  const std::string space = blk.contains("space") && blk.at("space").is_string() ? blk.at("space").get<std::string>() : "";
  if (space == "fixed") {
    if (blk.contains("class")) throw InputError(where + ".class: only for a zero-sum block");
    return {0, 1, space};
  }
  if (space != "zero-sum") throw InputError(where + ".space: missing or not \"fixed\" / \"zero-sum\"");
  const long a = detail::integer_field(blk, "class", where, 0, static_cast<long>(split.sizes.size()) - 1);
  if (split.sizes[size_t(a)] < 2) throw InputError(where + ".class: class " + std::to_string(a) + " has one DOF (no zero-sum space)");
  return {size_t(a) + 1, split.sizes[size_t(a)] - 1, space};
}

Verdict check_stability_loop_symmetric(const nlohmann::json& cert) {
  const auto [model, claim, evidence] = detail::certificate_parts(cert);
  detail::only_fields(claim, {"quantity", "status", "stable", "conserved"}, "claim");
  detail::only_fields(evidence, {"classes", "blocks"}, "evidence");
  if (!claim.contains("status") || claim.at("status") != "certified")
    throw InputError("claim.status: missing or not \"certified\" (the loop holds exponentials: an enclosure decides)");
  if (!claim.contains("stable") || !claim.at("stable").is_boolean()) throw InputError("claim.stable: missing or not true/false");
  const bool stable = claim.at("stable").get<bool>();
  if (!stable && claim.contains("conserved")) throw InputError("claim.conserved: only with stable (NOT stable is shown by one block)");
  const long conserved = claim.contains("conserved") ? detail::integer_field(claim, "conserved", "claim", 0, 1L << 20) : 0;
  if (!model.contains("scene")) throw InputError("model.scene: missing (this kind splits a scene's DOFs)");
  const detail::SceneLoop L = detail::read_scene_loop(model, detail::kMaxSymmetricDofs);
  const std::vector<std::vector<int>> classes = detail::read_classes(evidence, L.dofs());
  std::string why;
  const auto split = detail::split_loop(L, classes, why);
  if (!split) return {false, "evidence.classes: " + why};
  if (!evidence.contains("blocks") || !evidence.at("blocks").is_array()) throw InputError("evidence.blocks: missing or not an array");
  const auto& blocks = evidence.at("blocks");
  size_t needed = 1;
  for (size_t k : split->sizes) needed += k >= 2 ? 1 : 0;
  if (stable ? blocks.size() != needed : blocks.size() != 1)
    throw InputError("evidence.blocks: " + std::to_string(blocks.size()) + " blocks; " +
                     (stable ? "stable needs every one: the fixed space and each class of two DOFs or more, " + std::to_string(needed)
                             : std::string("NOT stable is shown by one")));
  std::vector<bool> seen(split->sizes.size() + 1, false);
  long total = 0;
  std::string said;
  for (size_t b = 0; b < blocks.size(); ++b) {
    const std::string where = "evidence.blocks[" + std::to_string(b + 1) + "]";
    const auto& blk = blocks[b];
    if (!blk.is_object()) throw InputError(where + ": not an object");
    detail::only_fields(blk, {"space", "class", "conserved", "P", "w"}, where);
    const auto [slot, copies, space] = detail::block_slot(blk, *split, where);
    if (seen[slot]) throw InputError(where + ": a block given twice");
    seen[slot] = true;
    const long k = blk.contains("conserved") ? detail::integer_field(blk, "conserved", where, 0, 1024) : 0;
    const Verdict v = detail::stein_verdict(split->block(slot), blk, stable, k, where);
    if (!v.verified) return {false, where + " (" + space + "): " + v.reason};
    total += static_cast<long>(copies) * k;
    said += (said.empty() ? "" : "; ") + space + (slot ? " of class " + std::to_string(slot - 1) + " (x" + std::to_string(copies) + ")" : "") +
            ": " + v.reason;
  }
  if (stable && total != conserved)
    return {false, "claim: " + std::to_string(conserved) + " conserved quantities, but the blocks have " + std::to_string(total) +
                       " (k_F + sum_a (k_a - 1) k_a')"};
  return {true, std::string(stable ? "stable" : "NOT stable") + " by the split of " + std::to_string(L.dofs()) + " DOFs into " +
                    std::to_string(classes.size()) + " classes of identical DOFs (invariance checked exactly on the scene as written): " + said};
}

}  // namespace hapstab::check
