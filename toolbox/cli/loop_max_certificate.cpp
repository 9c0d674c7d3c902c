// cli/loop_max_certificate.cpp -- see loop_max_certificate.hpp.
#include "cli/loop_max_certificate.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <utility>

#include "cli/certificate.hpp"
#include "hapstab/check/scene_model.hpp"
#include "hapstab/check/stability_loop_check.hpp"
#include "hapstab/check/stability_loop_max_check.hpp"
#include "hapstab/check/stability_loop_symmetric_check.hpp"
#include "hapstab/lmi/program.hpp"
#include "hapstab/lmi/solve.hpp"
#include "hapstab/lti/circle_crossing.hpp"
#include "hapstab/numeric/decimal.hpp"
#include "hapstab/numeric/error.hpp"
#include "hapstab/numeric/result.hpp"
#include "hapstab/poly/sturm.hpp"

namespace hapstab::cli {

namespace {

using check::detail::BallRows;
using check::rational_matrix::Mat;

constexpr long kBits = 128;
constexpr size_t kMaxIntervals = 2048;  // ~n^2 x 25 bytes per interval: at most ~4 MB at order 9 (the checker takes 4096)

// The cover's search, over every interval, block and claim_ends' try of one certificate: at most kMaxSolves double
// Stein solves and kMaxSdps SDPs, else the certificate is refused by name. A strongly non-normal loop (a one-way link
// of 1000 between devices: each P holds over a sliver of p, the SDP widening tried again and again) otherwise searched
// for minutes; the ctests' largest, the 96-DOF split, uses 2438 and 552 in 2 s.
constexpr long kMaxSolves = 8192, kMaxSdps = 1024;
struct Work {
  long solves = 0, sdps = 0;
  void solve() { check(++solves > kMaxSolves); }
  void sdp() { check(++sdps > kMaxSdps); }
  static void check(bool over) {
    if (over)
      throw InputError("--certificate: the cover's search is beyond its work limit (" + std::to_string(kMaxSolves) + " Stein solves, " +
                       std::to_string(kMaxSdps) + " SDPs: each Stein P holds over a sliver of the parameter, a loop far from normal): "
                       "no certificate");
  }
};

// M(p) = (2 - p) M1 + (p - 1) M2, the checker's own formula (check/stability_loop_max_check.hpp).
BallRows loop_at(const BallRows& M1, const BallRows& M2, const rational& p) { return check::detail::affine_loop_at(M1, M2, p); }

std::vector<std::vector<std::pair<rational, rational>>> intervals(const BallRows& M) {
  std::vector<std::vector<std::pair<rational, rational>>> out(M.size());
  for (size_t i = 0; i < M.size(); ++i)
    for (const auto& x : M[i]) {
      const auto e = x.bounds();
      out[i].emplace_back(e.lo, e.hi);
    }
  return out;
}

Mat exact(const Eigen::MatrixXd& P) {
  Mat out(static_cast<size_t>(P.rows()), std::vector<rational>(static_cast<size_t>(P.cols())));
  for (Eigen::Index i = 0; i < P.rows(); ++i)
    for (Eigen::Index j = 0; j < P.cols(); ++j) out[size_t(i)][size_t(j)] = exact_rational(P(i, j));
  return out;
}

nlohmann::json rows(const Mat& P) {
  nlohmann::json r = nlohmann::json::array();
  for (const auto& row : P) {
    nlohmann::json x = nlohmann::json::array();
    for (const rational& v : row) x.push_back(v.str());
    r.push_back(x);
  }
  return r;
}

// x rounded down to a multiple of 2^-k, 2^-k <= ulp (a short end for an interval whose width is ~1000 ulp).
rational round_down(const rational& x, const rational& ulp) {
  integer scale = 1;
  while (rational(1, 1) / rational(scale) > ulp) scale *= 2;
  const integer n = integer(numerator(x) * scale / denominator(x));  // floor for x >= 0
  return rational(n) / rational(scale);
}

// P's entries to `bits` significant bits (a shorter certificate; the caller checks it still passes).
Mat rounded(const Eigen::MatrixXd& P, int bits) {
  Eigen::MatrixXd R = P;
  for (Eigen::Index i = 0; i < R.rows(); ++i)
    for (Eigen::Index j = 0; j < R.cols(); ++j) {
      int e = 0;
      const double f = std::frexp(P(i, j), &e);
      R(i, j) = std::ldexp(std::round(std::ldexp(f, bits)), e - bits);
    }
  return exact(R);
}

Eigen::MatrixXd midpoints(const BallRows& M) {
  Eigen::MatrixXd D(static_cast<Eigen::Index>(M.size()), static_cast<Eigen::Index>(M.size()));
  for (size_t i = 0; i < M.size(); ++i)
    for (size_t j = 0; j < M.size(); ++j) {
      const auto e = M[i][j].bounds();
      D(Eigen::Index(i), Eigen::Index(j)) = rational((e.lo + e.hi) / 2).convert_to<double>();
    }
  return D;
}

// The program's strict LMIs with the best margin, on the built-in IPM alone (DSDP and CSDP's subprocess take
// seconds each here); nullopt unless feasible. The producer's numbers only: the checker's test decides.
std::optional<lmi::SolveResult> solve_for_margin(lmi::Program& prog) {
  prog.set_margin_objective(1.0);
  lmi::Options opt;
  opt.certify = false;
  opt.backend = lmi::Backend::ipm;
  lmi::SolveResult r = lmi::solve(prog, opt);
  if (r.verdict != lmi::Feasibility::feasible) return std::nullopt;
  return r;
}

// One P for both ends of [a, b], wider than a Lyapunov P reaches: an SDP in the balanced coordinates of
// M at the midpoint (I <= P <= 10^8 I, P - M^T P M > 0 at a and at b, the margin maximised), mapped back
// exactly; nullopt when the SDP finds none or the checker's test refuses it (24 bits, then 53).
std::optional<Mat> common_stein(const BallRows& Ma, const BallRows& Mb) {
  Eigen::MatrixXd A = midpoints(Ma), B = midpoints(Mb);
  const int n = static_cast<int>(A.rows());
  const std::vector<int> e = balancing_exponents((A + B) / 2);
  for (int i = 0; i < n; ++i)
    for (int k = 0; k < n; ++k) {
      A(i, k) = std::ldexp(A(i, k), e[size_t(k)] - e[size_t(i)]);
      B(i, k) = std::ldexp(B(i, k), e[size_t(k)] - e[size_t(i)]);
    }
  const Eigen::MatrixXd I = Eigen::MatrixXd::Identity(n, n);
  lmi::Program prog;
  const lmi::MatrixVariable P = prog.new_symmetric(n, "P");
  prog.add_lmi("P >= I", lmi::Expr(P) - lmi::Expr(I), lmi::Strictness::nonstrict);
  prog.add_lmi("P <= 10^8 I", lmi::Expr(Eigen::MatrixXd(1e8 * I)) - lmi::Expr(P), lmi::Strictness::nonstrict);
  prog.add_lmi("Stein at a", lmi::Expr(P) - Eigen::MatrixXd(A.transpose()) * lmi::Expr(P) * A);
  prog.add_lmi("Stein at b", lmi::Expr(P) - Eigen::MatrixXd(B.transpose()) * lmi::Expr(P) * B);
  const auto r = solve_for_margin(prog);
  if (!r) return std::nullopt;
  Eigen::MatrixXd Pb = r->solution(P);
  for (int i = 0; i < n; ++i)
    for (int k = 0; k < n; ++k) Pb(i, k) = std::ldexp(Pb(i, k), -e[size_t(i)] - e[size_t(k)]);
  std::string why;
  for (const int bits : {24, 53}) {
    const Mat Pq = rounded(Pb, bits);
    if (check::detail::stein_holds(Pq, Ma, why) && check::detail::stein_holds(Pq, Mb, why)) return Pq;
  }
  return std::nullopt;
}

// evidence.first_order_unstable from the SDP's P0, S (double): w from S's least eigenvector, eps lowered where w^T P(eps) w
// is not < 0, each rounding checked by the checker's own test; nullopt when none passes.
std::optional<nlohmann::json> first_order_unstable_json(const Eigen::MatrixXd& P0, const Eigen::MatrixXd& Sd, const Eigen::MatrixXd& Ld,
                                                        const Mat& L, const rational& eps, const check::detail::LoopMatrix& m1,
                                                        const check::detail::LoopMatrix& m2) {
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> es(Sd);
  if (es.info() != Eigen::Success || !(es.eigenvalues()(0) < 0)) return std::nullopt;
  const Eigen::VectorXd wd = Ld.transpose() * (Ld * Ld.transpose()).ldlt().solve(es.eigenvectors().col(0));
  if (!wd.allFinite()) return std::nullopt;
  const double s = wd.dot(Ld.transpose() * Sd * Ld * wd), q = wd.dot(P0 * wd);
  rational e = eps;
  if (s < 0 && q > 0 && q + s / eps.convert_to<double>() >= 0) e = rational(0.5 * (-s / q));
  for (const int bits : {24, 53}) {
    const Mat w = rounded(Eigen::MatrixXd(wd.transpose()), 53);
    nlohmann::json fo{{"to", e.str()}, {"P0", rows(rounded(P0, bits))}, {"S", rows(rounded(Sd, bits))}, {"w", rows(w)[0]}};
    bool refuted = false;
    if (check::detail::first_order_unstable(fo, m1, m2, L, "evidence", refuted).empty()) return fo;
  }
  return std::nullopt;
}

// The first-order start on (0, eps] (check/stability_loop_max_check.hpp): P0, S from an SDP in M(eps)'s
// balanced coordinates (x = D y: P0 = D^-1 P0_b D^-1, L_b = C L D, K_b = C K D, S = C S_b C, C scaling each
// slow row to unit length), P0 >= I, 0 <= S_b, both <= 10^8,
// Q(0) > 0 and Q(eps) > 0 with Q(p) = P0 - M(p)^T P0 M(p) - (K^T S L + L^T S K) - p K^T S K, the margin
// maximised; the dyadic rounding checked by the checker's own test. nullopt when none passes.
// outward: the mirror (first_order_unstable): S free (|S_b| <= 10^8), which Q(0) > 0 then makes indefinite, and w with
// L w the eigenvector of S's least eigenvalue (w = L^T (L L^T)^-1 u); eps lowered to half of -s / w^T P0 w (s = (L w)^T S
// (L w) < 0) where needed, Q staying > 0 on [0, eps] (concave).
std::optional<nlohmann::json> first_order_evidence(const BallRows& M1, const BallRows& M2, const Mat& L, const rational& eps,
                                                const check::detail::LoopMatrix& m1, const check::detail::LoopMatrix& m2,
                                                const rational& lo, bool outward = false) {
  const Eigen::MatrixXd A0 = midpoints(loop_at(M1, M2, rational(0))), Ae = midpoints(loop_at(M1, M2, eps));
  const Eigen::MatrixXd dM = midpoints(M2) - midpoints(M1);
  const int n = static_cast<int>(A0.rows()), k = static_cast<int>(L.size());
  Eigen::MatrixXd Ld(k, n);
  for (int r = 0; r < k; ++r)
    for (int i = 0; i < n; ++i) Ld(r, i) = L[size_t(r)][size_t(i)].convert_to<double>();
  const std::vector<int> e = balancing_exponents(Ae);
  Eigen::VectorXd d(n);
  for (int i = 0; i < n; ++i) d(i) = std::ldexp(1.0, e[size_t(i)]);
  const Eigen::MatrixXd D = d.asDiagonal(), Di = d.cwiseInverse().asDiagonal();
  // the slow rows scaled to unit length (a power of 2 each, S := C S_b C maps back): L in echelon form can be
  // 10^-4 in these coordinates and K = L dM 10^-11, out of reach of S <= 10^8
  Eigen::VectorXd c(k);
  for (int r = 0; r < k; ++r) c(r) = std::ldexp(1.0, -std::ilogb((Ld.row(r) * D).norm()));
  const Eigen::MatrixXd C = c.asDiagonal();
  const Eigen::MatrixXd B0 = Di * A0 * D, Be = Di * Ae * D, Lb = C * Ld * D, Kb = C * Ld * dM * D;
  const Eigen::MatrixXd In = Eigen::MatrixXd::Identity(n, n), Ik = Eigen::MatrixXd::Identity(k, k);
  lmi::Program prog;
  const lmi::MatrixVariable P = prog.new_symmetric(n, "P0"), S = prog.new_symmetric(k, "S");
  prog.add_lmi("P0 >= I", lmi::Expr(P) - lmi::Expr(In), lmi::Strictness::nonstrict);
  prog.add_lmi("P0 <= 10^8 I", lmi::Expr(Eigen::MatrixXd(1e8 * In)) - lmi::Expr(P), lmi::Strictness::nonstrict);
  if (outward) prog.add_lmi("S >= -10^8 I", lmi::Expr(S) + lmi::Expr(Eigen::MatrixXd(1e8 * Ik)), lmi::Strictness::nonstrict);
  else prog.add_lmi("S >= 0", lmi::Expr(S), lmi::Strictness::nonstrict);
  prog.add_lmi("S <= 10^8 I", lmi::Expr(Eigen::MatrixXd(1e8 * Ik)) - lmi::Expr(S), lmi::Strictness::nonstrict);
  const lmi::Expr cross = Eigen::MatrixXd(Kb.transpose()) * lmi::Expr(S) * Lb + Eigen::MatrixXd(Lb.transpose()) * lmi::Expr(S) * Kb;
  const lmi::Expr ksk = Eigen::MatrixXd(Kb.transpose()) * lmi::Expr(S) * Kb;
  prog.add_lmi("Q(0)", lmi::Expr(P) - Eigen::MatrixXd(B0.transpose()) * lmi::Expr(P) * B0 - cross);
  prog.add_lmi("Q(eps)", lmi::Expr(P) - Eigen::MatrixXd(Be.transpose()) * lmi::Expr(P) * Be - cross - eps.convert_to<double>() * ksk);
  const auto r = solve_for_margin(prog);
  if (!r) return std::nullopt;
  Eigen::MatrixXd P0 = Di * r->solution(P) * Di;
  const Eigen::MatrixXd Sd = C * r->solution(S) * C;
  if (outward) return first_order_unstable_json(P0, Sd, Ld, L, eps, m1, m2);
  for (const int bits : {24, 53}) {
    nlohmann::json fo{{"to", eps.str()}, {"P0", rows(rounded(P0, bits))}, {"S", rows(rounded(Sd, bits))}};
    rational from = 0;
    if (check::detail::first_order_start(fo, m1, m2, L, lo, from).empty()) return fo;
  }
  return std::nullopt;
}

struct Piece {
  rational to;
  Mat P, P_to;  // P_to empty: P constant on the interval; else P at its start, P_to at `to`, linear between
};

struct Found {  // an interval [a, b] of the cover, b the caller's
  rational a;
  Mat P;                 // the interval's P, or (P linear) the one at a
  bool widened = false;  // one P, made wider by an SDP
};

// The Stein P of M(p) (the double solve's, to 53 bits), nullopt where that solve finds M(p) not stable.
std::optional<Mat> stein_P(const BallRows& M1, const BallRows& M2, const rational& p, Work& work) {
  work.solve();
  const SchurDecision d = stein_evidence(intervals(loop_at(M1, M2, p)));
  if (!d.stable || !*d.stable) return std::nullopt;
  return rounded(d.P, 53);
}

// [a, b] with P linear between the Stein P's of its ends (the Bernstein test, check/stability_loop_check.hpp): near a
// crossing P follows M where one P cannot. The width quadrupled from the last one, halved until it passes, down to an
// eighth of the last (narrower: the one-P interval serves).
std::optional<Found> linear_interval(const BallRows& M1, const BallRows& M2, const rational& start, const rational& b, const rational& width,
                                     const Mat& Pb, Work& work) {
  std::string why;
  for (rational w = std::min(rational(4 * width), rational(b - start)); w >= width / 8; w /= 2) {
    const rational a = w == b - start ? start : std::max(start, round_down(b - w, w / 1024));
    auto Pa = stein_P(M1, M2, a, work);
    if (Pa && check::detail::bernstein_stein_holds(*Pa, Pb, loop_at(M1, M2, a), loop_at(M1, M2, b), why)) return Found{a, *Pa};
  }
  return std::nullopt;
}

// After two SDP misses in a row (near the crossing, where the margin is below the SDP's tolerance) the next 8
// intervals skip it. `work`: the certificate's budget.
struct SdpWidening {
  Work& work;
  int misses = 0, skip = 0;
};

// [a, b] with one P: the Stein P of its midpoint, the width doubled from the last one, halved until P passes at both
// ends; then wider by an SDP where one P holds over more (4, 16, 64, 256 times the width: a P made for the whole
// interval; 340 -> 107 intervals on the ctest's scene of order 8, at ~60 ms an SDP).
std::optional<Found> one_p_interval(const BallRows& M1, const BallRows& M2, const rational& start, const rational& b, const rational& width,
                                    SdpWidening& sdp) {
  std::string why;
  rational w = std::min(rational(2 * width), rational(b - start)), a;
  std::optional<Mat> P;
  for (int halving = 0; halving < 60 && !P; ++halving, w /= 2) {
    a = w == b - start ? start : std::max(start, round_down(b - w, w / 1024));
    sdp.work.solve();
    const SchurDecision d = stein_evidence(intervals(loop_at(M1, M2, (a + b) / 2)));
    if (!d.stable || !*d.stable) continue;
    for (const int bits : {24, 53}) {
      const Mat Pk = rounded(d.P, bits);
      if (check::detail::stein_holds(Pk, loop_at(M1, M2, a), why) && check::detail::stein_holds(Pk, loop_at(M1, M2, b), why)) {
        P = Pk;
        break;
      }
    }
  }
  if (!P) return std::nullopt;
  if (sdp.skip > 0) --sdp.skip;
  bool widened = false;
  for (const int k : {4, 16, 64, 256}) {
    if (a == start || sdp.skip > 0) break;
    const rational wide = b - rational(k) * (b - a);
    const rational a2 = wide <= start ? start : std::max(start, round_down(wide, (b - wide) / 1024));
    sdp.work.sdp();
    if (auto Pw = common_stein(loop_at(M1, M2, a2), loop_at(M1, M2, b))) {
      P = Pw, a = a2, sdp.misses = 0, widened = true;
    } else {
      if (k == 4 && ++sdp.misses >= 2) sdp.skip = 8, sdp.misses = 0;
      break;
    }
  }
  return Found{a, *P, widened};
}

// The certificate of "stable on [0, lo], NOT stable at hi" (lo = hi = 0: sup = 0), or why there is none.
struct Attempt {
  nlohmann::json evidence;
  std::string why;  ///< "" when the evidence is complete
};

// evidence.unstable_at: NOT stable at hi by Stein inertia (hi = 0 beside slow modes: M(0) on ker L); "" when written
// into `evidence`, else why not.
std::string unstable_evidence(const BallRows& M1, const BallRows& M2, const std::string& name, const rational& hi, const Mat& slow,
                              nlohmann::json& evidence) {
  SchurDecision u = stein_evidence(intervals(loop_at(M1, M2, hi)));
  bool on_ker = false;  // sup = 0 beside slow modes (their eigenvalue 1 leaves Stein inertia none): M(0) on ker L
  if ((!u.stable || *u.stable) && hi == 0 && !slow.empty()) {
    const SchurDecision r = stein_evidence(intervals(check::detail::restricted(loop_at(M1, M2, hi), slow)));
    if (r.stable && !*r.stable) u = r, on_ker = true;
  }
  if (!u.stable || *u.stable)
    return "no Stein inertia certificate that " + name + " = " + check::detail::decimal(hi) + " is NOT stable (" + u.why + ")" +
           (hi == 0 ? ": at " + name + " = 0 an eigenvalue on the circle too, which the slow rows do not carry" : "");
  evidence["unstable_at"] = {{"at", hi.str()}, {"P", rows(exact(u.P))}, {"w", rows(exact(u.w.transpose()))[0]}};
  if (on_ker) evidence["unstable_at"]["slow_quotient"] = true;
  return "";
}

// sup = 0: evidence.unstable_at at 0 (Stein inertia on M(0), or on ker L beside the slow modes), else, beside slow modes,
// first_order_unstable on (0, eps] (eps the producer's own mirror's end, first_order_to, else 4^-j; then 4^-j of it); ""
// when written into `evidence`, else why not.
std::string zero_evidence(const BallRows& M1, const BallRows& M2, const check::detail::LoopMatrix& m1, const check::detail::LoopMatrix& m2,
                          const std::string& name, const Mat& L, const rational& first_order_to, nlohmann::json& evidence) {
  const std::string why = unstable_evidence(M1, M2, name, 0, L, evidence);
  if (why.empty() || L.empty()) return why;
  rational eps = first_order_to > 0 ? first_order_to : rational(1);
  for (int j = 0; j < 24; ++j, eps /= 4)
    if (const auto fo = first_order_evidence(M1, M2, L, eps, m1, m2, eps, true)) {
      evidence["first_order_unstable"] = *fo;
      return "";
    }
  return why + "; nor a first-order mirror (no P0, S, w found showing (0, eps] NOT stable)";
}

// unstable_at at hi (its Stein inertia) where `unstable`, then the cover of [start, lo].
Attempt evidence_for(const BallRows& M1, const BallRows& M2, const std::string& name, const rational& lo, const rational& hi,
                     const rational& start, const Mat& slow, Work& work, bool unstable = true) {
  Attempt out;
  if (unstable)
    if (std::string why = unstable_evidence(M1, M2, name, hi, slow, out.evidence); !why.empty()) return {{}, why};
  std::vector<Piece> pieces;  // from lo down
  rational b = lo, width = lo - start;
  SdpWidening sdp{work};
  std::optional<Mat> P_at_b;  // the Stein P at b, kept from the last interval with P linear
  bool sdp_regime = false;    // the last interval was one P that an SDP widened
  while (b > start) {
    if (pieces.size() >= kMaxIntervals) return {{}, "more than " + std::to_string(kMaxIntervals) + " intervals to cover [" + check::detail::decimal(start) + ", " + check::detail::decimal(lo) +
                        "] (a Stein P, or a pair of them, holds over a width ~ a fraction of the distance to the crossing)"};
    // P linear first (double Stein solves and Bernstein tests, no SDP): kept at once where it holds over the last
    // width or more, unless the last interval was one P that an SDP widened (there one P may reach much farther:
    // 7 intervals against 19 on loop_max_free_wall_stiffness). Else one P (widened by SDPs), and P linear where it
    // reaches 2.5 times as far (its check costs ~2.5 times as much: 12 products and 4 tests of definiteness against
    // 4 and 2). Linear first: 20 s -> 6.6 s for a 3-DOF loop of order 12 whose SDPs reached 4 times the width and
    // missed at 16 in every interval (docs/certificates.md).
    if (!P_at_b) P_at_b = stein_P(M1, M2, b, work);
    std::optional<Found> lin;
    if (P_at_b) lin = linear_interval(M1, M2, start, b, width, *P_at_b, work);
    std::optional<Found> one;
    if (!(lin && b - lin->a >= width && !sdp_regime)) one = one_p_interval(M1, M2, start, b, width, sdp);
    if (lin && (!one || b - lin->a >= rational(5, 2) * (b - one->a))) {
      pieces.push_back({b, lin->P, *P_at_b});
      width = b - lin->a, b = lin->a, P_at_b = lin->P, sdp_regime = false;
      continue;
    }
    if (!one)
      return {{}, "no cover of [" + check::detail::decimal(start) + ", " + check::detail::decimal(lo) + "] below " + name + " = " +
                      check::detail::decimal(b)};
    pieces.push_back({b, one->P, {}});
    width = b - one->a, b = one->a, P_at_b.reset(), sdp_regime = one->widened;
  }
  nlohmann::json cover = nlohmann::json::array();
  const Mat* last_P_to = nullptr;  // a linear interval's P equal to the last one's P_to is left out (the checkers take that)
  for (auto it = pieces.rbegin(); it != pieces.rend(); ++it) {
    cover.push_back({{"to", it->to.str()}});
    if (it->P_to.empty() || !last_P_to || *last_P_to != it->P) cover.back()["P"] = rows(it->P);
    if (!it->P_to.empty()) cover.back()["P_to"] = rows(it->P_to);
    last_P_to = it->P_to.empty() ? nullptr : &it->P_to;
  }
  if (!cover.empty()) out.evidence["cover"] = cover;
  return out;
}

}  // namespace

SupClaim sup_claim(const stability::LoopMax& m) { return {m.outcome, m.crossing, m.stable_to, m.first_order_to, m.no_crossing_to}; }

SupClaim sup_claim(const stability::MaxGain& m) {
  if (m.infinite) throw InputError("--certificate: sup is +infinity: no stability-loop-max certificate (its claim is an enclosure)");
  const Enclosure<rational> e = m.exact ? Enclosure<rational>{*m.exact, *m.exact} : m.enclosure;
  return {m.outcome, e, e.lo, rational(0), rational(0)};
}

namespace {

// One loop read at p = 1 and 2, its matrices at kBits (the checker's own).
struct LoopPair {
  check::detail::SceneLoop loop1, loop2;
  check::detail::LoopMatrix m1, m2;
};

LoopPair loop_pair(check::detail::SceneLoop l1, check::detail::SceneLoop l2) {
  LoopPair out{std::move(l1), std::move(l2), {}, {}};
  flint::BallPrecision scope(kBits);
  out.m1 = check::detail::loop_matrix(out.loop1, kBits), out.m2 = check::detail::loop_matrix(out.loop2, kBits);
  check::detail::require_loop_max_order(out.m1.order);
  return out;
}

// The claim's ends: 0 and 0 (sup = 0), or decimals of 16 digits delta below and above the crossing's enclosure
// (relative), for the first delta whose Stein certificates a double solve finds: the narrowest enclosure this
// evidence proves (the crossing's own, Krawczyk's, is narrower still).
std::vector<std::pair<std::string, std::string>> claim_ends(const SupClaim& m, const std::string& name) {
  std::vector<std::pair<std::string, std::string>> ends;
  if (m.outcome == Outcome::fails) {
    ends.emplace_back("0", "0");
  } else if (m.outcome == Outcome::holds) {
    for (const rational& delta :
         {rational(1, 1000000000000), rational(1, 10000000000), rational(1, 100000000), rational(1, 1000000), rational(1, 10000)})
      ends.emplace_back(decimal_outward(std::min(rational(m.crossing.lo * (1 - delta)), m.stable_to), 16, -1),
                        decimal_outward(m.crossing.hi * (1 + delta), 16, +1));
  } else {
    throw InputError("--certificate: sup " + name + " is undecided: no certificate");
  }
  return ends;
}

// Where M(p) is rational (pure masses, no conserved quantity): a b <= lo such that no eigenvalue meets the unit circle
// on (0, b] (lti/circle_crossing.hpp: lo, or below R's first positive root); the evidence no_crossing {to: a} then
// takes a in (0, b], as near lo as the cover from a to lo allows (loop_evidence), far from the Jordan block
// at z = 1 that defeats the first-order start. nullopt where M is not rational or R vanishes identically.
std::optional<rational> no_crossing_bound(const LoopPair& lp, const rational& lo) {
  if (lp.m1.conserved != 0 || lp.m1.right_quotient || lp.loop1.own_conserved != 0) return std::nullopt;
  const auto X1 = check::detail::exact_loop_matrix(lp.loop1), X2 = check::detail::exact_loop_matrix(lp.loop2);
  if (!X1 || !X2 || X1->size() != X2->size() || static_cast<long>(X1->size()) > kCircleCrossingOrder) return std::nullopt;
  const long n = static_cast<long>(X1->size());
  MatQ M0(n, n), Md(n, n);
  for (long i = 0; i < n; ++i)
    for (long j = 0; j < n; ++j) {
      M0(i, j) = 2 * (*X1)[size_t(i)][size_t(j)] - (*X2)[size_t(i)][size_t(j)];
      Md(i, j) = (*X2)[size_t(i)][size_t(j)] - (*X1)[size_t(i)][size_t(j)];
    }
  CircleCrossing cc;
  try {
    cc = circle_crossing(M0, Md);
  } catch (const InputError&) {
    return std::nullopt;  // beyond its order or degree
  }
  if (cc.identically_zero) return std::nullopt;
  rational b = lo;
  for (const RootInterval& r : isolate_real_roots(cc.R, rational(0), lo))
    if (r.hi > 0) {
      b = r.lo > 0 ? r.lo : r.hi / 2;
      break;
    }
  while (b > 0 && count_real_roots(cc.R, rational(0), b) != 0) b /= 2;
  return b > 0 ? std::optional<rational>(b) : std::nullopt;
}

// sup = 0 where M(p) is rational: no_crossing {to: a} and unstable_at {at: a} (Stein inertia): NOT stable on (0, a]. a:
// the producer's own (hint, stability/loop_max.hpp's no_crossing_to), else half or an eighth of the bound below 1.
// "" when written into `evidence`, else why not.
std::string no_crossing_zero_evidence(const LoopPair& lp, const std::string& name, const rational& hint, nlohmann::json& evidence) {
  const std::optional<rational> b = no_crossing_bound(lp, rational(1));
  if (!b) return "M(" + name + ") not rational, or the resultant vanishes identically";
  std::vector<rational> tries{*b / 2, *b / 8};
  if (hint > 0 && hint <= *b) tries.insert(tries.begin(), hint);
  for (const rational& a : tries) {
    const SchurDecision u = stein_evidence(intervals(loop_at(lp.m1.M, lp.m2.M, a)));
    if (u.stable && !*u.stable) {
      evidence["no_crossing"] = {{"to", a.str()}};
      evidence["unstable_at"] = {{"at", a.str()}, {"P", rows(exact(u.P))}, {"w", rows(exact(u.w.transpose()))[0]}};
      return "";
    }
  }
  return "no Stein inertia certificate that " + name + " is NOT stable below the resultant's first root";
}

// One loop's evidence for sup in [lo, hi] ({first_order or no_crossing, cover, unstable_at} of check_max_part): where M(0)
// is only marginally stable (slow rows: L M(0) = L) no_crossing where M is rational, else the first-order start on (0,
// eps], eps the producer's own first-order cover's end (first_order_to), else lo / 4^j; unstable_at where `unstable`.
// nullopt with `why` when none is found.
std::optional<nlohmann::json> loop_evidence(const LoopPair& lp, const std::string& name, const rational& lo, const rational& hi,
                                            const rational& first_order_to, const rational& no_crossing_to, bool unstable, Work& work,
                                            std::string& why) {
  flint::BallPrecision scope(kBits);
  std::optional<nlohmann::json> start;
  // (not on a quotient by right eigenvectors: beyond the checker's start; at hi = 0 the slow rows serve
  // Stein inertia on ker L instead)
  const Mat L = !lp.m1.right_quotient ? check::detail::slow_rows(lp.loop1, lp.loop2, lp.m1) : Mat{};
  std::optional<rational> nc_bound = !L.empty() && lo > 0 ? no_crossing_bound(lp, lo) : std::nullopt;
  if (nc_bound && *nc_bound >= lo) {  // no crossing on (0, lo]: M(lo) stable by one P is all the cover needs
    std::string no;
    if (const auto P = stein_P(lp.m1.M, lp.m2.M, lo, work); P && check::detail::stein_holds(*P, loop_at(lp.m1.M, lp.m2.M, lo), no)) {
      nlohmann::json ev = nlohmann::json::object();
      if (unstable) no = unstable_evidence(lp.m1.M, lp.m2.M, name, hi, L, ev);
      if (no.empty()) {
        ev["cover"] = nlohmann::json::array({{{"to", lo.str()}, {"P", rows(*P)}}});
        ev["no_crossing"] = {{"to", lo.str()}};
        return ev;
      }
    }
  }
  if (nc_bound) {  // no_crossing {to: a}, a = b - b 2^-k: the cover [a, lo] shortest first, then from lower if it fails
    for (const int k : {10, 20, 30, 40}) {
      const rational a = round_down(*nc_bound - *nc_bound / rational(integer(1) << k), *nc_bound / rational(integer(1) << (k + 10)));
      if (a <= 0 || a >= lo) continue;
      Attempt at = evidence_for(lp.m1.M, lp.m2.M, name, lo, hi, a, L, work, unstable);
      if (!at.why.empty()) {
        why = at.why;
        continue;
      }
      at.evidence["no_crossing"] = {{"to", a.str()}};
      return at.evidence;
    }
  }
  if (!L.empty() && lo > 0) {
    std::vector<rational> tries;
    if (first_order_to > 0 && first_order_to <= lo) tries.push_back(first_order_to);
    for (rational t = lo / 4; tries.size() < 24; t /= 4) tries.push_back(t);
    try {
      for (const rational& eps : tries)
        if ((start = first_order_evidence(lp.m1.M, lp.m2.M, L, eps, lp.m1, lp.m2, lo))) break;
    } catch (const InputError& e) {  // not the environment's gain, conserved quantities, no slow mode
      why = std::string("no first-order start at 0: ") + e.what();
      return std::nullopt;
    }
    if (!start) {
      why = "no first-order start at 0 (the loop at " + name + " = 0 only marginally stable: no P0, S found for (0, eps])";
      return std::nullopt;
    }
  }
  if (hi == 0 && unstable) {  // sup = 0 (lo = 0: no cover)
    nlohmann::json ev = nlohmann::json::object();
    why = zero_evidence(lp.m1.M, lp.m2.M, lp.m1, lp.m2, name, L, first_order_to, ev);
    if (!why.empty()) {  // a Jordan block at z = 1 pushed out: the rational M's resultant
      nlohmann::json nc = nlohmann::json::object();
      if (no_crossing_zero_evidence(lp, name, no_crossing_to, nc).empty()) why.clear(), ev = nc;
    }
    return why.empty() ? std::optional<nlohmann::json>(ev) : std::nullopt;
  }
  const rational from = start ? parse_rational(start->at("to").get<std::string>()) : rational(0);
  Attempt a = evidence_for(lp.m1.M, lp.m2.M, name, lo, hi, from, L, work, unstable);
  if (!a.why.empty()) {
    why = a.why;
    return std::nullopt;
  }
  if (start) a.evidence["first_order"] = *start;
  return a.evidence;
}

nlohmann::json sup_claim_json(const std::string& quantity, const std::string& plo, const std::string& phi) {
  return {{"quantity", quantity}, {"status", "certified"}, {"lo", parse_rational(plo).str()}, {"hi", parse_rational(phi).str()},
          {"printed_lo", plo}, {"printed_hi", phi}};
}

// The scene's model read at p = v.
check::detail::SceneLoop read_at(const nlohmann::json& model, const std::string& name, long v, std::optional<size_t> max_dofs = std::nullopt) {
  nlohmann::json at = model;
  at["set"][name] = std::to_string(v);
  return max_dofs ? check::detail::read_scene_loop(at, *max_dofs) : check::detail::read_scene_loop(at);
}

}  // namespace

nlohmann::json stability_loop_max_certificate(const nlohmann::json& model, const std::string& name, const SupClaim& m) {
  nlohmann::json j = certificate_header("stability-loop-max");
  j["model"] = model;
  if (j["model"]["set"].contains(name)) throw InputError("--certificate: --set " + name + "=...: the parameter maximised has no value");
  j["model"]["name"] = name;
  LoopPair lp;
  try {
    lp = loop_pair(read_at(model, name, 1), read_at(model, name, 2));
  } catch (const InputError& e) {
    throw InputError(std::string("--certificate: the checker does not take this loop (") + e.what() + "): no certificate");
  }
  std::string why;
  Work work;
  for (const auto& [plo, phi] : claim_ends(m, name)) {
    const auto ev = loop_evidence(lp, name, parse_rational(plo), parse_rational(phi), m.first_order_to, m.no_crossing_to, true, work, why);
    if (!ev) continue;
    j["evidence"] = *ev;
    j["claim"] = sup_claim_json("sup " + name + " = sup{p0 > 0: the " + (model.contains("scene") ? "scene's " : "") +
                                    "loop as written is stable for every " + name + " in (0, p0)}, the closed-loop matrix built by the checker",
                                plo, phi);
    if (lp.m1.conserved > 0) j["claim"]["conserved"] = lp.m1.conserved;
    verify_before_writing(j);
    return j;
  }
  throw InputError("--certificate: " + why + ": no certificate");
}

nlohmann::json stability_loop_max_hidden_certificate(const nlohmann::json& model, const std::string& name, const nlohmann::json& hidden) {
  nlohmann::json j = certificate_header("stability-loop-max");
  j["model"] = model;
  if (j["model"]["set"].contains(name)) throw InputError("--certificate: --set " + name + "=...: the parameter maximised has no value");
  j["model"]["name"] = name;
  j["claim"] = {{"quantity", "sup " + name + " = sup{p0 > 0: the scene's loop as written is stable for every " + name +
                                 " in (0, p0)}, 0 by a hidden mode of a block that " + name + " does not move"},
                {"status", "exact"},
                {"value", "0"}};
  j["evidence"] = {{"hidden", hidden}};
  verify_before_writing(j);
  return j;
}

nlohmann::json stability_loop_max_symmetric_certificate(const nlohmann::json& model, const std::string& name, const SupClaim& m) {
  nlohmann::json j = certificate_header("stability-loop-max-symmetric");
  j["model"] = model;
  if (j["model"]["set"].contains(name)) throw InputError("--certificate: --set " + name + "=...: the parameter maximised has no value");
  j["model"]["name"] = name;
  std::vector<std::vector<int>> classes;
  std::vector<LoopPair> blocks;  // slot 0: the fixed space; then each class of two DOFs or more
  std::vector<nlohmann::json> labels;
  std::vector<long> copies;
  try {
    const auto r = check::detail::read_max_parameter(model.at("scene").get<std::string>(), name);
    if (r.block != "environment") throw InputError("'" + name + "' is the gain of [coupling] (the split compares the environment only)");
    const auto l1 = read_at(model, name, 1, check::detail::kMaxSymmetricDofs), l2 = read_at(model, name, 2, check::detail::kMaxSymmetricDofs);
    classes = check::detail::identical_dofs(l1);
    std::string why;
    const auto s1 = check::detail::split_loop(l1, classes, why), s2 = check::detail::split_loop(l2, classes, why);
    if (!s1 || !s2) throw InputError("the scene is not invariant under its identical DOFs' permutations (" + why + ")");
    for (size_t slot = 0; slot <= classes.size(); ++slot) {
      if (slot > 0 && s1->sizes[slot - 1] < 2) continue;
      blocks.push_back(loop_pair(s1->block(slot), s2->block(slot)));
      labels.push_back(slot == 0 ? nlohmann::json{{"space", "fixed"}} : nlohmann::json{{"space", "zero-sum"}, {"class", slot - 1}});
      copies.push_back(slot == 0 ? 1 : static_cast<long>(s1->sizes[slot - 1]) - 1);
    }
  } catch (const InputError& e) {
    throw InputError(std::string("--certificate: the checker does not take this loop (") + e.what() + "): no certificate");
  }
  std::string why;
  Work work;
  for (const auto& [plo, phi] : claim_ends(m, name)) {
    const rational lo = parse_rational(plo), hi = parse_rational(phi);
    // the block NOT stable at hi: the first whose Stein inertia shows it
    std::optional<size_t> deciding;
    nlohmann::json un;
    // Stein inertia on every block first; with hi = 0 then the first-order mirror (its SDPs are tried only where no
    // block's Stein inertia serves)
    for (int pass = 0; pass < (hi == 0 ? 2 : 1) && !deciding; ++pass)
      for (size_t b = 0; b < blocks.size() && !deciding; ++b) {
        flint::BallPrecision scope(kBits);
        const Mat L = !blocks[b].m1.right_quotient ? check::detail::slow_rows(blocks[b].loop1, blocks[b].loop2, blocks[b].m1) : Mat{};
        std::string no = pass == 1 ? zero_evidence(blocks[b].m1.M, blocks[b].m2.M, blocks[b].m1, blocks[b].m2, name, L, m.first_order_to, un)
                                   : unstable_evidence(blocks[b].m1.M, blocks[b].m2.M, name, hi, L, un);
        if (!no.empty() && pass == 1) no = no_crossing_zero_evidence(blocks[b], name, rational(0), un);  // rational M: the resultant
        if (no.empty()) deciding = b;
      }
    if (!deciding) {
      why = "no block with a Stein inertia certificate that " + name + " = " + phi + " is NOT stable";
      continue;
    }
    nlohmann::json evidence{{"classes", classes}, {"blocks", nlohmann::json::array()}};
    long total = 0;
    bool all = true;
    for (size_t b = 0; b < blocks.size() && all; ++b) {
      if (hi == 0 && b != *deciding) continue;  // sup = 0: the one block
      std::optional<nlohmann::json> ev = lo > 0 ? loop_evidence(blocks[b], name, lo, hi, 0, 0, false, work, why) : nlohmann::json::object();
      if (!ev) {
        why = "block " + labels[b].dump() + ": " + why;
        all = false;
        continue;
      }
      nlohmann::json blk = labels[b];
      if (blocks[b].m1.conserved > 0) blk["conserved"] = blocks[b].m1.conserved;
      for (auto& [k, v] : ev->items()) blk[k] = v;
      if (b == *deciding)
        for (auto& [key, v] : un.items()) blk[key] = v;  // unstable_at, or first_order_unstable (sup = 0)
      evidence["blocks"].push_back(blk);
      total += copies[b] * static_cast<long>(blocks[b].m1.conserved);
    }
    if (!all) continue;
    j["evidence"] = evidence;
    j["claim"] = sup_claim_json("sup " + name + " = sup{p0 > 0: the scene's loop as written is stable for every " + name +
                                    " in (0, p0)}, on the small loops of the split by identical DOFs the checker derives",
                                plo, phi);
    if (hi > 0 && total > 0) j["claim"]["conserved"] = total;
    verify_before_writing(j);
    return j;
  }
  throw InputError("--certificate: " + why + ": no certificate");
}

}  // namespace hapstab::cli
