// Explicit instantiations of the exact (rational) polynomial algebra, its FLINT kernels, and
// to_string.
#include "hapstab/poly/polynomial.hpp"

#include "hapstab/poly/rational_function.hpp"

#include <vector>

#include "hapstab/poly/flint_poly.hpp"

namespace hapstab {

template class Polynomial<rational>;
template std::pair<Polynomial<rational>, Polynomial<rational>> divmod(const Polynomial<rational>&,
                                                                      const Polynomial<rational>&);
template class RationalFunction<rational>;

namespace flint {

void to_flint(const Polynomial<rational>& a, FmpqPoly& out) {
  const auto& c = a.coeffs();
  std::vector<__mpq_struct> view(c.size());  // shallow views of the coefficients, read only
  for (size_t i = 0; i < c.size(); ++i) view[i] = *c[i].backend().data();
  fmpq_poly_set_array_mpq(out.get(), reinterpret_cast<const mpq_t*>(view.data()), slong(c.size()));
}
Polynomial<rational> from_flint(const FmpqPoly& p) {
  std::vector<rational> c(size_t(fmpq_poly_length(p.get())));
  for (size_t i = 0; i < c.size(); ++i) fmpq_poly_get_coeff_mpq(c[i].backend().data(), p.get(), slong(i));
  return Polynomial<rational>(std::move(c));
}

}  // namespace flint

using flint::from_flint;
using flint::to_flint;

namespace detail {

Polynomial<rational> flint_mul(const Polynomial<rational>& a, const Polynomial<rational>& b) {
  flint::FmpqPoly fa, fb, r;
  to_flint(a, fa);
  to_flint(b, fb);
  fmpq_poly_mul(r.get(), fa.get(), fb.get());
  return from_flint(r);
}

Polynomial<rational> flint_pow(const Polynomial<rational>& a, unsigned n) {
  flint::FmpqPoly fa, r;
  to_flint(a, fa);
  fmpq_poly_pow(r.get(), fa.get(), n);
  return from_flint(r);
}

std::pair<Polynomial<rational>, Polynomial<rational>> flint_divrem(const Polynomial<rational>& a,
                                                                   const Polynomial<rational>& b) {
  flint::FmpqPoly fa, fb, q, r;
  to_flint(a, fa);
  to_flint(b, fb);
  fmpq_poly_divrem(q.get(), r.get(), fa.get(), fb.get());
  return {from_flint(q), from_flint(r)};
}

}  // namespace detail

template <>
Polynomial<rational> gcd(Polynomial<rational> a, Polynomial<rational> b) {
  flint::FmpqPoly fa, fb, g;
  to_flint(a, fa);
  to_flint(b, fb);
  fmpq_poly_gcd(g.get(), fa.get(), fb.get());  // monic; gcd(0, 0) = 0
  return from_flint(g);
}

std::string to_string(const Polynomial<rational>& p, const std::string& var) {
  if (p.is_zero()) return "0";
  std::string out;
  for (int k = p.degree(); k >= 0; --k) {
    const rational& c = p.coeffs()[k];
    if (c == 0) continue;
    const bool neg = c < 0;
    const rational a = neg ? rational(-c) : c;
    if (out.empty()) out += neg ? "-" : "";
    else out += neg ? " - " : " + ";
    if (k == 0) {
      out += a.str();
    } else {
      if (a != 1) out += a.str() + "*";
      out += var;
      if (k > 1) out += "^" + std::to_string(k);
    }
  }
  return out;
}

}  // namespace hapstab
