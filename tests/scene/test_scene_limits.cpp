// Scenes are untrusted (docs/security.md; issue 32): [parameters] are resolved once each, in
// dependency order, at most limits::scene_parameters of them; a cycle is named; a table header
// deeper than toml++ can take is refused before parsing; a delay beyond limits::delay_samples is
// refused by name before it is converted to a sample count.
#include <gtest/gtest.h>

#include <string>

#include "hapstab/numeric/error.hpp"
#include "hapstab/scene/scene.hpp"
#include "hapstab/sim/simulator.hpp"

using namespace hapstab;
using hapstab::scene::parse_scene;

namespace {

const std::string kHead = "[scene]\nname = \"p\"\nT = \"1/1000\"\n";
const std::string kLoop =
    "[[device]]\nname = \"d\"\nm = \"1/10\"\nb = \"1\"\n[environment]\ntf = \"100\"\n[simulate]\nsteps = 20\n";

std::string error_of(const std::string& text) {
  try {
    parse_scene(text, "s.toml");
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

// n parameters p0 = 1, p_k = p_{k-1} + 1, written last first (the order a pass-based resolver
// handled worst: 1000 of them took 20 s).
std::string chain(int n) {
  std::string s = "[parameters]\n";
  for (int k = n - 1; k > 0; --k) s += "p" + std::to_string(k) + " = \"p" + std::to_string(k - 1) + " + 1\"\n";
  return s + "p0 = \"1\"\n";
}

}  // namespace

TEST(SceneLimits, ParametersResolveInDependencyOrder) {
  const auto sc = parse_scene(kHead + chain(1000) + kLoop, "s.toml");
  EXPECT_EQ(sc.parameters.at("p999"), rational(1000));
  EXPECT_EQ(sc.parameters.size(), 1000u);
  const std::string many = error_of(kHead + chain(1001) + kLoop);
  EXPECT_NE(many.find("s.toml: parameters: 1001 parameters, more than the limit of 1000"), std::string::npos) << many;
}

TEST(SceneLimits, ParameterCyclesAndUnknownNamesAreNamed) {
  const std::string cycle = error_of(kHead + "[parameters]\na = \"b + 1\"\nb = \"2*a\"\nc = \"1\"\nd = \"a\"\n" + kLoop);
  EXPECT_NE(cycle.find("s.toml: parameters: these parameters depend on each other in a cycle (or on one that does): a, b, d"),
            std::string::npos)
      << cycle;
  const std::string self = error_of(kHead + "[parameters]\na = \"a\"\n" + kLoop);
  EXPECT_NE(self.find("cycle (or on one that does): a"), std::string::npos) << self;
  const std::string unknown = error_of(kHead + "[parameters]\na = \"1\"\nb = \"a + q\"\n" + kLoop);
  EXPECT_NE(unknown.find("parameters.b"), std::string::npos) << unknown;
  EXPECT_NE(unknown.find("'q'"), std::string::npos) << unknown;
  // names inside numbers are not names: 1e3 is a number, e3 would be a parameter
  const auto sc = parse_scene(kHead + "[parameters]\ne3 = \"2\"\nx = \"1e3*e3\"\n" + kLoop, "s.toml");
  EXPECT_EQ(sc.parameters.at("x"), rational(2000));
}

TEST(SceneLimits, DeepHeadersAreRefusedBeforeToml) {
  std::string deep = "a";
  for (int i = 0; i < 50000; ++i) deep += ".a";  // 100 KB: toml++ overflowed its stack (SIGSEGV)
  const std::string msg = error_of(kHead + "[" + deep + "]\n" + kLoop);
  EXPECT_NE(msg.find("s.toml:4: a key or table nested 50001 levels deep"), std::string::npos) << msg;
  EXPECT_NE(msg.find("more than the limit of 64"), std::string::npos) << msg;
}

// A delay of 2e8 samples allocated 7.2 GB, then bad_alloc; time = "1e30" wrapped to a negative
// sample count ("negative time step"). Both are refused by name before any allocation; a delay
// within the limit but longer than the run runs, its forces never arriving.
TEST(SceneLimits, DelaysBeyondTheLimitAreRefusedByName) {
  for (const std::string& delay : {std::string("samples = \"200000000\""), std::string("time = \"1e30\"")}) {
    const auto sc = parse_scene(kHead + kLoop + "[delay]\n" + delay + "\n", "s.toml");
    try {
      sim::Simulator s(sc.loop);
      ADD_FAILURE() << delay << " accepted";
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find("delay: "), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find("sample periods (t_d / T), more than the limit of 10000000"), std::string::npos)
          << e.what();
    }
  }
  const auto sc = parse_scene(kHead + kLoop + "[delay]\nsamples = \"10000000\"\n", "s.toml");
  sim::Simulator s(sc.loop);
  EXPECT_EQ(s.delay_steps(), 10000000);
  sim::SimOptions o;
  o.steps = 20;
  const auto r = s.run(o);
  EXPECT_EQ(r.summary.steps_run, 20);
}
