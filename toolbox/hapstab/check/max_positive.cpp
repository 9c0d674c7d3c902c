// hapstab/check/max_positive.cpp -- see max_positive.hpp.
#include "hapstab/check/max_positive.hpp"

#include <utility>
#include <vector>

#include "hapstab/check/nonnegative.hpp"
#include "hapstab/numeric/decimal.hpp"

namespace hapstab::check {

namespace {

using P = Polynomial<rational>;

P squarefree(const P& p) {
  if (p.degree() < 1) return p;
  return divmod(p, gcd(p, p.derivative())).first;
}

bool has_root_in(const P& p, const rational& lo, const rational& hi) {  // p(lo), p(hi) != 0
  return !p.is_zero() && p.degree() >= 1 && sturm_count(squarefree(p), lo, hi) > 0;
}

std::string at(const rational& x) { return "c = " + x.str() + " (" + to_decimal(x, 12) + ")"; }

// The reason max(p1, p2) is not > 0 at the single root of R in (lo, hi), or nullopt.
std::optional<std::string> at_root(const P& p1, const P& p2, const rational& lo, const rational& hi) {
  const std::string where = "a root in (" + to_decimal(lo, 12) + ", " + to_decimal(hi, 12) + ")";
  if (p1.is_zero() || p2.is_zero()) return "max = 0 at " + where;  // the other is 0 there, this one <= 0 everywhere
  const P g = gcd(p1, p2);
  if (g.degree() >= 1 && has_root_in(g, lo, hi)) return "both are 0 at " + where;
  const bool first = has_root_in(p1, lo, hi);
  const P& other = first ? p2 : p1;
  if (other(lo) < 0) return "one is 0 and the other < 0 at " + where;
  return std::nullopt;
}

}  // namespace

std::optional<std::string> max_positive_on(const P& p1, const P& p2, const rational& a, const rational& b, bool strict) {
  auto fails = [&](const rational& x) -> std::optional<std::string> {
    if (strict ? (p1(x) > 0 || p2(x) > 0) : (p1(x) >= 0 || p2(x) >= 0)) return std::nullopt;
    return (strict ? "not > 0 at " : "< 0 at ") + at(x);
  };
  for (const rational& x : {a, b})
    if (auto why = fails(x)) return why;
  if (!strict && (p1.is_zero() || p2.is_zero())) return std::nullopt;  // max(0, p) >= 0
  P R = squarefree(p1.is_zero() ? p2 : p2.is_zero() ? p1 : p1 * p2);
  if (R.is_zero() || R.degree() < 1) {  // no root: one sign on [a, b], tested at a (and inside it)
    if (!strict)
      if (auto why = fails((a + b) / 2)) return why;
    return std::nullopt;
  }
  for (const rational& e : {a, b})  // roots at the ends were tested above
    while (R.degree() >= 1 && R(e) == 0) R = divmod(R, P{-e, rational(1)}).first;
  const std::vector<P> seq = sturm_sequence(R);  // R is fixed: one sequence for every piece of the bisection
  std::vector<std::pair<rational, rational>> todo{{a, b}};
  while (!todo.empty()) {
    const auto [lo, hi] = todo.back();
    todo.pop_back();
    for (const rational& x : {lo, hi})
      if (auto why = fails(x)) return why;
    const int n = R.degree() >= 1 ? sturm_count(seq, lo, hi) : 0;
    // non-strict: an end that is a root of p1 p2 (a or b) passes by itself and stands for no cell,
    // so a cell is sampled inside it: at the midpoint of a piece without roots, at lo and hi of a
    // piece with one root only when neither is a root of p1 p2 (else the piece is split)
    const bool ends_are_samples = p1(lo) * p2(lo) != 0 && p1(hi) * p2(hi) != 0;
    if (n == 0) {
      if (!strict)
        if (auto why = fails((lo + hi) / 2)) return why;
      continue;
    }
    if (n == 1 && !strict && ends_are_samples) continue;  // at the root one of them is 0: the max is >= 0 there
    if (n == 1 && strict) {
      if (auto why = at_root(p1, p2, lo, hi)) return why;
      continue;
    }
    rational mid = (lo + hi) / 2;
    while (R(mid) == 0) {  // an exact rational root: tested itself, the split moved off it
      if (auto why = fails(mid)) return why;
      mid = (mid + hi) / 2;
    }
    todo.emplace_back(lo, mid);
    todo.emplace_back(mid, hi);
  }
  return std::nullopt;
}

}  // namespace hapstab::check
