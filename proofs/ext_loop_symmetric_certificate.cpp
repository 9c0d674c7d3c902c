// proofs/ext_loop_symmetric_certificate.cpp -- the split the stability-loop-symmetric checkers rest on
// (check/stability_loop_symmetric_check.hpp; docs/certificates.md): for a scene whose DOFs fall into classes of
// identical ones under an invariant E(z), the closed-loop matrix the checkers build (E's columns over their lcm,
// on the quotient by the conserved quantities) has the spectrum of the fixed space's loop and of each class's
// zero-sum loop k_a - 1 times, and the conserved quantities add as k_F + sum_a (k_a - 1) k_a'.
// Checked on random scenes written as TOML (2-3 classes of 1-4 DOFs; mass-dampers, an operator damper or a spring
// written as tf "b + k/s", a conserved quantity; walls K + B (z - 1)/(T z) and constant links by class; delays
// 0-1): the whole loop's eigenvalues (the checker's own matrix, its midpoints in double, Eigen) matched one by one
// with the blocks' (to 1e-7 relative), and the counts exactly. A numeric claim: the identity of characteristic
// polynomials is the header's theorem; this checks the checker's construction of the blocks against it.
#include <complex>
#include <random>
#include <sstream>

#include <Eigen/Eigenvalues>
#include <nlohmann/json.hpp>

#include "hapstab/check/stability_loop_check.hpp"
#include "hapstab/check/stability_loop_symmetric_check.hpp"
#include "hapstab/numeric/ball.hpp"
#include "proofs/proof.hpp"

namespace ext_loop_symmetric_certificate_detail {

using namespace hapstab;

struct Drawn {
  std::string scene;
  bool spring = false, zero_sum = false;
};

Drawn draw_scene(std::mt19937& g) {
  auto pick = [&](int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(g); };
  const int r = pick(2, 3);
  std::vector<int> sizes, op(r);
  std::vector<std::string> m(r), K(r), B(r);
  Drawn d;
  for (int a = 0; a < r; ++a) {
    sizes.push_back(pick(1, 4));
    d.zero_sum = d.zero_sum || sizes.back() > 1;
    m[size_t(a)] = std::to_string(pick(1, 9)) + "/20";
    K[size_t(a)] = std::to_string(100 * pick(1, 30));
    B[size_t(a)] = std::to_string(pick(1, 6));
    op[size_t(a)] = pick(0, 2);  // none, a damper, a spring (tf, a conserved quantity)
    d.spring = d.spring || op[size_t(a)] == 2;
  }
  std::vector<int> cls;
  for (int a = 0; a < r; ++a)
    for (int k = 0; k < sizes[size_t(a)]; ++k) cls.push_back(a);
  std::shuffle(cls.begin(), cls.end(), g);  // the classes interleaved among the DOFs
  std::vector<std::vector<std::string>> link(static_cast<size_t>(r), std::vector<std::string>(static_cast<size_t>(r), ""));
  for (int a = 0; a < r; ++a)
    for (int b = 0; b < r; ++b) link[size_t(a)][size_t(b)] = "-" + std::to_string(pick(0, 40));
  std::ostringstream s;
  s << "[scene]\nT = \"1/1000\"\n\n";
  for (size_t i = 0; i < cls.size(); ++i) s << "[[device]]\nname = \"d" << i << "\"\nm = \"" << m[size_t(cls[i])] << "\"\nb = \"1\"\n\n";
  for (size_t i = 0; i < cls.size(); ++i)
    if (op[size_t(cls[i])] == 1)
      s << "[[operator]]\ndofs = [\"d" << i << "\"]\nb = \"2\"\n\n";
    else if (op[size_t(cls[i])] == 2)
      s << "[[operator]]\ndofs = [\"d" << i << "\"]\ntf = \"2 + 40/s\"\n\n";
  s << "[environment]\ntf = [";
  for (size_t i = 0; i < cls.size(); ++i) {
    s << (i ? ", [" : "[");
    for (size_t j = 0; j < cls.size(); ++j)
      s << (j ? ", " : "") << "\""
        << (i == j ? K[size_t(cls[i])] + " + " + B[size_t(cls[i])] + "*(z-1)/(T*z)" : link[size_t(cls[i])][size_t(cls[j])]) << "\"";
    s << "]";
  }
  s << "]\n\n[delay]\nsamples = \"" << pick(0, 1) << "\"\n";
  d.scene = s.str();
  return d;
}

std::vector<std::complex<double>> eigenvalues(const check::detail::BallRows& M) {
  Eigen::MatrixXd A(static_cast<long>(M.size()), static_cast<long>(M.size()));
  for (size_t i = 0; i < M.size(); ++i)
    for (size_t j = 0; j < M.size(); ++j) A(long(i), long(j)) = M[i][j].to_double();
  const Eigen::VectorXcd e = Eigen::EigenSolver<Eigen::MatrixXd>(A, false).eigenvalues();
  return {e.data(), e.data() + e.size()};
}

// The whole's eigenvalues matched one by one with the blocks' (each block's k_a - 1 times), and the counts.
bool split_holds(const std::string& scene) {
  const check::detail::SceneLoop L = check::detail::read_scene_loop(nlohmann::json{{"scene", scene}, {"set", nlohmann::json::object()}});
  std::string why;
  const auto split = check::detail::split_loop(L, check::detail::identical_dofs(L), why);
  if (!split) return false;
  flint::BallPrecision scope(128);
  const auto whole = check::detail::loop_matrix(L, 128);
  const auto fixed = check::detail::loop_matrix(split->fixed, 128);
  std::vector<std::complex<double>> blocks = eigenvalues(fixed.M);
  long conserved = static_cast<long>(fixed.conserved);
  for (size_t a = 0; a < split->sizes.size(); ++a) {
    if (split->sizes[a] < 2) continue;
    const auto zs = check::detail::loop_matrix(split->zero_sum[a], 128);
    const auto e = eigenvalues(zs.M);
    for (size_t c = 1; c < split->sizes[a]; ++c) blocks.insert(blocks.end(), e.begin(), e.end());
    conserved += static_cast<long>(split->sizes[a] - 1) * static_cast<long>(zs.conserved);
  }
  std::vector<std::complex<double>> rest = eigenvalues(whole.M);
  if (rest.size() != blocks.size() || conserved != static_cast<long>(whole.conserved)) return false;
  for (const auto& z : blocks) {
    auto best = rest.begin();
    for (auto it = rest.begin(); it != rest.end(); ++it)
      if (std::abs(*it - z) < std::abs(*best - z)) best = it;
    if (std::abs(*best - z) > 1e-7 * std::max(1.0, std::abs(z))) return false;
    rest.erase(best);
  }
  return true;
}

}  // namespace ext_loop_symmetric_certificate_detail

HAPSTAB_PROOF(ext_loop_symmetric_certificate, "ext", "the split of a loop of identical DOFs that stability-loop-symmetric checks") {
  using namespace ext_loop_symmetric_certificate_detail;
  std::mt19937 g(47075);
  proofs::Instances with_zero_sum{"scenes with a class of two DOFs or more", 20}, with_springs{"scenes with conserved quantities", 10};
  bool ok = true;
  for (int t = 0; t < 30; ++t) {
    const Drawn d = draw_scene(g);
    const bool holds = split_holds(d.scene);
    ok = ok && holds;
    with_zero_sum.count(d.zero_sum);
    with_springs.count(d.spring);
  }
  check.claim("ext.loop_symmetric.split", "the loop of identical DOFs, split",
              "DOFs in classes of identical ones under an invariant E(z): the checker's closed-loop matrix (E's columns over their lcm, "
              "on the quotient by the conserved quantities) has the eigenvalues of the fixed space's loop (E_F(a, a) = E(f_a, f_a) + "
              "(k_a - 1) E(f_a, s_a), E_F(a, b) = k_b E(f_a, f_b)) and of each class's zero-sum loop (E(f_a, f_a) - E(f_a, s_a)) k_a - 1 "
              "times, matched one by one to 1e-7 (double, Eigen), and k = k_F + sum_a (k_a - 1) k_a' exactly -- on 30 random scenes "
              "of 2-3 classes of 1-4 DOFs, interleaved, with operator dampers and springs, delays 0-1 (seed 47075)",
              Status::numeric, ok && with_zero_sum.enough() && with_springs.enough(),
              ok ? "every spectrum and count matched" : "a spectrum or a count DIFFERS", {with_zero_sum, with_springs});
}
