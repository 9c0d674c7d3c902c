// proofs/loop_as_written.cpp -- why a block's hidden mode decides the loop as written
// (sim/hidden_modes.hpp, stability/loop_as_written.hpp; DESIGN.md, "Theorem 5 is an input-output
// statement about the storage functions of the realisations as written").
//
// Argument. Write a block in Kalman coordinates, x = (x_r, x_u) with x_u+ = A_u x_u untouched by
// the input (uncontrollable), or y independent of x_o (unobservable: x_o+ = A_o x_o + B_o u, x_o
// never reaches y). Close any loop through the block's ports (any other realisation K in
// feedback, any feedthrough): the closed-loop state matrix is block triangular with A_u (or
// A_o) as a diagonal block, because the loop reaches the block only through u and hears it only
// through y. So det(zI - A_u) divides det(zI - A_closed) whatever K is: the hidden modes are
// eigenvalues of every loop, and an unstable one makes every loop unstable.
//
// The claim checks the divisibility exactly on random discrete blocks E with known hidden
// factors (disguised by a random rational similarity), each closed with a random discrete
// controller K (states and feedthrough) in negative feedback: the closed-loop characteristic
// polynomial, computed exactly, is divisible by lti::hidden_modes's factors.
#include <random>
#include <sstream>

#include "hapstab/lti/realization.hpp"
#include "hapstab/numeric/exact_matrix.hpp"
#include "proofs/proof.hpp"

namespace {

using namespace hapstab;

MatQ random(std::mt19937& g, int r, int c) {
  std::uniform_int_distribution<int> num(-5, 5), den(1, 4);
  MatQ M(r, c);
  for (int i = 0; i < M.size(); ++i) M.data()[i] = rational(num(g), den(g));
  return M;
}

// u = -y_K, K driven by y_E (K: nk states, feedthrough D_K); E's feedthrough D_E. With
// v = y_E = C_E x + D_E u and u = -(C_K xk + D_K v): (I + D_E D_K) ... solved exactly.
MatQ closed_loop(const StateSpace<rational>& E, const StateSpace<rational>& K) {
  const Eigen::Index m = E.inputs(), ne = E.states(), nk = K.states();
  // u = -(C_K xk + D_K (C_E x + D_E u))  =>  (I + D_K D_E) u = -(C_K xk + D_K C_E x)
  const MatQ S = MatQ::Identity(m, m) + exact_product(K.D, E.D);
  const MatQ Si = exact_solve(S, MatQ::Identity(m, m), "I + D_K D_E");
  MatQ Ux(m, ne + nk);  // u = Ux [x; xk]
  Ux << -exact_product(Si, exact_product(K.D, E.C)), -exact_product(Si, K.C);
  MatQ Vx(m, ne + nk);  // y_E = Vx [x; xk]
  Vx << E.C, MatQ::Zero(m, nk);
  Vx += exact_product(E.D, Ux);
  MatQ A(ne + nk, ne + nk);
  A.topRows(ne) = exact_product(E.B, Ux);
  A.topLeftCorner(ne, ne) += E.A;
  A.bottomRows(nk) = exact_product(K.B, Vx);
  A.bottomRightCorner(nk, nk) += K.A;
  return A;
}

}  // namespace

HAPSTAB_PROOF(hidden_modes_in_every_loop, "000", "A block's hidden modes are eigenvalues of every loop it is in") {
  std::mt19937 g(38);
  std::uniform_int_distribution<int> dim(1, 3), io(1, 2);
  bool ok = true;
  proofs::Instances uc{"loops around a block with an uncontrollable mode", 10}, uo{"loops around a block with an unobservable mode", 10};
  std::ostringstream ev;
  for (int c = 0; c < 40; ++c) {
    const int n1 = dim(g), n2 = dim(g), m = io(g), n = n1 + n2;
    const bool uncontrollable = c % 2 == 0;
    MatQ A = MatQ::Zero(n, n), B = MatQ::Zero(n, m), C = MatQ::Zero(m, n);
    A.topLeftCorner(n1, n1) = random(g, n1, n1);
    A.bottomRightCorner(n2, n2) = random(g, n2, n2);
    if (uncontrollable) {  // x2 not reached, but seen and driving x1
      A.topRightCorner(n1, n2) = random(g, n1, n2);
      B.topRows(n1) = random(g, n1, m);
      C = random(g, m, n);
    } else {  // x2 reached (and driven by x1), never seen
      A.bottomLeftCorner(n2, n1) = random(g, n2, n1);
      B = random(g, n, m);
      C.leftCols(n1) = random(g, m, n1);
    }
    const MatQ S = MatQ::Identity(n, n) + random(g, n, n) / rational(4 * n);
    const MatQ Si = exact_solve(S, MatQ::Identity(n, n), "S");
    const StateSpace<rational> E{exact_product(exact_product(S, A), Si), exact_product(S, B), exact_product(C, Si),
                                 random(g, m, m), rational(1, 100)};
    const HiddenModes h = hidden_modes(E);
    const Polynomial<rational> hidden = h.uncontrollable.expanded() * h.unobservable.expanded();
    const int nk = dim(g) - 1;
    StateSpace<rational> K{random(g, nk, nk), random(g, nk, m), random(g, m, nk), random(g, m, m), E.T};
    while (exact_rank(MatQ(MatQ::Identity(m, m) + exact_product(K.D, E.D))) < m) K.D = random(g, m, m);  // a well-posed loop
    const Polynomial<rational> cl = charpoly(closed_loop(E, K));
    const bool divides = divmod(cl, hidden).second.is_zero();
    ok = ok && divides && hidden.degree() >= n2;
    (uncontrollable ? uc : uo).count(hidden.degree() >= n2);
    if (!divides) ev << "case " << c << ": the closed loop's det(zI - A) is not divisible by the hidden factor; ";
  }
  ev << "40 blocks with known hidden parts, each closed by a random discrete controller: the hidden factor of "
        "lti::hidden_modes divides the closed loop's characteristic polynomial exactly in every case";
  check.claim("000.thm5.hidden_modes", "Theorem 5 (realisations as written)",
              "an uncontrollable or unobservable mode of a block is an eigenvalue of every loop closed through its ports -- "
              "at 40 random discrete blocks (orders 2-6, 1-2 ports, disguised by a similarity) each closed by a random "
              "controller, checked by exact divisibility of the characteristic polynomials",
              Status::exact, ok, ev.str(), {uc, uo});
}
