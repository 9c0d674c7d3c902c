// hapstab/check/interpolate.cpp -- see interpolate.hpp.
#include "hapstab/check/interpolate.hpp"

namespace hapstab::check {

Polynomial<rational> interpolate(const std::vector<rational>& x, std::vector<rational> y) {
  using P = Polynomial<rational>;
  const size_t N = x.size();
  for (size_t k = 1; k < N; ++k)
    for (size_t i = N - 1; i >= k; --i) y[i] = (y[i] - y[i - 1]) / (x[i] - x[i - k]);
  P p;
  for (size_t i = N; i-- > 0;) p = p * P{-x[i], rational(1)} + P(y[i]);
  return p;
}

}  // namespace hapstab::check
