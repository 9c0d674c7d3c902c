// hapstab/check/stability_loop_max_symmetric_check.cpp -- see stability_loop_max_symmetric_check.hpp.
#include "hapstab/check/stability_loop_max_symmetric_check.hpp"

#include <optional>
#include <string>
#include <vector>

#include "hapstab/check/scene_model.hpp"
#include "hapstab/check/stability_loop_check.hpp"
#include "hapstab/check/stability_loop_max_check.hpp"
#include "hapstab/check/stability_loop_symmetric_check.hpp"
#include "hapstab/numeric/error.hpp"

namespace hapstab::check {

Verdict check_stability_loop_max_symmetric(const nlohmann::json& cert) {
  const auto [model, claim, evidence] = detail::certificate_parts(cert);
  detail::only_fields(model, {"scene", "set", "name"}, "model");
  detail::only_fields(claim, {"quantity", "status", "lo", "hi", "printed_lo", "printed_hi", "conserved"}, "claim");
  detail::only_fields(evidence, {"classes", "blocks"}, "evidence");
  if (!model.contains("scene") || !model.at("scene").is_string()) throw InputError("model.scene: missing or not a string");
  const auto [p, c] = detail::sup_model(model, claim);
  if (c.refuted) return {false, *c.refuted};
  const bool zero = c.hi.is_zero();
  if (zero && claim.contains("conserved")) throw InputError("claim.conserved: only with hi > 0 (sup = 0 is shown by one block)");
  const long conserved = claim.contains("conserved") ? detail::integer_field(claim, "conserved", "claim", 0, 1L << 20) : 0;
  const detail::MaxReading r = detail::read_max_parameter(model.at("scene").get<std::string>(), p);
  if (r.block != "environment")
    throw InputError("model.name: '" + p + "' is the gain of [coupling]: beyond stability-loop-max-symmetric (the split compares the "
                     "environment only)");
  const detail::SceneLoop L1 = detail::read_scene_loop(detail::model_at(model, p, rational(1)), detail::kMaxSymmetricDofs),
                          L2 = detail::read_scene_loop(detail::model_at(model, p, rational(2)), detail::kMaxSymmetricDofs);
  const std::vector<std::vector<int>> classes = detail::read_classes(evidence, L1.dofs());
  std::string why;
  const auto s1 = detail::split_loop(L1, classes, why);
  if (!s1) return {false, "evidence.classes: at " + p + " = 1, " + why};
  const auto s2 = detail::split_loop(L2, classes, why);
  if (!s2) return {false, "evidence.classes: at " + p + " = 2, " + why};
  // p inside the environment's tf (header): each column's largest order (block b's column is realised over the
  // whole's column f_b), and the blocks split from the loop read at hi
  long degree = 0;
  const std::vector<size_t> column = r.inside ? detail::affine_column_orders(model, r, p, L1, degree) : std::vector<size_t>{};
  std::optional<detail::SymmetricSplit> s_hi;
  if (r.inside && !c.hi.is_zero()) {
    s_hi = detail::split_loop(detail::read_scene_loop(detail::model_at(model, p, c.hi), detail::kMaxSymmetricDofs), classes, why);
    if (!s_hi) return {false, "evidence.classes: at " + p + " = " + c.hi.str() + ", " + why};
  }
  if (!evidence.contains("blocks") || !evidence.at("blocks").is_array()) throw InputError("evidence.blocks: missing or not an array");
  const auto& blocks = evidence.at("blocks");
  size_t needed = 1;
  for (size_t k : s1->sizes) needed += k >= 2 ? 1 : 0;
  if (zero ? blocks.size() != 1 : blocks.size() != needed)
    throw InputError("evidence.blocks: " + std::to_string(blocks.size()) + " blocks; " +
                     (zero ? std::string("sup = 0 is shown by one") : "every one is needed: the fixed space and each class of two DOFs or more, " + std::to_string(needed)));
  std::vector<bool> seen(s1->sizes.size() + 1, false);
  long total = 0, unstable = 0;
  std::string said;
  for (size_t b = 0; b < blocks.size(); ++b) {
    const std::string where = "evidence.blocks[" + std::to_string(b + 1) + "]";
    const auto& blk = blocks[b];
    if (!blk.is_object()) throw InputError(where + ": not an object");
    detail::only_fields(blk, {"space", "class", "conserved", "cover", "first_order", "unstable_at", "first_order_unstable", "no_crossing"}, where);
    const auto [slot, copies, space] = detail::block_slot(blk, *s1, where);
    if (seen[slot]) throw InputError(where + ": a block given twice");
    seen[slot] = true;
    unstable += blk.contains("unstable_at") || blk.contains("first_order_unstable") ? 1 : 0;
    const long k = blk.contains("conserved") ? detail::integer_field(blk, "conserved", where, 0, 1024) : 0;
    size_t order = 0;  // p inside the tf: the block's largest order, the sum of its columns'
    std::optional<detail::LoopMatrix> at_hi;
    if (r.inside) {
      for (size_t a = 0; a < classes.size(); ++a)
        if (slot == 0 || slot == a + 1) order += column[static_cast<size_t>(classes[a][0])];
      if (s_hi) {
        flint::BallPrecision scope(128);
        at_hi = detail::loop_matrix(s_hi->block(slot), 128);
      }
    }
    const detail::MaxPart part = detail::check_max_part(s1->block(slot), s2->block(slot), r, p, blk, c, k, order, at_hi, where, false);
    if (!part.verified)
      return {false, "claim: sup " + p + " in [" + detail::decimal(c.lo) + ", " + detail::decimal(c.hi) + "], but " + where + " (" + space +
                         "): " + part.why + " at 512 bits"};
    if (!*part.verified) return {false, where + " (" + space + "): " + part.why};
    total += static_cast<long>(copies) * k;
    said += (said.empty() ? "" : "; ") + space + (slot ? " of class " + std::to_string(slot - 1) + " (x" + std::to_string(copies) + ")" : "") +
            ": " + std::to_string(part.order) + " states, " + (blk.contains("cover") ? std::to_string(blk.at("cover").size()) + " intervals" : "no cover") +
            (blk.contains("first_order") ? " after a first-order start" : "") + (blk.contains("unstable_at") ? ", NOT stable at hi" : "") +
            (blk.contains("first_order_unstable") ? ", NOT stable on (0, eps] by the first-order mirror" : "") + " (" +
            std::to_string(part.bits) + " bits)";
  }
  if (unstable != 1)
    throw InputError("evidence.blocks: " + std::to_string(unstable) + " with unstable_at or first_order_unstable; exactly one block bounds sup from above");
  if (!zero && total != conserved)
    return {false, "claim: " + std::to_string(conserved) + " conserved quantities, but the blocks have " + std::to_string(total) +
                       " (k_F + sum_a (k_a - 1) k_a')"};
  const std::string head = "by the split of " + std::to_string(L1.dofs()) + " DOFs into " + std::to_string(classes.size()) +
                           " classes of identical DOFs (invariance checked exactly on the scene at " + p + " = 1 and 2; " + p +
                           (r.inside ? " inside the environment's tf, each entry proven affine in it (degree bound " + std::to_string(degree) + ")"
                                     : " the environment's gain alone") + ", each block's loop affine in it): ";
  if (zero) return {true, "sup " + p + " = 0 " + head + said + ": that block is NOT stable for every small " + p + " > 0"};
  return {true, "sup " + p + " in [" + detail::decimal(c.lo) + ", " + detail::decimal(c.hi) + "] " + head + "every block stable on [0, " +
                    detail::decimal(c.lo) + "], one NOT stable at " + detail::decimal(c.hi) + ": " + said};
}

}  // namespace hapstab::check
