#include "hapstab/contact/limit_cycle.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <random>
#include <sstream>

#include "hapstab/contact/wedge.hpp"
#include "hapstab/lti/realization.hpp"
#include "hapstab/numeric/decimal.hpp"
#include "hapstab/numeric/error.hpp"

namespace hapstab::contact {

namespace {

double dbl(const rational& q) { return to_real<double>(q); }

struct DLoop {
  int n = 0;
  std::vector<double> A, B, C;  // A row-major n*n
  double D = 0, rho = 1, inv = 1;
};

DLoop to_double(const LureLoop& L) {
  DLoop d;
  d.n = L.order();
  for (int i = 0; i < d.n; ++i) {
    for (int j = 0; j < d.n; ++j) d.A.push_back(dbl(L.sys.A(i, j)));
    d.B.push_back(dbl(L.sys.B(i, 0)));
    d.C.push_back(dbl(L.sys.C(0, i)));
  }
  d.D = dbl(L.sys.D(0, 0));
  d.rho = dbl(L.rho);
  d.inv = 1.0 / (1.0 + d.D);
  return d;
}

// The hot loop, fixed order N: no allocation, no branches (u = -max(Cs/(1+D), -rho)).
// Records y_k into out[k - record_from] for k >= record_from. Returns false on divergence.
template <int N>
bool loop_fixed(const DLoop& L, double* s, long steps, double* out, long record_from, double* ylast) {
  std::array<double, N * N> A;
  std::array<double, N> B, C, x;
  for (int i = 0; i < N * N; ++i) A[i] = L.A[i];
  for (int i = 0; i < N; ++i) {
    B[i] = L.B[i];
    C[i] = L.C[i];
    x[i] = s[i];
  }
  const double D = L.D, inv = L.inv, mrho = -L.rho;
  double y = 0;
  for (long k = 0; k < steps; ++k) {
    double cs = 0;
    for (int i = 0; i < N; ++i) cs += C[i] * x[i];
    const double u = -std::max(cs * inv, mrho);
    y = cs + D * u;
    if (out && k >= record_from) out[k - record_from] = y;
    std::array<double, N> nx;
    for (int i = 0; i < N; ++i) {
      double a = B[i] * u;
      for (int j = 0; j < N; ++j) a += A[i * N + j] * x[j];
      nx[i] = a;
    }
    x = nx;
    if ((k & 1023) == 1023 && !(std::abs(y) < 1e150)) {
      for (int i = 0; i < N; ++i) s[i] = x[i];
      *ylast = y;
      return false;
    }
  }
  for (int i = 0; i < N; ++i) s[i] = x[i];
  *ylast = y;
  return true;
}

bool loop_dyn(const DLoop& L, double* s, long steps, double* out, long record_from, double* ylast) {
  const int n = L.n;
  std::vector<double> x(s, s + n), nx(n);
  const double mrho = -L.rho;
  double y = 0;
  for (long k = 0; k < steps; ++k) {
    double cs = 0;
    for (int i = 0; i < n; ++i) cs += L.C[i] * x[i];
    const double u = -std::max(cs * L.inv, mrho);
    y = cs + L.D * u;
    if (out && k >= record_from) out[k - record_from] = y;
    for (int i = 0; i < n; ++i) {
      double a = L.B[i] * u;
      for (int j = 0; j < n; ++j) a += L.A[i * n + j] * x[j];
      nx[i] = a;
    }
    x.swap(nx);
    if ((k & 1023) == 1023 && !(std::abs(y) < 1e150)) break;
  }
  std::copy(x.begin(), x.end(), s);
  *ylast = y;
  return std::abs(y) < 1e150;
}

bool loop(const DLoop& L, double* s, long steps, double* out, long record_from, double* ylast) {
  switch (L.n) {
    case 1: return loop_fixed<1>(L, s, steps, out, record_from, ylast);
    case 2: return loop_fixed<2>(L, s, steps, out, record_from, ylast);
    case 3: return loop_fixed<3>(L, s, steps, out, record_from, ylast);
    case 4: return loop_fixed<4>(L, s, steps, out, record_from, ylast);
    case 5: return loop_fixed<5>(L, s, steps, out, record_from, ylast);
    case 6: return loop_fixed<6>(L, s, steps, out, record_from, ylast);
    default: return loop_dyn(L, s, steps, out, record_from, ylast);
  }
}

double amplitude(const double* y, long n) {
  if (n <= 0) return 0;
  auto [mn, mx] = std::minmax_element(y, y + n);
  return (*mx - *mn) / 2;
}

using Q = rational;
using QVec = std::vector<Q>;
using QMat = std::vector<QVec>;

// One exact step of (4): returns the new state; y and the mode (true = contact) by reference.
QVec exact_step(const LureLoop& L, const QVec& s, Q& y, bool& contact) {
  const int n = L.order();
  Q cs = 0;
  for (int i = 0; i < n; ++i) cs += L.sys.C(0, i) * s[i];
  const Q D = L.sys.D(0, 0);
  const Q yc = cs / (1 + D);
  Q u;
  if (yc >= -L.rho) {
    contact = true;
    u = -yc;
  } else {
    contact = false;
    u = L.rho;
  }
  y = cs + D * u;
  QVec ns(n);
  for (int i = 0; i < n; ++i) {
    Q a = L.sys.B(i, 0) * u;
    for (int j = 0; j < n; ++j) a += L.sys.A(i, j) * s[j];
    ns[i] = a;
  }
  return ns;
}

// Solves M x = b exactly (Gauss-Jordan over Q); nullopt when singular.
std::optional<QVec> solve(QMat M, QVec b) {
  const size_t n = b.size();
  for (size_t c = 0; c < n; ++c) {
    size_t p = c;
    while (p < n && M[p][c] == 0) ++p;
    if (p == n) return std::nullopt;
    std::swap(M[p], M[c]);
    std::swap(b[p], b[c]);
    for (size_t r = 0; r < n; ++r) {
      if (r == c || M[r][c] == 0) continue;
      const Q f = M[r][c] / M[c][c];
      for (size_t k = c; k < n; ++k) M[r][k] -= f * M[c][k];
      b[r] -= f * b[c];
    }
  }
  QVec x(n);
  for (size_t i = 0; i < n; ++i) x[i] = b[i] / M[i][i];
  return x;
}

}  // namespace

LureLoop make_lure_loop(const TransferFunction& H, const rational& gain, const rational& rho) {
  if (rho <= 0) throw InputError("--rho: rho must be > 0 (the shifted nonlinearity of Fig. 4 needs rho > 0), got " +
                                 to_decimal(rho, 17));
  if (gain < 0) throw InputError("--gain: the gain must be >= 0, got " + to_decimal(gain, 17));
  if (!H.is_discrete()) throw InputError("limit cycle: H must be a discrete transfer function H(z)");
  if (!H.is_proper()) throw InputError("limit cycle: H(z) = " + H.to_string() + " is not causal");
  LureLoop L;
  L.sys = tf2ss(H);
  L.sys.C *= gain;
  L.sys.D *= gain;
  L.rho = rho;
  if (1 + L.sys.D(0, 0) <= 0)
    throw InputError("limit cycle: 1 + k H(inf) = " + to_decimal(1 + L.sys.D(0, 0), 17) +
                     " <= 0: the algebraic loop of Fig. 5 has no unique solution");
  if (L.order() > 0) {
    const Mat<rational> Ac = L.sys.A - L.sys.B * L.sys.C / (1 + L.sys.D(0, 0));
    L.contact_stable = schur_stable(charpoly(Ac));
  }
  return L;
}

SimTrace simulate(const LureLoop& L, const std::vector<double>& s0, long steps, long keep) {
  if (steps < 0 || keep < 0) throw InputError("simulate: steps and keep must be >= 0");
  keep = std::min(keep, steps);
  DLoop d = to_double(L);
  if (static_cast<int>(s0.size()) != d.n) throw InputError("simulate: initial state has the wrong size");
  SimTrace t;
  t.state = s0;
  t.y.assign(static_cast<size_t>(keep), 0.0);
  double ylast = 0;
  t.diverged = !loop(d, t.state.data(), steps, t.y.data(), steps - keep, &ylast);
  return t;
}

double run_steps(const LureLoop& L, std::vector<double>& state, long steps) {
  DLoop d = to_double(L);
  double ylast = 0;
  loop(d, state.data(), steps, nullptr, 0, &ylast);
  return ylast;
}

std::vector<double> simulate_fig2(const TransferFunction& H, double gain, double r, long steps) {
  // theta_k = kH (r - max(theta_k, 0)); same algebraic-loop resolution with the breakpoint at 0.
  StateSpace<rational> sys = tf2ss(H);
  const int n = static_cast<int>(sys.A.rows());
  std::vector<double> x(n, 0.0), nx(n), out;
  const double D = gain * dbl(sys.D(0, 0));
  for (long k = 0; k < steps; ++k) {
    double cs = 0;
    for (int i = 0; i < n; ++i) cs += gain * dbl(sys.C(0, i)) * x[i];
    const double sp = cs + D * r;
    const double th = sp / (1 + D) >= 0 ? sp / (1 + D) : sp;
    const double u = r - std::max(th, 0.0);
    out.push_back(th);
    for (int i = 0; i < n; ++i) {
      double a = dbl(sys.B(i, 0)) * u;
      for (int j = 0; j < n; ++j) a += dbl(sys.A(i, j)) * x[j];
      nx[i] = a;
    }
    x.swap(nx);
  }
  return out;
}

Oscillation detect(const LureLoop& L, const std::vector<double>& s0, long steps, long window) {
  Oscillation o;
  window = std::max<long>(64, window);
  steps = std::max(steps, 2 * window);
  SimTrace t = simulate(L, s0, steps, 2 * window);
  const double rho = dbl(L.rho);
  if (t.diverged) {
    o.diverged = o.growing = true;
    o.note = std::string("diverged: |y| passed 1e150") +
             (L.contact_stable ? "" : " (the linear loop (1 + kH)^-1 is unstable: exact, Schur-Cohn)");
    return o;
  }
  const double* prev = t.y.data();
  const double* last = t.y.data() + window;
  o.previous_amplitude = amplitude(prev, window);
  o.amplitude = amplitude(last, window);
  o.window.assign(last, last + window);
  o.state = t.state;
  const double ratio = o.amplitude / o.previous_amplitude;
  const bool loses_contact = *std::min_element(last, last + window) < -rho;
  if (!loses_contact) {  // linear over the last window: the exact test of (1 + kH)^-1 decides
    if (!L.contact_stable) {
      // the motion grows until it leaves the wall -- sustained, not decaying
      o.oscillates = o.growing = true;
      o.note = "growing in contact: the linear loop (1 + kH)^-1 is unstable (exact, Schur-Cohn); amplitude ratio "
               "over one window " + std::to_string(ratio);
    } else {
      o.note = o.amplitude <= 1e-9 * rho ? "decays to the equilibrium y = 0"
                                         : "stays in contact, where the loop (1 + kH)^-1 is stable (exact): decays";
    }
    return o;
  }
  if (o.amplitude >= 1e6 * rho && ratio > 1 + 1e-6) {
    // far beyond rho the loop is the scale-free cone u = -max(y, 0) (limit_cycle.hpp): the growth
    // does not stop
    o.oscillates = o.growing = o.diverged = true;
    std::ostringstream os;
    os << "diverges: the envelope grows by " << ratio << " per window of " << window << " samples at an amplitude of "
       << o.amplitude / rho << " rho (numeric: beyond 1e6 rho the loop is scale-free, so the growth does not stop)";
    o.note = os.str();
    return o;
  }
  if (o.amplitude <= 1e-9 * rho) {
    o.note = "decays to the equilibrium y = 0";
    return o;
  }
  // smallest period with max |y_k - y_{k-p}| <= 1e-7 * amplitude over the last window
  const double tol = 1e-7 * o.amplitude;
  for (long p = 1; p <= window / 2; ++p) {
    double m = 0;
    for (long k = window; k < 2 * window && m <= tol; ++k) m = std::max(m, std::abs(t.y[k] - t.y[k - p]));
    if (m <= tol) {
      o.period = p;
      o.mismatch = m / o.amplitude;
      break;
    }
  }
  const bool decaying = o.amplitude < o.previous_amplitude * (1 - 1e-6);
  if (o.period) {
    o.oscillates = true;
    o.note = "periodic, period " + std::to_string(*o.period) + " samples";
  } else if (decaying) {
    o.note = "slow decay: amplitude ratio over one window " + std::to_string(o.amplitude / o.previous_amplitude);
  } else {
    o.oscillates = true;
    o.note = "sustained but not periodic within the window (quasi-periodic or long period)";
  }
  return o;
}

Oscillation find_oscillation(const LureLoop& L, long steps, long window) {
  const int n = L.order();
  const double rho = dbl(L.rho);
  std::vector<std::vector<double>> starts;
  for (double c : {3.0, 300.0})
    for (int i = 0; i < n; ++i)
      for (double sg : {1.0, -1.0}) {
        std::vector<double> s(n, 0.0);
        s[i] = sg * c * rho;
        starts.push_back(s);
      }
  std::mt19937 gen(12345);
  std::normal_distribution<double> nd;
  for (int r = 0; r < 4; ++r) {
    std::vector<double> s(n);
    for (auto& v : s) v = 30 * rho * nd(gen);
    starts.push_back(s);
  }
  Oscillation last;
  for (const auto& s : starts) {
    last = detect(L, s, steps, window);
    if (last.oscillates || last.diverged) return last;
  }
  return last;
}

ExactOrbit certify_orbit(const LureLoop& L, const std::vector<double>& s_on_orbit, long period) {
  ExactOrbit e;
  e.period = period;
  const int n = L.order();
  if (period < 1 || static_cast<int>(s_on_orbit.size()) != n) throw InputError("certify_orbit: bad period or state");
  // mode pattern from the double trajectory
  DLoop d = to_double(L);
  std::vector<double> s = s_on_orbit;
  std::vector<bool> mode;
  for (long k = 0; k < period; ++k) {
    double cs = 0;
    for (int i = 0; i < n; ++i) cs += d.C[i] * s[i];
    mode.push_back(cs * d.inv >= -d.rho);
    double yl;
    loop(d, s.data(), 1, nullptr, 0, &yl);
  }
  // compose the affine maps: s_{k+1} = A_k s_k + b_k
  const Q D = L.sys.D(0, 0);
  QMat Ac(n, QVec(n)), Af(n, QVec(n));
  QVec bf(n);
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < n; ++j) {
      Af[i][j] = L.sys.A(i, j);
      Ac[i][j] = L.sys.A(i, j) - L.sys.B(i, 0) * L.sys.C(0, j) / (1 + D);
    }
    bf[i] = L.sys.B(i, 0) * L.rho;
  }
  QMat M(n, QVec(n));
  for (int i = 0; i < n; ++i) M[i][i] = 1;
  QVec c(n);
  for (long k = 0; k < period; ++k) {
    const QMat& Ak = mode[k] ? Ac : Af;
    QMat M2(n, QVec(n));
    QVec c2(n);
    for (int i = 0; i < n; ++i) {
      for (int j = 0; j < n; ++j) {
        Q a = 0;
        for (int l = 0; l < n; ++l) a += Ak[i][l] * M[l][j];
        M2[i][j] = a;
      }
      Q a = mode[k] ? Q(0) : bf[i];
      for (int l = 0; l < n; ++l) a += Ak[i][l] * c[l];
      c2[i] = a;
    }
    M.swap(M2);
    c.swap(c2);
  }
  QMat IM = M;
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < n; ++j) IM[i][j] = -IM[i][j];
    IM[i][i] += 1;
  }
  auto x0 = solve(IM, c);
  if (!x0) {
    e.note = "I - M is singular: no isolated periodic orbit with this pattern";
    return e;
  }
  // exact replay with the true nonlinearity
  QVec x = *x0;
  Q ymin, ymax;
  for (long k = 0; k < period; ++k) {
    Q y;
    bool contact;
    x = exact_step(L, x, y, contact);
    if (contact != mode[k]) {
      e.note = "the exact orbit leaves the assumed contact pattern at step " + std::to_string(k);
      return e;
    }
    if (k == 0 || y < ymin) ymin = y;
    if (k == 0 || y > ymax) ymax = y;
    if (!contact) ++e.free_steps;
    e.y.push_back(y);
  }
  if (x != *x0) {
    e.note = "the exact state does not repeat";
    return e;
  }
  e.found = true;
  e.amplitude = (ymax - ymin) / 2;
  // exact local stability of the orbit: monodromy matrix M Schur stable, decided when no sample
  // lies exactly on the switching boundary y = -rho (then every mode is locally constant)
  Mat<rational> Mm(n, n);
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) Mm(i, j) = M[i][j];
  e.stable = schur_stable(charpoly(Mm));
  // a sample on y = -rho: the period map is only piecewise affine near the orbit, and M alone
  // does not decide whether it attracts
  e.stability_decided = std::none_of(e.y.begin(), e.y.end(), [&](const Q& y) { return y == -L.rho; });
  return e;
}

std::optional<long> exact_repeat(const LureLoop& L, const std::vector<rational>& s0, long steps) {
  std::map<QVec, long> seen;
  QVec x = s0;
  for (long k = 0; k < steps; ++k) {
    auto [it, fresh] = seen.emplace(x, k);
    if (!fresh) return k - it->second;
    Q y;
    bool c;
    x = exact_step(L, x, y, c);
  }
  return std::nullopt;
}

std::optional<double> closed_loop_gain_limit(const TransferFunction& H, double kmax, double rel) {
  auto stable = [&](double k) { return schur_stable(H.den() + H.num() * exact_rational(k)); };
  // first stable gain on a log grid (H itself may be unstable, e.g. a pole at z = 1), then the
  // first unstable gain after it
  double lo = -1, hi = -1;
  const int n = 240;
  for (int i = 0; i <= n; ++i) {
    const double k = 1e-6 * std::pow(kmax / 1e-6, static_cast<double>(i) / n);
    const bool st = stable(k);
    if (st) lo = k;
    if (!st && lo > 0) {
      hi = k;
      break;
    }
  }
  if (lo < 0) return 0.0;
  if (hi < 0) return std::nullopt;
  while (hi - lo > rel * hi) {
    const double m = 0.5 * (lo + hi);
    (stable(m) ? lo : hi) = m;
  }
  return hi;
}

OnsetResult oscillation_onset(const TransferFunction& H, double kmin, double kmax, int n, double rel, long steps) {
  OnsetResult r;
  auto osc = [&](double k, Oscillation* out) {
    LureLoop L = make_lure_loop(H, exact_rational(k), 1);
    Oscillation o = find_oscillation(L, steps);
    if (out) *out = o;
    return o.oscillates || o.diverged;
  };
  double lo = 0, hi = -1;
  for (int i = 0; i < n; ++i) {
    const double k = kmin * std::pow(kmax / kmin, n > 1 ? static_cast<double>(i) / (n - 1) : 0.0);
    if (osc(k, nullptr)) {
      hi = k;
      break;
    }
    lo = k;
  }
  if (hi < 0) return r;
  // (lo = 0 when the first grid gain already oscillates: halve down, at most 60 steps)
  for (int it = 0; it < 60 && hi - lo > rel * hi; ++it) {
    const double m = lo > 0 ? std::sqrt(lo * hi) : 0.5 * hi;
    (osc(m, nullptr) ? hi : lo) = m;
  }
  Oscillation o;
  osc(hi, &o);
  r.k_onset = hi;
  r.period = o.period;
  r.amplitude_over_rho = o.amplitude;
  if (o.period && !o.diverged) {
    LureLoop L = make_lure_loop(H, exact_rational(hi), 1);
    r.certified = certify_orbit(L, o.state, *o.period).found;
  }
  return r;
}

}  // namespace hapstab::contact
