#include "hapstab/sampling/series.hpp"

#include <deque>
#include <mutex>

namespace hapstab::sampling {

// B_{2k} from the tangent numbers T_k (Brent-Harvey / Knuth-Buckholtz integer recurrence):
//   B_{2k} = (-1)^{k-1} 2k T_k / (2^{2k} (2^{2k} - 1)).
const rational& bernoulli_b2n(int k) {
  if (k < 0 || k > 2000) throw InputError("bernoulli_b2n: index " + std::to_string(k) + " outside [0, 2000]");
  static std::mutex m;
  static std::deque<rational> table{rational(1)};  // B_0; deque: references stay valid on growth
  std::lock_guard<std::mutex> lock(m);
  if (k < static_cast<int>(table.size())) return table[k];
  const int n = std::min(2000, std::max(k, 2 * static_cast<int>(table.size()) + 16));
  std::vector<integer> T(static_cast<size_t>(n) + 1, integer(0));
  T[1] = 1;
  for (int i = 2; i <= n; ++i) T[i] = (i - 1) * T[i - 1];
  for (int i = 2; i <= n; ++i)
    for (int j = i; j <= n; ++j) T[j] = (j - i) * T[j - 1] + (j - i + 2) * T[j];
  for (int i = static_cast<int>(table.size()); i <= n; ++i) {
    integer p = integer(1) << (2 * i);
    rational b(integer(2 * i) * T[i], p * (p - 1));
    table.push_back(i % 2 ? b : rational(-b));
  }
  return table[k];
}

}  // namespace hapstab::sampling
