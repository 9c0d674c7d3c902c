// proofs/passivity_closed_forms.cpp -- paper 001, Secs. VI-VII: the identities behind the
// closed-form passivity bounds, proven exactly as identities of rational functions of
// t = tan(wT/2) (through poly/'s unit-circle substitution, independent of passivity/'s c-form),
// and every closed form checked against the certified generic bound over a sweep of its
// parameters, boundary cases included.
#include <random>
#include <sstream>

#include "hapstab/numeric/decimal.hpp"
#include "hapstab/numeric/interval.hpp"
#include "hapstab/passivity/bound.hpp"
#include "hapstab/passivity/catalogue.hpp"
#include "hapstab/poly/unit_circle.hpp"
#include "proofs/certify.hpp"
#include "proofs/proof.hpp"

namespace {

using namespace hapstab;
using namespace hapstab::passivity;
using P = Polynomial<rational>;
using RF = RationalFunction<rational>;

const P z = P::monomial(1);
RF zpow(int k) { return k >= 0 ? RF(P::monomial(k)) : RF(P(rational(1)), P::monomial(-k)); }
RF one_minus_z() { return RF(P(std::vector<rational>{rational(1), rational(-1)})); }

// cos(k theta) as a rational function of t: T_k(c), c = (1 - t^2)/(1 + t^2)
RF cos_k(int k) {
  RF c(P(std::vector<rational>{rational(1), rational(0), rational(-1)}), P(std::vector<rational>{rational(1), rational(0), rational(1)}));
  RF t0(rational(1)), t1 = c;
  if (k == 0) return t0;
  for (int i = 1; i < k; ++i) {
    RF t2 = RF(rational(2)) * c * t1 - t0;
    t0 = t1;
    t1 = t2;
  }
  return t1;
}
RF dirichlet(int n, bool shifted_by_pi) {  // D_n(theta) or D_n(theta + pi)
  RF d(rational(1));
  for (int k = 1; k <= n; ++k) d += RF(rational(shifted_by_pi && k % 2 ? -2 : 2)) * cos_k(k);
  return d;
}
RF re_t(const RF& G) { return on_unit_circle(G).re; }
RF Hm(int m, const rational& T) {  // ((z-1)/(Tz))^m
  return RF(P(std::vector<rational>{rational(-1), rational(1)}), P::monomial(1, T)).pow(m);
}
rational pow_rational(const rational& x, int e) {
  rational r(1);
  for (int i = 0; i < e; ++i) r *= x;
  return r;
}
rational binom(int n, int k) {
  rational r(1);
  for (int i = 1; i <= k; ++i) r = r * (n - k + i) / i;
  return r;
}

BoundProblem prob(const RF& H, const rational& T, int n = 0) {
  BoundProblem p;
  p.H = H;
  p.T = T;
  p.delay = n;
  return p;
}
// (51) with a a polynomial variable over Q(t) (see passivity_sec6_identities): complex numbers
// re + j im with re, im in Q(t)[a].
using PA = Polynomial<RF>;
struct CA {
  PA re, im;
};
CA operator*(const CA& x, const CA& y) { return {x.re * y.re - x.im * y.im, x.re * y.im + x.im * y.re}; }
bool eq51_symbolic_in_a() {
  const RF one_plus(P(std::vector<rational>{rational(1), rational(0), rational(1)}));
  const RF c = cos_k(1), s = RF(P(std::vector<rational>{rational(0), rational(2)})) / one_plus;  // cos wT, sin wT
  const bool on_circle = c * c + s * s == RF(rational(1));
  const PA a = PA::monomial(1, RF(rational(1))), one(RF(rational(1)));
  const CA z{PA(c), PA(s)};
  const CA N{z.re - one, z.im};
  const CA D = CA{one - z.re, PA() - z.im} * CA{z.re + a, z.im};
  const CA NconjD = N * CA{D.re, PA() - D.im};
  const PA normD = D.re * D.re + D.im * D.im;
  const PA rhs_den = a * a + PA(RF(rational(2)) * c) * a + one;
  return on_circle && !normD.is_zero() && !rhs_den.is_zero() && (NconjD.re * rhs_den + (PA(c) + a) * normD).is_zero();
}
/// closed form value v agrees with the certified generic bound: v inside the enclosure
bool agrees(const Bound& b, const rational& v) { return !b.infinite && b.enclosure->contains(v); }
/// b* <= v proven: the whole enclosure lies at or below v
bool below(const Bound& b, const rational& v) { return !b.infinite && proofs::proves_upper_bound(*b.enclosure, v); }

// The certificates' models (proofs/certify.hpp): each instance as a user writes it for `hapstab bound`.
const char* const wall_text = "K + B*(z-1)/(T*z)";
const char* const tustin_text = "K + 2*B*(z-1)/(T*(z+1))";
proofs::BoundInstance wall_instance(const char* H, const rational& K, const rational& B, const rational& T, int n = 0) {
  proofs::BoundInstance b{H, T, {{"K", K}, {"B", B}}};
  b.delay = n;
  return b;
}
// sum alpha_m H_m as written: "2/7 + 5/7*((z-1)/(T*z)) + 1/7*((z-1)/(T*z))^2" (zero terms left out)
std::string backward_sum_text(const std::vector<rational>& alpha) {
  std::string s;
  for (size_t m = 0; m < alpha.size(); ++m) {
    if (alpha[m] == 0) continue;
    s += (s.empty() ? "" : " + ") + alpha[m].str();
    if (m >= 1) s += "*((z-1)/(T*z))" + (m > 1 ? "^" + std::to_string(m) : std::string());
  }
  return s;
}

}  // namespace

HAPSTAB_PROOF(passivity_sec6_identities, "001", "Sec. VI identities as exact rational identities in t = tan(wT/2)") {
  // T enters H_m = ((z-1)/(Tz))^m only as the factor T^-m: H_m(T) = T^-m H_m(1) as rational
  // functions of z (checked exactly), so T H_m/((1-z)z^n) = T^{1-m} [H_m(1)/((1-z)z^n)], and an
  // identity at T = 1 times T^{1-m} is the identity for every T > 0. Checked at T = 1 (the proof)
  // and, as a cross-check of the scaling, at T = 1/1000 and 7/3.
  const std::vector<rational> Ts = {rational(1), rational(1, 1000), rational(7, 3)};
  bool scaling = true;
  for (const auto& T : Ts)
    for (int m = 1; m <= 6; ++m) scaling = scaling && Hm(m, T) == RF(rational(1) / pow_rational(T, m)) * Hm(m, rational(1));
  // Re{T H_1/(1-z)} = -cos wT
  bool ok = scaling;
  for (const auto& T : Ts) ok = ok && re_t(RF(T) * Hm(1, T) / one_minus_z()) == -cos_k(1);
  check.claim("001.sec6.H1", "Example 1", "Re{T H_1(z)/(1-z)} = -cos wT, H_1 = (z-1)/(Tz), as an identity in t, every T > 0",
              Status::exact, ok,
              "on_unit_circle of T H_1/(1-z) equals -(1-t^2)/(1+t^2) exactly; T H_1 = (z-1)/z does not depend on T "
              "(H_1(T) = H_1(1)/T, exact), so T = 1 proves every T (cross-checked at T = 1/1000, 7/3)");
  // Re{T H_m/(1-z)} = T^{1-m} sum_k C(m-1,k)(-1)^{k+1} cos(k+1)wT, max (2/T)^{m-1} at wT = pi
  ok = scaling;
  for (const auto& T : Ts)
    for (int m = 1; m <= 6; ++m)
      for (int n = 0; n <= 4; ++n) {
        RF rhs(rational(0));
        for (int k = 0; k <= m - 1; ++k)
          rhs += RF(binom(m - 1, k) * ((k + 1) % 2 ? rational(-1) : rational(1)) / pow_rational(T, m - 1)) * cos_k(n + k + 1);
        ok = ok && re_t(RF(T) * Hm(m, T) / (one_minus_z() * zpow(n))) == rhs;
      }
  check.claim("001.ex4.Hm_delay", "Example 4",
              "Re{T H_m/((1-z)z^n)} = T^{1-m} sum_k C(m-1,k)(-1)^{k+1} cos(n+k+1)wT, m = 1..6, n = 0..4, every T > 0",
              Status::exact, ok,
              "exact identity in t at T = 1; both sides are T^{1-m} times their value at T = 1 (H_m(T) = T^-m H_m(1), "
              "exact), so this proves every T (cross-checked at T = 1/1000, 7/3)");
  // partial fractions 1/((1-z) z^n) = 1/(1-z) + z^-1 + ... + z^-n, for every n by induction: n = 0
  // is 1/(1-z) itself; multiplying the identity at n by z^-1 gives the one at n + 1 exactly when
  // z^-1/(1-z) = 1/(1-z) + z^-1 (one identity of rational functions, free of n: the step)
  const RF one(rational(1));
  bool step_pf = zpow(-1) / one_minus_z() == one / one_minus_z() + zpow(-1);
  ok = step_pf;
  // cross-check: the identity itself at n = 0..12, each comparing two non-zero rational functions
  proofs::Instances delays{"delays n", 13};
  for (int n = 0; n <= 12; ++n) {
    delays.count(true);
    RF rhs = one / one_minus_z();
    for (int k = 1; k <= n; ++k) rhs += zpow(-k);
    ok = ok && (one / (one_minus_z() * zpow(n))) == rhs;
  }
  check.claim("001.ex4.partial_fractions", "Example 4",
              "1/((1-z)z^n) = 1/(1-z) + sum_{k=1}^n z^-k for every n >= 0 (induction on n)", Status::exact, ok,
              std::string("induction: n = 0 is trivial, the step z^-1/(1-z) = 1/(1-z) + z^-1 holds exactly: ") +
                  (step_pf ? "yes" : "NO") + "; cross-checked as reduced rational functions of z at n = 0..12",
              {delays});
  // (52): T/(1-z) (z-1)/(z+1) = -(T/2)[1 - j tan(wT/2)]
  // T is a factor of the left side and of the right: the identity at T = 1 times T is the identity
  // for every T (the other T cross-check it).
  ok = true;
  for (const auto& T : Ts) {
    ReIm ri = on_unit_circle(RF(T) / one_minus_z() * RF(P(std::vector<rational>{rational(-1), rational(1)}), P(std::vector<rational>{rational(1), rational(1)})));
    ok = ok && ri.re == RF(-T / 2) && ri.im == RF(P::monomial(1, T / 2));
  }
  check.claim("001.eq52", "(52)", "T/(1-z) (z-1)/(z+1) = -(T/2)(1 - j tan(wT/2)) on the unit circle, every T", Status::exact, ok,
              "real part -1/2 and imaginary part t/2 exactly at T = 1; T is a factor of both sides, so this proves "
              "every T (cross-checked at T = 1/1000, 7/3)");
  // (51): Re{T/(1-z) (z-1)/(z+a)} = -T (cos wT + a)/(a^2 + 2 a cos wT + 1)
  //
  // Symbolically in a: with z = cos + j sin (rational functions of t), N = z - 1 and D = (1 - z)(z + a)
  // are complex polynomials in a over Q(t); Re(N/D) = Re(N conj D)/|D|^2 (a real), and (51)
  // cross-multiplied is the polynomial identity Re(N conj D) (a^2 + 2a cos + 1) + (cos + a) |D|^2 = 0
  // in Q(t)[a], with neither denominator identically zero: (51) for every a and every wT where both
  // sides are defined. The instances a in {-9/10, 0, 1/3, 999/1000} cross-check it through poly/.
  ok = eq51_symbolic_in_a();
  for (rational a : {rational(-9, 10), rational(0), rational(1, 3), rational(999, 1000)}) {
    RF lhs = re_t(RF(rational(1)) / one_minus_z() * RF(P(std::vector<rational>{rational(-1), rational(1)}), P(std::vector<rational>{a, rational(1)})));
    RF c = cos_k(1);
    ok = ok && lhs == RF(rational(-1)) * (c + RF(a)) / (RF(a * a + 1) + RF(2 * a) * c);
  }
  check.claim("001.eq51", "(51)", "Re{T/(1-z) (z-1)/(z+a)} = -T (cos wT + a)/(a^2 + 2a cos wT + 1), every a and T",
              Status::exact, ok,
              "cross-multiplied identity of polynomials in a over Q(t) (T = 1; T is a factor of both sides), both "
              "denominators not identically zero; cross-checked through on_unit_circle at a in {-9/10, 0, 1/3, 999/1000}");
  // (53): Re{T H/((1-z) z^n)} = (KT/2) D_n(wT) - B cos(n+1)wT, H = K + B(z-1)/(Tz); linear in (KT, B),
  // so the two basis cases (KT, B) = (1, 0), (0, 1) prove it for every K, B, T. For every n:
  //   spring, by induction: n = 0, Re{1/(1-z)} = 1/2 = D_0/2 (exact in t); the step from n to n + 1
  //     adds (z^-1 - 1)/((1-z) z^n) = z^-(n+1) -- exactly when (z^-1 - 1)/(1 - z) = z^-1 -- whose
  //     real part cos(n+1)wT is (D_{n+1} - D_n)/2 (D_n = 1 + 2 sum_{k<=n} cos k wT, by definition);
  //   damper: (z-1)/(z(1-z)) = -z^-1 exactly, so it is -Re z^-(n+1) = -cos(n+1)wT for every n.
  // (Re z^-k = cos k wT on |z| = 1 is de Moivre's formula, not re-derived.)
  const bool spring_base = re_t(one / one_minus_z()) == RF(rational(1, 2));
  const bool spring_step = (zpow(-1) - one) / one_minus_z() == zpow(-1);
  const bool damper_all = Hm(1, rational(1)) / one_minus_z() == RF(rational(-1)) * zpow(-1);
  ok = spring_base && spring_step && damper_all;
  proofs::Instances basis{"delays n with both basis parts non-zero", 9};
  for (int n = 0; n <= 8; ++n) {
    RF spring = re_t(RF(rational(1)) / (one_minus_z() * zpow(n)));                // KT = 1
    RF damper = re_t(Hm(1, rational(1)) / (one_minus_z() * zpow(n)));             // B = 1 (T = 1)
    basis.count(!spring.is_zero() && !damper.is_zero());
    ok = ok && spring == RF(rational(1, 2)) * dirichlet(n, false) && damper == RF(rational(-1)) * cos_k(n + 1);
  }
  check.claim("001.eq53", "(53)",
              "Re{T(K + B(z-1)/(Tz))/((1-z)z^n)} = (KT/2) D_n(wT) - B cos(n+1)wT for every K, B, T and n >= 0 "
              "(linear in KT and B; induction on n)",
              Status::exact, ok,
              std::string("basis (KT,B) = (1,0), (0,1); spring: n = 0 exact in t, step (z^-1 - 1)/(1 - z) = z^-1 exact; "
                          "damper: (z-1)/(z(1-z)) = -z^-1 exact: ") +
                  (spring_base && spring_step && damper_all ? "all hold" : "one FAILS") +
                  "; cross-checked as exact identities in t for n = 0..8",
              {basis});
  // Tustin with delay: (KT/2) D_n(wT) - B (-1)^n D_n(wT + pi); n = 1: KT/2 + B + (KT - 2B) cos wT.
  // Damper part f_n = Re{2(z-1)/(z+1)/((1-z)z^n)} for every n, by induction: n = 0 exact in t; the
  // step f_n + f_{n+1} = -2 Re z^-(n+1) = -2 cos(n+1)wT holds exactly when (1 + z^-1)/(z + 1) = z^-1,
  // and -(-1)^n D_n(wT + pi) satisfies the same recurrence (D_{n+1}(x + pi) = D_n(x + pi) +
  // 2 (-1)^{n+1} cos(n+1)x, by definition). The spring part is (53)'s.
  RF tust = RF(P(std::vector<rational>{rational(-2), rational(2)}), P(std::vector<rational>{rational(1), rational(1)}));  // 2(z-1)/(z+1), T = 1
  const bool tustin_base = re_t(tust / one_minus_z()) == RF(rational(-1)) * dirichlet(0, true);
  const bool tustin_step = (one + zpow(-1)) / RF(P(std::vector<rational>{rational(1), rational(1)})) == zpow(-1);
  ok = tustin_base && tustin_step;
  proofs::Instances tustin_delays{"delays n with a non-zero damper part", 9};
  for (int n = 0; n <= 8; ++n) {
    RF damper = re_t(tust / (one_minus_z() * zpow(n)));
    tustin_delays.count(!damper.is_zero());
    ok = ok && damper == RF(rational(n % 2 ? 1 : -1)) * dirichlet(n, true);
  }
  check.claim("001.ex4.tustin_delay", "Example 4",
              "Re{T(K + (2B/T)(z-1)/(z+1))/((1-z)z^n)} = (KT/2)D_n(wT) - B(-1)^n D_n(wT + pi) for every n >= 0 "
              "(induction on n)",
              Status::exact, ok,
              std::string("damper part: n = 0 exact in t, step (1 + z^-1)/(z + 1) = z^-1 exact: ") +
                  (tustin_base && tustin_step ? "both hold" : "one FAILS") +
                  "; the spring part is (53)'s; cross-checked as exact identities in t for n = 0..8",
              {tustin_delays});
  RF n1 = re_t(RF(rational(1)) / (one_minus_z() * zpow(1)));
  RF n1b = re_t(tust / (one_minus_z() * zpow(1)));
  bool ok1 = n1 == RF(rational(1, 2)) + cos_k(1) && n1b == RF(rational(1)) - RF(rational(2)) * cos_k(1);
  check.claim("001.ex4.tustin_n1", "Example 4", "n = 1: Re = KT/2 + B + (KT - 2B) cos wT", Status::exact, ok1,
              "spring part 1/2 + cos wT, damper part 1 - 2 cos wT, exactly in t");
}

namespace {

// passivity_closed_forms_vs_generic, part 1: (46)'s sums of backward differences, the virtual
// wall with and without a one-sample delay (53), (53)'s conservative bound and Example 4's H_m z^-n
void backward_difference_forms(proofs::Checker& check, const rational& T, std::mt19937& rng) {
  // (46) non-negative combinations of backward differences, random alpha
  std::uniform_int_distribution<int> pick(0, 40);
  int count = 0;
  bool ok = true;
  // Instances (proof.hpp): H = 0 is skipped; every other H is non-trivial, agrees() failing an
  // infinite b*. Below, each closed form's instances likewise, and each branch of a closed form
  // (KT >= 4B or not, tight or bound only) is a family of its own with its minimum.
  using proofs::Instances;
  Instances combos{"H != 0", 10};
  for (int trial = 0; trial < 12; ++trial) {
    std::vector<rational> alpha;
    RF H(rational(0));
    int M = 1 + trial % 4;
    for (int m = 0; m <= M; ++m) {
      rational a(trial % 3 == 0 && m == 0 ? 0 : pick(rng), 7);
      alpha.push_back(a);
      H += RF(a) * Hm(m, T);
    }
    if (!combos.count(!H.is_zero())) continue;
    rational cf = catalogue::backward_difference_sum(alpha, T);
    ok = ok && agrees(bound_certified(prob(H, T)), cf);
    check.certify("001.eq46.generic", proofs::bound_equals({backward_sum_text(alpha), T}, cf));
    ++count;
  }
  check.claim("001.eq46.generic", "(46)", "b* = sum alpha_m (2/T)^{m-1} for alpha_m >= 0 -- at T = 1/1000 on 12 pseudo-random combinations up to H_4 (seed 46)", Status::certified, ok,
              std::to_string(count) + " random non-negative combinations up to H_4; closed form inside the certified enclosure",
              {combos});
  // virtual wall KT/2 + B and with delay n = 1 (both cases, boundary KT = 4B)
  ok = true;
  bool ok1 = true;
  count = 0;
  Instances walls{"(K, B) not both 0", 23}, stiff{"n = 1 cases with KT >= 4B", 5}, soft{"n = 1 cases with KT < 4B", 5};
  for (rational K : {rational(0), rational(100), rational(1000), rational(4000), rational(20000), rational(100000)})
    for (rational B : {rational(0), rational(1), rational(5), rational(50)}) {
      if (!walls.count(K != 0 || B != 0)) continue;
      RF H = RF(K) + RF(B) * Hm(1, T);
      ok = ok && agrees(bound_certified(prob(H, T)), catalogue::virtual_wall(K, B, T));
      check.certify("001.wall.generic", proofs::bound_equals(wall_instance(wall_text, K, B, T), catalogue::virtual_wall(K, B, T)));
      (K * T >= 4 * B ? stiff : soft).count(true);
      ok1 = ok1 && agrees(bound_certified(prob(H, T, 1)), catalogue::delayed_wall_n1(K, B, T));
      check.certify("001.eq53.n1.generic",
                    proofs::bound_equals(wall_instance(wall_text, K, B, T, 1), catalogue::delayed_wall_n1(K, B, T)));
      ++count;
    }
  // exactly on the boundary KT = 4B and just beside it
  for (rational B : {rational(1), rational(5)})
    for (rational eps : {rational(0), rational(1, 1000000), rational(-1, 1000000)}) {
      rational K = 4 * B / T * (1 + eps);
      RF H = RF(K) + RF(B) * Hm(1, T);
      (K * T >= 4 * B ? stiff : soft).count(true);
      ok1 = ok1 && agrees(bound_certified(prob(H, T, 1)), catalogue::delayed_wall_n1(K, B, T));
      check.certify("001.eq53.n1.generic",
                    proofs::bound_equals(wall_instance(wall_text, K, B, T, 1), catalogue::delayed_wall_n1(K, B, T)));
    }
  check.claim("001.wall.generic", "(46)", "virtual wall K + B(z-1)/(Tz): b* = KT/2 + B -- at T = 1/1000, K in {0, 100, 1000, 4000, 20000, 100000}, B in {0, 1, 5, 50}", Status::certified, ok,
              std::to_string(count) + " (K, B) pairs incl. K = 0 and B = 0", {walls});
  check.claim("001.eq53.n1.generic", "(53)", "n = 1: KT/2 + B + (KT - 2B) if KT >= 4B, else KT/2 + B + K^2T^2/(8B) -- at T = 1/1000 on the (K, B) "
              "above and KT = 4B(1 + {0, +-1e-6}), B in {1, 5}",
              Status::certified, ok1, std::to_string(count) + " (K, B) pairs and KT = 4B(1 + {0, +-1e-6}) for B in {1, 5}",
              {stiff, soft});
  // conservative bound (2n+1)KT/2 + B for n = 0..5 is an upper bound
  ok = true;
  Instances delayed{"(n, K) cases; below() fails an infinite b*", 12};
  for (int n = 0; n <= 5; ++n)
    for (rational K : {rational(1000), rational(30000)}) {
      RF H = RF(K) + RF(rational(5)) * Hm(1, T);
      Bound b = bound_certified(prob(H, T, n));
      delayed.count(true);
      ok = ok && below(b, catalogue::delayed_wall_conservative(n, K, rational(5), T));
      check.certify("001.eq53.conservative", proofs::bound_at_most(wall_instance(wall_text, K, rational(5), T, n),
                                                                   catalogue::delayed_wall_conservative(n, K, rational(5), T)));
    }
  check.claim("001.eq53.conservative", "(53)", "b* <= (2n+1)KT/2 + B for the delayed wall -- at T = 1/1000, n = 0..5, K in {1000, 30000}, B = 5", Status::certified, ok,
              "n = 0..5, K in {1000, 30000}, B = 5", {delayed});
  // H_m z^-n: (2/T)^{m-1}, tight for even n; H_0 z^-n: (2n+1)T/2
  ok = true;
  Instances hm_tight{"(m, n) where the bound is tight", 5}, hm_bound{"(m, n) where it is an upper bound only", 5},
      h0{"H_0 delays", 7};
  for (int m = 1; m <= 4; ++m)
    for (int n = 0; n <= 4; ++n) {
      bool tight = false;
      rational v = catalogue::delayed_backward_difference(m, n, T, &tight);
      Bound b = bound_certified(prob(Hm(m, T), T, n));
      (tight ? hm_tight : hm_bound).count(true);
      ok = ok && (tight ? agrees(b, v) : below(b, v));
      proofs::BoundInstance inst{"((z-1)/(T*z))" + (m > 1 ? "^" + std::to_string(m) : std::string()), T};
      inst.delay = n;
      check.certify("001.ex4.Hm.generic", tight ? proofs::bound_equals(inst, v) : proofs::bound_at_most(inst, v));
    }
  for (int n = 0; n <= 6; ++n) {
    h0.count(true);
    ok = ok && agrees(bound_certified(prob(RF(rational(1)), T, n)), catalogue::delayed_constant(n, T));
    proofs::BoundInstance inst{"1", T};
    inst.delay = n;
    check.certify("001.ex4.Hm.generic", proofs::bound_equals(inst, catalogue::delayed_constant(n, T)));
  }
  check.claim("001.ex4.Hm.generic", "Example 4", "H_m z^-n: b* <= (2/T)^{m-1} (equal for even n or m = 1); H_0 z^-n: (2n+1)T/2 -- at T = 1/1000, m = "
              "1..4, n = 0..4 (H_0: n = 0..6)",
              Status::certified, ok, "m = 1..4, n = 0..4; n = 0..6 for H_0", {hm_tight, hm_bound, h0});
}

// part 2: the FIRs (47)-(49), the first-order IIRs (51)-(52), the Tustin wall (Examples 3-4), a
// fractional delay made exact, and eta (54)
void fir_iir_tustin_forms(proofs::Checker& check, const rational& T, std::mt19937& rng) {
  using proofs::Instances;
  bool ok = true;
  // FIR (47)-(49): non-negative and alternating sign structures are tight, others bounded
  bool okb = true;
  Instances fir_tight{"non-zero FIRs whose bound is tight (alpha >= 0 or alternating)", 5},
      fir_bound{"non-zero FIRs with mixed signs (upper bound only)", 3};
  std::uniform_int_distribution<int> sgnd(-20, 20);
  for (int trial = 0; trial < 15; ++trial) {
    int N = 2 + trial % 5;
    std::vector<rational> alpha;
    for (int k = 0; k <= N; ++k) {
      int v = sgnd(rng);
      if (trial % 3 == 0) v = std::abs(v);
      if (trial % 3 == 1) v = (k % 2 ? -1 : 1) * std::abs(v);
      alpha.push_back(rational(v, 3));
    }
    RF H(rational(0));
    for (int k = 0; k <= N; ++k) H += RF(alpha[k]) * zpow(-k);
    H = H * one_minus_z();
    if (H.is_zero()) continue;  // not counted: both families below need H != 0
    BoundProblem p = prob(H, T);
    p.allow_noncausal = true;  // (47) as written has a z^{+1} term
    bool tight = false;
    rational v = catalogue::fir_bound(alpha, T, &tight);
    Bound b = bound_certified(p);
    (tight ? fir_tight : fir_bound).count(true);
    if (tight) ok = ok && agrees(b, v);
    okb = okb && (tight ? agrees(b, v) : below(b, v));
    // its certificate: (47) as written, with its z^{+1} term (bound --allow-noncausal: (45) is the same sup on the circle)
    proofs::CertificateRequest r = tight ? proofs::bound_equals({proofs::rational_function_text(H), T}, v)
                                         : proofs::bound_at_most({proofs::rational_function_text(H), T}, v);
    r.args.push_back("--allow-noncausal");
    check.certify("001.eq49.generic", r);
  }
  check.claim("001.eq49.generic", "(47)-(49)", "FIR: b* <= T sum|alpha_k|, equal for alpha >= 0 or alternating signs -- at T = 1/1000 on 15 "
              "pseudo-random FIRs of length 3..7 (seed 46); its certificates: b* of each FIR as written (non-causal: "
              "bound --allow-noncausal)",
              Status::certified, ok && okb, "15 random FIRs of length 3..7 (5 non-negative, 5 alternating, 5 mixed)",
              {fir_tight, fir_bound});
  // IIR: T/(1-a), T/(1+a), a -> +-1, a = 1 (52)
  ok = true;
  Instances iir{"(a, sign) cases", 11};
  for (rational a : {rational(-999999, 1000000), rational(-9, 10), rational(0), rational(1, 2), rational(999999, 1000000)}) {
    iir.count(true);
    iir.count(true);
    RF Hp(P(std::vector<rational>{rational(-1), rational(1)}), P(std::vector<rational>{a, rational(1)}));
    ok = ok && agrees(bound_certified(prob(Hp, T)), catalogue::iir_zero_at_one(a, T));
    ok = ok && agrees(bound_certified(prob(RF(rational(-1)) * Hp, T)), catalogue::iir_zero_at_one_neg(a, T));
    check.certify("001.eq51.generic", proofs::bound_equals({"(z-1)/(z+a)", T, {{"a", a}}}, catalogue::iir_zero_at_one(a, T)));
    check.certify("001.eq51.generic", proofs::bound_equals({"(1-z)/(z+a)", T, {{"a", a}}}, catalogue::iir_zero_at_one_neg(a, T)));
  }
  RF H52(P(std::vector<rational>{rational(-1), rational(1)}), P(std::vector<rational>{rational(1), rational(1)}));
  iir.count(true);
  ok = ok && agrees(bound_certified(prob(H52, T)), catalogue::iir_zero_at_one(rational(1), T));
  check.certify("001.eq51.generic", proofs::bound_equals({"(z-1)/(z+a)", T, {{"a", rational(1)}}}, catalogue::iir_zero_at_one(rational(1), T)));
  check.claim("001.eq51.generic", "(51), (52)", "(z-1)/(z+a): T/(1-a); (1-z)/(z+a): T/(1+a); a = 1: -T/2 -- at T = 1/1000, a in {-0.999999, -0.9, 0, "
              "0.5, 0.999999} and a = 1", Status::certified,
              ok, "a in {-0.999999, -0.9, 0, 0.5, 0.999999} and a = 1", {iir});
  // Tustin wall KT/2 - B, with n = 1 KT/2 + B + |KT - 2B|, with 0 < t_d < T: +inf
  ok = true;
  bool okf = true;
  Instances tustin{"(K, B, n) cases", 18}, frac{"(K, B, t_d) cases", 27};
  for (rational K : {rational(0), rational(1000), rational(10000)})
    for (rational B : {rational(1, 2), rational(5), rational(50)}) {
      RF H = RF(K) + RF(2 * B / T) * H52;
      tustin.count(true);
      tustin.count(true);
      ok = ok && agrees(bound_certified(prob(H, T)), catalogue::tustin_wall(K, B, T));
      ok = ok && agrees(bound_certified(prob(H, T, 1)), catalogue::delayed_tustin_n1(K, B, T));
      check.certify("001.tustin.generic", proofs::bound_equals(wall_instance(tustin_text, K, B, T), catalogue::tustin_wall(K, B, T)));
      check.certify("001.tustin.generic",
                    proofs::bound_equals(wall_instance(tustin_text, K, B, T, 1), catalogue::delayed_tustin_n1(K, B, T)));
      for (rational td : {T / 100, T / 2, T * 99 / 100}) {
        BoundProblem p = prob(H, T);
        p.frac_delay = td;
        Bound b = bound_certified(p, 16);
        frac.count(true);
        okf = okf && b.infinite && b.status == Status::exact;
        {  // the pole z = -1 at the band's end c = cos(pi/q): 0 for q = 2, cos(pi/100) isolated by an interval
          proofs::BoundInstance inst = wall_instance(tustin_text, K, B, T);
          inst.frac_delay = td;
          proofs::CertificateRequest r;
          r.args = proofs::bound_args(inst);
          r.flags = {{"infinite", true}};
          check.certify("001.tustin.fracdelay", r);
        }
      }
    }
  check.claim("001.tustin.generic", "Example 3, 4", "Tustin wall: KT/2 - B; n = 1: KT/2 + B + |KT - 2B| -- at T = 1/1000, K in {0, 1000, 10000}, B in "
              "{1/2, 5, 50}", Status::certified, ok,
              "K in {0, 1000, 10000}, B in {1/2, 5, 50}", {tustin});
  check.claim("001.tustin.fracdelay", "Example 3", "Tustin wall with 0 < t_d < T: Re -> +inf as wT -> pi (not passive) -- at T = 1/1000, t_d/T in {1/100, "
              "1/2, 99/100}, the nine (K, B) above",
              Status::exact, okf, "exact leading-term test at wT = pi for t_d/T in {1/100, 1/2, 99/100}, 9 (K, B)", {frac});
  // a fractional delay t_d = (p/q) T made exact (bound.cpp, certified_frac_exact): for H_1 z^-n,
  // Re{T H_1 z^-n e^{-j w t_d}/(1 - z)} = -cos((n + 1 + t_d/T) wT), so b* = 1, attained at
  // w = pi/((n + 1 + t_d/T) T) -- an interior maximiser at an irrational cos(wT/q) for most p/q
  ok = true;
  Instances fractional{"(n, t_d/T) cases", 18};
  for (int n = 0; n <= 2; ++n)
    for (rational tau : {rational(1, 2), rational(1, 3), rational(2, 5), rational(3, 7), rational(5, 4), rational(9, 10)}) {
      BoundProblem p = prob(Hm(1, T), T, n);
      p.frac_delay = tau * T;
      Bound b = bound_certified(p, 30, BoundPath::exact);  // this claim is about the exact path's form
      // the maximiser pi/((n + 1 + t_d/T) T) enclosed (60 digits) and inside the certified enclosure of w
      const interval<60> w = ipi<60>() / ival<60>((n + 1 + tau) * T, (n + 1 + tau) * T);
      ok = ok && agrees(b, rational(1)) && b.method.find("made exact") != std::string::npos && b.omega_enclosure &&
           b.omega_enclosure->lo <= lower_rational(w) && upper_rational(w) <= b.omega_enclosure->hi;
      fractional.count(true);
      proofs::BoundInstance inst{"(z-1)/(T*z)", T};
      inst.delay = n;
      inst.frac_delay = tau * T;
      check.certify("001.eq45.fractional_exact", proofs::bound_equals(inst, rational(1)));
    }
  check.claim("001.eq45.fractional_exact", "(45), Example 3", "with t_d = (p/q) T the objective is rational in cos(wT/q): "
              "H_1 z^-n e^{-j w t_d} gives b* = 1 at w = pi/((n + 1 + t_d/T) T) -- at T = 1/1000, n = 0..2, t_d/T in "
              "{1/2, 1/3, 2/5, 3/7, 5/4, 9/10}", Status::certified, ok,
              std::to_string(fractional.total) + " cases, n = 0..2, t_d/T in {1/2, 1/3, 2/5, 3/7, 5/4, 9/10}: 1 inside the certified "
              "enclosure of b*, and the certified enclosure of the maximiser contains a 60-digit enclosure of "
              "pi/((n + 1 + t_d/T) T)", {fractional});
  // eta (54) adds
  ok = true;
  Instances etas{"values of eta", 3};
  for (rational eta : {rational(0), rational(1, 10), rational(7)}) {
    etas.count(true);
    BoundProblem p = prob(RF(rational(1000)) + RF(rational(5)) * Hm(1, T), T);
    p.eta = eta;
    ok = ok && agrees(bound_certified(p), catalogue::virtual_wall(1000, 5, T) + eta);
    proofs::BoundInstance inst = wall_instance(wall_text, rational(1000), rational(5), T);
    inst.eta = eta;
    check.certify("001.eq54", proofs::bound_equals(inst, catalogue::virtual_wall(1000, 5, T) + eta));
  }
  check.claim("001.eq54", "(54)", "operator shortage eta adds to the bound -- at eta in {0, 1/10, 7} on the wall K = 1000, B = 5, T = 1/1000", Status::certified, ok, "eta in {0, 1/10, 7}", {etas});
}

}  // namespace

HAPSTAB_PROOF(passivity_closed_forms_vs_generic, "001", "Every closed form of Secs. VI-VII equals the certified generic bound") {
  const rational T(1, 1000);
  std::mt19937 rng(46);  // one stream: (46)'s random combinations draw first, then the FIRs
  backward_difference_forms(check, T, rng);
  fir_iir_tustin_forms(check, T, rng);
}

HAPSTAB_PROOF(passivity_dirichlet, "001", "Dirichlet kernel case (50): C, D and b ~ (CN - D)T") {
  auto C = catalogue::dirichlet_C(60);
  auto D = catalogue::dirichlet_D(60);
  bool okc = parse_rational("0.2172336282") - rational(1, 20000000000LL) < C.lo &&
             C.hi < parse_rational("0.2172336282") + rational(1, 20000000000LL) &&
             parse_rational("0.3913831859") - rational(1, 20000000000LL) < D.lo &&
             D.hi < parse_rational("0.3913831859") + rational(1, 20000000000LL);
  check.no_certificate("001.dirichlet.C", "a constant of (50), not a verdict a command prints: the root of tan y = y is isolated here to 1e-60 (no certificate kind holds a constant)");
  check.claim("001.dirichlet.C", "(50)", "C = -min sin(y)/y = 0.2172336282..., D = (1 - C)/2 = 0.3913831859...",
              Status::certified, okc,
              "C in [" + decimal_outward(C.lo, 25, -1) + ", " + decimal_outward(C.hi, 25, +1) + "] (root of tan y = y in (pi, 3pi/2), width < 1e-60)");
  // b*_N / T - (C N - D) for growing N: the generic certified bound of (z-1) sum_0^N z^-k
  const rational T(1, 1000);
  std::ostringstream ev;
  std::vector<double> err;
  for (int N : {5, 10, 20, 40, 80}) {
    RF H(rational(0));
    for (int k = 0; k <= N; ++k) H += zpow(-k);
    H = H * RF(P(std::vector<rational>{rational(-1), rational(1)}));
    BoundProblem p = prob(H, T);
    p.allow_noncausal = true;
    Bound b = bound_certified(p, 20);
    double e = std::abs(to_real<double>(b.value / T - (C.lo * N - D.lo)));
    err.push_back(e);
    ev << "N=" << N << ": |b*/T - (CN - D)| = " << e << "; ";
  }
  bool ok = true;
  for (size_t i = 1; i < err.size(); ++i) ok = ok && err[i] < err[i - 1];
  ok = ok && err.back() < err.front() / 4;
  check.claim("001.dirichlet.approx", "(50)",
              "the error of b ~ (CN - D)T decreases with N and falls below a quarter of its N = 5 value by N = 80 "
              "(N = 5, 10, 20, 40, 80)",
              Status::numeric, ok, ev.str() + " (double differences of the midpoints)");
}
