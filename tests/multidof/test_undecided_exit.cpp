// Issue 46 (item 9's rule, "an undecided verdict is never counted as either answer"): `multidof
// analyze` and `design` exit 3 when it is not known whether Theorem 5 (6) concludes, and 1 only
// when it does not: SceneAnalysis::undecided and SceneDesign::undecided on each combination.
#include <gtest/gtest.h>

#include "hapstab/multidof/scene_analysis.hpp"

using namespace hapstab;
using namespace hapstab::multidof;

namespace {

AssumptionCheck premise(Outcome o) { return {"Assumption 1(a): device 'd'", Verdict{o, Status::exact, ""}}; }

SceneAnalysis analysis(bool feasible, bool certified, std::vector<Outcome> premises, std::optional<bool> loop_stable) {
  SceneAnalysis a;
  a.feasible = feasible;
  a.certified = certified;
  bool hold = true;
  for (Outcome o : premises) {
    a.premises.push_back(premise(o));
    hold = hold && o == Outcome::holds;
  }
  a.premises_hold = hold;
  a.stability_concluded = feasible && certified && hold;
  a.loop.stable = loop_stable;
  return a;
}

}  // namespace

TEST(UndecidedExit, AnalyzeSaysUndecidedOnlyWhenTheConclusionIsUnknown) {
  using O = Outcome;
  // concluded: exit 0, never undecided
  EXPECT_FALSE(analysis(true, true, {O::holds}, true).undecided());
  EXPECT_TRUE(analysis(true, true, {O::holds}, true).ok());
  // (16) not proven either way: undecided, unless a premise fails (then no conclusion whatever (16) is)
  EXPECT_TRUE(analysis(false, false, {O::holds}, std::nullopt).undecided());
  EXPECT_TRUE(analysis(true, false, {O::undecided}, std::nullopt).undecided());
  EXPECT_FALSE(analysis(true, false, {O::fails}, std::nullopt).undecided());
  // (16) proven infeasible, or a premise failing: no conclusion (exit 1)
  EXPECT_FALSE(analysis(false, true, {O::undecided}, std::nullopt).undecided());
  EXPECT_FALSE(analysis(true, true, {O::fails, O::undecided}, std::nullopt).undecided());
  // feasible, certified, a premise undecided and none failing: undecided
  EXPECT_TRUE(analysis(true, true, {O::holds, O::undecided}, std::nullopt).undecided());
  // the loop as written proven NOT stable: exit 1 whatever else is undecided
  EXPECT_FALSE(analysis(false, false, {O::holds}, false).undecided());
  EXPECT_FALSE(analysis(true, true, {O::undecided}, false).undecided());
}

TEST(UndecidedExit, DesignSaysUndecidedOnlyForAVerifiedVWithUndecidedPremises) {
  SceneDesign d;
  d.feasible = true;
  d.premises = {premise(Outcome::holds), premise(Outcome::undecided)};
  d.premise_failure = "a premise is undecided (Assumption 1(a): device 'd')";
  EXPECT_TRUE(d.undecided());
  d.premises.push_back(premise(Outcome::fails));
  EXPECT_FALSE(d.undecided());  // a failing premise: exit 1
  d.premises.pop_back();
  d.feasible = false;
  EXPECT_FALSE(d.undecided());  // no V found: exit 1
  d.feasible = true;
  d.contradiction = "the simulation diverges";
  EXPECT_FALSE(d.undecided());  // exit 3 by the contradiction, not by this
}
