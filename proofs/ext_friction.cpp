// proofs/ext_friction.cpp -- beyond the papers: the Coulomb-friction condition of a quantized
// sampled wall (Abbott and Okamura 2005, extended to FIR walls with delay; docs/friction.md).
//
// Checked here, in exact rational arithmetic: the closed forms the library returns (spring,
// delayed spring-damper), the energy identity the sufficiency proof rests on and its bound on
// random motions, and the necessity construction: the witness motion extracts a fixed, exactly
// computed energy per period when f_c < f_c*, and none when f_c = f_c* + its O(eps) margin.
#include <random>
#include <sstream>

#include "hapstab/numeric/decimal.hpp"
#include "hapstab/passivity/bound.hpp"
#include "hapstab/passivity/friction.hpp"
#include "proofs/proof.hpp"

namespace {

using namespace hapstab;
using namespace hapstab::passivity;
using P = Polynomial<rational>;
using RF = RationalFunction<rational>;

// K + B (z - 1)/(T z) = ((K + B/T) z - B/T)/z
RF spring_damper(const rational& K, const rational& B, const rational& T) {
  return RF(P(std::vector<rational>{-B / T, K + B / T}), P::monomial(1));
}

rational floor_q(const rational& x) {
  integer n = bmp::numerator(x), d = bmp::denominator(x);
  integer q = n / d;
  if (n % d != 0 && n < 0) q -= 1;
  return rational(q);
}
// the round (half up) quantizer of step D
rational round_q(const rational& x, const rational& D) { return D * floor_q(x / D + rational(1, 2)); }
rational abs_r(const rational& x) { return x < 0 ? rational(-x) : x; }

// Energy the human puts in over one period of a periodic sampled motion x_j (j mod P), moving at
// constant velocity within each period: sum_j u_j dx_j + b dx_j^2/T + f_c |dx_j| with the wall
// force u_j = sum_k w_k q(x_{j-k}) (the kinetic energy returns to its value after a period).
rational human_work_per_period(const std::vector<rational>& x, const std::vector<rational>& w, const rational& D,
                               const rational& T, const rational& b, const rational& fc) {
  const long Pn = long(x.size());
  rational E = 0;
  for (long j = 0; j < Pn; ++j) {
    rational u = 0;
    for (long k = 0; k < long(w.size()); ++k) u += w[size_t(k)] * round_q(x[size_t(((j - k) % Pn + Pn) % Pn)], D);
    const rational dx = x[size_t((j + 1) % Pn)] - x[size_t(j)];
    E += u * dx + b * dx * dx / T + fc * abs_r(dx);
  }
  return E;
}

}  // namespace

HAPSTAB_PROOF(ext_friction_closed_forms, "ext", "Friction condition: Abbott-Okamura's K Delta/2 and the delayed spring-damper") {
  int cases = 0;
  bool ok = true;
  std::string bad;
  // Instances (proof.hpp): every enumerated case is an exact equality, non-trivial; (K, B) = (0, 0)
  // is skipped for the spring-damper
  proofs::Instances springs{"(K, Delta, T) cases", 24}, walls{"(n, K, B) cases with (K, B) != (0, 0)", 77};
  for (int K : {1, 50, 1000, 20000})
    for (const rational& D : {rational(1, 1000), rational(1, 4096), rational(3, 7)})
      for (const rational& T : {rational(1, 1000), rational(1, 250)}) {
        BoundProblem p;
        p.H = RF(P(rational(K)));
        p.T = T;
        const Bound b = bound(p, Method::certified, 20);
        const FrictionCondition c = friction_condition(p.H, 0, D);
        const bool good = b.status == Status::exact && b.value == rational(K) * T / 2 && c.fc_star == rational(K) * D / 2 &&
                          c.tight;
        ok = ok && good;
        if (!good && bad.empty()) bad = "K = " + std::to_string(K) + ", Delta = " + D.str();
        springs.count(true);
        ++cases;
      }
  check.claim("ext.friction.abbott_okamura", "A&O 2005", "spring K: b* = KT/2 and f_c* = K Delta/2, both exact; f_c* tight (witness found) -- at K in {1, 50, "
              "1000, 20000}, Delta in {1/1000, 1/4096, 3/7}, T in {1/1000, 1/250}",
              Status::exact, ok, std::to_string(cases) + " (K, Delta, T) cases" + (bad.empty() ? "" : "; first failure " + bad),
              {springs});
  cases = 0;
  ok = true;
  for (int n = 0; n <= 6; ++n)
    for (int K : {0, 1000, 20000})
      for (int B : {0, 1, 5, 40}) {
        if (!walls.count(K != 0 || B != 0)) continue;
        const rational T(1, 1000), D(1, 2048);
        const FrictionCondition c = friction_condition(spring_damper(rational(K), rational(B), T), n, D);
        ok = ok && c.fc_star == D * (rational(K) / 2 + rational(B) / T) && c.tight;
        ++cases;
      }
  check.claim("ext.friction.spring_damper", "extension", "K + B(z-1)/(Tz) with delay n: f_c* = Delta (K/2 + B/T), independent of n, tight -- at n = 0..6, K in "
              "{0, 1000, 20000}, B in {0, 1, 5, 40}",
              Status::exact, ok, std::to_string(cases) + " cases, n = 0..6, K in {0, 1000, 20000}, B in {0, 1, 5, 40}",
              {walls});
}

HAPSTAB_PROOF(ext_friction_sufficiency, "ext", "Friction condition: the energy split behind sufficiency, on random motions") {
  // sum_j u_j dx_j = sum_j ulin_j dx_j - sum_j (sum_k w_k e_{j-k}) dx_j exactly, and the
  // quantization part is at most (Delta/2) sum|w_k| sum|dx_j| (|e| <= Delta/2, round quantizer).
  std::mt19937 rng(19);
  std::uniform_int_distribution<int> tap(-50, 50), pos(-4000, 4000), len(1, 6);
  int cases = 0;
  bool ok = true;
  rational worst_ratio = 0;
  // non-trivial (proof.hpp): a motion that travels, a wall with a tap, and a non-zero
  // quantization part -- else both sides of the bound are 0
  proofs::Instances moving{"motions with travel > 0, sum|w_k| > 0 and a non-zero quantization part", 250};
  for (int c = 0; c < 300; ++c) {
    std::vector<rational> w(size_t(len(rng)));
    for (auto& x : w) x = rational(tap(rng));
    const rational D(1, 1 + c % 17);
    std::vector<rational> x(40);
    for (auto& v : x) v = rational(pos(rng), 997);
    rational quant = 0, lin = 0, full = 0, travel = 0, l1 = 0;
    for (const auto& t : w) l1 += abs_r(t);
    for (size_t j = w.size(); j + 1 < x.size(); ++j) {
      rational u = 0, ul = 0, ue = 0;
      for (size_t k = 0; k < w.size(); ++k) {
        u += w[k] * round_q(x[j - k], D);
        ul += w[k] * x[j - k];
        ue += w[k] * (x[j - k] - round_q(x[j - k], D));
      }
      const rational dx = x[j + 1] - x[j];
      full += u * dx;
      lin += ul * dx;
      quant += ue * dx;
      travel += abs_r(dx);
    }
    moving.count(l1 * travel > 0 && quant != 0);
    ok = ok && full == lin - quant && abs_r(quant) <= D / 2 * l1 * travel;
    if (l1 * travel > 0) worst_ratio = std::max(worst_ratio, abs_r(quant) / (D / 2 * l1 * travel));
    ++cases;
  }
  check.claim("ext.friction.energy_split", "sufficiency", "wall work = linear part - quantization part, |quantization part| <= (Delta/2) sum|w_k| sum|dx_j|",
              Status::exact, ok, std::to_string(cases) + " random FIR walls and motions; largest ratio to the bound " +
                                     to_decimal(worst_ratio, 6),
              {moving});
}

HAPSTAB_PROOF(ext_friction_necessity, "ext", "Friction condition: the witness motion extracts energy when f_c < f_c*") {
  // The spring-damper K + B(z-1)/(Tz) with delay n: positions x_j = c - s_j eps around the
  // quantizer's switching point c = (i + 1/2) Delta, s the library's witness. Per period of the
  // witness the human's work is exactly  switches * [2 eps (f_c - f_c*) + 4 eps^2 b/T]  (the
  // linear part gives -2 eps^2 l1 per switch, the quantization part -2 eps l1 (Delta/2 - eps)):
  // negative for f_c < f_c* once eps < T (f_c* - f_c)/(2 b), so repeating it extracts unbounded energy.
  const rational T(1, 1000), D(1, 1000), K(1000), B(2);
  bool ok = true;
  int cases = 0;
  std::ostringstream ev;
  // non-trivial (proof.hpp): a witness that switches (a constant one does no work)
  proofs::Instances switching{"(n, b) cases whose witness switches", 15};
  for (int n = 0; n <= 4; ++n) {
    const FrictionCondition c = friction_condition(spring_damper(K, B, T), n, D);
    const rational eps = D / 100000, mid = D * 7 + D / 2;
    std::vector<rational> x;
    for (int s : c.witness) x.push_back(mid - rational(s) * eps);
    int switches = 0;
    for (size_t j = 0; j < c.witness.size(); ++j) switches += c.witness[j] != c.witness[(j + 1) % c.witness.size()];
    for (const rational& b : {rational(0), rational(10), rational(1000)}) {
      const rational below = human_work_per_period(x, c.taps, D, T, b, c.fc_star * 99 / 100);
      const rational above = human_work_per_period(x, c.taps, D, T, b, c.fc_star * 101 / 100);
      const rational predicted = switches * (2 * eps * (c.fc_star * 99 / 100 - c.fc_star) + 4 * eps * eps * b / T);
      switching.count(c.tight && switches > 0);
      ok = ok && below == predicted && below < 0 && above > 0;
      if (b == 10) ev << (n ? ", " : "") << "n = " << n << ": " << to_decimal(below, 4) << " J/period";
      ++cases;
    }
  }
  check.claim("ext.friction.witness_extracts", "necessity", "K + B(z-1)/(Tz), delay n = 0..4: the witness motion's work per period is exactly switches [2 eps (f_c - f_c*) + 4 eps^2 b/T]: energy extracted at f_c = 0.99 f_c*, none at 1.01 f_c*",
              Status::exact, ok, std::to_string(cases) + " (n, b) cases, eps = Delta/1e5; work per period at b = 10: " + ev.str(),
              {switching});
}
