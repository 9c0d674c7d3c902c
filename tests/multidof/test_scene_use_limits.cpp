// Issue 48: the limits follow the work done. `multidof analyze` never builds Theorem 6's coupling,
// so the coupling's size limits (limits::coupling_states: by default one state per device) refuse
// a scene for `multidof design` only; a [multidof.coupling] a scene writes is still checked
// against its DOFs for both (scene_multidof.hpp, check_coupling_structure).
#include <gtest/gtest.h>

#include <string>

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
  const auto sc = scene::parse_scene(array_scene(300), "a.toml");
  const auto sp = multidof::problem_from_scene(sc, SceneUse::analyze);
  EXPECT_EQ(sp.problem.structure.m(), 300);
  EXPECT_EQ(sp.problem.structure.operators.size(), 300u);
  const std::string design = error_of(sc, SceneUse::design);
  EXPECT_NE(design.find("a.toml: multidof.coupling.nbar: 300 states in all, more than the limit of 256 of the coupling "
                        "`multidof design` builds (by default one state per device; `multidof analyze` builds none)"),
            std::string::npos) << design;
  // at the limit, design poses its problem too
  EXPECT_EQ(error_of(scene::parse_scene(array_scene(256), "a.toml"), SceneUse::design), "");
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
