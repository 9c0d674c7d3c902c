// hapstab/multidof/assumptions.hpp -- Assumption 1 of paper 000, checked on the data.
//
//  (b) operator passivity of a continuous MIMO H(s) (velocity -> force impedance): every entry
//      stable (exact Routh-Hurwitz on its denominator) and the Hermitian part
//      He(jw) = (H(jw) + H(jw)^*)/2 positive semidefinite for ALL real w. Certified exactly:
//      He(jw) times the positive common denominator prod |D_ij(jw)|^2 is a Hermitian matrix of
//      polynomials in w; it is PSD iff every principal minor (a real polynomial in w) is >= 0
//      on R, which exact root isolation decides (sign at a rational point of every gap
//      between real roots).
//  (a) device OSP levels: a mass-damper 1/(m s + b) has OSP level b (storage 1/2 m v^2:
//      d/dt(1/2 m v^2) = v f - b v^2); the levels used in the analysis are reported.
//
// Implements: paper 000 Assumption 1.
#pragma once

#include <string>
#include <vector>

#include "hapstab/lti/realization.hpp"
#include "hapstab/multidof/structure.hpp"
#include "hapstab/numeric/result.hpp"

namespace hapstab::multidof {

/// Is the operator H passive? holds / fails, exact (Routh + root isolation), the evidence naming
/// the minor or entry that fails or what was proven; undecided (status failed) for an entry with
/// a pole in Re s >= 0, which this test does not cover. H must be square, continuous (Domain::s),
/// with proper entries; up to 4 x 4 (Leibniz minors).
Verdict operator_passive(const TransferMatrix& H);

/// One line of Assumption 1 as checked on a problem's data.
struct AssumptionCheck {
  std::string name;  ///< e.g. "Assumption 1(b): operator 'H1' passive (He(jw) >= 0 for all w)"
  Verdict verdict;
};
/// (b) for every operator (its Z_O(s) and name) and (a) for every device of `structure`
/// (OSP level positive definite, exactly). Theorem 5/6's conclusions need every line to hold.
std::vector<AssumptionCheck> check_assumptions(const Structure& structure, const std::vector<TransferMatrix>& operators,
                                               const std::vector<std::string>& operator_names);
bool all_hold(const std::vector<AssumptionCheck>& checks);

}  // namespace hapstab::multidof
