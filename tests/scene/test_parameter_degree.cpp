// scene/parameter_degree.hpp: how a parameter enters the loop, proven from the scene's text (issue
// 46 item 5). Each rule of the header, accepted and ruled out, with the key named; the points
// counts are the header's degree bounds.
#include <gtest/gtest.h>

#include <string>

#include "hapstab/numeric/error.hpp"
#include "hapstab/scene/parameter_degree.hpp"

// Its own namespace: the module's tests compile in unity batches (tests/CMakeLists.txt),
// and other files of the batch define helpers of the same names.
namespace test_parameter_degree {

using namespace hapstab;
using scene::ParameterDegree;

namespace {

const std::string kHead = R"toml([scene]
name = "t"
T = "1/1000"
[parameters]
g = "1"
k = "3"
[[device]]
name = "a"
m = "1"
b = "1"
[[device]]
name = "b"
m = "1"
b = "1"
)toml";

ParameterDegree degree(const std::string& body) {
  return scene::parameter_degree(scene::parse_scene(kHead + body, "t.toml"), "g");
}

std::string refusal(const std::string& body) {
  try {
    degree(body);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

const std::string kEnv = "[environment]\ntf = [[\"6000 - 5000*z^-1\", \"0\"], [\"0\", \"6000 - 5000*z^-1\"]]\n";

}  // namespace

TEST(ParameterDegree, GainOfTheEnvironmentIsAffineOutright) {
  const ParameterDegree d = degree(kEnv + "gain = \"2*g + k\"\n");
  EXPECT_TRUE(d.environment);
  EXPECT_FALSE(d.coupling);
  EXPECT_FALSE(d.dynamics_move);
  EXPECT_EQ(scene::points_needed(d), 2);  // no coupling: the controller is the environment's realisation
}

TEST(ParameterDegree, CouplingBoundsFollowTheFeedthroughLoop) {
  const std::string cpl = "[coupling]\nss = { A = [[\"0\", \"0\"], [\"0\", \"0\"]], B = [[\"1\", \"0\"], [\"0\", \"1\"]], "
                          "C = [[\"1/1000\", \"0\"], [\"0\", \"1/1000\"]], D = [[\"0\", \"0\"], [\"0\", \"0\"]] }\n";
  // g in the environment's gain: D_E moves, S = I + D_E D_V may move: 2N + 3 values
  ParameterDegree d = degree(kEnv + "gain = \"g\"\n" + cpl);
  EXPECT_TRUE(d.has_coupling);
  EXPECT_TRUE(d.feedthrough_moves);
  EXPECT_EQ(scene::points_needed(d), 2 * 2 + 3);
  // g only in the coupling's C: S constant, degree <= 4: 5 values
  std::string c2 = cpl;
  c2.replace(c2.find("C = [[\"1/1000\""), 14, "C = [[\"g/1000\"");
  d = degree(kEnv + c2);
  EXPECT_TRUE(d.coupling);
  EXPECT_FALSE(d.feedthrough_moves);
  EXPECT_EQ(scene::points_needed(d), 5);
}

TEST(ParameterDegree, AStiffnessInATfMovesOnlyD) {
  const ParameterDegree d = degree("[environment]\ntf = [[\"g + 5*(z-1)/(T*z)\", \"0\"], [\"0\", \"300\"]]\n");
  EXPECT_TRUE(d.feedthrough_moves);
  EXPECT_FALSE(d.dynamics_move);
}

TEST(ParameterDegree, WhatRulesTheProofOutIsNamed) {
  // a degree-4 gain that equals g at the old check values 1, 2, 1/3, 7/2
  EXPECT_NE(refusal(kEnv + "gain = \"g + 1000*(g - 1)*(g - 2)*(g - 1/3)*(g - 7/2)\"\n").find("environment.gain"), std::string::npos);
  EXPECT_NE(refusal(kEnv + "gain = \"1/g\"\n").find("degree <= 1"), std::string::npos);
  // the pole moves with g: not affine at all
  EXPECT_NE(refusal("[environment]\ntf = [[\"1/(z - g/2)\", \"0\"], [\"0\", \"1\"]]\n").find("environment.tf[0][0]"), std::string::npos);
  // affine, H1 = 1/z: proven for a one-DOF H, not for the realisation the loop's matrix is built from
  const ParameterDegree d = degree("[environment]\ntf = [[\"g/z\", \"0\"], [\"0\", \"1\"]]\n");
  EXPECT_NE(d.tf_dynamics.find("environment.tf[0][0]"), std::string::npos) << d.tf_dynamics;
  EXPECT_THROW(scene::points_needed(d), InputError);
  // gain and D both name g: degree 2
  EXPECT_NE(refusal("[environment]\nss = { A = [], B = [], C = [], D = [[\"g\", \"0\"], [\"0\", \"1\"]] }\ngain = \"g\"\n").find("degree 2"),
            std::string::npos);
  // through another parameter, or in the plant
  std::string head = kHead;
  head.replace(head.find("k = \"3\""), 7, "k = \"3*g\"");
  try {
    scene::parameter_degree(scene::parse_scene(head + kEnv + "gain = \"k\"\n", "t.toml"), "g");
    FAIL() << "a parameter defined from g was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("parameters.k"), std::string::npos) << e.what();
  }
  head = kHead;
  head.replace(head.find("m = \"1\""), 7, "m = \"g\"");
  try {
    scene::parameter_degree(scene::parse_scene(head + kEnv, "t.toml"), "g");
    FAIL() << "a device's mass in g was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("device[0].m"), std::string::npos) << e.what();
  }
}

TEST(ParameterDegree, OneDofBoundGrowsWithMovingDynamics) {
  const std::string one = R"toml([scene]
name = "t"
T = "1/1000"
[parameters]
g = "1"
[[device]]
name = "a"
m = "1"
b = "1"
[environment]
ss = { A = [["1/2", "g/4"], ["0", "1/3"]], B = [["1"], ["1"]], C = [["1", "0"]], D = [["2000"]] }
)toml";
  const ParameterDegree d = scene::parameter_degree(scene::parse_scene(one, "t.toml"), "g");
  EXPECT_TRUE(d.dynamics_move);
  EXPECT_EQ(scene::points_needed_one_dof(d), 2 + 3);  // n = 2 states: n + 3 values
}

}  // namespace test_parameter_degree
