// hapstab/lmi/passivity_level_report.cpp -- see passivity_level_report.hpp.
#include "hapstab/lmi/passivity_level_report.hpp"

#include <Eigen/Eigenvalues>
#include <cmath>
#include <sstream>

#include "hapstab/lti/realization.hpp"
#include "hapstab/numeric/decimal.hpp"
#include "hapstab/numeric/error.hpp"

namespace hapstab::lmi {

namespace {
// G(z) = D + C (zI - A)^{-1} B of a one-input, one-output model as written, exactly: by the matrix
// determinant lemma det(zI - A + BC) = det(zI - A) (1 + C (zI - A)^{-1} B), so
// G = D + (det(zI - A + BC) - det(zI - A)) / det(zI - A).
RationalFunction<rational> siso_transfer(const StateSpace<rational>& s) {
  const Polynomial<rational> d = charpoly(s.A);
  const Mat<rational> closed = s.A - s.B * s.C;
  return RationalFunction<rational>(charpoly(closed) - d + d * Polynomial<rational>(s.D(0, 0)), d);
}
// The LMI's exact check ran on the doubles the SDP saw; the printed "level >= lo" is about the model
// as written: Lemma 1 is checked again, exactly, on its entries (--ss, --mat) or on G's realisation
// (--H: tf2ss, which the doubles round), with the rounded P. Where it fails there, or cannot be
// checked (Lemma 2 keeps no P) and the doubles differ from the entries, no lower bound is stated.
void lower_bound_as_written(PassivityLevel& l, const LevelModel& m, PassivityKind kind) {
  if (!l.lower_bound || (!m.exact && !m.G)) return;
  const StateSpace<rational> written = m.exact ? *m.exact : tf2ss(TransferFunction{*m.G, Domain::z, m.sys.T});
  bool holds;
  if (l.lemma1_P) {
    holds = lemma1_holds(written, *l.lemma1_P, *l.lower_bound, kind);
  } else {
    const auto same = [](const Mat<rational>& E, const Mat<double>& R) {
      return E.rows() == R.rows() && E.cols() == R.cols() &&
             E == Mat<rational>(R.unaryExpr([](double x) { return exact_rational(x); }));
    };
    holds = same(written.A, m.sys.A) && same(written.B, m.sys.B) && same(written.C, m.sys.C) && same(written.D, m.sys.D);
  }
  if (holds) return;
  l.lower_bound.reset();
  l.lemma1_P.reset();
  l.note += std::string(l.note.empty() ? "" : "; ") +
            (l.lemma1_P ? "the rounded LMI solution meets Lemma 1 for the model's doubles, not for its entries as written"
                        : "the rounded LMI solution meets Lemma 2 for the model's doubles, which differ from its entries as "
                          "written (Lemma 2 keeps no P to check them with; --lemma 1 does)") +
            ": no lower bound is stated";
}

}  // namespace

void check_schur_stable(const StateSpace<double>& sys, const std::string& name) {
  if (sys.states() == 0) return;
  const Eigen::VectorXcd ev = Eigen::EigenSolver<Eigen::MatrixXd>(sys.A).eigenvalues();
  for (Eigen::Index i = 0; i < ev.size(); ++i)
    if (std::abs(ev(i)) > 1 - 1e-9) {
      std::ostringstream os;
      os << name << ": pole at z = " << ev(i).real() << (ev(i).imag() >= 0 ? " + " : " - ") << std::abs(ev(i).imag())
         << "j, |z| = " << std::abs(ev(i))
         << (std::abs(ev(i)) > 1 + 1e-9 ? " > 1: the system is unstable" : ": on the unit circle (within 1e-9)")
         << "; passivity levels (Lemmas 1-2) need a Schur-stable system";
      throw InputError(os.str());
    }
}

Levels passivity_levels(const LevelModel& m, PassivityKind kind, int lemma, Backend backend, int grid, int digits) {
  const StateSpace<double>& sys = m.sys;
  Levels v;
  auto &l = v.l, &f = v.f, &c = v.c;
  l.status = f.status = c.status = Status::failed;
  if (sys.states() == 0) l.note = f.note = c.note = "static gain: no state";
  if (sys.states() > 0) {
    l = passivity_level_lmi(sys, kind, lemma, backend);
    lower_bound_as_written(l, m, kind);
    f = passivity_level_freq(sys, kind, grid);
    if (sys.inputs() == 1)
      // the model as written (--H; --ss: its exact entries; --mat: its doubles' exact values)
      // (a one-input --ss certified on its doubles printed 0.24999999999999999 "exact" for 1/4)
      c = m.G       ? passivity_level_certified(*m.G, kind, digits)
          : m.exact ? passivity_level_certified(siso_transfer(*m.exact), kind, digits)
                    : passivity_level_certified(sys, kind, digits);
    else if (m.exact)
      c = passivity_level_certified_mimo(*m.exact, kind, digits, f.status != Status::failed ? f.theta_min : -1.0);
    else c.note = "certified frequency path: no exact model";
  }
  v.lmi_ok = l.status != Status::failed, v.freq_ok = f.status != Status::failed, v.cert_ok = c.status != Status::failed;
  // The certified value is the level of Definition 2 for ISP, and for OSP when delta* > 0
  // (passivity_level.hpp); an OSP delta* <= 0 is an upper bound on Lemma 1's level only.
  v.cert_is_level = v.cert_ok && (kind == PassivityKind::isp || c.level > 0);
  // main result: the certified level (an enclosure of the level itself), else the LMI
  // (a numeric level with a certified lower bound), else the frequency grid (numeric)
  using M = Levels::Main;
  v.which = v.cert_is_level ? M::cert : v.lmi_ok ? M::lmi : v.cert_ok ? M::cert : M::freq;
  v.only_bound = v.which == M::cert && !v.cert_is_level;  // OSP delta* <= 0 and no LMI level
  v.note = v.main().note;
  auto add = [&](const std::string& what, const std::string& n, M from) {
    if (!n.empty() && v.which != from) v.note += (v.note.empty() ? "" : "; ") + what + n;
  };
  add(sys.inputs() == 1 ? "certified frequency path: " : "", c.note, M::cert);
  if (!v.lmi_ok) add("LMI: ", l.note, M::lmi);
  // compared only where the frequency value is the level (ISP; OSP > 0): an OSP value <= 0 is
  // an upper bound that the LMI level may lie below
  const double ref = v.cert_ok ? c.level : f.level;
  const bool comparable = kind == PassivityKind::isp || ref > 0;
  if (v.lmi_ok && (v.cert_ok || v.freq_ok) && comparable && std::isfinite(ref) &&
      std::abs(l.level - ref) > 1e-5 * std::max(1.0, std::abs(ref)))
    v.note += (v.note.empty() ? "" : "; ") + std::string("LMI and frequency-domain levels disagree beyond 1e-5");
  v.any = v.cert_ok || v.lmi_ok || v.freq_ok;
  return v;
}

}  // namespace hapstab::lmi
