// hapstab/multidof/facial.cpp -- the facial reduction of (16)'s first LMI (analysis.hpp): which
// X in G(m; m_1..m_N) keep X E(1) symmetric, as a rational basis found by connected components.
#include <algorithm>
#include <sstream>

#include "hapstab/multidof/analysis.hpp"
#include "hapstab/numeric/numeric_decimal.hpp"

namespace hapstab::multidof {

namespace {

// The rational basis of {g in Q^N : X(g) G symmetric for every G in `gains`}, X(g) the block
// diagonal with g_b I on operator b's block (blk[i] = the operator of DOF i). Each condition
// (X G)_ij = (X G)_ji (i < j) reads g_p G_ij - g_q G_ji = 0, p = blk[i], q = blk[j]: at most two
// unknowns. So the conditions are a graph on the operators: an edge a g_p = b g_q (a, b != 0)
// fixes the ratio g_q / g_p; a condition with one nonzero coefficient (or p = q with
// G_ij != G_ji) forces g_p = 0, and so does a cycle whose ratios do not multiply to 1. Each
// connected component without such a contradiction contributes one basis vector w (the ratios,
// w = 1 at its largest column); the others contribute nothing. O(m^2) work where the rational
// RREF of the m(m-1)/2 x N condition matrix took O(m^2 N^2).
//
// The basis is the one the RREF gives, vector for vector (tests/multidof compares both): the
// RREF of a component's rows (rank = size - 1) has its largest column free, so its null vector
// is w with w = 1 there; vectors come in the order of their free columns, and each is signed so
// that its first nonzero entry is positive (g >= 1 wants positive directions).
std::vector<std::vector<rational>> symmetric_gain_basis(const std::vector<int>& blk, int N,
                                                        const std::vector<MatQ>& gains) {
  struct Edge {
    int to;
    rational a, b;  // a g_from = b g_to
  };
  std::vector<std::vector<Edge>> adj(static_cast<size_t>(N));
  std::vector<char> forced_zero(static_cast<size_t>(N), 0);
  const int m = static_cast<int>(blk.size());
  for (const auto& G : gains)
    for (int i = 0; i < m; ++i)
      for (int j = i + 1; j < m; ++j) {
        const int p = blk[static_cast<size_t>(i)], q = blk[static_cast<size_t>(j)];
        const rational &a = G(i, j), &b = G(j, i);
        if (p == q) {
          if (a != b) forced_zero[static_cast<size_t>(p)] = 1;
        } else if (a == 0 || b == 0) {
          if (a != 0) forced_zero[static_cast<size_t>(p)] = 1;
          if (b != 0) forced_zero[static_cast<size_t>(q)] = 1;
        } else {
          adj[static_cast<size_t>(p)].push_back({q, a, b});
          adj[static_cast<size_t>(q)].push_back({p, b, a});
        }
      }
  std::vector<std::vector<rational>> basis;
  std::vector<rational> w(static_cast<size_t>(N));
  std::vector<char> seen(static_cast<size_t>(N), 0);
  // From the largest column down: an unseen column is the largest of its component.
  for (int f = N - 1; f >= 0; --f) {
    if (seen[static_cast<size_t>(f)]) continue;
    std::vector<int> comp{f};
    seen[static_cast<size_t>(f)] = 1;
    w[static_cast<size_t>(f)] = 1;
    bool zero = false;
    for (size_t k = 0; k < comp.size(); ++k) {
      const int u = comp[k];
      zero = zero || forced_zero[static_cast<size_t>(u)];
      for (const Edge& e : adj[static_cast<size_t>(u)]) {
        const size_t v = static_cast<size_t>(e.to);
        if (!seen[v]) {
          seen[v] = 1;
          w[v] = e.a * w[static_cast<size_t>(u)] / e.b;
          comp.push_back(e.to);
        } else if (!zero && e.a * w[static_cast<size_t>(u)] != e.b * w[v]) {
          zero = true;  // the ratios around a cycle do not multiply to 1
        }
      }
    }
    if (zero) continue;
    std::vector<rational> v(static_cast<size_t>(N), rational(0));
    const int first = *std::min_element(comp.begin(), comp.end());
    const bool flip = w[static_cast<size_t>(first)] < 0;
    for (int c : comp) v[static_cast<size_t>(c)] = flip ? rational(-w[static_cast<size_t>(c)]) : w[static_cast<size_t>(c)];
    basis.push_back(std::move(v));
  }
  std::reverse(basis.begin(), basis.end());  // in the order of their largest (free) columns
  return basis;
}

std::string str(const rational& q, int digits = 6) { return numeric_decimal(to_real<double>(q), digits); }

}  // namespace

FacialConditions facial_conditions(const Problem& pb, const std::vector<MatQ>& extra) {
  FacialConditions fc;
  fc.E1 = dc_gain(pb.E);
  const int m = pb.structure.m();
  const auto sizes = pb.structure.operator_sizes();
  const int N = static_cast<int>(sizes.size());
  std::vector<int> blk;
  for (int i = 0; i < N; ++i)
    for (int k = 0; k < sizes[static_cast<size_t>(i)]; ++k) blk.push_back(i);
  std::vector<MatQ> gains{fc.E1};
  for (const auto& g : extra) gains.push_back(g);
  fc.gamma_basis = symmetric_gain_basis(blk, N, gains);
  fc.symmetric_possible = !fc.gamma_basis.empty();
  std::ostringstream o;
  o << "Facial reduction of (16)'s first LMI: E-hat has " << m << " eigenvalues at z = 1, so (16) needs "
    << "(A^T - I) P v = 0 and (B^T P - X C/2) v = 0 for each eigenvector v; these hold iff "
    << "P = Pi0^-T blockdiag(P11, X E(1)/(2T)) Pi0^-1, which requires X E(1) symmetric and positive definite. "
    << "E(1) (static stiffness) = ";
  if (m <= 4) {  // in full; a larger one summarised (one line of text, not m^2 numbers)
    o << "[";
    for (int i = 0; i < m; ++i) {
      for (int j = 0; j < m; ++j) o << (j ? ", " : "") << str(fc.E1(i, j));
      o << (i + 1 < m ? "; " : "]");
    }
  } else {
    rational lo = fc.E1(0, 0), hi = lo;
    for (int i = 0; i < m; ++i)
      for (int j = 0; j < m; ++j) lo = std::min(lo, fc.E1(i, j)), hi = std::max(hi, fc.E1(i, j));
    o << "(" << m << " x " << m << ", entries in [" << str(lo) << ", " << str(hi) << "])";
  }
  if (fc.E1 == MatQ(fc.E1.transpose()) && static_cast<int>(fc.gamma_basis.size()) == N)
    o << " is symmetric, so every X in G(m; ...) keeps X E(1) symmetric";
  else if (fc.E1 == MatQ(fc.E1.transpose()))
    o << " is symmetric; X E(1) is symmetric only on a " << fc.gamma_basis.size()
      << "-dimensional set of X (g_i = g_j wherever E(1) couples operators i and j)";
  else if (!fc.symmetric_possible)
    o << " is not symmetric and no X in G(m; m_1..m_N) makes X E(1) symmetric: (16) has NO solution for this "
         "structure (exact; no SDP needed)";
  else
    o << " is not symmetric; X E(1) is symmetric only on a " << fc.gamma_basis.size()
      << "-dimensional set of X (the ratios of the g_i are pinned by E(1)_ij / E(1)_ji)";
  fc.explanation = o.str();
  return fc;
}

}  // namespace hapstab::multidof
