#include "hapstab/poly/roots.hpp"

#if HAPSTAB_FLINT3
#include <flint/acb_poly.h>
#else
#include <acb_poly.h>
#endif
#include <flint/fmpz_poly_factor.h>

#include <cmath>
#include <sstream>

#include "hapstab/numeric/decimal.hpp"
#include "hapstab/numeric/error.hpp"
#include "hapstab/poly/flint_poly.hpp"

namespace hapstab {

namespace {

// A rational rounded down / up to a double (exact when it is one).
double to_real_down(const rational& q) {
  const double d = to_real<double>(q);
  return rational(d) > q ? std::nextafter(d, -INFINITY) : d;
}
double to_real_up(const rational& q) {
  const double d = to_real<double>(q);
  return rational(d) < q ? std::nextafter(d, INFINITY) : d;
}

// [lo, hi] of an arb, rounded outward to doubles.
void outward(const arb_t x, double& lo, double& hi) {
  arf_t a;
  arf_init(a);
  arb_get_lbound_arf(a, x, 53);
  lo = arf_get_d(a, ARF_RND_FLOOR);
  arb_get_ubound_arf(a, x, 53);
  hi = arf_get_d(a, ARF_RND_CEIL);
  arf_clear(a);
}

// [lo, hi] with 10 significant digits rounded outward (decimal_outward), one number when the
// interval is one value; so a printed enclosure still contains the root.
std::string range_text(double lo, double hi) {
  if (lo == hi) return decimal_outward(rational(lo), 17, -1);
  return "[" + decimal_outward(rational(lo), 10, -1) + ", " + decimal_outward(rational(hi), 10, +1) + "]";
}

}  // namespace

std::string RootEnclosure::text(const char* var, bool pair) const {
  std::string s = std::string(var) + " = " + range_text(re_lo, re_hi);
  if (!(im_lo == 0 && im_hi == 0)) s += (pair ? " +- j " : " + j ") + range_text(im_lo, im_hi);
  if (multiplicity > 1) s += " (multiplicity " + std::to_string(multiplicity) + ")";
  return s;
}

namespace {

// The distinct roots of one square-free (here: irreducible) integer polynomial f, each with
// multiplicity `mult`.
void enclose_squarefree(const fmpz_poly_t f, int mult, std::vector<RootEnclosure>& out) {
  const slong deg = fmpz_poly_degree(f);
  if (deg < 1) return;
  acb_poly_t a;
  acb_poly_init(a);
  acb_ptr roots = _acb_vec_init(deg);
  bool done = false;
  for (slong prec = 64; prec <= 4096 && !done; prec *= 2) {
    acb_poly_set_fmpz_poly(a, f, prec);
    done = acb_poly_find_roots(roots, a, nullptr, 0, prec) == deg;
    if (done) acb_poly_validate_real_roots(roots, a, prec);  // real roots of a real polynomial: Im = 0 exactly
  }
  if (done)
    for (slong i = 0; i < deg; ++i) {
      RootEnclosure r;
      outward(acb_realref(roots + i), r.re_lo, r.re_hi);
      if (!arb_is_zero(acb_imagref(roots + i))) outward(acb_imagref(roots + i), r.im_lo, r.im_hi);
      arb_t m;
      arb_init(m);
      acb_abs(m, roots + i, 256);
      outward(m, r.abs_lo, r.abs_hi);
      arb_clear(m);
      r.multiplicity = mult;
      out.push_back(r);
    }
  _acb_vec_clear(roots, deg);
  acb_poly_clear(a);
  if (!done)
    throw NumericalError("enclose_roots: the roots of a degree-" + std::to_string(deg) +
                         " polynomial were not isolated at 4096 bits");
}

}  // namespace

std::vector<IrreducibleFactor> factor_over_q(const Polynomial<rational>& p) {
  if (p.is_zero()) throw InputError("factor_over_q: the zero polynomial");
  std::vector<IrreducibleFactor> out;
  if (p.degree() < 1) return out;
  flint::FmpqPoly P;
  flint::to_flint(p, P);
  fmpz_poly_t num;
  fmpz_poly_init(num);
  fmpq_poly_get_numerator(num, P.get());
  fmpz_poly_factor_t fac;  // p = c prod f_k^{e_k}, the f_k irreducible over Z (Zassenhaus)
  fmpz_poly_factor_init(fac);
  fmpz_poly_factor(fac, num);
  for (slong k = 0; k < fac->num; ++k) {
    const fmpz_poly_struct* f = fac->p + k;
    std::vector<rational> c(static_cast<size_t>(fmpz_poly_length(f)));
    for (slong i = 0; i < fmpz_poly_length(f); ++i) c[static_cast<size_t>(i)] = rational(flint::to_integer(fmpz_poly_get_coeff_ptr(f, i)));
    out.push_back({Polynomial<rational>(std::move(c)), static_cast<int>(fac->exp[k])});
  }
  fmpz_poly_factor_clear(fac);
  fmpz_poly_clear(num);
  return out;
}

std::vector<RootEnclosure> enclose_roots(const Polynomial<rational>& p) {
  if (p.is_zero()) throw InputError("enclose_roots: the zero polynomial");
  std::vector<RootEnclosure> out;
  for (const IrreducibleFactor& F : factor_over_q(p)) {
    if (F.f.degree() == 1) {  // a rational root -b/a, exactly
      const rational root = -F.f.coeff(0) / F.f.coeff(1);
      RootEnclosure r;
      r.re_lo = to_real_down(root);
      r.re_hi = to_real_up(root);
      r.abs_lo = root < 0 ? -r.re_hi : r.re_lo;
      r.abs_hi = root < 0 ? -r.re_lo : r.re_hi;
      r.multiplicity = F.multiplicity;
      out.push_back(r);
    } else {
      flint::FmpqPoly Q;
      flint::to_flint(F.f, Q);
      fmpz_poly_t f;
      fmpz_poly_init(f);
      fmpq_poly_get_numerator(f, Q.get());
      try {
        enclose_squarefree(f, F.multiplicity, out);
      } catch (...) {
        fmpz_poly_clear(f);
        throw;
      }
      fmpz_poly_clear(f);
    }
  }
  return out;
}

}  // namespace hapstab
