// python/bind_passivity.cpp -- paper 001 and 002 in Python: the passivity bound b* (passivity/
// bound.hpp, (45)/(54)), r(jw) (sampling/, (34), (44)) and the wedge criterion (contact/wedge.hpp,
// paper 002 (25), (21)); each scalar, and b* and r vectorised over numpy arrays on threads.
//
// The passivity boundary as a number (`bound --max K --damping b`: the sup of a gain with b* < b,
// passivity::bound_max in passivity/max_gain.hpp: K_max with the closed form and the check) is
// bound_max, scalar and vectorised.
#include <mpfi.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <tuple>

#include "hapstab/contact/wedge.hpp"
#include "hapstab/numeric/decimal.hpp"
#include "hapstab/numeric/error.hpp"
#include "hapstab/passivity/bound.hpp"
#include "hapstab/passivity/catalogue.hpp"
#include "hapstab/passivity/max_gain.hpp"
#include "hapstab/sampling/r_decimal.hpp"
#include "hapstab/sampling/r_forms.hpp"
#include "python/binding.hpp"

namespace hapstab::python {
namespace {

using passivity::Bound;
using passivity::BoundProblem;
using passivity::Method;

/// The options of a bound call besides H (exact texts from Python, checked here and by the
/// library's check_assumptions).
struct BoundOptions {
  rational T;
  int delay = 0;
  std::optional<rational> frac_delay;
  rational eta = 0;
  int digits = 30;
  Method method = Method::certified;
  long grid_points = 100000;
  bool allow_noncausal = false;
};

BoundOptions bound_options(const std::string& T, int delay, const std::optional<std::string>& frac_delay,
                           const std::string& eta, int digits, const std::string& method, long grid_points,
                           bool allow_noncausal) {
  BoundOptions o;
  o.T = exact_arg(T, "T");
  if (o.T <= 0) throw InputError("T: the sample period must be > 0, got " + T);
  if (delay < 0) throw InputError("delay must be >= 0 (got " + std::to_string(delay) + ")");
  o.delay = delay;
  o.frac_delay = exact_arg(frac_delay, "frac_delay");
  if (o.frac_delay && *o.frac_delay < 0) throw InputError("frac_delay must be >= 0 (got " + *frac_delay + ")");
  if (o.frac_delay && *o.frac_delay == 0) o.frac_delay.reset();
  o.eta = exact_arg(eta, "eta");
  if (o.eta < 0) throw InputError("eta must be >= 0 (got " + eta + ")");
  o.digits = digits;
  if (method == "fast") o.method = Method::fast;
  else if (method == "grid") o.method = Method::grid;
  else if (method != "certified") throw InputError("method must be 'certified', 'fast' or 'grid' (got '" + method + "')");
  if (grid_points < 2 || grid_points > 100000000)
    throw InputError("grid_points must be in [2, 1e8] (got " + std::to_string(grid_points) + ")");
  o.grid_points = grid_points;
  o.allow_noncausal = allow_noncausal;
  return o;
}

BoundProblem problem(const RationalFunction<rational>& H, const BoundOptions& o) {
  BoundProblem p;
  p.H = H;
  p.T = o.T;
  p.delay = o.delay;
  p.frac_delay = o.frac_delay;
  p.eta = o.eta;
  p.allow_noncausal = o.allow_noncausal;
  return p;
}

Bound compute(const BoundProblem& p, const BoundOptions& o) {
  return passivity::bound(p, o.method, o.digits, o.grid_points);
}

/// The digits of the bound's printed enclosure (reported_enclosure: digits + 5 proven; 17 numeric).
int enclosure_digits(const Bound& b, int digits) { return b.status == Status::numeric ? 17 : digits + 5; }

py::dict bound_record(const Bound& b, int digits) {
  if (b.infinite) return record_infinite(b.status, b.method, b.note);
  py::dict d = record(b, enclosure_digits(b, digits));
  if (b.kind == Method::grid && b.status == Status::numeric) {  // the grid maximum only estimates b* from below
    d["hi"] = std::numeric_limits<double>::infinity();
    d["hi_text"] = "inf";
  }
  return d;
}

double omega_double(const Bound& b) {
  return b.omega ? std::strtod(b.omega->c_str(), nullptr) : std::numeric_limits<double>::quiet_NaN();
}

py::dict bound_scalar(const TransferFunction& H, const BoundOptions& o) {
  if (!H.is_discrete()) throw InputError("H: expected a transfer function in z");
  if (H.T != o.T) throw InputError("H was built with T = " + H.T.str() + ", not T = " + o.T.str());
  const BoundProblem p = problem(H.H, o);
  Bound b;
  std::optional<passivity::catalogue::Match> cf;
  {
    py::gil_scoped_release nogil;
    b = compute(p, o);
    cf = passivity::catalogue::match(p);
  }
  py::dict d = bound_record(b, o.digits);
  d["decimal"] = b.decimal;
  d["infinite"] = b.infinite;
  d["omega"] = b.omega ? py::object(py::str(*b.omega)) : py::object(py::none());
  d["where"] = b.where;
  d["enclosure_rigorous"] = passivity::enclosure_rigorous(b);
  if (cf) {
    py::dict c;
    c["name"] = cf->name;
    c["equation"] = cf->equation;
    c["formula"] = cf->formula;
    c["value"] = cf->infinite ? py::object(py::str("inf"))
                 : cf->value  ? py::object(py::str(cf->value->str()))
                              : py::object(py::none());
    c["approx"] = cf->approx ? py::object(py::float_(*cf->approx)) : py::object(py::none());
    c["tight"] = cf->tight;
    d["closed_form"] = c;
  } else {
    d["closed_form"] = py::none();
  }
  return d;
}

/// b* at every point of the parameter columns: H parsed from `expr` with point i's values.
py::dict bound_many(const std::string& expr, const std::map<std::string, std::string>& fixed_texts,
                    const std::vector<std::string>& names, const py::list& columns, const BoundOptions& o, unsigned jobs) {
  std::map<std::string, rational> fixed;
  for (const auto& [k, v] : fixed_texts) fixed[k] = exact_arg(v, "params['" + k + "']");
  const Columns cols = Columns::from_python(names, columns);
  const ParsedExpression H_of = parsed(expr, "H", 'z', o.T, fixed, cols, HiddenPoles::allow_marginal);  // once; as `bound`
  const size_t n = cols.points;
  PointColumns c(n);
  std::vector<double> omega(n, std::numeric_limits<double>::quiet_NaN());
  run_points(n, jobs, [&](uint64_t i) {
    try {
      TransferFunction H;
      try {
        H = H_of.at(cols.at({}, i));
      } catch (const InputError& e) {
        throw InputError(std::string("H: ") + e.what());
      }
      const Bound b = compute(problem(H.H, o), o);
      c.status[i] = status_code(b.status);
      omega[i] = omega_double(b);
      if (b.infinite) {
        c.value[i] = c.lo[i] = c.hi[i] = std::numeric_limits<double>::infinity();
        return;
      }
      c.enclose(i, b.enclosure->lo, b.enclosure->hi, enclosure_digits(b, o.digits));
      c.value[i] = b.value_double();
      if (b.kind == Method::grid && b.status == Status::numeric) {  // the grid maximum estimates b* from below
        c.hi[i] = std::numeric_limits<double>::infinity();
        c.hi_exact[i] = "inf";
      }
      if (b.status == Status::exact) c.exact[i] = b.value.str();
    } catch (const std::exception& e) {
      c.error[i] = point_error(e);
    }
  });
  py::dict d = c.dict();
  d["omega"] = doubles(omega);
  return d;
}

// ---- the passivity boundary as a number: sup K with b*(K) < b ---------------------------------

/// H = H0 + name H1 from the expression at these parameter values (lti/parse.hpp split_affine, as
/// `bound --max` splits --H), both in z.
passivity::GainProblem gain_problem(const std::string& expr, const std::string& name,
                                    const std::map<std::string, rational>& params, const rational& b,
                                    const BoundOptions& o) {
  AffineSplit h;
  try {
    h = split_affine(expr, parse_options('z', o.T, params, HiddenPoles::allow_marginal), name);  // as `bound --max`
  } catch (const InputError& e) {
    throw InputError("max='" + name + "': H: " + e.what());
  }
  for (const TransferFunction* t : {&h.H0, &h.H1})
    if (!t->is_discrete()) throw InputError("H: expected a transfer function in z");
  if (b <= 0) throw InputError("damping must be > 0 (got " + b.str() + ")");
  passivity::GainProblem g;
  g.base = problem(h.H0.H, o);
  g.H1 = h.H1.H;
  g.b = b;
  g.name = name;
  return g;
}

py::object omega_ends(const std::optional<Enclosure<rational>>& w) {
  if (!w) return py::none();
  return py::make_tuple(double_outward(w->lo, -1), double_outward(w->hi, +1));
}

/// K_max as a record (value, lo, hi, status, ...) and its fields: `bound --max` in Python.
py::dict bound_max_scalar(const std::string& expr, const std::map<std::string, std::string>& fixed_texts,
                          const std::string& name, const std::string& damping, const BoundOptions& o, bool check) {
  std::map<std::string, rational> params;
  for (const auto& [k, v] : fixed_texts) params[k] = exact_arg(v, "params['" + k + "']");
  if (params.count(name)) throw InputError("params['" + name + "']: " + name + " is the parameter maximised (max='" + name + "'); leave it out of params");
  passivity::GainProblem g = gain_problem(expr, name, params, exact_arg(damping, "damping"), o);
  passivity::BoundMax r;
  {
    py::gil_scoped_release nogil;
    r = passivity::bound_max(std::move(g), o.digits, check);
  }
  const passivity::MaxGain& m = r.max;
  py::dict d = m.infinite ? record_infinite(m.status, m.method, m.note)
                          : record(m, m.outcome == Outcome::holds ? o.digits + 3 : o.digits);
  d["name"] = name;
  d["outcome"] = to_string(m.outcome);
  d["infinite"] = m.infinite;
  d["decimal"] = m.decimal;
  d["digits_certified"] = m.digits;
  d["damping"] = r.problem.b.str();
  d["b_at_zero"] = bound_record(m.at_zero, o.digits);
  d["omega"] = omega_ends(m.omega);
  d["where"] = m.where;
  d["jump"] = m.jump;  // b*(K_max) <= b and +inf above (passivity::MaxGain::jump)
  d["b_at_sup"] = m.jump ? py::object(bound_record(*m.at_sup, o.digits)) : py::object(py::none());
  if (const auto& cf = r.closed_form) {
    py::dict c;
    c["name"] = cf->name;
    c["equation"] = cf->equation;
    c["formula"] = cf->formula;
    c["value"] = passivity::closed_form_decimal(*cf, o.digits);
    c["tight"] = cf->tight;
    c["agrees"] = passivity::agrees(*cf, m);
    d["closed_form"] = c;
  } else {
    d["closed_form"] = py::none();
  }
  if (const auto& k = r.check) {
    py::dict c;
    c["holds"] = k->holds;
    c["bound_at_lo"] = bound_record(k->at_lo, o.digits);
    c["bound_at_hi"] = bound_record(k->at_hi, o.digits);
    d["check"] = c;
  } else {
    d["check"] = py::none();
  }
  return d;
}

/// K_max at every point of parameter columns (the other parameters of H, and the damping b when
/// `damping` is a column), on threads: value/lo/hi (inf: passive for every K; 0: not passive at
/// K = 0), omega (where b* = b at K_max, NaN when unknown), b_at_zero (b*(0), its value).
py::dict bound_max_many(const std::string& expr, const std::map<std::string, std::string>& fixed_texts,
                        const std::vector<std::string>& names, const py::list& columns, const std::string& name,
                        const py::object& damping, const BoundOptions& o, unsigned jobs) {
  std::map<std::string, rational> fixed;
  for (const auto& [k, v] : fixed_texts) fixed[k] = exact_arg(v, "params['" + k + "']");
  const Columns cols = Columns::from_python(names, columns);
  if (fixed.count(name) || std::find(names.begin(), names.end(), name) != names.end())
    throw InputError("params['" + name + "']: " + name + " is the parameter maximised (max='" + name + "'); leave it out of params");
  std::optional<rational> b_fixed;
  Columns b_col;
  if (py::isinstance<py::str>(damping)) {
    b_fixed = exact_arg(damping.cast<std::string>(), "damping");
  } else {
    py::list l;
    l.append(damping);
    b_col = Columns::from_python({"damping"}, l);
    if (!names.empty() && b_col.points != cols.points)
      throw std::logic_error("bound_max_many: damping and params differ in length");
  }
  {
    std::map<std::string, rational> named = fixed;
    named[name] = 0;
    check_names(expr, "H", 'z', named, cols);  // a mistake of the whole call, raised once
  }
  const size_t n = b_fixed || !names.empty() ? cols.points : b_col.points;
  PointColumns c(n);
  std::vector<double> omega(n, std::numeric_limits<double>::quiet_NaN()), at_zero(omega);
  run_points(n, jobs, [&](uint64_t i) {
    try {
      const rational b = b_fixed ? *b_fixed : b_col.values[0][i];
      const passivity::MaxGain m = passivity::max_gain(gain_problem(expr, name, cols.at(fixed, i), b, o), o.digits);
      at_zero[i] = m.at_zero.infinite ? std::numeric_limits<double>::infinity() : m.at_zero.value_double();
      if (m.omega) omega[i] = to_real<double>((m.omega->lo + m.omega->hi) / 2);
      c.status[i] = status_code(m.status);
      if (m.infinite) {
        c.value[i] = c.lo[i] = c.hi[i] = std::numeric_limits<double>::infinity();
        return;
      }
      c.enclose(i, m.enclosure->lo, m.enclosure->hi, o.digits + 3);
      if (m.status == Status::exact) c.value[i] = to_real<double>(m.value), c.exact[i] = m.value.str();
    } catch (const std::exception& e) {
      c.error[i] = point_error(e);
    }
  });
  py::dict d = c.dict();
  d["omega"] = doubles(omega);
  d["b_at_zero"] = doubles(at_zero);
  return d;
}

// ---- r(jw) -----------------------------------------------------------------------------------

/// An enclosure of the value a correctly rounded `digits`-digit decimal stands for: the decimal
/// -+ half a unit in its last place (at the decade of |q|, or wider).
Enclosure<rational> correctly_rounded(const std::string& text, int digits) {
  const rational q = parse_rational(text, "r");
  if (q == 0) return {q, q};
  const rational a = q < 0 ? rational(-q) : q;
  long e = 0;
  while (a >= pow10(e + 1)) ++e;
  while (a < pow10(e)) --e;
  const rational half = pow10(e - digits + 1) / 2;
  return {q - half, q + half};
}

/// r(jw) at one exact w: (44) correctly rounded (sampling::r44_decimal); with `terms`, the series
/// (34) truncated at |n| <= terms beside (sampling::r_decimal: the same (44) digits). Without, the
/// series fields are None: a call that needs only r(jw) does not sum 2 terms + 1 terms (issue 49).
py::dict r_scalar(const std::string& T_text, const std::string& omega_text, int digits, std::optional<long> terms) {
  const rational T = exact_arg(T_text, "T"), w = exact_arg(omega_text, "omega");  // r_decimal checks them
  sampling::RDecimal r;
  {
    py::gil_scoped_release nogil;
    if (terms) {
      r = sampling::r_decimal(T, w, *terms, digits);
    } else {
      std::tie(r.re, r.im) = sampling::r44_decimal(T, w, digits);
    }
  }
  py::dict d;
  d["re"] = record(Certified<rational>::exact_value(-T / 2, "closed form (44): Re r = -T/2"), digits);
  const Enclosure<rational> im = correctly_rounded(r.im, digits);
  d["im"] = record(im, (im.lo + im.hi) / 2, Status::certified,
                   "closed form (44): Im r = -(T/2) cot(wT/2), correctly rounded from MPFI enclosures", "", digits + 2);
  d["re_text"] = r.re;
  d["im_text"] = r.im;
  const auto text_or_none = [&](const std::string& s) { return terms ? py::object(py::str(s)) : py::object(py::none()); };
  d["series_re"] = text_or_none(r.series_re);
  d["series_im"] = text_or_none(r.series_im);
  d["series_terms"] = terms ? py::object(py::int_(r.series_terms)) : py::object(py::none());
  d["series_error_bound"] = r.series_error_bound ? py::object(py::str(*r.series_error_bound)) : py::object(py::none());
  return d;
}

/// r(jw) over an array of w (each at its exact binary value) for one exact T.
///   method "double":    (44) in double with theta = fl(w T) (r_forms.hpp: <= 1.51 eps relative in
///                       Im for the rounded theta); lo/hi: that band widened by the effect of
///                       rounding theta, |d Im/d theta| |theta| eps/2 -- numeric (libm's tan is not proven).
///   method "certified": MPFI at 128 bits, the exact theta: lo/hi rounded outward, proven.
py::dict r_many(const std::string& T_text, const py::array_t<double, py::array::c_style | py::array::forcecast>& omega,
                const std::string& method, unsigned jobs) {
  const rational Tq = exact_arg(T_text, "T");
  if (Tq <= 0) throw InputError("T: the sample period must be > 0, got " + T_text);
  if (method != "double" && method != "certified")
    throw InputError("method must be 'double' or 'certified' (got '" + method + "')");
  const auto w = omega.unchecked<1>();
  const size_t n = size_t(w.shape(0));
  for (size_t i = 0; i < n; ++i)
    if (!std::isfinite(w(i)) || w(i) == 0)
      throw InputError("omega[" + std::to_string(i) + "]: " + std::to_string(w(i)) +
                       (w(i) == 0 ? " is a pole of r(jw) (w = 0)" : " is not a finite number"));
  const double* wp = omega.data();
  const auto size = static_cast<py::ssize_t>(n);
  py::array_t<double> im(size), lo(size), hi(size);
  double *imp = im.mutable_data(), *lop = lo.mutable_data(), *hip = hi.mutable_data();
  const double T = to_real<double>(Tq);
  const bool T_exact = exact_rational(T) == Tq;
  if (method == "double") {
    // block-wise on threads: one point is nanoseconds
    const size_t block = 1 << 14, blocks = (n + block - 1) / block;
    constexpr double eps = std::numeric_limits<double>::epsilon();
    run_points(blocks, jobs, [&](uint64_t k) {
      for (size_t i = k * block; i < std::min(n, (k + 1) * block); ++i) {
        const double theta = wp[i] * T;
        const double t = std::tan(theta / 2);
        const double v = -(T / 2) / t;  // r_eq44 (sampling/r_forms.hpp), its tan kept for the band
        // 1.51 eps |Im| for the rounded theta (r_forms.hpp), plus theta's own rounding (and T's,
        // when T is not a double) through |d Im/d theta| = (T/4)/sin^2(theta/2), sin^2 = t^2/(1 + t^2);
        // 2x for safety
        const double dtheta = std::fabs(theta) * eps * (T_exact ? 0.5 : 1.5);
        const double err = 2 * (1.51 * eps * std::fabs(v) + T / 4 * dtheta * (1 + t * t) / (t * t));
        imp[i] = v;
        lop[i] = v - err;
        hip[i] = v + err;
      }
    });
  } else {
    run_points(n, jobs, [&](uint64_t i) {
      mpfi_t t, x;
      mpfi_init2(t, 128);
      mpfi_init2(x, 128);
      mpfi_set_q(t, Tq.backend().data());
      mpfi_set_d(x, wp[i]);  // exact
      mpfi_mul(x, x, t);     // theta
      mpfi_div_2ui(x, x, 1);
      mpfi_cot(x, x);
      mpfi_div_2ui(t, t, 1);
      mpfi_mul(x, x, t);
      mpfi_neg(x, x);  // Im r = -(T/2) cot(theta/2)
      mpfr_t e;
      mpfr_init2(e, 128);
      mpfi_get_left(e, x);
      lop[i] = mpfr_get_d(e, MPFR_RNDD);
      mpfi_get_right(e, x);
      hip[i] = mpfr_get_d(e, MPFR_RNDU);
      mpfi_mid(e, x);
      imp[i] = mpfr_get_d(e, MPFR_RNDN);
      mpfr_clear(e);
      mpfi_clear(t);
      mpfi_clear(x);
    });
  }
  py::dict d;
  d["re"] = -to_real<double>(Tq / 2);
  d["re_exact"] = rational(-Tq / 2).str();
  d["im"] = im;
  d["lo"] = lo;
  d["hi"] = hi;
  return d;
}

// ---- wedge (paper 002) -----------------------------------------------------------------------

py::dict criterion(const contact::CriterionReport& c, int digits) {
  py::dict d;
  d["name"] = c.name;
  d["evaluated"] = c.evaluated();
  d["holds"] = c.evaluated() ? py::object(py::bool_(c.verdict.holds())) : py::object(py::none());
  d["evidence"] = c.verdict.evidence;
  if (!c.evaluated()) return d;
  d["margin"] = record(c.margin, digits + 5);
  d["theta_at_min"] = c.theta_at_min;
  d["gain_infinite"] = c.gain_infinite;
  d["max_gain"] = c.gain_infinite ? py::object(py::none()) : py::object(record(c.max_gain, digits + 5));
  return d;
}

py::dict wedge(const TransferFunction& H, int digits) {
  if (digits < 1 || digits > 60) throw InputError("digits must be in [1, 60], got " + std::to_string(digits));
  if (!H.is_discrete()) throw InputError("H: expected a transfer function in z");
  if (!H.is_proper()) throw InputError("H: H(z) = " + H.to_string() + " is not causal (deg num > deg den)");
  contact::ContactAnalysis a;
  {
    py::gil_scoped_release nogil;
    a = contact::analyze_contact(H, digits);
  }
  py::dict d;
  d["H"] = a.H.to_string();
  d["wedge"] = criterion(a.wedge, digits);
  d["tsypkin"] = criterion(a.tsypkin, digits);
  d["assumptions"] = a.assumptions.violated;
  d["applies"] = a.applies();
  d["H1"] = a.assumptions.h1 ? py::object(py::str(a.assumptions.h1->str())) : py::object(py::none());
  return d;
}

}  // namespace

void register_passivity(py::module_& m) {
  m.def(
      "bound",
      [](const TransferFunction& H, const std::string& T, int delay, const std::optional<std::string>& frac_delay,
         const std::string& eta, int digits, const std::string& method, long grid_points, bool allow_noncausal) {
        return bound_scalar(H, bound_options(T, delay, frac_delay, eta, digits, method, grid_points, allow_noncausal));
      },
      py::arg("H"), py::arg("T"), py::arg("delay"), py::arg("frac_delay"), py::arg("eta"), py::arg("digits"),
      py::arg("method"), py::arg("grid_points"), py::arg("allow_noncausal"),
      "b* of paper 001 (45)/(54) for H (passivity::bound), with the closed form of the catalogue that applies.");
  m.def(
      "bound_many",
      [](const std::string& expr, const std::map<std::string, std::string>& fixed, const std::vector<std::string>& names,
         const py::list& columns, const std::string& T, int delay, const std::optional<std::string>& frac_delay,
         const std::string& eta, int digits, const std::string& method, long grid_points, bool allow_noncausal,
         unsigned jobs) {
        return bound_many(expr, fixed, names, columns,
                          bound_options(T, delay, frac_delay, eta, digits, method, grid_points, allow_noncausal), jobs);
      },
      py::arg("expr"), py::arg("fixed"), py::arg("names"), py::arg("columns"), py::arg("T"), py::arg("delay"),
      py::arg("frac_delay"), py::arg("eta"), py::arg("digits"), py::arg("method"), py::arg("grid_points"),
      py::arg("allow_noncausal"), py::arg("jobs"),
      "b* at every point of parameter columns (numpy float64 arrays or lists of exact texts), on threads.");
  m.def(
      "bound_max",
      [](const std::string& expr, const std::map<std::string, std::string>& fixed, const std::string& name,
         const std::string& damping, const std::string& T, int delay, const std::optional<std::string>& frac_delay,
         const std::string& eta, int digits, bool allow_noncausal, bool check) {
        return bound_max_scalar(expr, fixed, name, damping,
                                bound_options(T, delay, frac_delay, eta, digits, "certified", 100000, allow_noncausal),
                                check);
      },
      py::arg("expr"), py::arg("fixed"), py::arg("name"), py::arg("damping"), py::arg("T"), py::arg("delay"),
      py::arg("frac_delay"), py::arg("eta"), py::arg("digits"), py::arg("allow_noncausal"), py::arg("check"),
      "sup of the gain `name` of H with b*(name) < damping (passivity::max_gain), its closed form, and with check "
      "b* at the ends of its enclosure (`hapstab bound --max NAME --damping b`).");
  m.def(
      "bound_max_many",
      [](const std::string& expr, const std::map<std::string, std::string>& fixed, const std::vector<std::string>& names,
         const py::list& columns, const std::string& name, const py::object& damping, const std::string& T, int delay,
         const std::optional<std::string>& frac_delay, const std::string& eta, int digits, bool allow_noncausal,
         unsigned jobs) {
        return bound_max_many(expr, fixed, names, columns, name, damping,
                              bound_options(T, delay, frac_delay, eta, digits, "certified", 100000, allow_noncausal),
                              jobs);
      },
      py::arg("expr"), py::arg("fixed"), py::arg("names"), py::arg("columns"), py::arg("name"), py::arg("damping"),
      py::arg("T"), py::arg("delay"), py::arg("frac_delay"), py::arg("eta"), py::arg("digits"),
      py::arg("allow_noncausal"), py::arg("jobs"),
      "bound_max at every point of parameter columns (and of a damping column), on threads.");
  m.def("r", &r_scalar, py::arg("T"), py::arg("omega"), py::arg("digits"), py::arg("terms"),
        "r(jw) of paper 001: (44) correctly rounded; with terms (not None), the series (34) truncated beside.");
  m.def("r_many", &r_many, py::arg("T"), py::arg("omega"), py::arg("method"), py::arg("jobs"),
        "Im r(jw) over a float64 array of w: 'double' (44) in double, or 'certified' MPFI enclosures.");
  m.def("wedge", &wedge, py::arg("H"), py::arg("digits"),
        "The wedge criterion (25) and Tsypkin's condition (21) of paper 002 (contact::analyze_contact).");
}

}  // namespace hapstab::python
