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
CP scaled(const CP& a, const rational& c) { return {a.re * c, a.im * c}; }
using CMat = std::vector<std::vector<CP>>;

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

// p(-s)
P mirrored(const P& p) {
  std::vector<rational> c(p.coeffs().begin(), p.coeffs().end());
  for (size_t k = 1; k < c.size(); k += 2) c[k] = -c[k];
  return P(c);
}

// determinant by Laplace expansion along the first row (n <= 4)
CP det(const CMat& M) {
  const size_t n = M.size();
  if (n == 1) return M[0][0];
  CP r{P(), P()};
  for (size_t j = 0; j < n; ++j) {
    CMat sub;
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

// "1,3": 0-based rows as the messages name them (1-based).
std::string row_text(const std::vector<size_t>& rows) {
  std::string s;
  for (size_t a : rows) s += (s.empty() ? "" : ",") + std::to_string(a + 1);
  return s;
}

// Every principal minor of M (as polynomials in w), with the rows it keeps (0-based).
std::vector<std::pair<std::vector<size_t>, CP>> principal_minors(const CMat& M) {
  const size_t m = M.size();
  std::vector<std::pair<std::vector<size_t>, CP>> out;
  for (unsigned mask = 1; mask < (1u << m); ++mask) {
    std::vector<size_t> idx;
    for (size_t i = 0; i < m; ++i)
      if (mask & (1u << i)) idx.push_back(i);
    CMat S;
    for (size_t a : idx) {
      std::vector<CP> row;
      for (size_t b : idx) row.push_back(M[a][b]);
      S.push_back(row);
    }
    out.emplace_back(idx, det(S));
  }
  return out;
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

// A Hermitian polynomial matrix is PSD for all real w: nullopt, else the first failing minor and w.
std::optional<NegativeMinor> first_negative_minor(const CMat& M) {
  for (const auto& [rows, d] : principal_minors(M)) {
    if (!d.im.is_zero()) throw NumericalError("a principal minor of a Hermitian matrix is not real");
    rational w;
    if (!nonnegative_on_R(d.re, w)) return NegativeMinor{rows, w};
  }
  return std::nullopt;
}

// The same as a message: empty string when PSD, else the failing minor ("{1,3}", 1-based).
std::string psd_on_R(const CMat& M) {
  const auto n = first_negative_minor(M);
  if (!n) return "";
  return "the principal minor {" + row_text(n->rows) + "} is negative at w = " + n->w.str();
}

// Sign (-1, 0, 1) of p at the root w0 of the square-free r isolated by I (exact).
int sign_at_root(const P& p, const P& r, RootInterval I) {
  if (p.is_zero()) return 0;
  if (I.is_exact()) return p(I.lo) > 0 ? 1 : p(I.lo) < 0 ? -1 : 0;
  const P g = gcd(p, r);  // p(w0) = 0 iff w0 is a root of g (a factor of r)
  if (g.degree() > 0 && count_real_roots(g, I.lo, I.hi) > 0) return 0;
  while (count_real_roots(p, I.lo, I.hi) > 0 || p(I.lo) == 0) {
    I = refine_root(r, I, (I.hi - I.lo) / 4);
    if (I.is_exact()) return p(I.lo) > 0 ? 1 : p(I.lo) < 0 ? -1 : 0;
  }
  return p(I.lo) > 0 ? 1 : -1;
}

// G = N(s)/d(s) over the lcm d of the entries' denominators.
struct CommonDenominator {
  P d;
  std::vector<std::vector<P>> N;
};
CommonDenominator common_denominator(const TransferMatrix& G, const std::string& what) {
  const size_t m = G.outputs();
  if (m == 0 || G.inputs() != m) throw InputError(what + " must be square");
  if (G.domain != Domain::s) throw InputError(what + " must be continuous (a transfer matrix in s)");
  CommonDenominator c;
  c.d = P(rational(1));
  for (size_t i = 0; i < m; ++i)
    for (size_t j = 0; j < m; ++j) {
      const auto& e = G(i, j);
      if (!e.is_proper())
        throw InputError(what + " entry (" + std::to_string(i + 1) + "," + std::to_string(j + 1) + ") is improper");
      if (e.num().is_zero()) continue;
      c.d = divmod(c.d * e.den(), gcd(c.d, e.den())).first;
    }
  c.d = c.d.monic();
  c.N.assign(m, std::vector<P>(m));
  for (size_t i = 0; i < m; ++i)
    for (size_t j = 0; j < m; ++j) {
      const auto& e = G(i, j);
      if (!e.num().is_zero()) c.N[i][j] = e.num() * divmod(c.d, e.den()).first;
    }
  return c;
}

// (N conj(d) + N^* d)/2 - delta N^* N at s = jw.
CMat hermitian_part(const CommonDenominator& c, const rational& delta) {
  const size_t m = c.N.size();
  const CP D = at_jw(c.d);
  CMat Nj(m, std::vector<CP>(m)), M(m, std::vector<CP>(m));
  for (size_t i = 0; i < m; ++i)
    for (size_t j = 0; j < m; ++j) Nj[i][j] = at_jw(c.N[i][j]);
  for (size_t i = 0; i < m; ++i)
    for (size_t j = 0; j < m; ++j) {
      M[i][j] = scaled(Nj[i][j] * conj(D) + conj(Nj[j][i]) * D, rational(1, 2));
      if (delta != 0) {
        CP s{P(), P()};
        for (size_t k = 0; k < m; ++k) s = s + conj(Nj[k][i]) * Nj[k][j];
        M[i][j] = M[i][j] - scaled(s, delta);
      }
    }
  return M;
}

std::string pole_text(const RootInterval& I) {
  if (I.is_exact()) return "s = " + (I.lo == 0 ? std::string("0") : I.lo.str() + "j");
  std::ostringstream o;
  o.precision(6);
  o << "s = j" << to_real<double>((I.lo + I.hi) / 2);
  return o.str();
}

// The imaginary-axis poles of c (all simple, residues Hermitian PSD): empty string when they
// are, else why not. `poles` receives how many there are.
std::string imaginary_axis_poles(const CommonDenominator& c, size_t& poles) {
  poles = 0;
  const P q = gcd(c.d, mirrored(c.d));
  if (q.degree() <= 0) return "";
  const CP qj = at_jw(q);  // q(-s) = +-q(s): q(jw) is real or purely imaginary
  const P r = qj.im.is_zero() ? qj.re : qj.re.is_zero() ? qj.im : P();
  if (r.is_zero()) throw NumericalError("operator passivity: gcd(d(s), d(-s)) is neither even nor odd");
  const auto roots = isolate_real_roots(r);
  if (static_cast<int>(roots.size()) != q.degree())
    return "a pole in Re s > 0 or a repeated pole on the imaginary axis (the roots of d(s) symmetric about the axis, "
           "gcd(d(s), d(-s)) of degree " + std::to_string(q.degree()) + ", include only " +
           std::to_string(roots.size()) + " simple ones on it): not positive real";
  poles = roots.size();
  const size_t m = c.N.size();
  const CP dp = conj(at_jw(c.d.derivative()));
  CMat R(m, std::vector<CP>(m));  // residue times |d'(jw0)|^2: N(jw) conj(d'(jw))
  for (size_t i = 0; i < m; ++i)
    for (size_t j = 0; j < m; ++j) R[i][j] = at_jw(c.N[i][j]) * dp;
  const auto minors = principal_minors(R);
  for (const auto& I : roots) {
    for (size_t i = 0; i < m; ++i)
      for (size_t j = i; j < m; ++j)
        if (sign_at_root(R[i][j].re - R[j][i].re, r, I) != 0 || sign_at_root(R[i][j].im + R[j][i].im, r, I) != 0)
          return "the residue at the pole " + pole_text(I) + " is not Hermitian: not positive real";
    for (const auto& [rows, d] : minors)
      if (sign_at_root(d.re, r, I) < 0)
        return "the residue at the pole " + pole_text(I) + " is not positive semidefinite (principal minor {" + row_text(rows) +
               "} < 0): not positive real";
  }
  return "";
}

Verdict too_large(size_t m) {
  return {Outcome::undecided, Status::failed,
          "undecided: the exact minor test covers blocks up to 4 x 4, this one is " + std::to_string(m) + " x " +
              std::to_string(m)};
}
}  // namespace

Verdict operator_passive(const TransferMatrix& H) {
  const CommonDenominator c = common_denominator(H, "operator H(s)");
  const size_t m = c.N.size();
  if (m > 4) return too_large(m);
  const P q = gcd(c.d, mirrored(c.d));
  const P h = q.degree() > 0 ? divmod(c.d, q).first : c.d;
  if (h.degree() > 0 && !hurwitz_stable(h))
    return Verdict::of(false, Status::exact, "a pole in Re s > 0 (exact Routh array): not passive (exact)");
  size_t poles = 0;
  const std::string why = imaginary_axis_poles(c, poles);
  if (!why.empty()) return Verdict::of(false, Status::exact, why + " (exact)");
  const std::string minor = psd_on_R(hermitian_part(c, 0));
  if (!minor.empty()) return Verdict::of(false, Status::exact, minor + " of |d|^2 He H(jw): not passive (exact)");
  return Verdict::of(true, Status::exact,
                     std::string("poles in Re s < 0 (exact Routh)") +
                         (poles ? ", " + std::to_string(poles) + " simple on the imaginary axis with Hermitian PSD residues"
                                : std::string()) +
                         "; all " + std::to_string((1u << m) - 1) +
                         " principal minors of He H(jw) >= 0 for all real w (exact root isolation)");
}

std::optional<NegativeMinor> negative_minor(const TransferMatrix& H) {
  const CommonDenominator c = common_denominator(H, "operator H(s)");
  if (c.N.size() > 4) return std::nullopt;
  return first_negative_minor(hermitian_part(c, 0));
}

Verdict device_is_osp(const TransferMatrix& G, const rational& delta) {
  const CommonDenominator c = common_denominator(G, "device G(s)");
  const size_t m = c.N.size();
  if (m > 4) return too_large(m);
  if (c.d.degree() > 0 && !hurwitz_stable(c.d))
    return Verdict::of(false, Status::exact,
                       "a pole in Re s >= 0 (exact Routh array): no positive OSP level (exact)");
  const std::string minor = psd_on_R(hermitian_part(c, delta));
  if (!minor.empty())
    return Verdict::of(false, Status::exact, "He G - " + delta.str() + " G^* G at s = jw: " + minor + " (exact)");
  return Verdict::of(true, Status::exact, "He G(jw) - " + delta.str() + " G(jw)^* G(jw) >= 0 for all real w (exact)");
}

DeviceLevel device_osp_level(const TransferMatrix& G, const std::optional<std::pair<rational, rational>>& md) {
  DeviceLevel L;
  if (md) {
    L.lo = L.hi = md->second;
    L.exact = true;
    L.verdict = Verdict::of(md->second > 0, Status::exact,
                            "a mass-damper 1/(m s + b) has OSP level b = " + md->second.str() + " (exact)");
    return L;
  }
  auto osp = [&](const rational& d) {
    const Verdict v = device_is_osp(G, d);
    if (!v.decided()) throw NumericalError(v.evidence);
    return v.holds();
  };
  try {
    if (!osp(rational(0))) {
      L.verdict = Verdict::of(false, Status::exact, "not passive: " + device_is_osp(G, 0).evidence);
      return L;
    }
    rational lo = 0, hi = 1;
    for (int k = 0; k < 64 && osp(hi); ++k) lo = hi, hi *= 2;
    if (lo == hi / 2 && osp(hi)) {  // beyond 2^64: report the proven lower bound
      L.lo = hi;
      L.hi = hi;
      L.verdict = Verdict::of(true, Status::certified, "OSP level >= " + hi.str() + " (exact bisection stopped)");
      return L;
    }
    for (int k = 0; k < 60 && hi - lo > hi * rational(1, 1000000000); ++k) {
      const rational mid = (lo + hi) / 2;
      (osp(mid) ? lo : hi) = mid;
    }
    L.lo = lo;
    L.hi = hi;
    std::ostringstream o;
    o.precision(10);
    o << "OSP level in [" << to_real<double>(lo) << ", " << to_real<double>(hi)
      << "] (certified: bisection on the exact test He G - delta G^* G >= 0; the lower end proven)";
    L.verdict = lo > 0 ? Verdict::of(true, Status::certified, o.str())
                       : Verdict{Outcome::undecided, Status::failed, "undecided: no positive level proven; " + o.str()};
  } catch (const NumericalError& e) {
    L.verdict = {Outcome::undecided, Status::failed, e.what()};
  }
  return L;
}

std::vector<AssumptionCheck> check_assumptions(const Structure& structure, const std::vector<TransferMatrix>& operators,
                                               const std::vector<std::string>& operator_names,
                                               const std::vector<std::string>& device_evidence) {
  std::vector<AssumptionCheck> out;
  for (size_t i = 0; i < operators.size(); ++i) {
    const std::string name = i < operator_names.size() ? operator_names[i] : "H" + std::to_string(i + 1);
    out.push_back({"Assumption 1(b): operator '" + name + "' passive (positive real)", operator_passive(operators[i])});
  }
  size_t k = 0;
  for (const auto& op : structure.operators)
    for (const auto& d : op.devices) {
      const auto k_dof = d.osp.rows();  // a scalar level delta I is printed as such, never as a matrix
      const bool scalar = d.osp == MatQ(d.osp(0, 0) * MatQ::Identity(k_dof, k_dof));
      const std::string lvl = scalar ? d.osp(0, 0).str() + (k_dof > 1 ? " I_" + std::to_string(k_dof) : "")
                                     : std::to_string(k_dof) + " x " + std::to_string(k_dof) + " matrix";
      const std::string how = k < device_evidence.size() ? device_evidence[k] : "";
      ++k;
      out.push_back({"Assumption 1(a): device '" + d.name + "' OSP level",
                     Verdict::of(lmi::exact_definiteness(d.osp).pd, Status::exact,
                                 "Delta_d = " + lvl + (how.empty() ? "" : " (" + how + ")"))});
    }
  return out;
}

bool all_hold(const std::vector<AssumptionCheck>& checks) {
  return std::all_of(checks.begin(), checks.end(), [](const AssumptionCheck& c) { return c.verdict.holds(); });
}

}  // namespace hapstab::multidof
