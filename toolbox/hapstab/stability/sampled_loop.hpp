// hapstab/stability/sampled_loop.hpp -- Schur stability of the sampled-data haptic loop (issue 19),
// and the largest environment gain that keeps it stable.
//
//   device   P(s): force -> position, continuous; with an operator impedance Z_op(s) (force =
//            -Z_op(s) * velocity, acting on the device beside the environment) the loop sees
//            P_eff = P / (1 + s Z_op P) = 1/(1/P + s Z_op).
//   sampler  zero-order hold on the force, position sampled every T:
//            P_d(z) = (1 - z^-1) Z{P_eff(s)/s} = N_d(z)/D_d(z), D_d = prod (z - e^{p_i T}).
//   wall     force = -z^-n H(z) x(kT).
// Closed loop: 1 + z^-n H P_d = 0; with H = A/L (A, L polynomials, L monic) the characteristic
// polynomial is  c(z) = z^n L(z) D_d(z) + A(z) N_d(z)  (no cancellation: every mode counts).
//
// Exact where P_eff's poles are all at s = 0 (e.g. a pure mass 1/(m s^2): e^{AT} is a finite
// sum), with the Schur-Cohn test of poly/stability.hpp; otherwise the e^{p T} are Arb balls
// (arb_mat_exp of Van Loan's block) and the decision is read from certified root enclosures
// (acb_poly_find_roots), raising the precision until it is decided, or reported undecided.
//
// max_gain: H = H0 + K H1 is affine in the named gain K, so c(z, K) = c0(z) + K c1(z). The
// number of roots inside |z| < 1 changes only at a K where c has a root on the circle: at
// z = 1 (K = -c0(1)/c1(1)), z = -1, or z = e^{+-j theta}, where c0 conj(c1) is real, i.e.
// Im(c0 conj c1)(theta) = sin(theta) Q(cos theta) = 0, and then K = -Re(c0 conj c1)/|c1|^2 =
// -R(x)/S(x) with x = cos(theta) (Chebyshev T and U bases; the identity is the claim
// ext.stability.crossing of proofs/ext_stability.cpp). The roots move continuously with K and
// their number is fixed (the leading coefficient does not depend on K), so the supremum is the
// smallest positive such K when the loop is stable at one K below it (docs/stability.md).
//
// Long delays (stability/long_delay.hpp): c(z, K) = z^n P + Q0 + K Q1 with P, Q0, Q1 of low
// degree; the Schur test by the argument principle on the unit circle and the crossings by a
// best-first search over theta with q(theta) = Im(c0 conj c1)/sin(theta) evaluated as a sum of a
// few kernels sin(m theta)/sin(theta), in Arb balls: nothing of degree n is formed and the work
// grows like n. A planner takes it where the characteristic polynomial would exceed
// limits::model_degree or cost more (path and plan in the results); delays up to
// limits::criterion_delay samples.
#pragma once

#include <optional>
#include <string>

#include "hapstab/lti/tf.hpp"
#include "hapstab/numeric/result.hpp"

namespace hapstab::stability {

/// Which algorithm decides (see the header): the planner's choice, or one forced (comparisons,
/// benchmarks; the polynomial path refuses a characteristic polynomial above limits::model_degree).
enum class LoopPath { automatic, polynomial, long_delay };

struct Loop {
  TransferFunction plant;                            ///< P(s), force -> position (continuous)
  std::optional<TransferFunction> operator_impedance;  ///< Z_op(s), force per velocity
  TransferFunction H;                                ///< the wall H(z) (H0 when a gain is maximised)
  std::optional<TransferFunction> H_gain;            ///< H1 of H = H0 + K H1 (max_gain only)
  int delay = 0;                                     ///< n of z^-n
  rational T = 0;                                    ///< sample period
  LoopPath path = LoopPath::automatic;               ///< force a path (comparisons, benchmarks)
};

/// P_eff = P/(1 + s Z_op P), exact and reduced. InputError when it is not strictly proper (a
/// device must have mass: force -> position has relative degree >= 1) or the data are not in s.
RationalFunction<rational> effective_device(const Loop& loop);

struct StabilityResult {
  Verdict verdict;                                ///< holds = every closed-loop root in |z| < 1
  std::optional<Enclosure<rational>> spectral_radius;  ///< max |root|, proven enclosure
  int degree = 0;                                 ///< degree of the characteristic polynomial
  bool exact_data = false;                        ///< P_d rational (all device poles at s = 0)
  long precision_bits = 0;                        ///< Arb precision of the decision (0: exact)
  std::string path;                               ///< "polynomial" or "long_delay" (see the header)
  std::string plan;                               ///< why the planner chose it
};

/// Schur stability of the loop with H = loop.H (loop.H_gain must be empty).
StabilityResult decide(const Loop& loop);

/// The exact characteristic polynomial c(z) = z^n L D_d + A N_d of the loop (H = loop.H; loop.H_gain
/// must be empty) when the data are exact (every pole of the device at s = 0), else nullopt: the
/// evidence of a `stability` certificate (cli/certificate.hpp). Built as decide() builds it.
std::optional<Polynomial<rational>> exact_characteristic(const Loop& loop);

struct MaxGain {
  Outcome outcome = Outcome::undecided;  ///< holds: a supremum (finite or infinite) was found;
                                         ///< fails: unstable for every small K > 0
  Status status = Status::failed;        ///< exact (rational value), certified (enclosure), failed
  bool infinite = false;                 ///< stable for every K > 0
  Enclosure<rational> enclosure{0, 0};   ///< contains the supremum
  std::optional<rational> exact;         ///< the value itself when rational (status exact)
  std::string crossing;                  ///< "z = 1", "z = -1", "complex pair" (or "" when none)
  std::optional<Enclosure<rational>> theta;  ///< angle of the crossing root (rad), when at the sup
  std::string note;                      ///< why it is undecided, or what was proven
  long precision_bits = 0;
  std::string path;                      ///< "polynomial" or "long_delay" (see the header)
  std::string plan;                      ///< why the planner chose it
};

/// sup{K >= 0 : the loop is stable for every K in (0, sup)} with H = loop.H + K loop.H_gain,
/// to `digits` significant digits (the enclosure is at most 10^-digits relative wide, or the
/// status says why not).
MaxGain max_gain(const Loop& loop, int digits);
/// The same, with the gain named `gain_name` in the notes (`stability --max B`: "stable at B = ...").
MaxGain max_gain(const Loop& loop, int digits, const std::string& gain_name);

/// The same supremum estimated on a grid (comparison only, status numeric): K(theta) = -c0/c1 in
/// double at theta = pi i/N, every sign change of Im K between neighbours interpolated linearly, the
/// smallest positive Re K there (and at z = +-1). It misses crossings once N under-samples the
/// e^{-j n theta} of the delay (N ~ n). nullopt when no positive crossing is seen.
struct GridGain {
  double K = 0, omega = 0;  ///< the estimate and its crossing frequency (rad/s)
};
std::optional<GridGain> max_gain_grid(const Loop& loop, long N);

/// The standard case of the literature (Gil et al. 2004, Hulin et al. 2006) and of paper 001's
/// wall: device 1/(m s^2 + b s), H = K + B (z - 1)/(T z) with the gain K free (H = H0 + K * 1),
/// delay n. InputError for m < 0, T <= 0 or m = b = 0.
Loop mass_damper_wall(const rational& m, const rational& b, const rational& B, const rational& T, int n);

/// The crossing polynomials of max_gain, exact, for real polynomials c0, c1 and x = cos(theta):
/// Im(c0 conj c1)(e^{j theta}) = sin(theta) Q(x), Re(c0 conj c1) = R(x), |c1|^2 = S(x).
struct CirclePolynomials {
  Polynomial<rational> Q, R, S;
};
CirclePolynomials circle_polynomials(const Polynomial<rational>& c0, const Polynomial<rational>& c1);

/// The polynomials of the long-delay crossing search (stability/long_delay.hpp), exact, for
/// c(z, K) = z^n P(z) + Q0(z) + K Q1(z) with real P, Q0, Q1, U = P conj Q1, V = Q0 conj Q1 on
/// |z| = 1 and x = cos(theta): Re U = RU(x), Im U = sin(theta) SU(x), Re V = RV(x),
/// Im V = sin(theta) SV(x), |Q1|^2 = H1(x). Then for every n (claim ext.stability.crossing_delay)
///   Im(c0 conj c1)/sin(theta) = K_n(theta) RU + cos(n theta) SU + SV,  K_n = sin(n theta)/sin(theta),
///   Re(c0 conj c1) = cos(n theta) RU - sin(n theta) sin(theta) SU + RV.
/// And |P|^2 = PP(x), |Q0|^2 = QQ(x): the search's gain floor, |K| >= (|P| - |Q0|)/|Q1| at every
/// crossing (claim ext.stability.crossing_floor).
struct DelayCirclePolynomials {
  Polynomial<rational> RU, SU, RV, SV, H1, PP, QQ;
};
DelayCirclePolynomials delay_circle_polynomials(const Polynomial<rational>& P, const Polynomial<rational>& Q0,
                                                const Polynomial<rational>& Q1);

}  // namespace hapstab::stability
