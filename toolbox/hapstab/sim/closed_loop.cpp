// The sampled closed loop as one matrix (see closed_loop.hpp).
#include "hapstab/sim/closed_loop.hpp"

#include <algorithm>
#include <sstream>

#include "hapstab/numeric/ball_expm.hpp"
#include "hapstab/numeric/error.hpp"
#include "hapstab/numeric/exact_matrix.hpp"
#include "hapstab/numeric/limits.hpp"
#include "hapstab/lti/realization.hpp"
#include "hapstab/poly/stability.hpp"

namespace hapstab::sim {

namespace {

using Indices = std::vector<Eigen::Index>;

// A^k = 0 for some k <= n (exact, by repeated products; n is a component's size).
bool nilpotent(const MatQ& A) {
  MatQ P = A;
  for (Eigen::Index k = 1; k <= A.rows(); ++k) {
    if (P.isZero(0)) return true;
    P = exact_product(P, A);
  }
  return P.isZero(0);
}

// e^{A h} and int_0^h e^{A t} dt B for a nilpotent A: finite sums, exact.
void nilpotent_zoh(const MatQ& A, const MatQ& B, const rational& h, MatQ& Phi, MatQ& Gamma) {
  const Eigen::Index n = A.rows();
  Phi = MatQ::Identity(n, n);
  MatQ S = MatQ::Identity(n, n) * h;  // sum_k A^k h^(k+1)/(k+1)!
  MatQ term = MatQ::Identity(n, n);   // (A h)^k / k!
  for (Eigen::Index k = 1; k <= n; ++k) {
    term = exact_product(term, A) * (h / rational(k));
    if (term.isZero(0)) break;
    Phi += term;
    S += term * (h / rational(k + 1));
  }
  Gamma = exact_product(S, B);
}

}  // namespace

namespace {
// The removed plant modes (closed_loop.hpp): s^k q(s) with q(0) != 0 for each removed block (no
// force reaches it; no sampled position shows it); conserved quantities when k equals the nullity
// of the block (semisimple zero) and q is Hurwitz. Zeros in BOTH blocks are not decided: an
// unreached constant can drive the loop to a constant that an unshown integrator then integrates
// (a Jordan chain through the rest), or not.
void classify_removed(const MatQ& Au, const MatQ& Ao, SampledClosedLoop& out) {
  struct Part {
    long n = 0, k = 0, degree = 0;
    bool semisimple = true, rest_stable = true;
  };
  auto part = [](const MatQ& M) {
    Part r;
    r.n = M.rows();
    if (r.n == 0) return r;
    Polynomial<rational> p = charpoly(M);
    while (p.degree() > 0 && p.coeff(0) == 0) {
      p = divmod(p, Polynomial<rational>(std::vector<rational>{rational(0), rational(1)})).first;
      ++r.k;
    }
    r.semisimple = r.k == 0 || exact_rank(M) == r.n - r.k;
    r.rest_stable = p.degree() < 1 || hurwitz_stable(p);
    r.degree = p.degree();
    return r;
  };
  const Part u = part(Au), o = part(Ao);
  if (u.n + o.n == 0) return;
  const long k = u.k + o.k, rest = u.degree + o.degree;
  const bool semisimple = u.semisimple && o.semisimple, rest_stable = u.rest_stable && o.rest_stable;
  out.conserved = semisimple ? k : 0;
  out.removed_unstable = !semisimple || !rest_stable;
  out.removed_undecided = !out.removed_unstable && u.k > 0 && o.k > 0;
  if (out.removed_undecided) out.conserved = 0;
  std::ostringstream o_;
  o_ << u.n + o.n << " plant mode(s) no force reaches or no sampled position shows (exact Kalman splits of the composed plant)";
  if (k > 0)
    o_ << (out.removed_undecided
               ? ": " + std::to_string(u.k) + " at s = 0 that no force reaches and " + std::to_string(o.k) +
                     " that no position shows: whether they chain through the loop (an unreached constant integrated by an "
                     "unshown integrator) is not decided"
           : semisimple ? ": " + std::to_string(k) + " conserved quantit" + (k == 1 ? "y" : "ies") +
                              " at s = 0 (a position and an operator's spring deflection integrate the same velocity, or a "
                              "device's own position no output shows: they keep or settle to a constant, so the loop settles "
                              "to the equilibrium they select)"
                        : ": s = 0 with a Jordan block (a quantity no force reaches, or no output shows, grows linearly)");
  if (rest > 0) o_ << (rest_stable ? "; the other " : "; NOT all of the other ") << rest << " in Re s < 0 (exact Routh)";
  out.removed = o_.str();
}
}  // namespace

std::string nonlinear_parts(const LoopSpec& spec) {
  std::string s;
  auto add = [&](const std::string& w) { s += (s.empty() ? "" : ", ") + w; };
  if (!spec.contact.empty()) add("[contact] (a unilateral wall)");
  if (!spec.passivity_controller.empty()) add("[passivity_controller]");
  if (!spec.quantizers.empty()) add("an encoder (quantum)");
  for (const auto& c : spec.coulomb)
    if (c.force > 0) {
      add("Coulomb friction");
      break;
    }
  return s;
}

namespace {
// The inputs B feeds into the component C of A.
Indices fed_inputs(const MatQ& B, const Indices& C) {
  Indices I;
  for (Eigen::Index k = 0; k < B.cols(); ++k)
    if (std::any_of(C.begin(), C.end(), [&](Eigen::Index i) { return B(i, k) != 0; })) I.push_back(k);
  return I;
}
}  // namespace

PlantZoh plant_zoh(const MatQ& A, const MatQ& B, const rational& h) {
  PlantZoh z{BallMatrix(A.rows(), A.rows()), BallMatrix(A.rows(), B.cols())};
  for (const Indices& C : components(A)) {
    const Indices I = fed_inputs(B, C);
    const ZohEnclosure b = zoh_enclosure(MatQ(A(C, C)), MatQ(B(C, I)), h);
    z.Phi.mid(C, C) = b.Phi.mid;
    z.Phi.rad(C, C).setConstant(b.Phi.radius);
    z.Gamma.mid(C, I) = b.Gamma.mid;
    z.Gamma.rad(C, I).setConstant(b.Gamma.radius);
  }
  return z;
}

std::optional<std::pair<MatQ, MatQ>> exact_plant_zoh(const MatQ& A, const MatQ& B, const rational& h) {
  MatQ Phi = MatQ::Zero(A.rows(), A.rows()), Gamma = MatQ::Zero(A.rows(), B.cols());
  for (const Indices& C : components(A)) {
    const MatQ Ac = A(C, C);
    if (!nilpotent(Ac)) return std::nullopt;
    const Indices I = fed_inputs(B, C);
    MatQ P, G;
    nilpotent_zoh(Ac, MatQ(B(C, I)), h, P, G);
    Phi(C, C) = P;
    Gamma(C, I) = G;
  }
  return std::make_pair(Phi, Gamma);
}

SampledClosedLoop sampled_closed_loop(const LoopSpec& spec) {
  const std::string nl = nonlinear_parts(spec);
  if (!nl.empty()) throw InputError("the loop has " + nl + ": it is not one linear map per period");
  const ComposedLoop L = compose(spec);
  const int N = L.N;
  const rational& T = L.T;
  const rational q = spec.delay / T;
  const long n = static_cast<long>(integer(bmp::numerator(q) / bmp::denominator(q)));
  const rational f = spec.delay - rational(n) * T;
  SampledClosedLoop out;
  // the part of the plant the forces [u, w] reach, and what is removed (closed_loop.hpp)
  const StateSpace<rational> positions{L.plant.A, L.plant.B, MatQ(L.plant.C.topRows(N)), MatQ::Zero(N, 2 * N), 0};
  const KalmanSplit ks = controllable_split(positions);
  // then the part the sampled positions show (the dual split): a device's own position state
  // behind its velocity output is integrated again by the composition, and no sampled output shows
  // it -- removed and classified like the modes no force reaches (the block's hidden-mode check
  // names it, sim/hidden_modes.hpp)
  const StateSpace<rational>& c = ks.controllable;
  const KalmanSplit ko = controllable_split(
      StateSpace<rational>{MatQ(c.A.transpose()), MatQ(c.C.transpose()), MatQ(c.B.transpose()), MatQ(c.D.transpose()), 0});
  classify_removed(ks.uncontrollable_A, MatQ(ko.uncontrollable_A.transpose()), out);
  const MatQ A = ko.controllable.A.transpose();
  const MatQ Bplant = ko.controllable.C.transpose();  // [B_u, B_w] of the observable part
  const MatQ Bu = Bplant.leftCols(N);
  const MatQ Cx = ko.controllable.B.transpose();
  const auto& K = L.controller;
  const Eigen::Index ns = A.rows(), nc = K.A.rows();
  const long slots = n + (f > 0 ? 1 : 0);
  if (static_cast<double>(ns + nc) + static_cast<double>(slots) * N > static_cast<double>(limits::closed_loop_states))
    throw InputError("the loop as one matrix per period would have " + std::to_string(ns) + " plant, " + std::to_string(nc) +
                     " controller and " + std::to_string(slots) + " x " + std::to_string(N) +
                     " delay states ([delay] of " + std::to_string(slots) + " sample(s)), more than the limit of " +
                     std::to_string(limits::closed_loop_states) + " states");
  const Eigen::Index nb = slots * N;
  out.plant_states = ns;
  out.controller_states = nc;
  out.buffer_states = nb;
  const Eigen::Index nx = ns + nc + nb;
  // the exact rows of the controller: u_k = Ku [s; xi], xi+ = [B_c C_x, A_c] [s; xi]
  MatQ Ku(N, ns + nc), Kx(nc, ns + nc);
  Ku << exact_product(K.D, Cx), K.C;
  Kx << exact_product(K.B, Cx), K.A;
  // the plant over the period: s+ = Phi_T s + Go u_{k-n-1} + Gn u_{k-n}
  const PlantZoh whole = plant_zoh(A, Bu, T);
  BallMatrix Go(ns, N), Gn = whole.Gamma;
  if (f > 0) {
    const PlantZoh a = plant_zoh(A, Bu, f), b = plant_zoh(A, Bu, T - f);
    Go = b.Phi * a.Gamma;
    Gn = b.Gamma;
  }
  // M by blocks: s+ = Phi_T s + Gn u_{k-n} + Go u_{k-n-1}; xi+ = Kx [s; xi]; the buffer shifts, slot 1 := u_k
  BallMatrix M(nx, nx);
  M.set_block(0, 0, whole.Phi);
  const BallMatrix Kub = BallMatrix::exact(Ku), Kxb = BallMatrix::exact(Kx);
  if (n == 0) {
    const BallMatrix GK = Gn * Kub;  // s+ gets Gn u_k = Gn Ku [s; xi]
    BallMatrix top(ns, ns + nc);
    top.set_block(0, 0, whole.Phi);
    M.set_block(0, 0, top + GK);
  } else {
    M.set_block(0, ns + nc + (n - 1) * N, Gn);
  }
  if (f > 0) M.set_block(0, ns + nc + n * N, Go);
  M.set_block(ns, 0, Kxb);
  if (nb > 0) {
    M.set_block(ns + nc, 0, Kub);
    for (Eigen::Index j = 1; j < nb / N; ++j)
      M.set_block(ns + nc + j * N, ns + nc + (j - 1) * N, BallMatrix::exact(Eigen::MatrixXd(Eigen::MatrixXd::Identity(N, N))));
  }
  out.M = M;
  out.A = A;
  out.Bu = Bu;
  out.Ku = Ku;
  out.Kx = Kx;
  out.n = n;
  out.f = f;
  out.T = T;
  out.jump = MatQ::Zero(nx, N);
  out.jump.topRows(ns) = Bplant.rightCols(N);
  out.positions = MatQ::Zero(N, nx);
  out.positions.leftCols(ns) = Cx;
  // The same exactly when every piece is rational
  if (const auto wq = exact_plant_zoh(A, Bu, T)) {
    MatQ GnQ = wq->second, GoQ;
    if (f > 0) {
      const auto aq = exact_plant_zoh(A, Bu, f), bq = exact_plant_zoh(A, Bu, T - f);
      GoQ = exact_product(bq->first, aq->second);
      GnQ = bq->second;
    }
    MatQ E = MatQ::Zero(nx, nx);
    E.topLeftCorner(ns, ns) = wq->first;
    if (n == 0)
      E.topLeftCorner(ns, ns + nc) += exact_product(GnQ, Ku);
    else
      E.block(0, ns + nc + (n - 1) * N, ns, N) = GnQ;
    if (f > 0) E.block(0, ns + nc + n * N, ns, N) = GoQ;
    E.block(ns, 0, nc, ns + nc) = Kx;
    if (nb > 0) {
      E.block(ns + nc, 0, N, ns + nc) = Ku;
      for (Eigen::Index j = 1; j < nb / N; ++j) E.block(ns + nc + j * N, ns + nc + (j - 1) * N, N, N) = MatQ::Identity(N, N);
    }
    out.exact = E;
  }
  // G1 (closed_loop.hpp)
  out.dc = MatQ::Zero(ns + nc + N, ns + nc + N);
  out.dc.topLeftCorner(ns, ns) = A;
  out.dc.block(0, ns + nc, ns, N) = Bu;
  out.dc.block(ns, 0, nc, ns + nc) = Kx;
  out.dc.block(ns, ns, nc, nc) -= MatQ::Identity(nc, nc);
  out.dc.block(ns + nc, 0, N, ns + nc) = Ku;
  out.dc.block(ns + nc, ns + nc, N, N) = -MatQ::Identity(N, N);
  return out;
}

}  // namespace hapstab::sim
