// hapstab/stability/max_evidence.cpp -- see max_evidence.hpp (exact_family is defined in
// sampled_loop.cpp, beside the characteristic polynomial it reads).
#include "hapstab/stability/max_evidence.hpp"

#include <vector>

#include "hapstab/numeric/error.hpp"
#include "hapstab/numeric/flint.hpp"
#include "hapstab/poly/flint_poly.hpp"

namespace hapstab::stability {

namespace {

using QP = Polynomial<rational>;

/// Res_{d,d}(c, z^d c(1/z)): FLINT's resultant at the actual degrees, times lc(c)^(d - deg c*).
rational reciprocal_resultant_at(const QP& c) {
  const QP star = reversed(c);
  flint::FmpqPoly f, g;
  flint::to_flint(c, f);
  flint::to_flint(star, g);
  fmpq_t r;
  fmpq_init(r);
  fmpq_poly_resultant(r, f.get(), g.get());
  rational res = flint::to_rational(r);
  fmpq_clear(r);
  for (int i = star.degree(); i < c.degree(); ++i) res *= c.leading();
  return res;
}

}  // namespace

QP reciprocal_resultant(const QP& c0, const QP& c1) {
  const int d = c0.degree();
  if (d < 1 || c1.degree() >= d) throw InputError("reciprocal_resultant: need deg c1 < deg c0 >= 1");
  // Lagrange at K = 0 .. 2d: D = sum_i D(i) prod_{j != i} (K - j)/(i - j)
  QP D;
  for (int i = 0; i <= 2 * d; ++i) {
    const rational v = reciprocal_resultant_at(c0 + c1 * QP(rational(i)));
    if (v == 0) continue;
    QP basis(v);
    for (int j = 0; j <= 2 * d; ++j)
      if (j != i) basis = basis * QP{rational(-j), rational(1)} * QP(rational(rational(1) / rational(i - j)));
    D = D + basis;
  }
  return D;
}

}  // namespace hapstab::stability
