// hapstab/stability/max_evidence.cpp -- see max_evidence.hpp (exact_family is defined in
// sampled_loop.cpp, beside the characteristic polynomial it reads).
#include "hapstab/stability/max_evidence.hpp"

#include <vector>

#include "hapstab/lti/circle_crossing.hpp"
#include "hapstab/numeric/error.hpp"

namespace hapstab::stability {

using QP = Polynomial<rational>;

QP reciprocal_resultant(const QP& c0, const QP& c1) {
  const int d = c0.degree();
  if (d < 1 || c1.degree() >= d) throw InputError("reciprocal_resultant: need deg c1 < deg c0 >= 1");
  // Lagrange at K = 0 .. 2d: D = sum_i D(i) prod_{j != i} (K - j)/(i - j)
  QP D;
  for (int i = 0; i <= 2 * d; ++i) {
    const rational v = hapstab::reciprocal_resultant(c0 + c1 * QP(rational(i)));  // lti/circle_crossing.hpp
    if (v == 0) continue;
    QP basis(v);
    for (int j = 0; j <= 2 * d; ++j)
      if (j != i) basis = basis * QP{rational(-j), rational(1)} * QP(rational(rational(1) / rational(i - j)));
    D = D + basis;
  }
  return D;
}

}  // namespace hapstab::stability
