#include "hapstab/multidof/assumptions.hpp"

#include <algorithm>
#include <numeric>
#include <sstream>

#include "hapstab/lmi/certificate.hpp"
#include "hapstab/multidof/analysis.hpp"
#include "hapstab/multidof/environment.hpp"
#include "hapstab/numeric/error.hpp"
#include "hapstab/poly/sturm.hpp"

namespace hapstab::multidof {

namespace {
using P = QPoly;
struct CP {  // complex polynomial in real w: re + j im
  P re, im;
};
CP operator+(const CP& a, const CP& b) { return {a.re + b.re, a.im + b.im}; }
CP operator-(const CP& a, const CP& b) { return {a.re - b.re, a.im - b.im}; }
CP operator*(const CP& a, const CP& b) { return {a.re * b.re - a.im * b.im, a.re * b.im + a.im * b.re}; }
CP conj(const CP& a) { return {a.re, -a.im}; }
CP real(const P& p) { return {p, P()}; }

// p(jw) for a real polynomial p(s)
CP at_jw(const P& p) {
  std::vector<rational> re(static_cast<size_t>(std::max(p.degree() + 1, 0)), rational(0)), im = re;
  for (int k = 0; k <= p.degree(); ++k) {
    const rational a = p.coeff(k);
    switch (k % 4) {
      case 0: re[static_cast<size_t>(k)] = a; break;
      case 1: im[static_cast<size_t>(k)] = a; break;
      case 2: re[static_cast<size_t>(k)] = -a; break;
      default: im[static_cast<size_t>(k)] = -a; break;
    }
  }
  return {P(re), P(im)};
}

// determinant by Laplace expansion along the first row (n <= 4)
CP det(const std::vector<std::vector<CP>>& M) {
  const size_t n = M.size();
  if (n == 1) return M[0][0];
  CP r{P(), P()};
  for (size_t j = 0; j < n; ++j) {
    std::vector<std::vector<CP>> sub;
    for (size_t i = 1; i < n; ++i) {
      std::vector<CP> row;
      for (size_t c = 0; c < n; ++c)
        if (c != j) row.push_back(M[i][c]);
      sub.push_back(row);
    }
    const CP t = M[0][j] * det(sub);
    r = (j % 2 == 0) ? r + t : r - t;
  }
  return r;
}

// p(w) >= 0 for every real w (exact).
bool nonnegative_on_R(const P& p, rational& witness) {
  if (p.is_zero()) return true;
  if (p.degree() == 0) {
    witness = 0;
    return p.coeff(0) >= 0;
  }
  const auto roots = isolate_real_roots(p);
  std::vector<rational> pts;
  if (roots.empty()) pts.push_back(rational(0));
  else {
    pts.push_back(roots.front().lo - 1);
    for (size_t i = 0; i + 1 < roots.size(); ++i) pts.push_back((roots[i].hi + roots[i + 1].lo) / 2);
    pts.push_back(roots.back().hi + 1);
  }
  for (const auto& x : pts)
    if (p(x) < 0) {
      witness = x;
      return false;
    }
  return true;
}
}  // namespace

Verdict operator_passive(const TransferMatrix& H) {
  const size_t m = H.outputs();
  if (m == 0 || H.inputs() != m) throw InputError("operator H(s) must be square");
  if (H.domain != Domain::s) throw InputError("operator H must be continuous (a transfer matrix in s)");
  if (m > 4) throw InputError("operator passivity check supports up to 4 x 4 blocks (got " + std::to_string(m) + ")");
  P L(rational(1));
  std::vector<std::vector<CP>> num(m, std::vector<CP>(m));
  std::vector<std::vector<P>> den(m, std::vector<P>(m));
  for (size_t i = 0; i < m; ++i)
    for (size_t j = 0; j < m; ++j) {
      const auto& e = H(i, j);
      if (!e.is_proper()) throw InputError("operator H(s) entry (" + std::to_string(i + 1) + "," + std::to_string(j + 1) + ") is improper");
      if (!e.num().is_zero() && !hurwitz_stable(e.den())) {
        return {Outcome::undecided, Status::failed,
                "entry (" + std::to_string(i + 1) + "," + std::to_string(j + 1) + ") " + e.to_string() +
                    " has a pole in Re s >= 0 (exact Routh array): not certified passive (this test covers operators "
                    "analytic in Re s >= 0; a positive-real operator with imaginary-axis poles, e.g. a spring k/s, "
                    "is outside it, so no verdict either way)"};
      }
      const CP D = at_jw(e.den());
      num[i][j] = at_jw(e.num()) * conj(D);  // H = N conj(D) / |D|^2
      den[i][j] = D.re * D.re + D.im * D.im;
    }
  // common denominator: product of the distinct |D|^2 (positive on R: no imaginary-axis poles)
  std::vector<P> ds;
  for (size_t i = 0; i < m; ++i)
    for (size_t j = 0; j < m; ++j) {
      bool seen = false;
      for (const auto& d : ds) seen |= d == den[i][j];
      if (!seen) ds.push_back(den[i][j]);
    }
  for (const auto& d : ds) L = L * d;
  std::vector<std::vector<CP>> M(m, std::vector<CP>(m));
  for (size_t i = 0; i < m; ++i)
    for (size_t j = 0; j < m; ++j) {
      const P fij = divmod(L, den[i][j]).first, fji = divmod(L, den[j][i]).first;
      const CP a = num[i][j] * real(fij), b = conj(num[j][i]) * real(fji);
      M[i][j] = {(a.re + b.re) * rational(1, 2), (a.im + b.im) * rational(1, 2)};
    }
  // every principal minor >= 0 on R
  for (unsigned mask = 1; mask < (1u << m); ++mask) {
    std::vector<size_t> idx;
    for (size_t i = 0; i < m; ++i)
      if (mask & (1u << i)) idx.push_back(i);
    std::vector<std::vector<CP>> S;
    for (size_t a : idx) {
      std::vector<CP> row;
      for (size_t b : idx) row.push_back(M[a][b]);
      S.push_back(row);
    }
    const CP d = det(S);
    if (!d.im.is_zero()) throw NumericalError("operator passivity: a principal minor of a Hermitian matrix is not real");
    rational w;
    if (!nonnegative_on_R(d.re, w)) {
      std::string rows;
      for (size_t a : idx) rows += (rows.empty() ? "" : ",") + std::to_string(a + 1);
      return Verdict::of(false, Status::exact,
                         "the principal minor {" + rows + "} of He(jw) is negative at w = " + w.str() + ": not passive (exact)");
    }
  }
  return Verdict::of(true, Status::exact,
                     "every entry stable (exact Routh); all " + std::to_string((1u << m) - 1) +
                         " principal minors of He(jw) >= 0 for all real w (exact root isolation)");
}

std::vector<AssumptionCheck> check_assumptions(const Structure& structure, const std::vector<TransferMatrix>& operators,
                                               const std::vector<std::string>& operator_names) {
  std::vector<AssumptionCheck> out;
  for (size_t i = 0; i < operators.size(); ++i) {
    const std::string name = i < operator_names.size() ? operator_names[i] : "H" + std::to_string(i + 1);
    out.push_back({"Assumption 1(b): operator '" + name + "' passive (He(jw) >= 0 for all w)",
                   operator_passive(operators[i])});
  }
  for (const auto& op : structure.operators)
    for (const auto& d : op.devices) {
      std::ostringstream lv;
      lv << to_double(d.osp).format(Eigen::IOFormat(6, 0, ", ", "; ", "", "", "[", "]"));
      out.push_back({"Assumption 1(a): device '" + d.name + "' OSP level",
                     Verdict::of(lmi::exact_definiteness(d.osp).pd, Status::exact,
                                 "Delta_d = " + lv.str() + " (a mass-damper 1/(m s + b) has level b)")});
    }
  return out;
}

bool all_hold(const std::vector<AssumptionCheck>& checks) {
  return std::all_of(checks.begin(), checks.end(), [](const AssumptionCheck& c) { return c.verdict.holds(); });
}

}  // namespace hapstab::multidof
