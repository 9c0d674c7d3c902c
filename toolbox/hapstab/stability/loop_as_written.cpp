// The loop as written, decided (see loop_as_written.hpp).
#include "hapstab/stability/loop_as_written.hpp"

#include <cmath>
#include <sstream>

#include "hapstab/lti/realization.hpp"
#include "hapstab/numeric/decimal.hpp"
#include "hapstab/numeric/error.hpp"
#include "hapstab/numeric/exact_matrix.hpp"
#include "hapstab/numeric/limits.hpp"
#include "hapstab/numeric/numeric_decimal.hpp"
#include "hapstab/poly/stability.hpp"
#include "hapstab/sim/closed_loop.hpp"
#include "hapstab/stability/sampled_loop.hpp"
#include "hapstab/stability/symmetry.hpp"

namespace hapstab::stability {

namespace {

bool one_dof(const sim::LoopSpec& s) {
  return s.dofs() == 1 && s.devices.size() == 1 && s.operators.size() <= 1;
}

// Step 2: the one-DOF loop on transfer functions (sampled_loop.hpp). nullopt when that test
// does not apply (a fractional delay) or refuses the loop (its size limits): the matrix decides.
std::optional<LoopVerdict> one_dof_test(const sim::LoopSpec& L, LoopVerdict out) {
  if (bmp::denominator(L.delay / L.T) != 1) return std::nullopt;  // fractional delay: the matrix models it
  if (!L.environment) return std::nullopt;  // no controller: the matrix (a free device) decides
  Loop loop = one_dof_loop(L);
  const TransferFunction E = loop.H;
  std::string hidden;
  if (L.coupling) {
    const TransferFunction V = ss2tf(*L.coupling)(0, 0);
    loop.H = feedback(E, V);  // u = -E (x + V u): force -E/(1 + E V) x
    // the full controller's characteristic polynomial over the reduced one: the cancelled modes
    const Polynomial<rational> full = E.den() * V.den() + E.num() * V.num();
    if (full.is_zero()) throw InputError("the coupling's algebraic loop 1 + E V is identically zero");
    const auto [cancelled, rem] = divmod(full, loop.H.den());
    if (!rem.is_zero()) throw NumericalError("loop as written: E/(1 + E V) does not divide the controller's polynomial");
    if (cancelled.degree() > 0 && !hapstab::schur_stable(cancelled)) {
      out.stable = false;
      out.status = Status::exact;
      out.method = "exact Schur test (one DOF)";
      out.path = "polynomial";
      out.why = "the controller E/(1 + E V) cancels a mode outside the open unit disk (Schur-Cohn on the exact "
                "cancelled factor of degree " + std::to_string(cancelled.degree()) + "): NOT stable as written (exact)";
      return out;
    }
    if (cancelled.degree() > 0)
      hidden = "; the " + std::to_string(cancelled.degree()) + " modes E/(1 + E V) cancels are stable (exact)";
  }
  StabilityResult r;
  try {
    r = decide(loop);
  } catch (const InputError&) {  // a size the transfer-function test refuses: the matrix decides
    return std::nullopt;
  }
  if (!r.verdict.decided()) return std::nullopt;
  out.method = "exact Schur test (one DOF; the loop of `hapstab stability`)";
  out.path = r.path;
  out.stable = r.verdict.holds();
  out.status = r.verdict.status;
  std::ostringstream o;
  o << (r.verdict.holds() ? "stable" : "NOT stable") << " [" << to_string(r.verdict.status)
    << "]: the one-DOF sampled loop (device, operator, ZOH, " << (L.coupling ? "E/(1 + E V)" : "E")
    << (loop.delay ? ", delay z^-" + std::to_string(loop.delay) : std::string()) << ")";
  if (r.spectral_radius) {
    // the loop as written's: the reduced loop's and every hidden mode's (they are eigenvalues of
    // it too): a hidden mode at 1 - 1e-30 is the radius, not the reduced loop's 0.96
    // one ulp outward of the nearest doubles, then printed rounded outward: 1 - 1e-30 is printed
    // [0.999999, 1], never [1, 1]
    double lo = std::nextafter(to_real<double>(r.spectral_radius->lo), 0.0);
    double hi = std::nextafter(to_real<double>(r.spectral_radius->hi), INFINITY);
    const double T = to_real<double>(L.T);
    for (const auto& h : out.hidden.modes) {
      if (h.settles) continue;  // set aside, like the plant's conserved quantities (named below)
      const double a = h.discrete ? h.where.abs_lo : std::exp(h.where.re_lo * T), b = h.discrete ? h.where.abs_hi : std::exp(h.where.re_hi * T);
      lo = std::max(lo, std::nextafter(a, 0.0));
      hi = std::max(hi, std::nextafter(b, INFINITY));
    }
    o << ", spectral radius " << (out.hidden.modes.empty() ? "" : "of the loop as written (its decaying hidden modes included) ") << "in ["
      << decimal_outward(exact_rational(lo), 6, -1) << ", " << decimal_outward(exact_rational(hi), 6, +1) << "]";
    out.spectral_radius = hi;
  }
  out.why = o.str() + hidden;
  return out;
}

// Step 3: the closed-loop matrix.
// `reduced`: which blocks were replaced by their minimal realisations ("" when none).
LoopVerdict matrix_test(const sim::LoopSpec& L, LoopVerdict out, const std::string& reduced) {
  const sim::SampledClosedLoop cl = sim::sampled_closed_loop(L);
  out.states = static_cast<long>(cl.M.rows());
  out.path = "closed_loop_matrix";
  if (cl.removed_undecided) {
    out.method = "closed-loop matrix, exact Kalman splits of the plant";
    out.why = "undecided: " + cl.removed;
    return out;
  }
  if (cl.removed_unstable) {
    out.stable = false;
    out.status = Status::exact;
    out.method = "closed-loop matrix, exact Kalman split of the plant";
    out.why = "NOT stable [exact]: " + cl.removed;
    return out;
  }
  const std::string dims = "closed-loop matrix M of order " + std::to_string(out.states) + " (" +
                           std::to_string(cl.plant_states) + " plant, " + std::to_string(cl.controller_states) +
                           " controller, " + std::to_string(cl.buffer_states) + " delay states; realisations as written" + reduced +
                           (cl.removed.empty() ? "" : "; " + cl.removed) + ")";
  if (cl.exact && out.states <= kExactOrder) {
    const Polynomial<rational> c = charpoly(*cl.exact);
    std::string why;
    const bool st = hapstab::schur_stable(c, &why);
    out.stable = st;
    out.status = Status::exact;
    out.method = "closed-loop matrix, exact (Schur-Cohn on det(zI - M))";
    out.why = std::string(st ? "stable" : "NOT stable") + " [exact]: " + dims +
              " is rational (every plant pole at s = 0, so e^{AT} is a finite sum); Schur-Cohn on its characteristic "
              "polynomial of degree " + std::to_string(c.degree()) + (st ? "" : ": " + why);
    return out;
  }
  SchurDecision d = schur_decide(cl.M);
  if (!d.stable)  // entries over many decades: the balanced ball (the same eigenvalues) is decided where M is not
    if (const auto B = balanced(cl.M)) {
      SchurDecision db = schur_decide(*B);
      if (db.stable) d = std::move(db), d.why += " (on M balanced by a diagonal of powers of two: D^-1 M D)";
    }
  out.spectral_radius = d.spectral_radius;
  if (d.stable) {
    out.stable = *d.stable;
    out.status = Status::certified;
    out.method = "closed-loop matrix, Stein certificate in ball arithmetic";
    out.why = std::string(*d.stable ? "stable" : "NOT stable") + " [certified]: " + dims + " enclosed (largest radius " +
              numeric_decimal(cl.M.max_radius(), 3) + "); " + d.why;
    return out;
  }
  // the certificate cannot decide: z = 1 exactly (closed_loop.hpp, G1)
  if (exact_rank(cl.dc) < cl.dc.rows()) {
    out.stable = false;
    out.status = Status::exact;
    out.method = "closed-loop matrix, exact test of z = 1";
    out.why = "NOT stable [exact]: " + dims + " has the eigenvalue z = 1 (the DC equations A s + B u = 0, "
              "(A_c - I) xi + B_c y = 0, u = C_c xi + D_c y have a nonzero solution: a family of equilibria, exact rank "
              "test); " + d.why;
    return out;
  }
  out.method = "closed-loop matrix";
  out.why = "undecided: " + dims + ": " + d.why + "; z = 1 is not an eigenvalue (exact)";
  return out;
}

// Step 2b: a loop of identical DOFs, split by its symmetry (symmetry.hpp) into an r-DOF loop and
// one one-DOF loop per class, each decided by decide_loop: stable iff every one is.
LoopVerdict by_symmetry(const detail::LoopSymmetry& s, LoopVerdict out) {
  struct Part {
    std::string label;
    LoopVerdict v;
  };
  std::vector<Part> parts;
  parts.push_back({"the loop of " + std::to_string(s.classes.size()) + " DOF" + (s.classes.size() > 1 ? "s" : "") +
                       " on the space fixed by the group", decide_loop(s.fixed)});
  for (size_t k = 0; k < s.standard.size(); ++k) {
    const auto& c = s.classes[static_cast<size_t>(s.standard_class[k])];
    parts.push_back({"the one-DOF loop of class " + std::to_string(s.standard_class[k] + 1) + " (DOFs " +
                         std::to_string(c.front() + 1) + ", " + std::to_string(c[1] + 1) + (c.size() > 2 ? ", ..." : "") +
                         "), multiplicity " + std::to_string(c.size() - 1),
                     decide_loop(s.standard[k])});
  }
  out.path = "symmetry";
  out.method = "symmetry " + s.group() + ": " + std::to_string(parts.size()) + " small loops";
  const std::string head = "by the permutations of identical DOFs, " + s.group() +
                           " (proven exactly on the realisations as written), the closed loop's spectrum is that of " +
                           std::to_string(parts.size()) + " small loops (stability/symmetry.hpp)";
  const Part* fail = nullptr;
  const Part* open = nullptr;
  bool certified = false;
  std::optional<double> radius = 0.0;
  for (const Part& p : parts) {
    if (p.v.stable && !*p.v.stable && !fail) fail = &p;
    if (!p.v.stable && !open) open = &p;
    certified = certified || p.v.status == Status::certified;
    radius = radius && p.v.spectral_radius ? std::optional<double>(std::max(*radius, *p.v.spectral_radius)) : std::nullopt;
  }
  out.spectral_radius = radius;
  if (fail) {
    out.stable = false;
    out.status = fail->v.status;
    out.why = std::string("NOT stable [") + to_string(fail->v.status) + "]: " + head + "; " + fail->label + " is " + fail->v.why;
  } else if (open) {
    out.why = "undecided: " + head + "; " + open->label + ": " + open->v.why;
  } else {
    out.stable = true;
    out.status = certified ? Status::certified : Status::exact;
    out.why = std::string("stable [") + to_string(out.status) + "]: " + head + ", each stable:";
    for (const Part& p : parts) out.why += " " + p.label + ": " + p.v.why + ";";
    out.why.pop_back();
  }
  return out;
}

}  // namespace

Loop one_dof_loop(const sim::LoopSpec& L) {
  if (L.dofs() != 1 || L.devices.size() != 1 || L.operators.size() > 1 || !L.environment)
    throw InputError("the one-DOF loop needs one device of one DOF, at most one operator and an [environment]");
  const rational n = L.delay / L.T;
  if (bmp::denominator(n) != 1)
    throw InputError("[delay]: t_d/T = " + n.str() + " is not a whole number of samples (the one-DOF Schur test takes z^-n)");
  if (n > limits::criterion_delay)
    throw InputError("[delay]: " + n.str() + " samples, more than the limit of " + std::to_string(limits::criterion_delay));
  Loop loop;
  loop.T = L.T;
  loop.delay = static_cast<int>(static_cast<long>(bmp::numerator(n)));
  const Polynomial<rational> s_poly(std::vector<rational>{rational(0), rational(1)});
  const TransferFunction g = ss2tf(L.devices[0].G)(0, 0);  // force -> velocity
  loop.plant = tf(g.num(), g.den() * s_poly, 0);            // force -> position
  if (!L.operators.empty()) {
    const auto& op = L.operators[0];
    TransferFunction z = ss2tf(op.Z)(0, 0);
    if (!op.mass.empty() && op.mass[0] != 0) z = parallel(z, tf(op.mass[0] * s_poly, Polynomial<rational>(rational(1)), 0));
    loop.operator_impedance = z;
  }
  loop.H = ss2tf(*L.environment)(0, 0);
  return loop;
}

LoopVerdict decide_loop(const sim::LoopSpec& spec, Decider decider, const sim::LoopHiddenModes* hidden) {
  LoopVerdict out;
  const std::string nl = sim::nonlinear_parts(spec);
  if (!nl.empty()) {
    out.why = "the loop has " + nl + ", which the Schur test of the linear loop does not model (`hapstab simulate` does)";
    return out;
  }
  // identical DOFs: the environment's hidden modes from the split's blocks (Kalman decompositions
  // of their order, not of the whole's: a 1024-device environment has 3072 states)
  std::string no_symmetry;  // why the symmetry of identical DOFs is not used ("" when none)
  const auto sym = detail::split_by_symmetry(spec, no_symmetry);
  if (hidden) {
    out.hidden = *hidden;
  } else if (sym) {
    const HiddenModes env = detail::environment_hidden_modes(*sym, *spec.environment);
    out.hidden = sim::hidden_modes(spec, &env);
  } else {
    out.hidden = sim::hidden_modes(spec);
  }
  if (!out.hidden.stable()) {
    out.stable = false;
    out.status = Status::exact;
    out.method = "hidden mode";
    out.path = "hidden_modes";
    out.why = "NOT stable [exact]: " + out.hidden.summary() +
              ". A mode no input reaches or no output shows is an eigenvalue of the loop whatever the rest does";
    return out;
  }
  if (!out.hidden.undecided.empty()) {  // set-aside modes at z = 1 that may chain (sim/hidden_modes.hpp)
    out.method = "hidden mode";
    out.path = "hidden_modes";
    out.why = "undecided: " + out.hidden.undecided + "; " + out.hidden.summary();
    return out;
  }
  if (decider != Decider::matrix && one_dof(spec))
    if (std::optional<LoopVerdict> v = one_dof_test(spec, out)) return *v;
  if (decider == Decider::automatic && sym) return by_symmetry(*sym, out);
  // the discrete blocks' hidden modes are stable: the matrix on their minimal realisations has
  // the same stability and fewer states (sim/hidden_modes.hpp)
  sim::LoopSpec L = spec;
  std::string reduced;
  if (out.hidden.environment_minimal) L.environment = *out.hidden.environment_minimal, reduced = "the environment's";
  if (out.hidden.coupling_minimal) L.coupling = *out.hidden.coupling_minimal, reduced += reduced.empty() ? "the coupling's" : " and the coupling's";
  if (!reduced.empty()) reduced = ", except " + reduced + ", cut to minimal: the loop as written only adds their hidden modes, stable (exact)";
  LoopVerdict v = matrix_test(L, out, reduced);
  if (!no_symmetry.empty()) v.why += "; no symmetry of identical DOFs used: " + no_symmetry;
  return v;
}

}  // namespace hapstab::stability
