#include "hapstab/poly/ball_range.hpp"

#include "hapstab/numeric/error.hpp"
#include "hapstab/numeric/flint.hpp"

#if HAPSTAB_FLINT3
#include <flint/arb_poly.h>
#else
#include <arb_poly.h>
#endif

namespace hapstab {

namespace {

void set_poly(arb_poly_t out, const Polynomial<rational>& p, long prec) {
  arb_poly_fit_length(out, p.degree() + 1);
  for (int i = 0; i <= p.degree(); ++i) flint::set(out->coeffs + i, p.coeff(i), prec);
  _arb_poly_set_length(out, p.degree() + 1);
  _arb_poly_normalise(out);
}

}  // namespace

struct BallRationalFunction::Balls {
  arb_poly_t num, den;
  Balls() {
    arb_poly_init(num);
    arb_poly_init(den);
  }
  ~Balls() {
    arb_poly_clear(num);
    arb_poly_clear(den);
  }
  Balls(const Balls&) = delete;
  Balls& operator=(const Balls&) = delete;
};

BallRationalFunction::BallRationalFunction(const RationalFunction<rational>& f, long prec) {
  auto b = std::make_shared<Balls>();
  set_poly(b->num, f.num(), prec);
  set_poly(b->den, f.den(), prec);
  b_ = std::move(b);
}

Enclosure<rational> BallRationalFunction::range(const rational& lo, const rational& hi, long prec) const {
  arb_t x, y, d;
  arb_init(x);
  arb_init(y);
  arb_init(d);
  flint::set(x, lo, prec);
  if (hi != lo) {
    flint::set(y, hi, prec);
    arb_union(x, x, y, prec);
  }
  arb_poly_evaluate(y, b_->num, x, prec);
  arb_poly_evaluate(d, b_->den, x, prec);
  bool ok = !arb_contains_zero(d) && arb_is_finite(y);
  if (ok) {
    arb_div(y, y, d, prec);
    ok = arb_is_finite(y);
  }
  Enclosure<rational> r{rational(0), rational(0)};
  if (ok) {
    arf_t l, u;
    arf_init(l);
    arf_init(u);
    arb_get_lbound_arf(l, y, prec);
    arb_get_ubound_arf(u, y, prec);
    r = {flint::to_rational(l), flint::to_rational(u)};
    arf_clear(l);
    arf_clear(u);
  }
  arb_clear(x);
  arb_clear(y);
  arb_clear(d);
  if (!ok) throw NumericalError("ball range: the denominator's enclosure contains 0 on [" + lo.str() + ", " + hi.str() + "]");
  return r;
}

}  // namespace hapstab
