// proofs/known_spectrum.hpp -- exact rational matrices whose eigenvalues are known: for the
// Lyapunov certificate's proof (proofs/schur_lyapunov.cpp) and tests
// (tests/multidof/test_schur_lyapunov.cpp).
#pragma once

#include <random>

#include "hapstab/numeric/eigen_traits.hpp"

namespace hapstab::proofs {

/// S^-1 D S with S = I + L, L strictly lower triangular with entries in {-1, -3/4, ..., 1} drawn
/// from `g` (S^-1 exact by the Neumann sum): a dense rational matrix with the eigenvalues and
/// the Jordan structure of D.
inline MatQ dense_similar(const MatQ& D, std::mt19937& g) {
  const auto n = D.rows();
  std::uniform_int_distribution<int> k(-4, 4);
  MatQ L = MatQ::Zero(n, n);
  for (Eigen::Index i = 1; i < n; ++i)
    for (Eigen::Index j = 0; j < i; ++j) L(i, j) = rational(k(g), 4);
  MatQ Si = MatQ::Identity(n, n), P = MatQ::Identity(n, n);
  for (Eigen::Index p = 1; p < n; ++p) {
    P = (-P * L).eval();
    Si += P;
  }
  return Si * D * (MatQ::Identity(n, n) + L);
}

/// Block-diagonal 2x2 rotation-scaling blocks r [c -s; s c] with the rational point
/// (c, s) = ((1 - t^2)/(1 + t^2), 2t/(1 + t^2)) of the unit circle, t = (b + 1)/(blocks + 2):
/// eigenvalues r e^{+-j theta_b}, all of modulus exactly r.
inline MatQ rotation_blocks(int blocks, const rational& r) {
  MatQ D = MatQ::Zero(2 * blocks, 2 * blocks);
  for (int b = 0; b < blocks; ++b) {
    const rational t(b + 1, blocks + 2), c = (1 - t * t) / (1 + t * t), s = 2 * t / (1 + t * t);
    D(2 * b, 2 * b) = r * c;
    D(2 * b, 2 * b + 1) = -r * s;
    D(2 * b + 1, 2 * b) = r * s;
    D(2 * b + 1, 2 * b + 1) = r * c;
  }
  return D;
}

}  // namespace hapstab::proofs
