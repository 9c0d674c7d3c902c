// hapstab/lmi/passivity_level.cpp -- Lemma 1 / Lemma 2 LMIs and the frequency-domain levels.
#include "hapstab/lmi/passivity_level.hpp"

#include <Eigen/Eigenvalues>
#include <Eigen/LU>
#include <Eigen/SVD>
#include <algorithm>
#include <cmath>
#include <complex>
#include <cstdio>

#include "hapstab/lmi/certificate.hpp"
#include "hapstab/lmi/certify.hpp"
#include "hapstab/lti/realization.hpp"
#include "hapstab/numeric/decimal.hpp"
#include "hapstab/passivity/bound.hpp"
#include "hapstab/poly/stability.hpp"
#include "hapstab/numeric/error.hpp"

namespace hapstab::lmi {

using Eigen::MatrixXd;
using cplx = std::complex<double>;
using MatC = Eigen::MatrixXcd;

const char* to_string(PassivityKind k) { return k == PassivityKind::osp ? "osp" : "isp"; }

namespace {

void check_state_space(const StateSpace<double>& sys) {
  sys.validate("system");
  if (!sys.is_discrete()) throw InputError("system: the passivity levels of paper 000 need a discrete system (T > 0)");
  if (sys.inputs() != sys.outputs())
    throw InputError("system: passivity needs as many outputs as inputs (got " + std::to_string(sys.outputs()) + "x" +
                     std::to_string(sys.inputs()) + ")");
  if (sys.states() == 0) throw InputError("system: a static gain has no state; its level is (D+D')/2's");
  if (!sys.A.allFinite() || !sys.B.allFinite() || !sys.C.allFinite() || !sys.D.allFinite())
    throw InputError("system: a matrix entry is not finite");
}

double spectral_radius(const MatrixXd& A) {
  Eigen::EigenSolver<MatrixXd> es(A, false);
  return es.eigenvalues().cwiseAbs().maxCoeff();
}

// Lemma 1's matrix M(P, Delta, Phi) as an expression; `level` multiplies Delta (osp) or Phi (isp)
// when given, otherwise fixed delta/phi are used.
Expr lemma1_M(const StateSpace<double>& s, const Expr& P, const Expr* level, PassivityKind kind, double delta,
              double phi) {
  const MatrixXd &A = s.A, &B = s.B, &C = s.C, &D = s.D;
  const auto m = B.cols();
  const MatrixXd HeD = 0.5 * (D + D.transpose());
  Expr M11 = A.transpose() * P * A - P;
  Expr M12 = A.transpose() * P * B - Expr(MatrixXd(0.5 * C.transpose()));
  Expr M22 = B.transpose() * P * B - Expr(HeD);
  if (level && kind == PassivityKind::osp) {
    M11 += kron(MatrixXd(C.transpose() * C), *level);
    M12 += kron(MatrixXd(C.transpose() * D), *level);
    M22 += kron(MatrixXd(D.transpose() * D), *level);
  } else {
    const double dl = level ? 0.0 : delta;
    M11 += Expr(MatrixXd(dl * C.transpose() * C));
    M12 += Expr(MatrixXd(dl * C.transpose() * D));
    M22 += Expr(MatrixXd(dl * D.transpose() * D));
    if (level) M22 += kron(MatrixXd::Identity(m, m), *level);
    else M22 += Expr(MatrixXd(phi * MatrixXd::Identity(m, m)));
  }
  return blocks({{M11, M12}, {Expr(), M22}}, "Lemma 1 (2)");
}

// Lemma 2 after the second Schur complement: S(Q) - R Q R'. `mu` = Delta^{-1} (osp, expression)
// or fixed inv_delta (< 0: Delta = 0, third block dropped). `phi_expr`: variable Phi (isp).
Expr lemma2_matrix(const StateSpace<double>& s, const Expr& Q, const Expr* mu, double inv_delta, const Expr* phi_expr,
                   double phi, bool typo) {
  const MatrixXd &A = s.A, &B = s.B, &C = s.C, &D = s.D;
  const auto m = B.cols(), n = A.rows();
  const MatrixXd HeD = 0.5 * (D + D.transpose());
  const double sg = typo ? 1.0 : -1.0;  // S11 = HeD - Phi (correct) or HeD + Phi (transcribed)
  Expr S11 = Expr(HeD);
  if (phi_expr) S11 += sg * kron(MatrixXd::Identity(m, m), *phi_expr);
  else S11 += Expr(MatrixXd(sg * phi * MatrixXd::Identity(m, m)));
  const bool third = mu || inv_delta >= 0;
  MatrixXd R;
  if (third) {
    R.resize(2 * m + n, n);
    R << 0.5 * C, A, C;
  } else {
    R.resize(m + n, n);
    R << 0.5 * C, A;
  }
  Expr S;
  if (third) {
    Expr S33 = mu ? kron(MatrixXd::Identity(m, m), *mu) : Expr(MatrixXd(inv_delta * MatrixXd::Identity(m, m)));
    S = blocks({{S11, Expr(MatrixXd(B.transpose())), Expr(MatrixXd(D.transpose()))},
                {Expr(), Q, Expr::zero(static_cast<int>(n), static_cast<int>(m))},
                {Expr(), Expr(), S33}},
               "Lemma 2 S");
  } else {
    S = blocks({{S11, Expr(MatrixXd(B.transpose()))}, {Expr(), Q}}, "Lemma 2 S");
  }
  return S - R * Q * R.transpose();
}

// Solves a level program and reads the level from its scalar variable L: level = L, or 1/L
// when `reciprocal` (Lemma 2's mu = 1/delta). An exactly certified point proves lower_bound
// (for 1/L only when L > 0). `hint` explains a failure.
PassivityLevel solve_level(const Program& prog, Backend backend, int lemma, const MatrixVariable& L, bool reciprocal,
                           const MatrixVariable* P = nullptr, const std::string& hint = "") {
  Options opt;
  opt.backend = backend;
  const CertifiedSolve cs = certify_lmi(prog, opt);
  const SolveResult& r = cs.result;
  PassivityLevel out;
  out.method = std::string("Lemma ") + std::to_string(lemma) + " LMI (" + r.solver + ")";
  if (!r.is_success()) {
    out.status = Status::failed;
    out.note = std::string("LMI ") + to_string(r.status) + "/" + to_string(r.verdict) + hint + ": " + r.detail;
    return out;
  }
  const double x = r.solution(L)(0, 0);
  out.level = reciprocal ? 1.0 / x : x;
  if (cs.verdict.holds() && cs.verdict.proven()) {
    const rational q = cs.point(L)(0, 0);
    if (!reciprocal) out.lower_bound = q;
    else if (q > 0) out.lower_bound = 1 / q;
    if (P && out.lower_bound) out.lemma1_P = cs.point(*P);
  }
  return out;
}

}  // namespace

PassivityLevel passivity_level_lmi(const StateSpace<double>& sys, PassivityKind kind, int lemma, Backend backend) {
  check_state_space(sys);
  if (lemma != 1 && lemma != 2) throw InputError("passivity level: lemma must be 1 or 2");
  const int n = static_cast<int>(sys.states());
  Program prog;
  if (lemma == 1) {
    auto P = prog.new_symmetric(n, "P");
    auto L = prog.new_scalar(kind == PassivityKind::osp ? "delta" : "phi");
    Expr Lx(L);
    prog.add_lmi("P > 0", Expr(P));
    prog.add_lmi("Lemma 1 (2) < 0", -lemma1_M(sys, Expr(P), &Lx, kind, 0, 0));
    prog.set_minimize(-Lx);
    return solve_level(prog, backend, lemma, L, false, &P);
  }
  // Lemma 2
  auto Q = prog.new_symmetric(n, "Q");
  prog.add_lmi("Q > 0", Expr(Q));
  if (kind == PassivityKind::osp) {
    auto mu = prog.new_scalar("mu = 1/delta");
    Expr mx(mu);
    prog.add_lmi("Lemma 2 (Schur form) > 0", lemma2_matrix(sys, Expr(Q), &mx, 0, nullptr, 0, false));
    prog.set_minimize(mx);
    return solve_level(prog, backend, lemma, mu, true, nullptr, " (Lemma 2 needs Delta > 0: the OSP level may be <= 0)");
  }
  auto phi = prog.new_scalar("phi");
  Expr px(phi);
  prog.add_lmi("Lemma 2 (Schur form, Delta = 0) > 0", lemma2_matrix(sys, Expr(Q), nullptr, -1, &px, 0, false));
  prog.set_minimize(-px);
  return solve_level(prog, backend, lemma, phi, false);
}

bool lemma1_holds(const StateSpace<rational>& s, const MatQ& P, const rational& level, PassivityKind kind) {
  const auto n = s.A.rows(), m = s.B.cols();
  if (P.rows() != n || P.cols() != n || P != P.transpose() || !exact_pd_bareiss(P)) return false;
  const MatQ At = s.A.transpose(), Ct = s.C.transpose();
  const rational delta = kind == PassivityKind::osp ? level : rational(0);
  MatQ M11 = At * P * s.A - P + delta * Ct * s.C;
  MatQ M12 = At * P * s.B - rational(1, 2) * Ct + delta * Ct * s.D;
  MatQ M22 = s.B.transpose() * P * s.B - rational(1, 2) * (s.D + s.D.transpose()) + delta * s.D.transpose() * s.D;
  if (kind == PassivityKind::isp) M22 += level * MatQ::Identity(m, m);
  MatQ negM(n + m, n + m);
  negM << -M11, -M12, -M12.transpose(), -M22;
  return exact_pd_bareiss(negM);
}

double lemma_margin(const StateSpace<double>& sys, int lemma, double delta, double phi, bool typo, Backend backend) {
  check_state_space(sys);
  const int n = static_cast<int>(sys.states());
  Program prog;
  Options opt;
  opt.backend = backend;
  opt.certify = false;
  if (lemma == 1) {
    auto P = prog.new_symmetric(n, "P");
    prog.add_lmi("P > 0", Expr(P));
    prog.add_lmi("Lemma 1 (2) < 0", -lemma1_M(sys, Expr(P), nullptr, PassivityKind::osp, delta, phi));
  } else {
    auto Q = prog.new_symmetric(n, "Q");
    prog.add_lmi("Q > 0", Expr(Q));
    prog.add_lmi("Lemma 2 > 0", lemma2_matrix(sys, Expr(Q), nullptr, delta > 0 ? 1.0 / delta : -1.0, nullptr, phi, typo));
  }
  SolveResult r = solve(prog, opt);
  if (r.status != SolveStatus::optimal) throw NumericalError("lemma_margin: solver " + std::string(to_string(r.status)) + ": " + r.detail);
  return r.margin;
}

namespace {

MatC freqresp(const StateSpace<double>& s, double theta) {
  const auto n = s.A.rows();
  const cplx z = std::polar(1.0, theta);
  MatC Zm = z * MatC::Identity(n, n) - s.A.cast<cplx>();
  MatC X = Zm.partialPivLu().solve(s.B.cast<cplx>());
  return s.C.cast<cplx>() * X + s.D.cast<cplx>();
}

double osp_index_at(const StateSpace<double>& s, double theta, bool& singular, double* smin = nullptr,
                    double* smax = nullptr) {
  MatC G = freqresp(s, theta);
  MatC H = 0.5 * (G + G.adjoint());
  Eigen::JacobiSVD<MatC> svd(G, Eigen::ComputeFullV);
  const auto sv = svd.singularValues();
  if (smin) *smin = sv(sv.size() - 1);
  if (smax) *smax = sv(0);
  const double tol = 1e-10 * std::max(1.0, sv(0));
  int r = 0;
  while (r < sv.size() && sv(r) > tol) ++r;
  if (r < sv.size()) singular = true;
  if (r == 0) return INFINITY;  // G = 0: no constraint at this frequency
  MatC Vr = svd.matrixV().leftCols(r);
  Eigen::VectorXd inv = sv.head(r).cwiseInverse();
  MatC W = inv.cast<cplx>().asDiagonal() * (Vr.adjoint() * H * Vr) * inv.cast<cplx>().asDiagonal();
  W = 0.5 * (W + W.adjoint());
  Eigen::SelfAdjointEigenSolver<MatC> es(W, Eigen::EigenvaluesOnly);
  return es.eigenvalues()(0);
}

}  // namespace

double isp_index_at(const StateSpace<double>& sys, double theta) {
  MatC G = freqresp(sys, theta);
  MatC H = 0.5 * (G + G.adjoint());
  Eigen::SelfAdjointEigenSolver<MatC> es(H, Eigen::EigenvaluesOnly);
  return es.eigenvalues()(0);
}

PassivityLevel passivity_level_freq(const StateSpace<double>& sys, PassivityKind kind, int grid) {
  check_state_space(sys);
  if (grid < 16) throw InputError("passivity level: the frequency grid needs at least 16 points");
  PassivityLevel out;
  out.method = "frequency domain (" + std::to_string(grid) + "-point grid + golden-section refinement)";
  const double rho = spectral_radius(sys.A);
  if (!(rho < 1)) {
    out.status = Status::failed;
    out.note = "A is not Schur stable (spectral radius " + std::to_string(rho) +
               "): the frequency-domain level is not a passivity level";
    return out;
  }
  bool singular = false;
  auto f = [&](double th) { return kind == PassivityKind::isp ? isp_index_at(sys, th) : osp_index_at(sys, th, singular); };
  std::vector<double> th(static_cast<size_t>(grid)), v(static_cast<size_t>(grid));
  // OSP: smallest sigma_min(G) and largest sigma_max(G) on the grid (a zero near the circle)
  double smin_all = INFINITY, smax_all = 0, near_zero_th = 0;
  for (int i = 0; i < grid; ++i) {
    th[static_cast<size_t>(i)] = M_PI * i / (grid - 1);
    if (kind == PassivityKind::osp) {
      double lo = INFINITY, hi = 0;
      v[static_cast<size_t>(i)] = osp_index_at(sys, th[static_cast<size_t>(i)], singular, &lo, &hi);
      if (lo < smin_all) smin_all = lo, near_zero_th = th[static_cast<size_t>(i)];
      smax_all = std::max(smax_all, hi);
    } else {
      v[static_cast<size_t>(i)] = f(th[static_cast<size_t>(i)]);
    }
  }
  // local minima of the grid (ends included), 8 smallest
  std::vector<int> mins;
  for (int i = 0; i < grid; ++i) {
    const double l = i > 0 ? v[static_cast<size_t>(i - 1)] : INFINITY, r = i + 1 < grid ? v[static_cast<size_t>(i + 1)] : INFINITY;
    if (v[static_cast<size_t>(i)] <= l && v[static_cast<size_t>(i)] <= r) mins.push_back(i);
  }
  std::sort(mins.begin(), mins.end(), [&](int a, int b) { return v[static_cast<size_t>(a)] < v[static_cast<size_t>(b)]; });
  if (mins.size() > 8) mins.resize(8);
  double best = INFINITY, best_th = 0;
  for (int i : mins) {
    double a = th[static_cast<size_t>(std::max(0, i - 1))], b = th[static_cast<size_t>(std::min(grid - 1, i + 1))];
    const double g = (std::sqrt(5.0) - 1) / 2;
    double c = b - g * (b - a), d = a + g * (b - a), fc = f(c), fd = f(d);
    while (b - a > 1e-12) {
      if (fc < fd) {
        b = d;
        d = c;
        fd = fc;
        c = b - g * (b - a);
        fc = f(c);
      } else {
        a = c;
        c = d;
        fc = fd;
        d = a + g * (b - a);
        fd = f(d);
      }
    }
    for (auto [t, val] : {std::pair{th[static_cast<size_t>(i)], v[static_cast<size_t>(i)]}, std::pair{c, fc}, std::pair{d, fd}})
      if (val < best) {
        best = val;
        best_th = t;
      }
  }
  out.level = best;
  out.theta_min = best_th;
  if (singular)
    out.note = "G(e^{j theta}) is singular at some frequency (a zero on the unit circle): those directions impose no "
               "OSP constraint and were skipped";
  else if (const double near_zero = smin_all / smax_all; near_zero < 1e-3) {
    // a zero on or near the circle between grid points (the pencil value there is mostly
    // rounding): say where, since the strict LMI then has (almost) no interior
    char buf[160];
    std::snprintf(buf, sizeof buf,
                  "G(e^{j theta}) is nearly singular near theta = %.6g (min sigma_min / max sigma_max = %.2g on the grid): a zero "
                  "on or near the unit circle",
                  near_zero_th, near_zero);
    out.note = buf;
  }
  if (!std::isfinite(best)) {
    out.status = Status::failed;
    out.note = "G vanishes on the whole grid: the OSP level is unbounded";
  }
  return out;
}

PassivityLevel passivity_level_certified(const RationalFunction<rational>& G, PassivityKind kind, int digits) {
  PassivityLevel out;
  out.method = "frequency domain, certified: -b* of (z - 1)" + std::string(kind == PassivityKind::isp ? " G" : "/G") +
               " at T = 1 (exact objective in cos theta, Descartes isolation, MPFI)";
  out.status = Status::failed;
  if (G.num().is_zero()) {
    out.note = "G = 0";
    return out;
  }
  std::string why;
  if (!marginally_stable(G.den(), &why)) {
    out.note = "G is not stable (" + why + ")";
    return out;
  }
  // Schur stability: no pole on the circle either (marginally_stable allows simple ones)
  if (unit_circle_roots(G.den()) > 0) {
    out.note = "G has a pole on the unit circle: its passivity levels are not defined (Lemma 1 needs a stable A)";
    return out;
  }
  const RationalFunction<rational> W = kind == PassivityKind::isp ? G : RationalFunction<rational>(G.den(), G.num());
  passivity::BoundProblem p;
  p.H = RationalFunction<rational>(Polynomial<rational>({rational(-1), rational(1)})) * W;
  p.T = 1;
  p.allow_noncausal = true;
  passivity::Bound b;
  try {
    b = passivity::bound_certified(p, digits);
  } catch (const InputError& e) {
    out.note = kind == PassivityKind::osp
                   ? std::string("1/G does not meet the assumptions of the certified path (zeros of G outside the unit "
                                 "circle, or repeated on it): ") + e.what()
                   : std::string(e.what());
    return out;
  } catch (const NumericalError& e) {
    out.note = e.what();
    return out;
  }
  out.status = Status::certified;
  if (b.infinite) {
    out.level = -INFINITY;
    out.value = "-inf";
    out.note = "Re W -> -inf at " + b.where;
  } else {
    out.enclosure = Enclosure<rational>{-b.enclosure->hi, -b.enclosure->lo};
    out.lower_bound = -b.enclosure->hi;
    out.level = -b.value_double() + 0.0;  // no -0
    const std::string& d = b.decimal;
    out.value = d.empty() || d == "0" ? d : (d[0] == '-' ? d.substr(1) : "-" + d);
    if (b.status == Status::exact) out.status = Status::exact;
  }
  if (b.omega_enclosure)  // T = 1: omega = theta
    out.theta_min = to_real<double>((b.omega_enclosure->lo + b.omega_enclosure->hi) / 2);
  if (kind == PassivityKind::osp) {
    if (unit_circle_roots(G.num()) > 0)
      out.note = "G has a zero on the unit circle: delta* is the supremum of the non-strict levels; the strict "
                 "inequality (1) holds for no delta (Lemma 1's strict LMI is infeasible)";
    if (!(out.level > 0))
      out.note += std::string(out.note.empty() ? "" : "; ") +
                  "delta* <= 0: a frequency-domain index and an upper bound on Lemma 1's level only (Lemma 1 "
                  "also needs P > 0, which the frequency inequality does not impose)";
  }
  // b*'s maximiser over w (T = 1) is the level's minimiser over theta
  std::string where = b.where;
  for (auto [from, to] : {std::pair<std::string, std::string>{"w = pi/T", "theta = pi"}, {"w = 0", "theta = 0"},
                          {"every w", "every theta"}})
    if (auto i = where.find(from); i != std::string::npos) where.replace(i, from.size(), to);
  out.method += ", minimiser: " + where;
  return out;
}

PassivityLevel passivity_level_certified(const StateSpace<double>& sys, PassivityKind kind, int digits) {
  check_state_space(sys);
  if (sys.inputs() != 1)
    throw InputError("certified frequency level: SISO systems only (got " + std::to_string(sys.inputs()) + " inputs)");
  StateSpace<rational> q;
  q.A = sys.A.unaryExpr([](double v) { return exact_rational(v); });
  q.B = sys.B.unaryExpr([](double v) { return exact_rational(v); });
  q.C = sys.C.unaryExpr([](double v) { return exact_rational(v); });
  q.D = sys.D.unaryExpr([](double v) { return exact_rational(v); });
  q.T = sys.T;
  return passivity_level_certified(ss2tf(q)(0, 0).H, kind, digits);
}

}  // namespace hapstab::lmi
