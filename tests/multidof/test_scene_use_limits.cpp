// Issue 48: the limits follow the work done. `multidof analyze` never builds Theorem 6's coupling,
// so the coupling's size limits (limits::coupling_states: by default one state per device) refuse
// a scene for `multidof design` only; a [multidof.coupling] a scene writes is still checked
// against its DOFs for both (scene_multidof.hpp, check_coupling_structure).
#include <gtest/gtest.h>

#include <string>

#include "hapstab/multidof/scene_analysis.hpp"
#include "hapstab/multidof/scene_multidof.hpp"
#include "hapstab/numeric/error.hpp"
#include "hapstab/scene/scene.hpp"

using namespace hapstab;
using multidof::SceneUse;

namespace {

// n mass-dampers, each held by its own operator, on a static diagonal spring (no environment states).
std::string array_scene(int n, const std::string& extra = "") {
  return "[scene]\nT = \"1/1000\"\n[[device]]\ncount = " + std::to_string(n) +
         "\nname = \"d\"\nm = \"1/10\"\nb = \"2\"\n[[operator]]\ncount = " + std::to_string(n) +
         "\nname = \"H\"\ndofs = \"d[i]\"\nb = \"1\"\n[environment]\ndiagonal = \"100\"\n" + extra;
}

// The same with every device's damping different (b = 2 + i/1000): no two DOFs alike, no symmetry.
std::string distinct_array_scene(int n) {
  std::string bs;
  for (int i = 0; i < n; ++i) bs += std::string(i ? ", " : "") + "\"" + std::to_string(2000 + i) + "/1000\"";
  return "[scene]\nT = \"1/1000\"\n[parameters]\nb = [" + bs + "]\n[[device]]\ncount = " + std::to_string(n) +
         "\nname = \"d\"\nm = \"1/10\"\nb = \"b[i]\"\n[[operator]]\ncount = " + std::to_string(n) +
         "\nname = \"H\"\ndofs = \"d[i]\"\nb = \"1\"\n[environment]\ndiagonal = \"100\"\n";
}

std::string error_of(const scene::Scene& sc, SceneUse use) {
  try {
    multidof::problem_from_scene(sc, use);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST(SceneUseLimits, AnalyzeIsNotRefusedForTheCouplingDesignWouldBuild) {
  const auto sc = scene::parse_scene(distinct_array_scene(300), "a.toml");
  const auto sp = multidof::problem_from_scene(sc, SceneUse::analyze);
  EXPECT_EQ(sp.problem.structure.m(), 300);
  EXPECT_EQ(sp.problem.structure.operators.size(), 300u);
  const std::string design = error_of(sc, SceneUse::design);
  EXPECT_NE(design.find("a.toml: multidof.coupling.nbar: 300 states in all, more than the limit of 256 of the coupling "
                        "`multidof design` builds (by default one state per device; `multidof analyze` builds none)"),
            std::string::npos) << design;
  // at the limit, design poses its problem too
  EXPECT_EQ(error_of(scene::parse_scene(distinct_array_scene(256), "a.toml"), SceneUse::design), "");
}

// 300 identical DOFs: the design works on the split (multidof/design_symmetry.cpp), one coupling
// block per class, so reading the scene refuses nothing; the whole coupling's limit is applied
// only when the split does not decide (--no-symmetry here), and the refusal says why.
TEST(SceneUseLimits, ASymmetricSceneIsDesignedByTheSplitBeyondTheWholeCouplingsLimit) {
  const auto sc = scene::parse_scene(array_scene(300), "a.toml");
  EXPECT_EQ(error_of(sc, SceneUse::design), "");
  multidof::SceneDesignOptions opt;
  opt.duration = 0.01;  // the simulated cross-check of 300 DOFs: 10 steps (10 s would be 10,000)
  const multidof::SceneDesign d = multidof::design_scene(sc, opt);
  EXPECT_EQ(d.design.path, "symmetry of identical DOFs (block-wise)") << d.design.verdict.evidence;
  EXPECT_TRUE(d.ok()) << d.design.verdict.evidence;
  EXPECT_EQ(d.design.V.D.rows(), 300);
  multidof::SceneDesignOptions whole;
  whole.symmetry = false;
  try {
    multidof::design_scene(sc, whole);
    ADD_FAILURE() << "the whole design of 300 coupling states was not refused";
  } catch (const InputError& e) {
    const std::string msg = e.what();
    EXPECT_NE(msg.find("300 states in all, more than the limit of 256"), std::string::npos) << msg;
    EXPECT_NE(msg.find("(--no-symmetry)"), std::string::npos) << msg;
  }
}

TEST(SceneUseLimits, AWrittenCouplingIsCheckedForBoth) {
  const auto sc = scene::parse_scene(array_scene(3, "[multidof.coupling]\nmbar = [1, 1]\n"), "w.toml");
  for (SceneUse use : {SceneUse::analyze, SceneUse::design}) {
    const std::string msg = error_of(sc, use);
    EXPECT_NE(msg.find("w.toml: multidof.coupling: "), std::string::npos) << msg;
  }
  // a block of 40 states is design's limit, not analyze's
  const auto big = scene::parse_scene(array_scene(1, "[multidof.coupling]\nmbar = [1]\nnbar = [40]\n"), "b.toml");
  EXPECT_EQ(error_of(big, SceneUse::analyze), "");
  EXPECT_NE(error_of(big, SceneUse::design).find("b.toml: multidof.coupling.nbar[0] = 40 states, more than the limit of 32 per block"),
            std::string::npos);
}
