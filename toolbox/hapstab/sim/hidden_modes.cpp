#include "hapstab/sim/hidden_modes.hpp"

#include <algorithm>
#include <sstream>

#include "hapstab/numeric/decimal.hpp"
#include "hapstab/numeric/error.hpp"
#include "hapstab/numeric/exact_matrix.hpp"
#include "hapstab/poly/stability.hpp"

namespace hapstab::sim {

namespace {

// The roots of one hidden factor, each marked stable or not. The polynomial is factored over Q
// exactly (poly/roots.hpp) and each distinct irreducible factor is decided exactly (Schur-Cohn /
// Routh): a factor q^63 of degree 126 costs what q costs. A root is marked unstable when its
// factor is not exactly stable and its enclosure does not certify it inside (|z| < 1, Re s < 0),
// so an unstable factor always names at least one root (the enclosures are certified).
void add_factor(const PolynomialProduct& product, const std::string& block, const std::string& kind, bool discrete,
                bool marginal_semisimple, std::vector<HiddenMode>& out) {
  const rational marginal = discrete ? 1 : 0;  // z = 1, s = 0
  // each irreducible factor of the product over Q once, its multiplicities (times the powers) added
  std::vector<IrreducibleFactor> irreducible;
  for (const auto& [p, power] : product.factors)
    for (const IrreducibleFactor& F : factor_over_q(p)) {
      auto same = std::find_if(irreducible.begin(), irreducible.end(), [&](const IrreducibleFactor& G) { return G.f == F.f; });
      if (same == irreducible.end()) same = irreducible.insert(irreducible.end(), IrreducibleFactor{F.f, 0});
      same->multiplicity += F.multiplicity * power;
    }
  for (const IrreducibleFactor& F : irreducible) {
    const bool at_marginal = F.f.degree() == 1 && F.f(marginal) == 0;
    const bool settles = at_marginal && marginal_semisimple;
    const bool stable = settles || (discrete ? schur_stable(F.f) : hurwitz_stable(F.f));
    for (RootEnclosure& r : enclose_roots(F.f)) {
      if (r.im_hi < 0) continue;  // the conjugate of a root listed as a pair (p is real)
      r.multiplicity = F.multiplicity;
      HiddenMode h;
      h.pair = r.im_lo > 0;
      h.block = block;
      h.kind = kind;
      h.discrete = discrete;
      h.where = r;
      h.stable = stable || (discrete ? r.abs_hi < 1 : r.re_hi < 0);
      h.settles = settles;
      out.push_back(h);
    }
  }
}

long multiplicity_at(Polynomial<rational> p, const rational& at) {
  long k = 0;
  const Polynomial<rational> factor{-at, rational(1)};
  while (p.degree() >= 1 && p(at) == 0) p = divmod(p, factor).first, ++k;
  return k;
}

StateSpace<rational> dual(const StateSpace<rational>& s) {
  return StateSpace<rational>{Mat<rational>(s.A.transpose()), Mat<rational>(s.C.transpose()), Mat<rational>(s.B.transpose()),
                              Mat<rational>(s.D.transpose()), s.T};
}

// The plant as the loop sees it (sim/loop.hpp's composition: forces in, sampled positions out) --
// a device's own position state behind its velocity output is neither reached apart from the
// composition's position nor shown (it is neither kind there), an operator's spring deflection is
// an injector (no force changes deflection minus position; the force it makes is seen). Larger
// plants are not composed here (nullopt): the caller stays undecided.
std::optional<MarginalParts> plant_marginal_parts(const LoopSpec& spec) {
  const ComposedLoop L = compose(spec);
  if (L.plant.A.rows() > 200) return std::nullopt;
  // the loop's forces u only (w, the hand's, is not fed by the loop: a mode only w reaches is unreached here)
  const StateSpace<rational> positions{L.plant.A, Mat<rational>(L.plant.B.leftCols(L.N)), Mat<rational>(L.plant.C.topRows(L.N)),
                                       Mat<rational>::Zero(L.N, L.N), 0};
  return marginal_parts(positions, rational(0));
}

// LoopHiddenModes::undecided: every block that holds a mode set aside at z = 1 (s = 0) counted by
// Kalman part; the continuous blocks through the composed plant (a block's own view of them is not
// the loop's: a device's position state is an integrator to its block, neither kind in the loop).
std::string marginal_chain(const LoopSpec& spec, const std::vector<HiddenMode>& modes) {
  auto settles_in = [&](const std::string& block) {
    return std::any_of(modes.begin(), modes.end(), [&](const HiddenMode& h) { return h.settles && h.block == block; });
  };
  const bool continuous = std::any_of(modes.begin(), modes.end(), [](const HiddenMode& h) { return h.settles && !h.discrete; });
  long injectors = 0, integrators = 0;
  if (spec.environment && settles_in("environment")) {
    const MarginalParts e = marginal_parts(*spec.environment, rational(1));
    injectors += e.injectors, integrators += e.integrators;
  }
  if (spec.coupling && settles_in("coupling")) {
    const MarginalParts v = marginal_parts(*spec.coupling, rational(1));
    injectors += v.injectors, integrators += v.integrators;
  }
  // the plant alone: the closed-loop matrix classifies it itself (sim/closed_loop.hpp); a one-DOF loop
  // decided on transfer functions does not, so it is composed here
  const bool discrete_marginal = injectors + integrators > 0;
  if (!discrete_marginal && !(continuous && spec.dofs() == 1)) return "";
  const std::optional<MarginalParts> plant = plant_marginal_parts(spec);
  const std::string kinds = "mode(s) at z = 1 / s = 0 that no input reaches and an output sees (a constant the loop must "
                            "balance, moving its equilibrium off 0) beside mode(s) an input reaches and no output shows (they "
                            "sum what the loop feeds them): at that equilibrium they would grow linearly (a Jordan block at "
                            "z = 1 of the loop as written, though each block's A is semisimple there)";
  if (!plant) return "the plant has more than 200 states, beyond what this test of set-aside " + kinds + " composes: not decided";
  injectors += plant->injectors, integrators += plant->integrators;
  if (injectors == 0 || integrators == 0) return "";
  return std::to_string(injectors) + " " + kinds.substr(0, kinds.find(" beside ")) + " beside " + std::to_string(integrators) +
         kinds.substr(kinds.find(" beside ") + 7) + ": whether the constant reaches them is not decided";
}

}  // namespace

MarginalParts marginal_parts(const StateSpace<rational>& s, const rational& at) {
  const KalmanSplit reached = controllable_split(s);                     // X / R: not reached (shown or not)
  const KalmanSplit seen = controllable_split(dual(s));                  // N: not shown (reached or not)
  const KalmanSplit reached_unseen = controllable_split(dual(reached.controllable));  // R cap N
  const long unreached = multiplicity_at(charpoly(reached.uncontrollable_A), at);
  const long unshown = multiplicity_at(charpoly(seen.uncontrollable_A), at);
  const long integrators = multiplicity_at(charpoly(reached_unseen.uncontrollable_A), at);
  const long neither = unshown - integrators;  // N / (R cap N)
  return {unreached - neither, integrators};
}

std::string HiddenMode::text() const {
  std::ostringstream o;
  o.precision(6);
  o << block << ": " << kind << (pair ? " modes " : " mode ") << where.text(discrete ? "z" : "s", pair);
  if (settles)
    o << " (semisimple in the block's hidden parts: it neither grows nor decays, a conserved quantity that settles as the loop "
         "decays)";
  else if (discrete)
    o << " (|z| in [" << decimal_outward(rational(where.abs_lo), 6, -1) << ", " << decimal_outward(rational(where.abs_hi), 6, +1)
      << "]" << (stable ? ", inside the unit circle)" : ": not inside the unit circle)");
  else
    o << (stable ? " (Re s < 0)" : " (Re s >= 0: |e^{sT}| >= 1 after the hold)");
  return o.str();
}

bool LoopHiddenModes::stable() const {
  for (const auto& h : modes)
    if (!h.stable) return false;
  return true;
}

std::string LoopHiddenModes::summary() const {
  if (modes.empty()) return "";
  std::string bad, good, kept;
  int n_good = 0;
  for (const auto& h : modes) {
    if (!h.stable)
      bad += (bad.empty() ? "" : "; ") + h.text();
    else if (h.settles)  // always named: the verdict says what it is about
      kept += (kept.empty() ? "" : "; ") + h.text();
    else if (++n_good <= 6)
      good += (good.empty() ? "" : "; ") + h.text();
  }
  if (!bad.empty()) return "unstable hidden mode(s), exact: " + bad;
  std::string s;
  if (!kept.empty()) s = "conserved hidden mode(s) at z = 1 / s = 0, exact: " + kept;
  if (!good.empty())
    s += (s.empty() ? "" : "; ") + std::string("stable hidden modes (exact; they do not move in any loop): ") + good +
         (n_good > 6 ? "; and " + std::to_string(n_good - 6) + " more" : "");
  return s;
}

std::vector<HiddenMode> block_hidden_modes(const HiddenModes& h, bool discrete, const std::string& name,
                                           bool marginal_semisimple) {
  std::vector<HiddenMode> out;
  add_factor(h.uncontrollable, name, "uncontrollable", discrete, marginal_semisimple, out);
  add_factor(h.unobservable, name, "unobservable", discrete, marginal_semisimple, out);
  return out;
}

LoopHiddenModes hidden_modes(const LoopSpec& spec, const HiddenModes* environment) {
  LoopHiddenModes r;
  auto add = [&](const StateSpace<rational>& s, const std::string& name, const HiddenModes* known = nullptr,
                 std::optional<StateSpace<rational>>* minimal = nullptr) {
    if (s.states() == 0) return;
    std::optional<HiddenModes> own;  // a known block's are not copied (a large environment's minimal realisation is big)
    const HiddenModes& h = known ? *known : own.emplace(hapstab::hidden_modes(s));
    const rational at = s.is_discrete() ? 1 : 0;  // z = 1, s = 0
    const bool marginal = (h.uncontrollable.vanishes_at(at) || h.unobservable.vanishes_at(at)) &&
                          (h.marginal_semisimple ? *h.marginal_semisimple : hidden_marginal_semisimple(s));
    for (auto& m : block_hidden_modes(h, s.is_discrete(), name, marginal)) r.modes.push_back(std::move(m));
    if (minimal && h.any()) *minimal = h.minimal;
  };
  for (const auto& d : spec.devices) add(d.G, "device '" + d.name + "'");
  for (const auto& o : spec.operators) add(o.Z, "operator '" + o.name + "'");
  if (spec.environment) add(*spec.environment, "environment", environment, &r.environment_minimal);
  if (spec.coupling) add(*spec.coupling, "coupling", nullptr, &r.coupling_minimal);
  if (r.stable()) r.undecided = marginal_chain(spec, r.modes);
  return r;
}

}  // namespace hapstab::sim
