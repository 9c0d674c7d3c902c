// Certified frequency-domain passivity levels of a square MIMO G (passivity_level.hpp,
// passivity_level_certified_mimo). With G = N(z)/d(z) (d the lcm of the entries' denominators)
// and c = cos theta, on the unit circle
//   He G - nu I         = K(c, nu) / (2 B(c)),  K = M - nu W,  W = 2 B I          (ISP)
//   He G - nu G^* G     = K(c, nu) / (2 B(c)),               W = 2 N^* N         (OSP)
// where B = |d|^2 > 0 and M = N conj(d) + N^* d. Every entry of M and W is a(c) + t b(c) with
// t = j sin theta (t^2 = c^2 - 1): the c-form of passivity/bound_detail.hpp (N conj(D) = R + j
// sin theta Q). F(c, nu) = det K(c, nu) is even in t, so a polynomial in (c, nu) with rational
// coefficients (Faddeev-LeVerrier over Q[c][t]/(t^2 - c^2 + 1) at nu = 0..m, then Lagrange).
//
// The level nu* = sup {nu : K(c, nu) >= 0 for all c in [-1, 1]}. For a rational nu, decide()
// settles nu <= nu*, nu = nu* or nu > nu* exactly: the number of negative eigenvalues of
// K(c, nu) is constant between consecutive roots of p(c) = F(c, nu) in [-1, 1] (eigenvalues are
// continuous in c and K is singular exactly at the roots of p) and, being lower semicontinuous,
// is not larger at a root than nearby. So it is 0 on [-1, 1] iff it is 0 at one rational sample
// of every piece between the roots. At a sample c_s it is the number of roots of the real-rooted
// x -> F(c_s, x) below nu (W(c_s) > 0: a Hermitian pencil), counted exactly by Descartes' rule on
// F(c_s, nu - y) (exact for real-rooted polynomials). If it is 0 everywhere and p has a root c_r
// in [-1, 1] (where W(c_r) > 0), K(c_r, nu) is singular with a kernel vector v, v^* W v > 0, so
// no larger nu is feasible: nu = nu*. Upper bounds: any root of F(c, .) at a rational c.
//
// Search: the smallest root of F(c, .) at c = cos(theta_hint) and c = +-1 gives nu_up >= nu*;
// decide(nu_up - gap) (gap = 10^-(digits+3) max(1, |nu_up|)) either proves the enclosure or
// finds the pieces of [-1, 1] where lambda_min < nu_up - gap; the middle of such a piece (the
// vertex of a parabola-like dip, to second order) gives the next nu_up. A rational nu* is
// guessed from nu_up's continued fraction and proven by decide() (status exact).
#include <cmath>
#include <optional>

#include "hapstab/lmi/passivity_level.hpp"
#include "hapstab/lti/realization.hpp"
#include "hapstab/numeric/decimal.hpp"
#include "hapstab/numeric/error.hpp"
#include "hapstab/passivity/bound_detail.hpp"
#include "hapstab/poly/stability.hpp"
#include "hapstab/poly/sturm.hpp"

namespace hapstab::lmi {

namespace {

/// a(c) + t b(c), t = j sin theta, t^2 = c^2 - 1.
struct HElem {
  QPoly a, b;
};
using HMat = std::vector<std::vector<HElem>>;

HElem operator+(const HElem& x, const HElem& y) { return {x.a + y.a, x.b + y.b}; }
HElem mul(const HElem& x, const HElem& y, const QPoly& t2) {
  return {x.a * y.a + t2 * (x.b * y.b), x.a * y.b + x.b * y.a};
}

/// det K over Q[c][t]/(t^2 - t2) by Faddeev-LeVerrier (divisions by integers only). The t part
/// of the determinant of a Hermitian form vanishes (det K = det K^T = det conj K); checked.
QPoly det(const HMat& K, const QPoly& t2) {
  const size_t m = K.size();
  HMat Mk(m, std::vector<HElem>(m)), next(m, std::vector<HElem>(m));
  HElem ck{QPoly(rational(1)), QPoly()};  // c_{m-k+1}, starting with c_m = 1
  for (size_t k = 1; k <= m; ++k) {
    for (size_t i = 0; i < m; ++i)
      for (size_t j = 0; j < m; ++j) {
        HElem s{};
        for (size_t l = 0; l < m; ++l)
          if (!Mk[l][j].a.is_zero() || !Mk[l][j].b.is_zero()) s = s + mul(K[i][l], Mk[l][j], t2);
        next[i][j] = std::move(s);
      }
    for (size_t i = 0; i < m; ++i) next[i][i] = next[i][i] + ck;
    std::swap(Mk, next);
    HElem tr{};
    for (size_t i = 0; i < m; ++i)
      for (size_t l = 0; l < m; ++l) tr = tr + mul(K[i][l], Mk[l][i], t2);
    const rational f = rational(-1) / rational(static_cast<long>(k));
    ck = {tr.a * QPoly(f), tr.b * QPoly(f)};
  }
  if (!ck.b.is_zero()) throw NumericalError("certified MIMO level: det of a Hermitian form has an imaginary part");
  return m % 2 ? -ck.a : ck.a;
}

/// a(z) conj(b(z)) on the unit circle as R(c) + t Q(c).
HElem circle_product(const QPoly& a, const QPoly& b, const passivity::detail::ChebyshevTables<integer>& ct) {
  const auto cf = passivity::detail::c_form<rational>(
      a.coeffs(), b.coeffs(), ct, [](const rational& x) { return x.is_zero(); },
      [](const integer& x) { return rational(x); });
  return {QPoly(cf.R), QPoly(cf.Q)};
}

/// F(c, nu) = sum_k F[k](c) nu^k.
using Bivariate = std::vector<QPoly>;

QPoly at_nu(const Bivariate& F, const rational& nu) {
  QPoly p;
  for (size_t k = F.size(); k-- > 0;) p = p * QPoly(nu) + F[k];
  return p;
}
QPoly at_c(const Bivariate& F, const rational& c) {
  std::vector<rational> v;
  for (const auto& f : F) v.push_back(f(c));
  return QPoly(std::move(v));
}

/// Sign variations of the coefficients (zeros skipped): Descartes' bound on the positive roots,
/// exact for a real-rooted polynomial.
int sign_variations(const QPoly& p) {
  int v = 0, last = 0;
  for (const auto& x : p.coeffs()) {
    const int s = sgn(x);
    if (s == 0) continue;
    if (last != 0 && s != last) ++v;
    last = s;
  }
  return v;
}

struct Pencil {
  Bivariate F;          ///< det K(c, nu)
  bool w_regular = true;  ///< det W has no root in [-1, 1] (always for ISP)
};

enum class Side { below, equal, above, unknown };
struct Decision {
  Side side = Side::unknown;
  std::vector<rational> dips;  ///< above: middles of the pieces where K(c, nu) is not >= 0
  std::optional<rational> touch;  ///< equal: a point of [-1, 1] near a root of p
};

/// nu <= nu* (below), nu = nu* (equal), nu > nu* (above), exactly; see the file comment.
Decision decide(const Pencil& P, const rational& nu, const rational& refine_width) {
  Decision d;
  const QPoly p = at_nu(P.F, nu);
  if (p.is_zero()) return d;  // K(c, nu) singular for every c: not decided here
  const std::vector<RootInterval> roots = isolate_real_roots(p, rational(-1), rational(1));
  bool negative = false;
  const QPoly shift({nu, rational(-1)});  // x = nu - y
  for (size_t i = 0; i <= roots.size(); ++i) {
    const rational left = i == 0 ? rational(-1) : roots[i - 1].hi;
    const rational right = i == roots.size() ? rational(1) : roots[i].lo;
    rational s = (left + right) / 2;
    if (p(s) == 0) continue;  // an empty piece (a root at an end of [-1, 1])
    // a sample where W is regular (det W = +-F[m] has finitely many roots)
    for (int k = 0; k < 64 && P.F.back()(s) == 0; ++k) s = (s + right) / 2;
    if (P.F.back()(s) == 0) return {};
    if (sign_variations(at_c(P.F, s).compose(shift)) == 0) continue;
    negative = true;
    // the middle of the piece: roots of p refined so that it is close to the dip's vertex
    auto centre = [&](const RootInterval& x) {
      const RootInterval y = refine_root(p, x, refine_width);
      return (y.lo + y.hi) / 2;
    };
    const rational mid = i == 0 ? rational(-1) : i == roots.size() ? rational(1) : (centre(roots[i - 1]) + centre(roots[i])) / 2;
    d.dips.push_back(p(mid) != 0 && P.F.back()(mid) != 0 ? mid : s);
  }
  if (negative) d.side = Side::above;
  else if (!roots.empty() && P.w_regular) {
    d.side = Side::equal;
    const RootInterval r = refine_root(p, roots[0], refine_width);
    d.touch = (r.lo + r.hi) / 2;
  } else d.side = Side::below;
  return d;
}

/// An upper bound on nu*: the upper end of the smallest root of F(c, .), isolated to `width`.
std::optional<rational> upper_at(const Pencil& P, const rational& c, const rational& width) {
  const QPoly f = at_c(P.F, c);
  if (f.degree() < 1) return std::nullopt;
  const auto roots = isolate_real_roots(f);
  if (roots.empty()) return std::nullopt;
  return refine_root(f, roots[0], width).hi;
}

/// The first continued-fraction convergent of x within tol of it (denominator <= 10^9).
std::optional<rational> simple_rational_near(const rational& x, const rational& tol) {
  integer h0 = 0, h1 = 1, k0 = 1, k1 = 0;
  rational y = x;
  for (int it = 0; it < 80; ++it) {
    integer a = num(y) / den(y);
    if (num(y) < 0 && a * den(y) != num(y)) a -= 1;  // floor
    const integer h2 = a * h1 + h0, k2 = a * k1 + k0;
    if (k2 > integer(1000000000)) return std::nullopt;
    const rational cand(h2, k2);
    if (abs(cand - x) <= tol) return cand;
    h0 = h1, h1 = h2, k0 = k1, k1 = k2;
    const rational frac = y - rational(a);
    if (frac == 0) return std::nullopt;
    y = 1 / frac;
  }
  return std::nullopt;
}

/// The lcm of the entries' denominators and the numerators over it.
void common_denominator(const TransferMatrix& T, std::vector<std::vector<QPoly>>& N, QPoly& d) {
  d = QPoly(rational(1));
  for (const auto& row : T.entries)
    for (const auto& e : row) d = divmod(d * e.den(), gcd(d, e.den())).first;
  N.assign(T.outputs(), std::vector<QPoly>(T.inputs()));
  for (size_t i = 0; i < T.outputs(); ++i)
    for (size_t j = 0; j < T.inputs(); ++j) N[i][j] = T(i, j).num() * divmod(d, T(i, j).den()).first;
}

double theta_of(const rational& c) { return std::acos(std::clamp(to_real<double>(c), -1.0, 1.0)); }

}  // namespace

namespace {
PassivityLevel certified_mimo(const StateSpace<rational>& sys, PassivityKind kind, int digits, double theta_hint);
}  // namespace

PassivityLevel passivity_level_certified_mimo(const StateSpace<rational>& sys, PassivityKind kind, int digits,
                                              double theta_hint) {
  if (sys.outputs() != sys.inputs() || sys.inputs() == 0) throw InputError("certified MIMO level: G must be square");
  if (digits < 10 || digits > 100) throw InputError("certified MIMO level: digits must be in [10, 100]");
  try {
    return certified_mimo(sys, kind, digits, theta_hint);
  } catch (const NumericalError& e) {  // an internal consistency check: no level, never a wrong one
    PassivityLevel out;
    out.status = Status::failed;
    out.note = std::string("certified frequency path: ") + e.what();
    return out;
  }
}

namespace {
PassivityLevel certified_mimo(const StateSpace<rational>& sys, PassivityKind kind, int digits, double theta_hint) {
  const bool isp = kind == PassivityKind::isp;
  PassivityLevel out;
  out.method = "frequency domain, certified: det(He G - nu " + std::string(isp ? "I" : "G^* G") +
               ") exact in (cos theta, nu), exact root isolation and inertia counts";
  out.status = Status::failed;
  const size_t m = static_cast<size_t>(sys.inputs());
  if (static_cast<long>(m) * std::max<long>(1, sys.states()) > 64) {
    out.note = "certified frequency path: inputs x states = " + std::to_string(m * sys.states()) +
               " > 64 (the exact determinant's degree); not attempted";
    return out;
  }
  std::vector<std::vector<QPoly>> N;
  QPoly d;
  common_denominator(ss2tf(sys), N, d);
  std::string why;
  if (!marginally_stable(d, &why) || unit_circle_roots(d) > 0) {
    out.note = "G is not Schur stable" + (why.empty() ? std::string() : " (" + why + ")");
    return out;
  }
  int deg = d.degree();
  for (const auto& row : N)
    for (const auto& e : row) deg = std::max(deg, e.degree());
  const auto ct = passivity::detail::chebyshev_tables<integer>(deg + 1);
  const HElem Bd = circle_product(d, d, ct);  // |d|^2 = B(c), b = 0
  HMat U(m, std::vector<HElem>(m)), M(m, std::vector<HElem>(m)), W(m, std::vector<HElem>(m));
  for (size_t i = 0; i < m; ++i)
    for (size_t j = 0; j < m; ++j) U[i][j] = circle_product(N[i][j], d, ct);
  for (size_t i = 0; i < m; ++i)
    for (size_t j = 0; j < m; ++j) {
      M[i][j] = {U[i][j].a + U[j][i].a, U[i][j].b - U[j][i].b};  // N conj(d) + (N conj(d))^*
      if (isp) W[i][j] = i == j ? HElem{Bd.a * QPoly(rational(2)), QPoly()} : HElem{};
      else {
        HElem s{};
        for (size_t k = 0; k < m; ++k) s = s + circle_product(N[k][j], N[k][i], ct);  // conj(N_ki) N_kj
        W[i][j] = {s.a * QPoly(rational(2)), s.b * QPoly(rational(2))};
      }
    }
  const QPoly t2({rational(-1), rational(0), rational(1)});  // c^2 - 1
  // F(c, nu) at nu = 0..m, then Lagrange interpolation in nu
  Pencil P;
  P.F.assign(m + 1, QPoly());
  for (size_t i = 0; i <= m; ++i) {
    HMat K = M;
    for (size_t r = 0; r < m; ++r)
      for (size_t c = 0; c < m; ++c) {
        K[r][c].a -= W[r][c].a * QPoly(rational(static_cast<long>(i)));
        K[r][c].b -= W[r][c].b * QPoly(rational(static_cast<long>(i)));
      }
    const QPoly Fi = det(K, t2);
    QPoly L(rational(1));
    for (size_t j = 0; j <= m; ++j)
      if (j != i)
        L = L * QPoly({rational(-static_cast<long>(j)), rational(1)}) *
            QPoly(rational(1) / rational(static_cast<long>(i) - static_cast<long>(j)));
    for (size_t k = 0; k <= m; ++k)
      if (!L.coeff(static_cast<int>(k)).is_zero()) P.F[k] += Fi * QPoly(L.coeff(static_cast<int>(k)));
  }
  if (P.F.back().is_zero()) {
    out.note = isp ? "certified frequency path: internal error (det(-2 B I) = 0)"
                   : "G(e^{j theta}) is singular at every theta: the OSP pencil is degenerate";
    return out;
  }
  const bool w_zero_on_circle = !isolate_real_roots(P.F.back(), rational(-1), rational(1)).empty();
  P.w_regular = !w_zero_on_circle;

  // the search (file comment)
  const rational scale_digits = pow10(-(digits + 3));
  rational c_best = theta_hint >= 0 ? exact_rational(std::cos(theta_hint)) : rational(0);
  c_best = std::clamp(c_best, rational(-1), rational(1));
  std::optional<rational> up;
  auto consider = [&](const rational& c) {
    const rational width = scale_digits * rational(1, 100) * (up ? std::max(rational(1), abs(*up)) : rational(1));
    if (auto u = upper_at(P, c, width); u && (!up || *u < *up)) up = *u, c_best = c;
  };
  for (const rational& c : {c_best, rational(1), rational(-1)}) consider(c);
  if (!up) {
    out.note = "certified frequency path: no eigenvalue branch found";
    return out;
  }
  for (int iter = 0; iter < 24; ++iter) {
    const rational gap = scale_digits * std::max(rational(1), abs(*up));
    const rational width = gap / 1000;
    if (auto q = simple_rational_near(*up, gap); q && *q <= *up) {
      const Decision e = decide(P, *q, width);
      if (e.side == Side::equal) {
        out.status = Status::exact;
        out.enclosure = Enclosure<rational>{*q, *q};
        out.lower_bound = *q;
        out.level = to_real<double>(*q) + 0.0;
        out.value = to_decimal(*q, digits);
        out.theta_min = theta_of(*e.touch);
        out.c_min = *e.touch;
        break;
      }
    }
    const rational lo = *up - gap;
    const Decision e = decide(P, lo, width);
    if (e.side == Side::below || e.side == Side::equal) {
      out.status = Status::certified;
      out.enclosure = Enclosure<rational>{lo, *up};
      out.lower_bound = lo;
      out.level = to_real<double>((lo + *up) / 2) + 0.0;
      out.value = passivity::detail::enclosure_decimal(lo, *up, digits);
      out.theta_min = theta_of(c_best);
      out.c_min = c_best;
      break;
    }
    if (e.side == Side::unknown) {
      out.note = "certified frequency path: He G - nu W is singular at every theta for nu = " + to_decimal(lo, 17);
      return out;
    }
    const rational before = *up;
    for (const auto& c : e.dips) consider(c);
    if (!(*up < before)) {
      out.note = "certified frequency path: no progress (internal)";
      return out;
    }
  }
  if (out.status == Status::failed) {
    out.note = "certified frequency path: the enclosure did not converge";
    return out;
  }
  if (!isp) {
    if (w_zero_on_circle)
      out.note = "G(e^{j theta}) is singular at some theta (a transmission zero on the unit circle): delta* is the "
                 "supremum of the non-strict levels (Lemma 1's strict LMI is infeasible)";
    if (!(out.level > 0))
      out.note += std::string(out.note.empty() ? "" : "; ") +
                  "delta* <= 0: a frequency-domain index and an upper bound on Lemma 1's level only (Lemma 1 "
                  "also needs P > 0, which the frequency inequality does not impose)";
  }
  return out;
}
}  // namespace

}  // namespace hapstab::lmi
