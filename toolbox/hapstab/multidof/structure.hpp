// hapstab/multidof/structure.hpp -- problem structures of paper 000 (Bianchini-Orlandesi-
// Prattichizzo): N operators H_i with m_i DOF, operator i using M_i devices d_ij of m_ij DOF
// each, every device with its OSP level Delta_dij (Assumption 1(a)).
//
//   BD(m; m_1..m_N)   block sizes of the operator partition (H, D, Remark 3's Q_V)
//   G(m; m_1..m_N)    Gamma = blockdiag(g_1 I_m1, ..., g_N I_mN), g_i >= 1            (9)
//   Delta_D           blockdiag over operators of blockdiag over devices of Delta_dij  (7),(8)
//   K                 (T/2) Delta_D^{-1}                                              (12)
// and the virtual-coupling structure of Theorem 6 (R2): N-bar blocks V_i with m-bar_i inputs =
// outputs and n-bar_i states. Everything is exact (rational). Inconsistent structures (block
// sizes that do not add up, a device level that is not positive definite) throw InputError
// naming the offending operator/device/block.
//
// Implements: paper 000 (7), (8), (9), (12).
#pragma once

#include <string>
#include <vector>

#include "hapstab/lti/state_space.hpp"
#include "hapstab/numeric/scalar.hpp"

namespace hapstab::multidof {

struct Device {
  std::string name;
  int dof = 1;     ///< m_ij
  MatQ osp;        ///< Delta_dij, m_ij x m_ij, symmetric positive definite
};

struct Operator {
  std::string name;
  int dof = 0;                  ///< m_i (must equal the sum of its devices' m_ij)
  std::vector<Device> devices;  ///< d_i1 .. d_iMi
};

struct Structure {
  std::vector<Operator> operators;

  int m() const;                               ///< total DOF
  std::vector<int> operator_sizes() const;     ///< m_1 .. m_N
  std::vector<int> device_sizes() const;       ///< every m_ij, in order
  /// Throws InputError naming the inconsistency (empty structure, m_i != sum_j m_ij, device
  /// level not m_ij x m_ij, not symmetric, or not positive definite (exact LDL^T)).
  void validate() const;
  MatQ delta_D() const;                        ///< (7), (8)
  MatQ K(const rational& T) const;             ///< (12): (T/2) Delta_D^{-1}
  /// Gamma (or X) in G(m; m_1..m_N) from the scalars g_1..g_N.
  template <class S>
  Mat<S> scalar_blocks(const std::vector<S>& g) const {
    const auto sizes = operator_sizes();
    Mat<S> G = Mat<S>::Zero(m(), m());
    int off = 0;
    for (size_t i = 0; i < sizes.size(); ++i) {
      for (int k = 0; k < sizes[i]; ++k) G(off + k, off + k) = g.at(i);
      off += sizes[i];
    }
    return G;
  }
};

/// Exact inverse (Gauss-Jordan); InputError naming `what` if singular.
MatQ inverse(const MatQ& A, const std::string& what);

/// Convenience: each device with scalar level delta (Delta_dij = delta I).
Device device(std::string name, int dof, const rational& delta);

/// Theorem 6's (R2): V = blockdiag(V_1..V_Nbar), V_i with mbar_i inputs/outputs, nbar_i states.
struct CouplingStructure {
  std::vector<int> mbar, nbar;
  int m() const;
  int n() const;
  /// Throws InputError unless sizes match (mbar, nbar same length, mbar_i >= 1, nbar_i >= 0)
  /// and sum mbar_i == m ("block sizes of the coupling add up to X, the environment has m").
  void validate(int m) const;
};

/// The coarsest partition refining both partitions of m (block sizes); used so that Q_V is in
/// BD(m; m_1..m_N) (Remark 3) and in BD(m; mbar_1..) (18) at once.
std::vector<int> common_refinement(const std::vector<int>& a, const std::vector<int>& b);

}  // namespace hapstab::multidof
