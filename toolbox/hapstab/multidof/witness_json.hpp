// hapstab/multidof/witness_json.hpp -- the exact witnesses of infeasibility of paper 000's programs, as decided,
// in JSON: every rational as a "p/q" string so that an outside check can re-evaluate them
// (tests/verify/indep_coupling.py, indep_witness.py). docs/json.md describes the keys; the CLI's
// --json and the Python bindings print the same objects.
#pragma once

#include <nlohmann/json.hpp>
#include <optional>

#include "hapstab/multidof/analysis.hpp"

namespace hapstab::multidof {

/// The one-frequency witness of (16) (FrequencyWitness); null when none.
nlohmann::json frequency_witness_json(const std::optional<FrequencyWitness>& w);
/// Theorem 4's two-frequency witness for a given coupling (CouplingWitness); null when none.
nlohmann::json coupling_witness_json(const std::optional<CouplingWitness>& w);
/// The several-frequency witness of (16) (WeightedWitness); null when none.
nlohmann::json weighted_witness_json(const std::optional<WeightedWitness>& w);

}  // namespace hapstab::multidof
