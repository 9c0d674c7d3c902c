// proofs/schur_lyapunov.cpp -- the Lyapunov certificate of Schur stability used for large
// matrices (numeric/lyapunov.hpp, multidof::schur_stable from 12 states on).
//
// Argument. Let P be a real symmetric matrix with P > 0 and P - A^T P A > 0 (A real). For an
// eigenpair A v = lambda v, v != 0 (complex),
//     0 < v^* (P - A^T P A) v = v^* P v - |lambda|^2 v^* P v = (1 - |lambda|^2) v^* P v,
// and v^* P v > 0, so |lambda| < 1: A is Schur stable. Nothing about P matters but the two
// inequalities, so P may come from any floating-point solver; it is taken as the exact dyadic
// matrix of its doubles. The inequalities are checked on the EXACT A with Arb: A's entries are
// enclosed in balls, P - A^T P A is computed in ball arithmetic (the exact matrix lies inside),
// and arb_mat_cho succeeds only when every symmetric matrix inside the balls is positive
// definite. A failed check proves nothing either way; the caller then runs Schur-Cohn.
//
// The proof runs the certificate on the N-contact-point environments of the scaling scenes
// (Fig. 5 generalised, backward Euler, N + 2 states, N = 8, 16, 32) and on matrices of known
// spectrum (dense similarity transforms of rotation blocks at radius 9/10, 1 - 1e-9, 1 and
// 1 + 1e-9), and checks that it never contradicts the exact Schur-Cohn test and proves every
// stable one.
//
// The Stein inertia direction (numeric/ball_matrix.hpp, schur_decide: the closed-loop matrix of
// the loop as written, stability/loop_as_written.hpp). Let P be real symmetric with
// Q = P - M^T P M > 0. Then (i) no eigenvalue of M is on |z| = 1: M v = z v with |z| = 1 would give
// v^* Q v = (1 - |z|^2) v^* P v = 0; (ii) if M were Schur stable, the Stein map X -> X - M^T X M
// would be invertible with X = sum_k (M^T)^k Q M^k > 0 its only solution for Q, so P > 0. Hence
// w^T P w < 0 for some w proves an eigenvalue with |z| > 1. The claim runs schur_decide (P from the
// double Stein equation, both inequalities in Arb balls) on matrices of known spectrum at radius
// 1/2, 9/10, 1 -+ 1e-9, 11/10 and 2, orders 6 and 40, and checks that every decided verdict is the
// exact one and that none away from the circle is left undecided.
#include <random>
#include <sstream>

#include "hapstab/lti/realization.hpp"
#include "hapstab/multidof/environment.hpp"
#include "hapstab/numeric/ball_matrix.hpp"
#include "hapstab/numeric/lyapunov.hpp"
#include "proofs/known_spectrum.hpp"
#include "proofs/proof.hpp"

namespace {

using namespace hapstab;

multidof::MechanicalEnvironment scene_environment(int n) {  // bench/contact_scene.py's values
  multidof::MechanicalEnvironment env{rational(3, 10), rational(1000), rational(5), {}, {}};
  const rational B[] = {rational(1), rational(2), rational(3, 2), rational(5, 2)};
  for (int i = 0; i < n; ++i) {
    env.kc.push_back(rational(500 + 100 * (i % 4)));
    env.Bc.push_back(B[i % 4]);
  }
  return env;
}

using proofs::dense_similar;
using proofs::rotation_blocks;

}  // namespace

HAPSTAB_PROOF(schur_lyapunov, "000", "A Lyapunov inequality checked in balls proves Schur stability") {
  std::vector<std::pair<std::string, MatQ>> cases;
  for (int n : {8, 16, 32})
    cases.emplace_back("E, N = " + std::to_string(n),
                       multidof::mechanical_environment_be_ss(scene_environment(n), rational(1, 100)).A);
  std::mt19937 g(15);
  for (const rational& r : {rational(9, 10), 1 - rational(1, 1000000000), rational(1), 1 + rational(1, 1000000000)})
    cases.emplace_back("radius " + r.str(), dense_similar(rotation_blocks(6, r), g));
  bool sound = true, complete = true;
  int proven = 0, stable = 0;
  // non-trivial (proof.hpp): completeness is exercised by the stable matrices (the certificate
  // must prove them), soundness by the others (it must not)
  proofs::Instances stable_cases{"Schur stable matrices", 4}, unstable_cases{"matrices not Schur stable", 2};
  std::ostringstream ev;
  for (const auto& [name, A] : cases) {
    const bool exact = schur_stable(charpoly(A));
    const bool cert = lyapunov_proves_schur_stable(A);
    stable += exact;
    stable_cases.count(exact);
    unstable_cases.count(!exact);
    proven += cert;
    sound = sound && (!cert || exact);
    complete = complete && (cert == exact);
    ev << name << " (" << A.rows() << " states): Schur-Cohn " << (exact ? "stable" : "not stable") << ", certificate "
       << (cert ? "proves it" : "no proof") << "; ";
  }
  ev << proven << " proofs for " << stable << " stable of " << cases.size();
  check.no_certificate("000.schur.lyapunov_certificate", "the theorem the stability checkers rely on (docs/certificates.md), shown on known spectra, not a verdict of a command; the loop verdicts that use it have certificates (000.thm5.*, ext.loop_max.*)");
  check.claim("000.schur.lyapunov_certificate", "Theorem 5 (E Schur stable)",
              "P > 0 and P - A^T P A > 0, checked by ball Cholesky on the exact A, prove Schur stability: on the "
              "scaling scenes' environments (N = 8, 16, 32) and on spectra at radius 9/10, 1 - 1e-9, 1, 1 + 1e-9 "
              "the certificate proves exactly the matrices Schur-Cohn finds stable",
              Status::certified, sound && complete, ev.str(), {stable_cases, unstable_cases});
}

HAPSTAB_PROOF(schur_stein_inertia, "000", "The Stein inertia theorem checked in balls decides Schur stability both ways") {
  std::mt19937 g(38);
  bool sound = true, complete = true;
  proofs::Instances stable_cases{"Schur stable matrices decided", 4}, unstable_cases{"unstable matrices proven unstable", 4};
  std::ostringstream ev;
  for (const int n : {3, 20})  // blocks: orders 6 and 40
    for (const rational& r : {rational(1, 2), rational(9, 10), 1 - rational(1, 1000000000), 1 + rational(1, 1000000000), rational(11, 10), rational(2)}) {
      const MatQ A = dense_similar(rotation_blocks(n, r), g);
      const bool exact = r < 1;  // rotation_blocks: spectral radius exactly r
      const SchurDecision d = schur_decide(BallMatrix::exact(A));
      const bool near = abs(r - 1) < rational(1, 1000);
      if (d.stable) {
        sound = sound && *d.stable == exact;
        (exact ? stable_cases : unstable_cases).count(true);
      } else {
        complete = complete && near;
      }
      ev << "order " << 2 * n << ", radius " << r.str() << ": " << (d.stable ? (*d.stable ? "stable" : "NOT stable") : "undecided")
         << "; ";
    }
  check.no_certificate("000.schur.stein_inertia", "the theorem the stability-loop checkers rely on (docs/certificates.md), shown on known spectra, not a verdict of a command; the loop verdicts that use it have certificates (kinds stability-loop, stability-loop-max)");
  check.claim("000.schur.stein_inertia", "Theorem 5 (the loop as written)",
              "P - M^T P M > 0 in balls with P > 0 proves Schur stability, with w^T P w < 0 an eigenvalue |z| > 1 (Stein "
              "inertia): on spectra at radius 1/2, 9/10, 1 -+ 1e-9, 11/10, 2 (orders 6 and 40) every decided verdict is the "
              "exact one and every radius away from 1 is decided",
              Status::certified, sound && complete, ev.str(), {stable_cases, unstable_cases});
}
