// Paper 001, (34), (9), (42)-(44): certified enclosures of the INFINITE series (34) (interval partial
// sum + Euler-Maclaurin remainder enclosure) contain the closed form (44) at many (T, w); rhat of
// (9) is certified positive there; the triangle (43) samples c(kT) = T [k = 1] exactly; the starred
// transform of C(s) = ((1 - e^{-sT})/s)^2 is certified to contain k(s) = T e^{-sT} at sample points.
#include <sstream>

#include "hapstab/numeric/decimal.hpp"
#include "hapstab/sampling/starred.hpp"
#include "proofs/proof.hpp"

namespace {
using namespace hapstab;
using namespace hapstab::sampling;
using I = interval<60>;

bool overlaps(const I& a, const I& b) { return !(certainly_greater(a, b) || certainly_greater(b, a)); }
rational lo(const I& x) { return exact_rational(mpfloat<60>(lower(x))); }
rational hi(const I& x) { return exact_rational(mpfloat<60>(upper(x))); }
}  // namespace

HAPSTAB_PROOF(sampling_series_certified, "001", "Certified enclosures of the infinite series (34) contain (44)") {
  const std::vector<rational> Ts{rational(1, 1000), rational(1, 100), rational(1, 3), rational(2)};
  int count = 0, re_in = 0, im_in = 0, rhat_pos = 0;
  double worst_width = 0;
  // non-trivial (proof.hpp): a containment or overlap is exercised only by a narrow enclosure;
  // a point counts when both the Re and the Im enclosure are narrower than 1e-30 relative
  proofs::Instances narrow{"points with Re and Im enclosed within 1e-30 relative", 368},
      points{"points (a positive lower end cannot hold trivially)", 368};
  for (const rational& T : Ts) {
    // w from 1e-6/T to ~ pi/T (and a few beyond, and negative): theta = w T in (0, 3.5]
    for (int i = 0; i <= 45; ++i) {
      rational theta = rational(1, 1000000) * rational(integer(1) << (i / 2)) * (i % 2 ? rational(3, 2) : rational(1));
      if (theta > rational(7, 2)) theta = rational(7, 2) - rational(1, i + 1);
      for (rational th : {theta, rational(-theta)}) {
        ++count;
        const auto e = r_series_certified<60>(T, th, 20, 40);
        // (44): re = -T/2 exactly, im = -(T/2) cot(theta/2) enclosed by MPFI
        const rational re44 = -T / 2;
        if (lo(e.re) <= re44 && re44 <= hi(e.re)) ++re_in;
        I half = scalar_cast<I>(th / 2), cot;
        mpfi_cot(cot.backend().data(), half.backend().data());
        const I im44 = -scalar_cast<I>(T / 2) * cot;
        if (overlaps(e.im, im44)) ++im_in;
        if (lo(e.rhat) > 0) ++rhat_pos;
        const double w = static_cast<double>(mpfloat<60>((upper(e.im) - lower(e.im)) / abs(im44)));
        worst_width = std::max(worst_width, w);
        const double wr = static_cast<double>(mpfloat<60>((upper(e.re) - lower(e.re)) / (T / 2)));
        narrow.count(w < 1e-30 && wr < 1e-30);
        points.count(true);
      }
    }
  }
  std::ostringstream ev;
  ev << count << " (T, w) points, T in {1/1000, 1/100, 1/3, 2}, wT in [-3.5, -1e-6] u [1e-6, 3.5]: -T/2 inside "
     << re_in << ", (44) Im enclosure overlaps " << im_in << "; N = 20 terms + Euler-Maclaurin K = 40 remainder "
     << "enclosure; worst relative width of Im " << worst_width;
  check.no_certificate("001.eq34.certified_contains_eq44", "the r kind certifies r(jw) from the closed form (44); this claim is about the series (34)'s own enclosure, which no command prints");
  check.claim("001.eq34.certified_contains_eq44", "(34) = (44)",
              "the infinite series (34), enclosed rigorously (interval partial sum + Euler-Maclaurin remainder), "
              "contains the closed form (44)",
              hapstab::Status::certified, re_in == count && im_in == count && worst_width < 1e-30, ev.str(), {narrow});
  check.no_certificate("001.eq9.rhat_positive_certified", "a property of the series (9)'s enclosure at every point, which no command prints: no certificate kind holds it");
  check.claim("001.eq9.rhat_positive_certified", "(9), Theorem 1",
              "the enclosure of rhat = sum_n 1/(wT + 2 n pi)^2 is strictly positive at every point",
              hapstab::Status::certified, rhat_pos == count,
              std::to_string(rhat_pos) + " of " + std::to_string(count) + " enclosures have a positive lower end",
              {points});

  // integral tail bound: the truncated series error lies within the bound (certified, 60 digits)
  int tb_ok = 0, tb_n = 0;
  // non-trivial: tau_N enclosed narrower than the gap between its two bounds (a wider enclosure
  // would overlap them whatever tau_N is)
  proofs::Instances resolved{"cases with tau_N enclosed narrower than the gap between its bounds", 12};
  for (long N : {1L, 10L, 100L, 1000L}) {
    for (rational th : {rational(1, 1000), rational(1), rational(3)}) {
      ++tb_n;
      const I t = scalar_cast<I>(th);
      const I tau = rhat_closed(t) - rhat_partial(t, N);
      resolved.count(certainly_greater(rhat_tail_upper(t, N) - rhat_tail_lower(t, N), scalar_cast<I>(upper(tau) - lower(tau))));
      if (!certainly_greater(rhat_tail_lower(t, N), tau) && !certainly_greater(tau, rhat_tail_upper(t, N))) ++tb_ok;
    }
  }
  check.no_certificate("001.eq34.tail_bound", "an inequality for every N and wT (the series' tail), proven here, not a verdict a command prints");
  check.claim("001.eq34.tail_bound", "(34), (9)",
              "tail of the truncated series: 1/(2pi(2pi(N+1)+wT)) + 1/(2pi(2pi(N+1)-wT)) <= tau_N <= "
              "1/(2pi(2pi N+wT)) + 1/(2pi(2pi N-wT))",
              hapstab::Status::certified, tb_ok == tb_n,
              std::to_string(tb_ok) + " of " + std::to_string(tb_n) +
                  " cases (N = 1..1000, wT = 1e-3, 1, 3) consistent with tau_N = 1/(4 sin^2(wT/2)) - rhat_N",
              {resolved});
}

HAPSTAB_PROOF(sampling_triangle_k, "001", "The triangle (43): c(kT) = T [k = 1], and C*(s) = T e^{-sT} (42)-(44)") {
  // exact samples of (43) for several T
  bool samples = true;
  // every sample is compared exactly with its value, so each is non-trivial (proof.hpp); the
  // k = 1 samples are the ones where c is not 0
  proofs::Instances peaks{"samples at k = 1 (c = T)", 3}, zeros{"samples at k != 1 (c = 0)", 159};
  for (rational T : {rational(1, 1000), rational(7, 3), rational(1)}) {
    for (int k = -3; k <= 50; ++k) {
      (k == 1 ? peaks : zeros).count(true);
      samples = samples && triangle_c(rational(k) * T, T) == (k == 1 ? T : rational(0));
    }
    // continuity at the break points, and the peak
    samples = samples && triangle_c(T, T) == T && triangle_c(2 * T, T) == 0 && triangle_c(T / 2, T) == T / 2 &&
              triangle_c(3 * T / 2, T) == T / 2;
  }
  check.claim("001.eq43.triangle_samples", "(43)", "c(kT) = T for k = 1 and 0 for every other integer k -- at k = -3..50, T in {1/1000, 7/3, 1}",
              hapstab::Status::exact, samples, "k = -3..50 at T = 1/1000, 7/3, 1 (exact rationals)", {peaks, zeros});

  // Certified C*(s) = (1/T) sum_n C(s + j n w_s) vs T e^{-sT}, s = sigma + j w
  int pts = 0, ok = 0;
  double worst_rel = 0;
  // non-trivial (proof.hpp): an overlap is exercised only by a narrow enclosure; a point counts
  // when both enclosures are narrower than 1e-3 of |k(s)| (the tail disc of |n| > 2000 makes
  // them up to about 2e-4 wide)
  proofs::Instances narrow{"points with C*(s) enclosed within 1e-3 of |k(s)|", 24};
  for (rational T : {rational(1, 1000), rational(1, 10)}) {
    for (rational sigma : {rational(0), rational(1, 2) / T, rational(-1, 3) / T}) {
      for (rational wT : {rational(1, 1000), rational(1, 2), rational(3), rational(-2)}) {
        ++pts;
        auto [re, im] = starred_triangle_certified<50>(T, sigma, wT / T, 2000);
        using J = interval<50>;
        const J Tj = scalar_cast<J>(T);
        const auto k = k_closed(Tj, std::complex<J>(scalar_cast<J>(sigma), scalar_cast<J>(wT / T)));
        auto ov = [](const J& a, const J& b) { return !(certainly_greater(a, b) || certainly_greater(b, a)); };
        if (ov(re, k.real()) && ov(im, k.imag())) ++ok;
        const double mag = static_cast<double>(mpfloat<50>(upper(abs(k.real()) + abs(k.imag()))));
        const double rel = std::max(static_cast<double>(mpfloat<50>(upper(re) - lower(re))),
                                    static_cast<double>(mpfloat<50>(upper(im) - lower(im)))) / mag;
        worst_rel = std::max(worst_rel, rel);
        narrow.count(rel < 1e-3);
      }
    }
  }
  std::ostringstream widest;
  widest.precision(3);
  widest << worst_rel;
  check.no_certificate("001.eq42.starred_triangle_is_T_exp", "an identity of the starred transform (42), enclosed here, not a verdict a command prints");
  check.claim("001.eq42.starred_triangle_is_T_exp", "(42), (44)",
              "C*(s) = (1/T) sum_n C(s + j n w_s) with C = ((1 - e^{-sT})/s)^2 encloses k(s) = T e^{-sT}",
              hapstab::Status::certified, ok == pts,
              std::to_string(ok) + " of " + std::to_string(pts) +
                  " points s = sigma + j w (sigma in {0, 1/(2T), -1/(3T)}, wT in {1e-3, 1/2, 3, -2}): "
                  "|n| <= 2000 in intervals + tail disc (1/T)|1-e^{-sT}|^2 T^2 tau_N; widest enclosure " +
                  widest.str() + " of |k(s)|",
              {narrow});
}
