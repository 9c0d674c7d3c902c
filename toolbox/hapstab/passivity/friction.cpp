// The Coulomb-friction condition of a quantized FIR wall (see friction.hpp, docs/friction.md).
#include "hapstab/passivity/friction.hpp"

#include "hapstab/numeric/error.hpp"

namespace hapstab::passivity {

namespace {

constexpr int max_witness_taps = 8;  // L <= 7: periods up to 16, 2^15 sequences each

int sign_of(const rational& x) { return x > 0 ? 1 : x < 0 ? -1 : 0; }

// Does the periodic sequence s satisfy the witness condition at every switch (and switch once)?
bool is_witness(const std::vector<int>& s, const std::vector<rational>& taps) {
  const int P = int(s.size());
  bool switched = false;
  for (int j = 0; j < P; ++j) {
    if (s[size_t((j + 1) % P)] == s[size_t(j)]) continue;
    switched = true;
    for (int k = 0; k < int(taps.size()); ++k) {
      const int sg = sign_of(taps[size_t(k)]);
      if (sg != 0 && s[size_t(((j - k) % P + P) % P)] != sg * s[size_t(j)]) return false;
    }
  }
  return switched;
}

}  // namespace

std::optional<std::vector<rational>> fir_taps(const RationalFunction<rational>& H, int delay) {
  if (delay < 0) throw InputError("friction condition: delay must be >= 0");
  const Polynomial<rational>& den = H.den();  // monic, reduced
  if (den.nonzero_terms() != 1) return std::nullopt;
  const int m = den.degree();
  const Polynomial<rational>& num = H.num();
  if (num.degree() > m + delay)
    throw InputError("friction condition: H z^-n is not causal (numerator degree " + std::to_string(num.degree()) +
                     " > " + std::to_string(m + delay) + ")");
  // H z^{-n} = sum_i num_i z^{i - m - n}: tap k = m + n - i.
  std::vector<rational> taps(size_t(m + delay) + 1, rational(0));
  for (int i = 0; i <= num.degree(); ++i) taps[size_t(m + delay - i)] = num.coeff(i);
  while (taps.size() > 1 && taps.back() == 0) taps.pop_back();
  return taps;
}

std::vector<int> sign_witness(const std::vector<rational>& taps) {
  const int L = int(taps.size()) - 1;
  if (L + 1 > max_witness_taps) return {};
  for (int P = 2; P <= 2 * (L + 1); ++P) {
    for (unsigned bits = 0; bits < (1u << (P - 1)); ++bits) {  // s_0 = +1 (the sign flip of a witness is one)
      std::vector<int> s(size_t(P), 1);
      for (int i = 1; i < P; ++i) s[size_t(i)] = (bits >> (i - 1)) & 1u ? -1 : 1;
      if (is_witness(s, taps)) return s;
    }
  }
  return {};
}

FrictionCondition friction_condition(const RationalFunction<rational>& H, int delay, const rational& quantum,
                                     bool fractional_delay) {
  if (quantum <= 0) throw InputError("--quantum must be > 0 (got " + quantum.str() + ")");
  const auto taps = fir_taps(H, delay);
  if (!taps)
    throw InputError("the friction condition is derived for FIR walls only (denominator a power of z); this H(z) has "
                     "poles away from z = 0");
  FrictionCondition c;
  c.taps = *taps;
  for (const rational& w : c.taps) c.l1 += w < 0 ? rational(-w) : w;
  c.fc_star = quantum * c.l1 / 2;
  if (c.l1 == 0) {
    c.tight = true;
    c.why = "W = 0: no quantized force, f_c* = 0";
    return c;
  }
  if (fractional_delay) {
    c.why = "fractional delay: f_c* is sufficient; necessity not derived";
    return c;
  }
  c.witness = sign_witness(c.taps);
  c.tight = !c.witness.empty();
  c.why = c.tight ? "necessary and sufficient: a sign witness of period " + std::to_string(c.witness.size()) +
                        " realises (Delta/2) sum |w_k| per unit of travel"
          : int(c.taps.size()) > max_witness_taps
              ? "sufficient only: more than " + std::to_string(max_witness_taps) + " taps (witness not searched)"
              : "sufficient only: no sign witness of period <= " + std::to_string(2 * c.taps.size());
  return c;
}

}  // namespace hapstab::passivity
