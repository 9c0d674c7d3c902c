// Where an eigenvalue of M0 + p M1 can meet the unit circle (header).
#include "hapstab/lti/circle_crossing.hpp"

#include <vector>

#include "hapstab/lti/realization.hpp"
#include "hapstab/numeric/error.hpp"
#include "hapstab/numeric/exact_matrix.hpp"
#include "hapstab/numeric/flint.hpp"
#include "hapstab/poly/flint_poly.hpp"
#include "hapstab/poly/sturm.hpp"

namespace hapstab {

namespace {

// The polynomial of degree < xs.size() through (xs[i], ys[i]), the xs distinct integers, exactly: the ys scaled to
// integers by their common denominator, FLINT's interpolation, scaled back.
Polynomial<rational> interpolate(const std::vector<long>& xs, const std::vector<rational>& ys) {
  integer den = 1;
  for (const rational& y : ys) den = boost::multiprecision::lcm(den, denominator(y));
  const long n = static_cast<long>(xs.size());
  fmpz* fx = _fmpz_vec_init(n);
  fmpz* fy = _fmpz_vec_init(n);
  for (long i = 0; i < n; ++i) {
    fmpz_set_si(fx + i, xs[size_t(i)]);
    flint::set(fy + i, integer(numerator(ys[size_t(i)]) * (den / denominator(ys[size_t(i)]))));
  }
  flint::FmpqPoly p;
  fmpq_poly_interpolate_fmpz_vec(p.get(), fx, fy, n);
  _fmpz_vec_clear(fx, n);
  _fmpz_vec_clear(fy, n);
  const Polynomial<rational> q = flint::from_flint(p);
  std::vector<rational> c(q.coeffs());
  for (rational& x : c) x /= rational(den);
  return Polynomial<rational>(std::move(c));
}

}  // namespace

rational reciprocal_resultant(const Polynomial<rational>& c) {
  const Polynomial<rational> star = reversed(c);
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

CircleCrossing circle_crossing(const Mat<rational>& M0, const Mat<rational>& M1) {
  const long n = static_cast<long>(M0.rows());
  if (M0.cols() != n || M1.rows() != n || M1.cols() != n) throw InputError("circle_crossing: M0 and M1 must be square, of one order");
  if (n > kCircleCrossingOrder)
    throw InputError("circle_crossing: order " + std::to_string(n) + ", beyond " + std::to_string(kCircleCrossingOrder));
  const long r = exact_rank(M1);
  const long degree = 2 * n * r;
  if (degree > kCircleCrossingDegree)
    throw InputError("circle_crossing: 2 n rank(M1) = " + std::to_string(degree) + ", beyond " + std::to_string(kCircleCrossingDegree));
  // c(z, p): each coefficient of z^k a polynomial of degree <= r in p, from r + 1 characteristic polynomials
  std::vector<long> ps;
  std::vector<Polynomial<rational>> cs;
  for (long j = 0; j <= r; ++j) {
    ps.push_back(j);
    cs.push_back(charpoly(Mat<rational>(M0 + M1 * rational(j))));
  }
  std::vector<Polynomial<rational>> ck;  // ck[k](p): the coefficient of z^k
  for (long k = 0; k <= n; ++k) {
    std::vector<rational> ys;
    for (const auto& c : cs) ys.push_back(c.coeff(static_cast<int>(k)));
    ck.push_back(interpolate(ps, ys));
  }
  // R at p = 0 .. 2 n r
  std::vector<long> xs;
  std::vector<rational> values;
  for (long i = 0; i <= degree; ++i) {
    std::vector<rational> c(size_t(n + 1));
    for (long k = 0; k <= n; ++k) c[size_t(k)] = ck[size_t(k)](rational(i));
    xs.push_back(i);
    values.push_back(reciprocal_resultant(Polynomial<rational>(std::move(c))));  // c monic: prod over its roots of z^n c(1/z)
  }
  CircleCrossing out;
  const Polynomial<rational> R = interpolate(xs, values);
  if (R.is_zero()) {
    out.identically_zero = true;
    return out;
  }
  std::vector<rational> c(R.coeffs());
  size_t m = 0;
  while (m < c.size() && c[m] == 0) ++m;
  out.zero_order = static_cast<long>(m);
  out.R = Polynomial<rational>(std::vector<rational>(c.begin() + static_cast<long>(m), c.end()));
  return out;
}

std::string no_circle_crossing(const Mat<rational>& M0, const Mat<rational>& M1, const rational& a) {
  if (a <= 0) return "the interval (0, a] is empty";
  const CircleCrossing cc = circle_crossing(M0, M1);
  if (cc.identically_zero) return "R vanishes for every p (a pair of eigenvalues mu, 1/mu at every p): nothing shown";
  const int roots = count_real_roots(cc.R, rational(0), a);
  if (roots > 0)
    return "R(p) / p^" + std::to_string(cc.zero_order) + " (degree " + std::to_string(cc.R.degree()) + ") has " + std::to_string(roots) +
           " real root(s) in (0, " + a.str() + "]";
  return "";
}

}  // namespace hapstab
