// hapstab/lmi/sparse_ops.hpp -- internal to lmi/: small operations on the sparse terms
// (program.hpp's SpMat) shared by the program object and solve()'s standard-form builder.
#pragma once

#include <algorithm>
#include <cmath>

#include "hapstab/lmi/program.hpp"

namespace hapstab::lmi {

/// The largest |entry| of m (0 for no non-zeros).
inline double max_abs(const SpMat& m) {
  double v = 0;
  for (Eigen::Index i = 0; i < m.nonZeros(); ++i) v = std::max(v, std::abs(m.valuePtr()[i]));
  return v;
}

}  // namespace hapstab::lmi
