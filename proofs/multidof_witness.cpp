// proofs/multidof_witness.cpp -- the identities the frequency-domain witness of Theorem 4's
// program rests on (multidof/path_witness.cpp, theorem4_witness; issue 39).
//
// For a realisation (A, B, C, D), a point z of the unit circle that is not an eigenvalue of A,
// a complex u and x = (zI - A)^-1 B u (so A x + B u = z x), v = [x; u]:
//   (a) v^* [[A^T P A - P, A^T P B], [B^T P A, B^T P B]] v = |z|^2 x^* P x - x^* P x = 0 for every
//       symmetric P;
//   (b) hence V-hat's Lemma 1 matrix F(P) (multidof/detail.hpp, lemma1_matrix, the matrix the exact
//       re-check tests) gives v^* F v = y^* Q_V y - Re(u^* X y), y = C x + D u = G(z) u;
//   (c) and (16)'s first LMI M1 = [[A^T P A - P, A^T P B - C^T X/2], [., B^T P B - (X D + D^T X)/2
//       - Q_E]] gives v^* M1 v = -Re(u^* X y) - u^* Q_E u.
// With -F >= 0, M1 <= 0 and (14) > 0 at [p; q] these give the witness inequality phi(X) > 0 of
// path_witness.cpp. The proof checks (a)-(c) in exact complex-rational arithmetic (pairs of
// rational matrices) at rational points z = ((1 - t^2) + 2 t j)/(1 + t^2) of the circle, on random
// dyadic data and random symmetric P, X, Q.
#include <random>
#include <sstream>

#include "hapstab/multidof/detail.hpp"
#include "hapstab/numeric/error.hpp"
#include "hapstab/numeric/exact_matrix.hpp"
#include "proofs/proof.hpp"

namespace {

using namespace hapstab;

MatQ dyadic(std::mt19937& g, int rows, int cols) {
  std::uniform_int_distribution<int> k(-8, 8);
  MatQ M(rows, cols);
  for (int i = 0; i < rows; ++i)
    for (int j = 0; j < cols; ++j) M(i, j) = rational(k(g), 8);
  return M;
}
MatQ symmetric(std::mt19937& g, int n) {
  const MatQ R = dyadic(g, n, n);
  return (R + MatQ(R.transpose())) / 2;
}

struct C {  // a complex rational vector
  MatQ re, im;
};
// the Hermitian form v^* M v of a real symmetric M: its imaginary part vanishes
rational form(const C& v, const MatQ& M) {
  return (v.re.transpose() * M * v.re)(0, 0) + (v.im.transpose() * M * v.im)(0, 0);
}
// Re(a^* M b) for a real M
rational re_form(const C& a, const MatQ& M, const C& b) {
  return (a.re.transpose() * M * b.re)(0, 0) + (a.im.transpose() * M * b.im)(0, 0);
}
C stack(const C& x, const C& u) {
  C v{MatQ(x.re.rows() + u.re.rows(), 1), MatQ(x.re.rows() + u.re.rows(), 1)};
  v.re << x.re, u.re;
  v.im << x.im, u.im;
  return v;
}

}  // namespace

HAPSTAB_PROOF(multidof_witness_identities, "000",
              "the frequency-domain witness of Theorem 4's program: the storage terms vanish on the circle") {
  std::mt19937 g(39);
  std::uniform_int_distribution<int> order(1, 4), width(1, 3), tk(-12, 12);
  bool a_holds = true, b_holds = true, c_holds = true;
  proofs::Instances inst{"instances with x != 0 and z not real", 40};
  for (int trial = 0; trial < 50; ++trial) {
    const int n = order(g), m = width(g);
    StateSpace<rational> S;
    S.T = rational(1, 100);
    S.A = dyadic(g, n, n) / 4;
    S.B = dyadic(g, n, m);
    S.C = dyadic(g, m, n);
    S.D = dyadic(g, m, m);
    const MatQ P = symmetric(g, n), X = symmetric(g, m), Q = symmetric(g, m), QE = symmetric(g, m);
    const rational t(tk(g), 4), den = 1 + t * t, za = (1 - t * t) / den, zb = 2 * t / den;
    const C u{dyadic(g, m, 1), dyadic(g, m, 1)};
    // x = (zI - A)^-1 B u: [[za I - A, -zb I], [zb I, za I - A]] [xr; xi] = [B ur; B ui]
    MatQ L = MatQ::Zero(2 * n, 2 * n), r(2 * n, 1);
    const MatQ I = MatQ::Identity(n, n);
    L.topLeftCorner(n, n) = L.bottomRightCorner(n, n) = za * I - S.A;
    L.topRightCorner(n, n) = -zb * I;
    L.bottomLeftCorner(n, n) = zb * I;
    r << S.B * u.re, S.B * u.im;
    MatQ xs;
    try {
      xs = exact_solve(L, r, "zI - A");
    } catch (const InputError&) {
      continue;  // z an eigenvalue of A: not an instance
    }
    const C x{xs.topRows(n), xs.bottomRows(n)};
    const C v = stack(x, u);
    const C y{S.C * x.re + S.D * u.re, S.C * x.im + S.D * u.im};
    // (a)
    MatQ W(n + m, n + m);
    W << S.A.transpose() * P * S.A - P, S.A.transpose() * P * S.B, S.B.transpose() * P * S.A, S.B.transpose() * P * S.B;
    a_holds = a_holds && form(v, W) == 0;
    // (b) Lemma 1's matrix for the system as V-hat (lemma1_matrix takes any realisation)
    const MatQ F = multidof::detail::lemma1_matrix(S, P, X, Q);
    b_holds = b_holds && form(v, F) == form(y, Q) - re_form(u, X, y);
    // (c) (16)'s first LMI
    MatQ M1(n + m, n + m);
    M1 << S.A.transpose() * P * S.A - P, S.A.transpose() * P * S.B - S.C.transpose() * X / 2,
        S.B.transpose() * P * S.A - X * S.C / 2, S.B.transpose() * P * S.B - (X * S.D + S.D.transpose() * X) / 2 - QE;
    c_holds = c_holds && form(v, M1) == -re_form(u, X, y) - form(u, QE);
    inst.count(!x.re.isZero(0) && zb != 0);
  }
  std::ostringstream ev;
  ev << "rational arithmetic at rational points of the unit circle: (a) " << (a_holds ? "holds" : "FAILS") << ", (b) "
     << (b_holds ? "holds" : "FAILS") << ", (c) " << (c_holds ? "holds" : "FAILS") << " (1-4 states, 1-3 channels)";
  check.claim("000.thm4.witness_identities", "Theorem 4, Lemma 1, (16)",
              "at z on the unit circle, x = (zI - A)^-1 B u, v = [x; u]: the storage terms of Lemma 1's matrix and of (16)'s "
              "first LMI vanish (v^* F v = y^* Q_V y - Re(u^* X y), v^* M1 v = -Re(u^* X y) - u^* Q_E u, y = G(z) u) -- on 50 "
              "random instances",
              Status::exact, a_holds && b_holds && c_holds, ev.str(), {inst});
}
