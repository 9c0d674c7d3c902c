// hapstab/numeric/ball_expm.hpp -- rigorous matrix exponentials of exact data, by Arb's ball
// arithmetic (arb_mat_exp: scaling and squaring with a bounded Taylor remainder). Each result
// is a double matrix `mid` and a radius r such that every entry of the exact matrix lies within
// r of the entry of mid: Arb's ball radius plus the rounding of the ball's midpoint to double.
// The sampled-data simulator's exact ZOH (sim/simulator.hpp) is built on these, so its step
// matrices carry a proven error instead of "computed in 50 digits".
//
//   expm_enclosure(A, t)       e^{A t}
//   zoh_enclosure(A, B, t)     (e^{A t}, int_0^t e^{A s} ds B), Van Loan: exp([[A, B], [0, 0]] t)
//   gram_enclosure(M, Q, t)    int_0^t e^{M^T s} Q e^{M s} ds (Q symmetric), Van Loan:
//                              exp([[-M^T, Q], [0, M]] h) = [[., F12], [0, F22]], W(h) = F22^T F12,
//                              on h = t/2^k with ||M|| h <= 1/2 (e^{-M^T h} would grow and the
//                              product cancel), then W(2h) = W(h) + e^{M^T h} W(h) e^{M h}.
// Working precision 128 bits (the radii stay near 2^-120 relative for the simulator's data; a
// radius that is not small is reported, never hidden). A, B, M, Q, t exact (rational).
#pragma once

#include <Eigen/Core>

#include "hapstab/numeric/eigen_traits.hpp"
#include "hapstab/numeric/scalar.hpp"

namespace hapstab {

struct DoubleEnclosure {
  Eigen::MatrixXd mid;
  double radius = 0;  ///< max over entries of |exact - mid| (an upper bound)
};

DoubleEnclosure expm_enclosure(const MatQ& A, const rational& t);

struct ZohEnclosure {
  DoubleEnclosure Phi, Gamma;
};
ZohEnclosure zoh_enclosure(const MatQ& A, const MatQ& B, const rational& t);

DoubleEnclosure gram_enclosure(const MatQ& M, const MatQ& Q, const rational& t);

}  // namespace hapstab
