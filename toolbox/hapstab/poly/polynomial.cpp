// Explicit instantiations of the exact (rational) polynomial algebra, and to_string.
#include "hapstab/poly/polynomial.hpp"

#include "hapstab/poly/rational_function.hpp"

#include <cstdint>

namespace hapstab {

template class Polynomial<rational>;
template std::pair<Polynomial<rational>, Polynomial<rational>> divmod(const Polynomial<rational>&,
                                                                      const Polynomial<rational>&);
template class RationalFunction<rational>;

namespace {

using u64 = std::uint64_t;

// arithmetic modulo a prime p < 2^31: products fit in 64 bits (no 128-bit division)
u64 mulmod(u64 a, u64 b, u64 p) { return a * b % p; }
u64 invmod(u64 a, u64 p) {  // extended Euclid; a != 0 mod p
  std::int64_t r0 = static_cast<std::int64_t>(p), r1 = static_cast<std::int64_t>(a), s0 = 0, s1 = 1;
  while (r1 != 0) {
    const std::int64_t qt = r0 / r1;
    std::swap(r0, r1);
    r1 -= qt * r0;
    std::swap(s0, s1);
    s1 -= qt * s0;
  }
  return static_cast<u64>(s0 < 0 ? s0 + static_cast<std::int64_t>(p) : s0);
}
u64 mod_p(const integer& z, u64 p) { return mpz_fdiv_ui(z.backend().data(), p); }  // in [0, p), z < 0 too

// a mod p as a dense vector (ascending), scaled by the (nonzero mod p) lcm of the denominators;
// false if p divides a denominator or the leading numerator (the degree would drop).
bool reduce(const Polynomial<rational>& a, u64 p, std::vector<u64>& out) {
  out.clear();
  for (const auto& c : a.coeffs()) {
    const u64 d = mod_p(den(c), p);
    if (d == 0) return false;
    out.push_back(mulmod(mod_p(num(c), p), invmod(d, p), p));
  }
  return out.back() != 0;
}

// degree of gcd(a, b) over Z/p (a, b nonzero with their true degrees)
int gcd_degree_mod(std::vector<u64> a, std::vector<u64> b, u64 p) {
  if (a.size() < b.size()) std::swap(a, b);
  while (!b.empty()) {
    const u64 inv = invmod(b.back(), p);
    const size_t db = b.size() - 1;
    while (a.size() >= b.size()) {
      const u64 f = mulmod(a.back(), inv, p);
      const size_t shift = a.size() - b.size();
      for (size_t i = 0; i < db; ++i) a[shift + i] = (a[shift + i] + p - mulmod(f, b[i], p)) % p;
      a.pop_back();
      while (!a.empty() && a.back() == 0) a.pop_back();
    }
    std::swap(a, b);
  }
  return static_cast<int>(a.size()) - 1;
}

}  // namespace

bool coprime_modular(const Polynomial<rational>& a, const Polynomial<rational>& b) {
  if (a.is_zero() || b.is_zero()) return false;
  if (a.degree() == 0 || b.degree() == 0) return true;
  // primes just below 2^31; a prime dividing a leading numerator or a denominator is skipped
  static const u64 primes[] = {2147483647ULL, 2147483629ULL, 2147483587ULL, 2147483579ULL, 2147483563ULL};
  std::vector<u64> ra, rb;
  for (u64 p : primes)
    if (reduce(a, p, ra) && reduce(b, p, rb)) return gcd_degree_mod(ra, rb, p) == 0;
  return false;
}

template <>
Polynomial<rational> gcd(Polynomial<rational> a, Polynomial<rational> b) {
  if (coprime_modular(a, b)) return Polynomial<rational>(rational(1));
  return detail::euclid_gcd(std::move(a), std::move(b));
}

std::string to_string(const Polynomial<rational>& p, const std::string& var) {
  if (p.is_zero()) return "0";
  std::string out;
  for (int k = p.degree(); k >= 0; --k) {
    const rational& c = p.coeffs()[k];
    if (c == 0) continue;
    const bool neg = c < 0;
    const rational a = neg ? rational(-c) : c;
    if (out.empty()) out += neg ? "-" : "";
    else out += neg ? " - " : " + ";
    if (k == 0) {
      out += a.str();
    } else {
      if (a != 1) out += a.str() + "*";
      out += var;
      if (k > 1) out += "^" + std::to_string(k);
    }
  }
  return out;
}

}  // namespace hapstab
