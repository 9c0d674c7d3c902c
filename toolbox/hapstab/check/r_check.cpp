// hapstab/check/r_check.cpp -- see r_check.hpp.
#include "hapstab/check/r_check.hpp"

#include <mpfi.h>

#include "hapstab/numeric/decimal.hpp"
#include "hapstab/numeric/error.hpp"

namespace hapstab::check {

namespace {

// -(T/2) cot(wT/2) enclosed at `bits`, compared with [lo, hi]: +1 inside, -1 outside, 0 straddles.
int compare_im(const rational& T, const rational& w, const rational& lo, const rational& hi, long bits) {
  mpfi_t x;
  mpfi_init2(x, bits);
  const rational half_x = w * T / 2, minus_half_T = -T / 2;
  mpfi_set_q(x, half_x.backend().data());
  mpfi_cot(x, x);
  mpfi_mul_q(x, x, minus_half_T.backend().data());
  mpfr_t a, b;
  mpfr_init2(a, bits);
  mpfr_init2(b, bits);
  mpfi_get_left(a, x);
  mpfi_get_right(b, x);
  int out = 0;
  if (mpfr_nan_p(a) || mpfr_nan_p(b) || mpfr_inf_p(a) || mpfr_inf_p(b)) {
    out = 0;
  } else {
    // exact comparisons of the endpoints with the rationals
    const bool inside = mpfr_cmp_q(a, lo.backend().data()) >= 0 && mpfr_cmp_q(b, hi.backend().data()) <= 0;
    const bool outside = mpfr_cmp_q(b, lo.backend().data()) < 0 || mpfr_cmp_q(a, hi.backend().data()) > 0;
    out = inside ? 1 : outside ? -1 : 0;
  }
  mpfr_clear(a);
  mpfr_clear(b);
  mpfi_clear(x);
  return out;
}

}  // namespace

Verdict check_r(const nlohmann::json& cert) {
  using detail::exact_field;
  using detail::object_field;
  detail::only_fields(cert, {"certificate", "version", "kind", "model", "claim", "evidence", "produced_by"}, "certificate");
  const nlohmann::json& model = object_field(cert, "model", "certificate");
  const nlohmann::json& claim = object_field(cert, "claim", "certificate");
  detail::only_fields(model, {"T", "omega"}, "model");
  detail::only_fields(claim, {"quantity", "re", "im_lo", "im_hi", "printed_im"}, "claim");
  if (cert.contains("evidence")) detail::only_fields(object_field(cert, "evidence", "certificate"), {}, "evidence");
  const rational T = exact_field(model, "T", "model"), w = exact_field(model, "omega", "model");
  if (T <= 0) throw InputError("model.T: the sample period must be > 0, got " + T.str());
  if (w == 0) throw InputError("model.omega: w = 0 is a pole of r(jw)");
  const rational re = exact_field(claim, "re", "claim");
  const rational lo = exact_field(claim, "im_lo", "claim"), hi = exact_field(claim, "im_hi", "claim");
  if (re != -T / 2) return {false, "claim.re = " + re.str() + " is not -T/2 = " + rational(-T / 2).str()};
  if (lo > hi) return {false, "claim: im_lo = " + lo.str() + " > im_hi = " + hi.str()};
  if (claim.contains("printed_im")) {  // the printed decimal lies in the claimed enclosure
    const auto& v = claim.at("printed_im");
    if (!v.is_string()) throw InputError("claim.printed_im: not a string");
    const auto q = try_parse_rational(v.get<std::string>());
    if (!q) throw InputError("claim.printed_im: '" + v.get<std::string>() + "' is not a number");
    if (*q < lo || *q > hi) return {false, "claim.printed_im = " + v.get<std::string>() + " is outside [im_lo, im_hi]"};
  }
  for (long bits = 128; bits <= 65536; bits *= 2) {
    const int c = compare_im(T, w, lo, hi, bits);
    if (c > 0)
      return {true, "Re r = -T/2 = " + re.str() + " (identity (44)), Im r = -(T/2) cot(wT/2) in [" + to_decimal(lo, 12) + ", " +
                        to_decimal(hi, 12) + "] (MPFI, " + std::to_string(bits) + " bits)"};
    if (c < 0)
      return {false, "Im r = -(T/2) cot(wT/2) is outside [im_lo, im_hi] = [" + to_decimal(lo, 20) + ", " +
                         to_decimal(hi, 20) + "] (MPFI enclosure at " + std::to_string(bits) + " bits)"};
  }
  return {false, "Im r in [im_lo, im_hi] not shown: the MPFI enclosure at 65536 bits still straddles an end"};
}

}  // namespace hapstab::check
