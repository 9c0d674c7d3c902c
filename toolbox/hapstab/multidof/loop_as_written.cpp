#include "hapstab/multidof/loop_as_written.hpp"

#include <sstream>

#include "hapstab/lti/realization.hpp"
#include "hapstab/numeric/error.hpp"
#include "hapstab/poly/stability.hpp"
#include "hapstab/stability/sampled_loop.hpp"

namespace hapstab::multidof {

namespace {

// What in the loop is not linear time-invariant (empty when nothing).
std::string nonlinear_parts(const scene::Scene& sc) {
  std::string s;
  auto add = [&](const std::string& w) { s += (s.empty() ? "" : ", ") + w; };
  if (!sc.loop.contact.empty()) add("[contact] (a unilateral wall)");
  if (!sc.loop.passivity_controller.empty()) add("[passivity_controller]");
  if (!sc.loop.quantizers.empty()) add("an encoder (quantum)");
  for (const auto& c : sc.loop.coulomb)
    if (c.force > 0) {
      add("Coulomb friction");
      break;
    }
  return s;
}

std::string radius_text(const stability::StabilityResult& r) {
  if (!r.spectral_radius) return "";
  std::ostringstream o;
  o.precision(6);
  o << ", spectral radius in [" << to_real<double>(r.spectral_radius->lo) << ", " << to_real<double>(r.spectral_radius->hi)
    << "]";
  return o.str();
}

// Step 2: the one-DOF loop by the exact/certified Schur test (see the header).
LoopAsWritten schur_one_dof(const scene::Scene& sc, const SceneProblem& sp, LoopAsWritten out) {
  const auto& L = sc.loop;
  const rational T = sp.problem.T();
  const TransferFunction g = ss2tf(L.devices[0].G)(0, 0);
  const Polynomial<rational> s_poly(std::vector<rational>{rational(0), rational(1)});
  stability::Loop loop;
  loop.T = T;
  loop.delay = sp.delay;
  loop.plant = tf(g.num(), g.den() * s_poly, 0);  // force -> position
  if (!L.operators.empty()) {
    const auto& op = L.operators[0];
    TransferFunction z = ss2tf(op.Z)(0, 0);
    if (!op.mass.empty() && op.mass[0] != 0) z = parallel(z, tf(op.mass[0] * s_poly, Polynomial<rational>(rational(1)), 0));
    loop.operator_impedance = z;
  }
  const TransferFunction E = ss2tf(sp.E_undelayed)(0, 0);
  loop.H = E;
  std::string hidden;
  if (L.coupling) {
    const TransferFunction V = ss2tf(minreal(*L.coupling))(0, 0);
    loop.H = feedback(E, V);  // u = -E (x + V u): force -E/(1 + E V) x
    // the full controller's characteristic polynomial over the reduced one: the cancelled modes
    const Polynomial<rational> full = E.den() * V.den() + E.num() * V.num();
    if (full.is_zero()) throw InputError(sc.file + ": the coupling's algebraic loop 1 + E V is identically zero");
    const auto [q, rem] = divmod(full, loop.H.den());
    if (!rem.is_zero()) throw NumericalError("loop as written: E/(1 + E V) does not divide the controller's polynomial");
    if (q.degree() > 0 && !hapstab::schur_stable(q)) {
      out.stable = false;
      out.status = Status::exact;
      out.method = "exact Schur test";
      out.why = "the controller E/(1 + E V) cancels a mode outside the open unit disk (Schur-Cohn on the exact "
                "cancelled factor of degree " + std::to_string(q.degree()) + "): NOT stable as written (exact)";
      return out;
    }
    if (q.degree() > 0) hidden = "; the " + std::to_string(q.degree()) + " modes E/(1 + E V) cancels are stable (exact)";
  }
  stability::StabilityResult r;
  try {
    r = stability::decide(loop);
  } catch (const std::runtime_error& e) {  // InputError, NumericalError: a loop the stability module refuses (size limits): not decided
    out.why = std::string("the exact Schur test does not decide this loop: ") + e.what();
    return out;
  }
  out.method = "exact Schur test (the loop of `hapstab stability`)";
  std::string delay = sp.delay ? ", delay z^-" + std::to_string(sp.delay) : "";
  if (!r.verdict.decided()) {
    out.why = "undecided by the Schur test: " + r.verdict.evidence;
    return out;
  }
  out.stable = r.verdict.holds();
  out.status = r.verdict.status;
  out.why = std::string(r.verdict.holds() ? "stable" : "NOT stable") + " [" + to_string(r.verdict.status) +
            "]: the one-DOF sampled loop (device, operator, ZOH, " + (L.coupling ? "E/(1 + E V)" : "E") + delay +
            ")" + radius_text(r) + hidden;
  return out;
}

}  // namespace

LoopAsWritten loop_as_written(const scene::Scene& sc, const SceneProblem& sp, bool assumptions_hold,
                              const lmi::Options& opt) {
  const auto& L = sc.loop;
  LoopAsWritten out;
  out.coupling = L.coupling ? "the scene's [coupling] (" + std::to_string(L.coupling->states()) + " states)"
                            : "none (the direct connection)";
  const std::string nl = nonlinear_parts(sc);
  if (!nl.empty()) {
    out.why = "the loop has " + nl + ", which neither Theorem 5 nor the exact Schur test models (`hapstab simulate` does)";
    return out;
  }
  std::string note;
  if (L.coupling && sp.delay == 0) {
    if (assumptions_hold) {
      const CouplingCheck cc = check_theorem4(sp.problem, *L.coupling, opt);
      if (cc.verdict.holds() && cc.verdict.proven()) {
        out.stable = true;
        out.status = Status::exact;
        out.method = "Theorem 4 with the scene's coupling";
        out.why = "stable [exact]: Theorem 4 holds for the scene's coupling V (its V-hat^Gamma meets the level (14) "
                  "requires; exact re-check) and Assumption 1 holds";
        return out;
      }
      note = "Theorem 4 with the scene's coupling does not conclude (" +
             std::string(cc.verdict.fails() ? "infeasible" : "not certified") + "; it is sufficient only)";
    } else {
      note = "Theorem 4 with the scene's coupling needs Assumption 1, which does not hold";
    }
  } else if (L.coupling) {
    note = "with a delay the scene's coupling is fed the computed force and the devices the delayed one, a loop "
           "Theorem 4 with z^-n E does not describe";
  }
  const bool one_dof = L.dofs() == 1 && L.devices.size() == 1 && L.operators.size() <= 1;
  if (one_dof) {
    out = schur_one_dof(sc, sp, out);
    if (!note.empty()) out.why = note + "; " + out.why;
    return out;
  }
  out.why = (note.empty() ? "" : note + "; ") + std::string("the exact Schur test (`hapstab stability`) models one-DOF loops, this one has ") +
            std::to_string(L.dofs()) + " DOF: not decided here (`hapstab simulate` runs it)";
  return out;
}

}  // namespace hapstab::multidof
