// cli/certificate.hpp -- `--certificate FILE` of `bound`, `limit-cycle --exact`, `multidof analyze`
// (cli/multidof_certificate.hpp), `passivity-level` (SISO --H, MIMO --ss), `r`, `stability` (and its --max) and `wedge` (issue 47): the JSON a reviewer
// checks with `hapstab check FILE` or checks/hapstab_check.py without trusting the producer.
// Each holds the model as written (exact "p/q" strings), the claim (the printed numbers,
// exactly) and the evidence; docs/certificates.md has the format. The producer side may use any
// hapstab code (here passivity::objective to place the witness); the checkers (check/) never do.
#pragma once

#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "cli/tf_options.hpp"
#include "hapstab/passivity/bound.hpp"
#include "hapstab/passivity/max_gain.hpp"
#include "hapstab/contact/limit_cycle.hpp"
#include "hapstab/contact/wedge.hpp"
#include "hapstab/lmi/passivity_level.hpp"
#include "hapstab/numeric/ball_matrix.hpp"
#include "hapstab/sim/loop.hpp"
#include "hapstab/stability/sampled_loop.hpp"

namespace hapstab::cli {

/// The certificate of b* (paper 001, (45)/(54), an integer delay n and a delay t_d): claim
/// "b* = v" [exact] or "b* in [lo, hi]" [certified, lo and hi exactly the printed enclosure],
/// evidence a rational witness c0 = cos(w0 T/q) in the domain [cos(pi/q), 1] with f(c0) >= lo
/// (n + t_d/T = P/q; q = 1 for an integer delay) and, for q >= 2, domain_c_lo <= cos(pi/q).
/// InputError (exit 2) for what has no certificate: b* = +inf, H not given by --H, a numeric
/// result, a delay whose exact expansion exceeds the checkers' size limit; NumericalError when no
/// witness is found.
nlohmann::json bound_certificate(const TfOptions& tf, const passivity::BoundProblem& p,
                                 const passivity::Bound& b, int digits);

/// The certificate of `bound --max K --damping b` (check/bound_max_check.hpp): H as written by
/// --H with K free, the claim "K_max in [lo, hi]" (the printed enclosure), "= v" [exact], "= 0"
/// (b*(0) >= b) or "= +inf", and the evidence: b0_hi (b*(0) <= b0_hi < b, when K_max > 0), a
/// witness c1 with f(c1) >= b for H0 + hi H1 (when finite), domain_c_lo for a fractional delay;
/// K_max = 0 by b*(0) = +inf: bound_certificate's evidence of it at K = 0 (at_zero_infinite).
/// InputError (exit 2) for what has no certificate: H not given by --H, an undecided or numeric
/// answer, a delay beyond the checkers' size limit; NumericalError when no witness is
/// found.
nlohmann::json bound_max_certificate(const TfOptions& tf, const passivity::BoundMax& r, int digits);

/// The certificate of `passivity-level --H` (check/passivity_level_check.hpp): G as written, the
/// kind (isp, osp), the certified frequency level c as claim (exact, or its enclosure printed at
/// `digits`), a witness c0 = cos(theta0) with Re W(c0) <= hi (W = G, or 1/G for osp). InputError
/// (exit 2) when c is not certified. With `upper_only` (the command's result is c as an upper bound
/// of the level only: an OSP value <= 0, or a zero of G on the circle) the claim is status
/// "upper_bound", hi = c's upper end as printed (rounded up), and the same witness.
/// Where c is not the level and the LMI `l` has an exactly checked lower bound with its P, the claim is
/// "lower_bound" (or "bounds", with c's hi and witness beside it) with evidence G's realisation (A, B,
/// C, D) by tf2ss -- the one the LMI solved -- and P.
nlohmann::json passivity_level_certificate(const TfOptions& tf, const RationalFunction<rational>& G, bool osp,
                                           const lmi::PassivityLevel& c, const lmi::PassivityLevel& l, bool is_level,
                                           bool upper_only, int digits);

/// The certificate of `passivity-level --ss FILE --kind isp|osp` with a square MIMO G (or a .mat's
/// A, B, C, D; check/passivity_level_mimo_check.hpp, kind passivity-level-mimo): the exact A, B, C, D
/// and T as written, the certified level c as claim (exact, or its enclosure printed at `digits`; with
/// `upper_only`, an OSP value <= 0, "upper_bound" with the printed hi), and for an enclosure or an upper
/// bound a witness z0 = c0 + j s0, a rational point of the unit circle near c.c_min with the pencil at
/// hi not positive definite (OSP: G(z0) regular). Where c is not the level and the LMI `l` has an
/// exactly checked lower bound with its P (the LMI's numeric level is the printed result), the claim
/// is "lower_bound" (lo as printed, rounded down; evidence P), or "bounds" with c's hi and witness
/// beside it (`upper_only`). The certificate is checked (check/) before it is returned. InputError
/// (exit 2) for what has no certificate: a level that is not certified; NumericalError (exit 3) when
/// no witness is found.
nlohmann::json passivity_level_mimo_certificate(const StateSpace<rational>& sys, bool osp, const lmi::PassivityLevel& c,
                                                const lmi::PassivityLevel& l, bool is_level, bool upper_only, int digits);

/// The certificate of r(jw) (44): Re r = -T/2 exactly, Im r in [im - u, im + u] with `im` the printed
/// correctly rounded decimal of `digits` digits and u = |im| 10^(1 - digits) (at least one unit
/// in its last place).
nlohmann::json r_certificate(const rational& T, const rational& omega, const std::string& printed_im, int digits);

/// The inputs of `stability --plant --H [--operator] --T [--delay] [--set]`, as written; or of
/// `stability --scene FILE [--set]` (a one-DOF scene: its text is the model, check/scene_model.hpp).
struct StabilityText {
  std::string plant, H, op;
  int delay = 0;
  std::vector<std::string> sets;
  std::string scene;  ///< the scene file's path (then plant, H, op and delay are empty)
};

/// The evidence of a `stability` certificate of `loop` (one DOF, no --max): the exact
/// characteristic polynomial. InputError (exit 2) for what has no certificate yet: a device with a
/// pole off s = 0 (transcendental e^{pT}), a polynomial above the checkers' degree limit (2000).
nlohmann::json stability_evidence(const stability::Loop& loop);

/// The certificate of the verdict `r` on the loop (check/stability_check.hpp): the model as
/// written, the claim stable / NOT stable with r's status, the evidence of stability_evidence.
/// r must be decided.
nlohmann::json stability_certificate(const StabilityText& text, const stability::Loop& loop,
                                     const stability::StabilityResult& r, const nlohmann::json& evidence);

/// Is `loop` beyond the `stability` kind (three device poles off s = 0 or more)? Its certificate is
/// then of kind stability-loop (stability_loop_certificate), from the model as written.
bool beyond_stability_kind(const stability::Loop& loop);

/// The certificate of kind stability-loop (check/stability_loop_check.hpp) of `stability --scene S`
/// beyond one DOF (the scene's text and --set values as the model), or of a one-DOF `--plant/--H`
/// loop beyond the stability kind (its model as written, T the sample period): the claim stable / NOT
/// stable (`stable`, the verdict of the loop as written), and the Stein P (and w) that schur_decide
/// finds for the checker's own closed-loop matrix. Checked before it is returned; InputError (exit 2)
/// when the checker does not take the model or no P proves the verdict.
nlohmann::json stability_loop_certificate(const StabilityText& text, const rational& T, bool stable);

/// The certificate of kind stability-loop-verdicts (check/stability_loop_verdicts_check.hpp) of `stability --scene S
/// --max NAME` where the loop is not affine in NAME (the bisection on verdicts): one stability-loop certificate per
/// (value, verdict) of `verdicts`, each of the scene with NAME set to the value. Checked before it is returned;
/// InputError (exit 2) when a verdict has no certificate.
nlohmann::json stability_loop_verdicts_certificate(const std::string& scene, const std::vector<std::string>& sets, const rational& T,
                                                   const std::string& name, const std::vector<std::pair<rational, bool>>& verdicts);

/// Parlett-Reinsch balancing by powers of two: e with D^-1 M D (D = diag(2^e)) of comparable off-diagonal row
/// and column norms; a Stein P of the balanced matrix maps back exactly (P = D^-1 P_b D^-1, a congruence).
std::vector<int> balancing_exponents(const Eigen::MatrixXd& M);
/// The Stein P (and w) that schur_decide finds for a closed-loop matrix given by entrywise enclosures
/// (the checker's own M), balanced first by powers of two (exact) and scaled back: P - M^T P M > 0
/// and P > 0 (stable) or w^T P w < 0 (NOT stable). `stable` unset when no P was found.
SchurDecision stein_evidence(const std::vector<std::vector<std::pair<rational, rational>>>& M);

/// NOT stable by a hidden mode (kind stability-loop, claim exact, evidence.hidden): a block of the loop as
/// written -- an ss environment or coupling, an ss device or operator (by name) -- whose unobservable
/// subspace (ker of the observability matrix; A_h the restriction, A V = V A_h) or uncontrollable one
/// (rows W, W A = A_h W) carries an eigenvalue != 1 with |z| >= 1 (discrete), or != 0 with Re s >= 0
/// (continuous) (check/stability_loop_check.hpp). The first such block and kind that the checker
/// verifies; nullopt where none (a tf block, a mass-damper: the caller falls back on the closed-loop matrix).
std::optional<nlohmann::json> hidden_mode_certificate(const StabilityText& text, const rational& T, const sim::LoopSpec& spec);

/// The certificate of `stability --plant --H --max K` (check/stability_max_check.hpp): the model as
/// written with K free, the claim as printed (the enclosure at digits + 3 rounded outward, the exact
/// value, 0, or +inf), the evidence stable_at (a short rational in (0, lo); 1 for +inf) or
/// unstable_at (sup = 0: below the first positive root of D(K) = Res_z(c, c*),
/// stability/max_evidence.hpp). The certificate is checked (check/) before it is returned: one that
/// does not prove the printed claim is an InputError (exit 2, no file) naming what fails, never a
/// weaker claim. InputError too for an undecided or numeric answer, a device pole off s = 0, a
/// characteristic polynomial of degree above the checkers' limit (150).
nlohmann::json stability_max_certificate(const StabilityText& text, const std::string& name, const stability::Loop& loop,
                                         const stability::MaxGain& m, int digits);

/// The certificate of `wedge` (check/wedge_check.hpp): H as written by --H, the exact verdicts of
/// (25), (21) and the three assumptions, and each criterion's margin and largest gain k* as printed
/// at `digits` (their enclosures rounded outward at digits + 5, the shared digits printed; k* when
/// certified or +inf) with a witness c0 of their upper bounds. Checked (check/) before it is
/// returned. InputError (exit 2) when H is not given by --H or has a pole on the unit circle (the
/// criteria are then limits, or not evaluated; the checkers refuse it); NumericalError when no
/// witness is found.
nlohmann::json wedge_certificate(const TfOptions& tf, const contact::ContactAnalysis& a, int digits);

/// The certificate of `limit-cycle --exact` (check/limit_cycle_check.hpp): H as written by --H, the
/// gain k and rho, the claim as printed (the least period, the amplitude (max - min)/2 exactly and as
/// printed, the samples out of contact, attracting or not when decided) and the evidence: the
/// orbit's outputs y_0..y_{n-1} (n = `order`, the order of H), the state of the difference equation
/// of (4). The certificate is checked (check/) before it is returned: one that does not verify is an
/// InputError (exit 2, no file) naming what fails.
nlohmann::json limit_cycle_certificate(const TfOptions& tf, const rational& k, const rational& rho,
                                       const contact::ExactOrbit& orbit, int order);

/// A certificate's envelope: certificate, version, kind, produced_by (every producer starts here).
nlohmann::json certificate_header(const char* kind);
/// {"scene": the file's text, "set": the --set values}: the model of a certificate about a scene as
/// written (the checkers read it themselves: check/scene_model.hpp).
nlohmann::json scene_model_json(const std::string& path, const std::vector<std::string>& sets);
/// check/ verifies the certificate before it is written: InputError (exit 2, no file) naming what
/// fails, never a weaker claim written silently.
void verify_before_writing(const nlohmann::json& certificate);

/// An exact matrix as rows of "p/q" strings (the certificates' matrices).
nlohmann::json matrix_json(const Mat<rational>& M);

/// Writes the certificate to FILE; InputError naming --certificate when it cannot.
void write_certificate(const std::string& file, const nlohmann::json& certificate);

}  // namespace hapstab::cli
