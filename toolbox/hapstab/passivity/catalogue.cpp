// Implementation of hapstab/passivity/catalogue.hpp (paper 001, Secs. VI-VII).
#include "hapstab/passivity/catalogue.hpp"

#include "hapstab/numeric/decimal.hpp"
#include "hapstab/numeric/error.hpp"
#include "hapstab/numeric/interval.hpp"

namespace hapstab::passivity::catalogue {


namespace {
rational ipow(const rational& x, int e) {
  rational r(1);
  for (int i = 0; i < std::abs(e); ++i) r *= x;
  return e >= 0 ? r : rational(1) / r;
}
void need_T(const rational& T) {
  if (T <= 0) throw InputError("T must be > 0");
}
std::string dec(const rational& q) { return to_decimal(q, 17); }
}  // namespace

rational backward_difference(int m, const rational& T) {
  need_T(T);
  if (m < 0) throw InputError("backward difference order m must be >= 0");
  return ipow(2 / T, m - 1);
}

rational backward_difference_sum(const std::vector<rational>& alpha, const rational& T) {
  need_T(T);
  bool pos = false;
  rational s = 0;
  for (size_t m = 0; m < alpha.size(); ++m) {
    if (alpha[m] < 0) throw InputError("(46) needs alpha_m >= 0 (alpha_" + std::to_string(m) + " < 0)");
    if (alpha[m] > 0) pos = true;
    s += alpha[m] * ipow(2 / T, static_cast<int>(m) - 1);
  }
  if (!pos) throw InputError("(46) needs at least one alpha_m > 0");
  return s;
}

rational virtual_wall(const rational& K, const rational& B, const rational& T) {
  if (K < 0 || B < 0 || (K == 0 && B == 0)) throw InputError("virtual wall (46) needs K, B >= 0, not both 0");
  return backward_difference_sum({K, B}, T);
}

rational fir_bound(const std::vector<rational>& alpha, const rational& T, bool* tight) {
  need_T(T);
  rational s = 0;
  bool nonneg = true, alternating = true, any = false;
  for (size_t k = 0; k < alpha.size(); ++k) {
    s += abs(alpha[k]);
    if (alpha[k] != 0) any = true;
    if (alpha[k] < 0) nonneg = false;
    if ((k % 2 == 0 && alpha[k] < 0) || (k % 2 == 1 && alpha[k] > 0)) alternating = false;
  }
  if (tight) *tight = any && (nonneg || alternating);
  return T * s;
}

rational iir_zero_at_one(const rational& a, const rational& T) {
  need_T(T);
  if (a == 1) return -T / 2;  // (52)
  if (abs(a) >= 1) throw InputError("(z-1)/(z+a) needs |a| < 1 (or a = 1, (52))");
  return T / (1 - a);
}

rational iir_zero_at_one_neg(const rational& a, const rational& T) {
  need_T(T);
  if (a == 1) return T / 2;  // -(52)
  if (abs(a) >= 1) throw InputError("(1-z)/(z+a) needs |a| < 1");
  return T / (1 + a);
}

rational tustin_wall(const rational& K, const rational& B, const rational& T) {
  need_T(T);
  return K * T / 2 - B;
}

rational delayed_constant(int n, const rational& T) {
  need_T(T);
  if (n < 0) throw InputError("delay n must be >= 0");
  return rational(2 * n + 1) * T / 2;  // max of the Dirichlet kernel D_n is D_n(0) = 2n + 1
}

rational delayed_backward_difference(int m, int n, const rational& T, bool* tight) {
  need_T(T);
  if (m < 1 || n < 0) throw InputError("H_m z^-n needs m >= 1, n >= 0");
  // attained at wT = pi iff (-1)^n = 1; for m = 1, -cos(n+1)wT reaches 1 at wT = pi/(n+1) for every n
  if (tight) *tight = (n % 2 == 0) || m == 1;
  return ipow(2 / T, m - 1);
}

rational delayed_wall_n1(const rational& K, const rational& B, const rational& T) {
  need_T(T);
  if (K < 0 || B < 0) throw InputError("(53) with n = 1 needs K >= 0, B >= 0");
  if (K * T >= 4 * B) return K * T / 2 + B + (K * T - 2 * B);
  return K * T / 2 + B + K * K * T * T / (8 * B);
}

rational delayed_wall_conservative(int n, const rational& K, const rational& B, const rational& T) {
  need_T(T);
  if (K < 0 || B < 0 || n < 0) throw InputError("(53) conservative bound needs K, B >= 0, n >= 0");
  return rational(2 * n + 1) * K * T / 2 + B;
}

rational delayed_tustin_n1(const rational& K, const rational& B, const rational& T) {
  need_T(T);
  return K * T / 2 + B + abs(K * T - 2 * B);
}

Enclosure<rational> dirichlet_C(int digits) {
  // y* in (pi, 3pi/2) solves g(y) = sin y - y cos y = 0 (tan y = y); there sin(y)/y = cos(y), the
  // global minimum of sin(y)/y (the first negative lobe, deepest). C = -cos(y*).
  if (digits < 1 || digits > 900) throw InputError("dirichlet_C: digits in [1, 900]");
  using R = mp1000;
  using I = interval<1000>;
  R y = 4.4934094579;
  for (int it = 0; it < 100; ++it) {
    R g = sin(y) - y * cos(y), dg = y * sin(y);
    R step = g / dg;
    y -= step;
    if (abs(step) < pow(R(10), -980)) break;
  }
  rational yr = exact_rational(y), d = rational(1);
  for (int i = 0; i < digits + 10; ++i) d /= 10;
  rational lo = yr - d, hi = yr + d;
  auto gI = [](const rational& t) {
    I x;
    mpfi_set_q(x.backend().data(), t.backend().data());
    return I(sin(x) - x * cos(x));
  };
  I glo = gI(lo), ghi = gI(hi);
  // g' = y sin y < 0 on (pi, 3pi/2): g decreasing, so g(lo) > 0 > g(hi) certifies the root
  if (!(lower(glo) > 0 && upper(ghi) < 0)) throw NumericalError("dirichlet_C: root of tan y = y not certified");
  I C = -cos(ival<1000>(lo, hi));
  return {lower_rational(C), upper_rational(C)};
}

Enclosure<rational> dirichlet_D(int digits) {
  auto C = dirichlet_C(digits);
  return {(1 - C.hi) / 2, (1 - C.lo) / 2};
}

double dirichlet_approx(int N, const rational& T) {
  auto C = dirichlet_C(20), D = dirichlet_D(20);
  return to_real<double>((C.lo * N - D.hi) * T);
}

// ---------------------------------------------------------------------------------------------
std::optional<std::vector<rational>> backward_difference_coefficients(const QRatFun& H, const rational& T) {
  const QPoly& d = H.den();
  if (d.degree() < 0) return std::nullopt;
  for (int i = 0; i < d.degree(); ++i)
    if (d.coeff(i) != 0) return std::nullopt;  // den must be z^k (monic)
  const int k = d.degree();
  if (H.num().degree() > k) return std::nullopt;
  // z = 1/(1 - T w): H = sum_j n_j (1 - T w)^{k - j}
  QPoly lin(std::vector<rational>{rational(1), -T});
  QPoly acc;
  for (int j = 0; j <= H.num().degree(); ++j)
    if (H.num().coeff(j) != 0) acc += lin.pow(static_cast<unsigned>(k - j)) * H.num().coeff(j);
  std::vector<rational> alpha;
  for (int m = 0; m <= acc.degree(); ++m) alpha.push_back(acc.coeff(m));
  if (alpha.empty()) alpha.push_back(0);
  return alpha;
}

namespace {

/// W = H z^-n = (1 - z) sum beta_j z^-j ? Returns beta or nullopt; the first `offset` coefficients
/// are zero and left out (beta[i] is beta_{offset + i}), so a delay of n samples costs nothing.
struct Fir {
  std::vector<rational> beta;
  int offset = 0;
};
std::optional<Fir> fir_coefficients(const QRatFun& H, int n) {
  const QPoly& d = H.den();
  for (int i = 0; i < d.degree(); ++i)
    if (d.coeff(i) != 0) return std::nullopt;
  const int k = d.degree() + n;  // W = N / z^k
  QPoly one_minus_z(std::vector<rational>{rational(1), rational(-1)});
  auto [q, r] = divmod(H.num(), one_minus_z);
  if (!r.is_zero() || H.num().is_zero()) return std::nullopt;
  // W = (1 - z) q(z) / z^k, q of degree <= k: beta_j = coefficient of z^{k-j}, zero for j < k - deg q
  if (q.degree() > k) return std::nullopt;
  Fir f;
  f.offset = k - q.degree();
  for (int j = f.offset; j <= k; ++j) f.beta.push_back(q.coeff(k - j));
  while (f.beta.size() > 1 && f.beta.back() == 0) f.beta.pop_back();
  return f;
}

}  // namespace

std::optional<Match> match(const BoundProblem& raw) {
  const BoundProblem p = with_integer_delay(raw);  // t_d = kT is the integer delay n + k
  check_problem_size(p);
  const rational& T = p.T;
  const int n = p.delay;
  const rational eta = p.eta;
  auto with_eta = [&](Match m) {
    if (m.value) *m.value += eta;
    if (m.approx) *m.approx += to_real<double>(eta);
    if (eta != 0) {
      m.formula += " + eta (54), eta = " + dec(eta);
      m.equation += ", (54)";
    }
    return m;
  };
  const bool frac = p.frac_delay && den(*p.frac_delay / T) != 1;
  // Tustin wall: den z + 1, deg num <= 1
  if (p.H.den() == QPoly(std::vector<rational>{rational(1), rational(1)}) && p.H.num().degree() <= 1) {
    rational n0 = p.H.num().coeff(0), n1 = p.H.num().coeff(1);
    rational K = (n0 + n1) / 2, B = (n1 - n0) / 2 * T / 2;
    std::string kb = "K = " + dec(K) + ", B = " + dec(B);
    if (frac) {
      rational td = *p.frac_delay - rational(n) * T;
      if (B > 0 && n == 0 && td > 0 && td < T)
        return with_eta({"Tustin wall with a fractional delay 0 < t_d < T", "Example 3",
                         "not passive for any b (-cos w t_d + sin w t_d tan(wT/2) -> +inf as wT -> pi); " + kb,
                         std::nullopt, std::nullopt, true, true});
      return std::nullopt;
    }
    if (n == 0)
      return with_eta({K == 0 && B != 0 ? "IIR (z-1)/(z+1), a = 1" : "Tustin wall", K == 0 ? "(52)" : "Example 3",
                       "KT/2 - B with " + kb, tustin_wall(K, B, T), std::nullopt, false, true});
    if (n == 1)
      return with_eta({"Tustin wall with delay n = 1", "Example 4", "KT/2 + B + |KT - 2B| with " + kb,
                       delayed_tustin_n1(K, B, T), std::nullopt, false, true});
    return std::nullopt;
  }
  if (frac) return std::nullopt;
  // backward differences
  if (auto alpha = backward_difference_coefficients(p.H, T)) {
    const auto& a = *alpha;
    bool nonneg = true, anypos = false;
    int nz = 0, last = -1;
    for (size_t m = 0; m < a.size(); ++m) {
      if (a[m] < 0) nonneg = false;
      if (a[m] > 0) anypos = true;
      if (a[m] != 0) { ++nz; last = static_cast<int>(m); }
    }
    if (nonneg && anypos) {
      if (n == 0) {
        if (a.size() <= 2) {
          rational K = a[0], B = a.size() > 1 ? a[1] : rational(0);
          return with_eta({"virtual wall (backward difference)", "(46)",
                           "KT/2 + B with K = " + dec(K) + ", B = " + dec(B), virtual_wall(K, B, T), std::nullopt,
                           false, true});
        }
        return with_eta({"non-negative combination of backward differences H_m", "(46)",
                         "sum alpha_m (2/T)^{m-1}", backward_difference_sum(a, T), std::nullopt, false, true});
      }
      if (nz == 1 && last == 0)
        return with_eta({"constant with delay n (Dirichlet kernel)", "Example 4", "(2n+1) alpha_0 T/2",
                         a[0] * delayed_constant(n, T), std::nullopt, false, true});
      if (nz == 1 && last >= 1) {
        bool tight = false;
        rational v = a[last] * delayed_backward_difference(last, n, T, &tight);
        if (tight)
          // tight for an even delay n (attained at wT = pi), and for m = 1 at any n (at wT = pi/(n+1))
          return with_eta({"backward difference H_" + std::to_string(last) + " with delay n = " + std::to_string(n) +
                               (n % 2 == 0 ? " (even)" : " (m = 1: any n)"),
                           "Example 4", "alpha_m (2/T)^{m-1}", v, std::nullopt, false, true});
      }
      if (n == 1 && a.size() <= 2) {
        rational K = a[0], B = a.size() > 1 ? a[1] : rational(0);
        return with_eta({"virtual wall with delay n = 1", "(53)",
                         std::string(K * T >= 4 * B ? "KT/2 + B + (KT - 2B) (KT >= 4B)" : "KT/2 + B + K^2T^2/(8B) (KT < 4B)") +
                             " with K = " + dec(K) + ", B = " + dec(B),
                         delayed_wall_n1(K, B, T), std::nullopt, false, true});
      }
      if (n >= 2 && a.size() <= 2) {
        rational K = a[0], B = a.size() > 1 ? a[1] : rational(0);
        return with_eta({"virtual wall with delay n = " + std::to_string(n) + " (conservative)", "(53)",
                         "(2n+1) KT/2 + B with K = " + dec(K) + ", B = " + dec(B) + " (upper bound)",
                         delayed_wall_conservative(n, K, B, T), std::nullopt, false, false});
      }
    }
  }
  // FIR (47), with delay folded in
  if (auto fir = fir_coefficients(p.H, n)) {
    // the leading zeros shift the sign pattern's parity: one zero in front of the nonzero taps when
    // the offset is odd (fir_bound reads the alternating structure from the index)
    std::vector<rational> b(static_cast<size_t>(fir->offset % 2), rational(0));
    b.insert(b.end(), fir->beta.begin(), fir->beta.end());
    bool tight = false;
    rational v = fir_bound(b, T, &tight);
    // Dirichlet: (z - 1) sum_{k=0}^N z^-k, i.e. beta_k = -g for all k (no leading zeros)
    bool allneg_equal = fir->offset == 0 && b.size() >= 2 && b[0] < 0;
    for (auto& x : b) allneg_equal = allneg_equal && x == b[0];
    if (allneg_equal) {
      int N = static_cast<int>(b.size()) - 1;
      Match m{"FIR (z-1) sum_{k=0}^N z^-k (Dirichlet kernel)", "(50)",
              "(C N - D) T g with N = " + std::to_string(N) + ", g = " + dec(-b[0]) + " (approximation for large N)",
              std::nullopt, dirichlet_approx(N, T) * to_real<double>(-b[0]), false, false};
      return with_eta(m);
    }
    if (tight)
      return with_eta({"FIR (47) with a tight sign structure", "(49)", "T sum |alpha_k|", v, std::nullopt, false, true});
    return with_eta({"FIR (47), general signs (upper bound only)", "(49)", "T sum |alpha_k|", v, std::nullopt, false,
                     false});
  }
  // IIR g (z - 1)/(z + a)
  if (n == 0 && p.H.den().degree() == 1 && p.H.num().degree() == 1) {
    rational a = p.H.den().coeff(0);
    rational g = p.H.num().coeff(1);
    if (p.H.num().coeff(0) == -g && (abs(a) < 1)) {
      if (g > 0)
        return with_eta({"IIR (z-1)/(z+a)", "(51)", "g T/(1-a) with g = " + dec(g) + ", a = " + dec(a),
                         g * iir_zero_at_one(a, T), std::nullopt, false, true});
      return with_eta({"IIR (1-z)/(z+a)", "(51)", "|g| T/(1+a) with g = " + dec(g) + ", a = " + dec(a),
                       -g * iir_zero_at_one_neg(a, T), std::nullopt, false, true});
    }
  }
  return std::nullopt;
}

std::optional<bool> agrees(const Match& m, const Bound& b) {
  if (m.approx) return std::nullopt;
  if (m.infinite) return b.infinite;
  if (!m.value || b.infinite) return false;
  return m.tight ? b.enclosure->contains(*m.value) : b.enclosure->lo <= *m.value;
}

}  // namespace hapstab::passivity::catalogue
