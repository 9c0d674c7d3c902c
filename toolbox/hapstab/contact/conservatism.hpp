// hapstab/contact/conservatism.hpp -- how conservative the wedge criterion (25) and Tsypkin's
// condition (21) of paper 002 are: for a family of virtual walls (backward-difference and
// Tustin spring-dampers, delays 0-2) touched through a device by operators from "none" to a
// stiff hand, the largest certified wall gains k*_wedge, k*_Tsypkin beside the smallest gain
// k_osc at which the simulated loop of Fig. 5 oscillates (and the linear stability limit of
// (1 + kH)^{-1}). A case where a criterion's k* exceeds k_osc (it claims "no oscillation" where
// the simulation finds one) is flagged as a contradiction.
//
// Implements: paper 002 (21), (25), Fig. 5.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "hapstab/contact/model.hpp"

namespace hapstab::contact {

struct ConservatismCase {
  std::string name;          ///< e.g. "bd d=1 hand-med"
  WallKind wall = WallKind::backward_difference;
  int delay = 0;
  std::string operator_name;
  PhysicalModel model;        ///< with the wall at unit gain (k scales it)
};

struct ConservatismRow {
  ConservatismCase c;
  TransferFunction H;               ///< unit-gain H(z)
  bool criteria_evaluated = false;  ///< wedge evaluated (false when its branches are unbounded on the circle)
  bool tsypkin_evaluated = false;
  std::vector<std::string> assumptions;  ///< violated paper assumptions at unit gain
  bool wedge_inf = false, tsypkin_inf = false;
  double k_wedge = 0, k_tsypkin = 0;  ///< certified (printed from the enclosures' midpoints)
  std::optional<double> k_linear;     ///< (1 + kH)^-1 loses stability (exact bisection)
  std::optional<double> k_osc;        ///< smallest gain with a sustained oscillation (numeric)
  std::optional<long> period;         ///< at k_osc
  bool orbit_certified = false;       ///< the orbit at k_osc was proven exactly
  bool wedge_contradicted = false, tsypkin_contradicted = false;
};

/// The default family: device m = 0.2 kg, b = 0.5 Ns/m, T = 1 ms; walls K(1 + tau D(z)) z^-d with
/// tau = 2 ms; operators none, soft (K 100 N/m, B 2 Ns/m), medium (500, 5), stiff (3000, 10, 0.1 kg).
std::vector<ConservatismCase> default_family();

/// One row: criteria (certified) and the simulated onset (log grid over [kmin, kmax] then bisection).
ConservatismRow evaluate_case(const ConservatismCase& c, long steps = 40000);

}  // namespace hapstab::contact
