// proofs/ext_loop_max_symmetric.cpp -- the supremum of a loop of identical DOFs as the least of its split's
// (stability/loop_max_symmetric.hpp, `stability --scene S --max g` with a class of three or more, or beyond 8 DOFs):
// sup g of the whole loop is min over the blocks of sup_b g, because at every g the whole's spectrum is the union
// of the blocks' (ext.loop_symmetric.split). Checked on random scenes where the whole's own supremum
// (stability/loop_max.hpp on the whole closed-loop matrix: its own crossing, Krawczyk enclosure and cover) is
// certified too -- classes of one or two DOFs, so no crossing eigenvalue is repeated: the two certified enclosures
// must intersect, and the split's must be no wider than 1e-12 relative. One more scene, with a class of three
// (where the whole's crossing is a repeated eigenvalue), is the claim's certificate in `reproduce` (kind
// stability-loop-max-symmetric, its enclosure containing the split's supremum).
#include <random>
#include <sstream>

#include "hapstab/scene/parameter_degree.hpp"
#include "hapstab/scene/scene.hpp"
#include "hapstab/stability/loop_max.hpp"
#include "hapstab/stability/loop_max_symmetric.hpp"
#include "proofs/proof.hpp"

namespace ext_loop_max_symmetric_detail {

using namespace hapstab;

// 2 classes (sizes 2 and 1-2), interleaved: mass-dampers, walls K + B (z - 1)/(T z) and constant links by class,
// all of them times g (the environment's gain), a delay of 0-1 samples.
std::string draw_scene(std::mt19937& g, bool three = false) {
  auto pick = [&](int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(g); };
  std::vector<int> cls{0, 0, 1};
  if (three) cls = {0, 0, 0, 1};
  else if (pick(0, 1)) cls.push_back(1);
  std::shuffle(cls.begin(), cls.end(), g);
  const std::string m[2] = {std::to_string(pick(1, 9)) + "/20", std::to_string(pick(1, 9)) + "/20"};
  const std::string K[2] = {std::to_string(100 * pick(5, 30)), std::to_string(100 * pick(5, 30))};
  const std::string B[2] = {std::to_string(pick(1, 6)), std::to_string(pick(1, 6))};
  int link[2][2];
  for (auto& row : link)
    for (int& x : row) x = pick(0, 40);
  std::ostringstream s;
  s << "[scene]\nT = \"1/1000\"\n\n[parameters]\ng = \"1\"\n\n";
  for (size_t i = 0; i < cls.size(); ++i) s << "[[device]]\nname = \"d" << i << "\"\nm = \"" << m[cls[i]] << "\"\nb = \"1\"\n\n";
  s << "[environment]\ngain = \"g\"\ntf = [";
  for (size_t i = 0; i < cls.size(); ++i) {
    s << (i ? ", [" : "[");
    for (size_t j = 0; j < cls.size(); ++j)
      s << (j ? ", " : "") << "\"" << (i == j ? K[cls[i]] + " + " + B[cls[i]] + "*(z-1)/(T*z)" : "-" + std::to_string(link[cls[i]][cls[j]])) << "\"";
    s << "]";
  }
  s << "]\n\n[delay]\nsamples = \"" << pick(0, 1) << "\"\n";
  return s.str();
}

}  // namespace ext_loop_max_symmetric_detail

HAPSTAB_PROOF(ext_loop_max_symmetric, "ext", "the supremum of a loop of identical DOFs as the least of its split's") {
  using namespace ext_loop_max_symmetric_detail;
  std::mt19937 g(47076);
  proofs::Instances both{"scenes whose whole and split suprema are both certified", 4};
  bool ok = true;
  std::string worst;
  for (int t = 0; t < 6; ++t) {
    const std::string text = draw_scene(g);
    const stability::LoopAt at = [&](const rational& p) { return scene::parse_scene(text, "drawn", {{"g", p}}).loop; };
    const scene::Scene sc = scene::parse_scene(text, "drawn");
    const long points = scene::points_needed(scene::parameter_degree(sc, "g"));
    const stability::LoopMax whole = stability::max_parameter(at, rational(1), "g", points, 16);
    std::string why;
    const auto split = stability::max_parameter_by_symmetry(at, rational(1), "g", points, 16, why);
    if (!both.count(split && whole.outcome == Outcome::holds && split->whole.outcome == Outcome::holds)) {
      ok = ok && split.has_value();  // the scenes are built to split
      continue;
    }
    const auto& s = split->whole.sup;
    const bool meet = s.lo <= whole.sup.hi && whole.sup.lo <= s.hi && (s.hi - s.lo) <= s.lo / rational(1000000000000LL);
    if (!meet) worst = "whole [" + whole.sup.lo.str() + ", " + whole.sup.hi.str() + "], split [" + s.lo.str() + ", " + s.hi.str() + "]";
    ok = ok && meet;
  }
  {  // the certificate: a class of three (the split pays), its supremum inside the certificate's enclosure
    const std::string text = draw_scene(g, true);
    const stability::LoopAt at = [&](const rational& p) { return scene::parse_scene(text, "drawn", {{"g", p}}).loop; };
    std::string why;
    const auto split = stability::max_parameter_by_symmetry(at, rational(1), "g", 2, 16, why);
    if (split && split->whole.outcome == Outcome::holds) {
      proofs::CertificateRequest r;
      r.args = {"stability", "--scene", "{input}", "--max", "g", "--quiet"};
      r.input = text;
      r.contains = ((split->whole.sup.lo + split->whole.sup.hi) / 2).str();
      check.certify("ext.loop_max_symmetric.least", r);
    } else {
      ok = false;
      worst = "the scene with a class of three: no certified split supremum (" + (split ? split->whole.note : why) + ")";
    }
  }
  check.claim("ext.loop_max_symmetric.least", "the supremum of identical DOFs, the least of the split's",
              "sup g of a loop of identical DOFs (g the environment's gain) = min over the split's small loops of their suprema: "
              "on 6 random scenes (2 classes of 1-2 mass-dampers, interleaved; walls K + B (z - 1)/(T z) and constant links by "
              "class; delays 0-1; seed 47076) the split's certified enclosure (stability/loop_max_symmetric.hpp) meets the whole "
              "closed-loop matrix's own (stability/loop_max.hpp: its crossing, Krawczyk enclosure and cover) and is 1e-12 "
              "relative or narrower; one more scene with a class of three DOFs is its certificate (kind stability-loop-max-symmetric)",
              Status::certified, ok && both.enough(), ok ? "every pair of enclosures meets" : "FAILS: " + worst, {both});
}
