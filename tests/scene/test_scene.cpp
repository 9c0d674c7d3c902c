// Scene files (scene/scene.hpp): the common schema, exact numbers, and errors that name the
// file, the key and what is wrong.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>

#include "hapstab/lti/realization.hpp"
#include "hapstab/sim/simulator.hpp"
#include "hapstab/numeric/error.hpp"
#include "hapstab/scene/scene.hpp"
#include "scene/scene_text.hpp"

// Its own namespace: the module's tests compile in unity batches (tests/CMakeLists.txt),
// and other files of the batch define helpers of the same names.
namespace test_scene {

using namespace hapstab;
using hapstab::scene::parse_scene;
using scene_test::error_of;
using scene_test::replace;

namespace {

const char* kWall = R"TOML(
[scene]
name = "wall"
T = "1/1000"
[parameters]
K = "20000"
B = "5"
bstar = "K*T/2 + B"
[[device]]
name = "haptic"
m = "1/10"
b = "bstar"
[[operator]]
name = "hand"
dofs = ["haptic"]
m = "1/5"
b = "2"
k = "500"
[environment]
tf = "K + B*(z-1)/(T*z)"
[contact]
dofs = ["haptic"]
[delay]
samples = "3/2"
[[input]]
type = "bias"
dof = "haptic"
force = "2"
[simulate]
duration = "1/2"
)TOML";

}  // namespace

TEST(Scene, ParsesTheWallExactly) {
  auto sc = parse_scene(kWall, "wall.toml");
  EXPECT_EQ(sc.T, rational(1, 1000));
  EXPECT_EQ(sc.parameters.at("bstar"), rational(15));  // KT/2 + B = 10 + 5, exact
  ASSERT_EQ(sc.loop.devices.size(), 1u);
  EXPECT_EQ(sc.loop.devices[0].G.A(0, 0), rational(-150));  // -b/m
  ASSERT_TRUE(sc.loop.environment);
  // E(z) realised exactly: E(1) = K, E(inf) = K + B/T
  EXPECT_EQ(sc.loop.environment->D(0, 0), rational(25000));
  EXPECT_EQ(sc.loop.delay, rational(3, 2000));
  EXPECT_EQ(sc.simulate.steps, 500);
  EXPECT_EQ(sc.loop.contact, std::vector<int>{0});
  EXPECT_EQ(sc.loop.biases.size(), 1u);
}

TEST(Scene, SetOverridesParametersExactly) {
  auto sc = parse_scene(kWall, "wall.toml", {{"K", rational(30000)}});
  EXPECT_EQ(sc.parameters.at("bstar"), rational(20));
}

// An s-domain environment discretised by backward Euler is the z-form exactly:
// K + B s at s = (z-1)/(Tz) is K + B(z-1)/(Tz) (improper in s, proper in z).
TEST(Scene, SDomainEnvironmentByBackwardEuler) {
  auto a = parse_scene(kWall, "a.toml");
  auto b = parse_scene(replace(kWall, "tf = \"K + B*(z-1)/(T*z)\"", "domain = \"s\"\nmethod = \"backward_euler\"\ntf = \"K + B*s\""),
                       "b.toml");
  auto ta = ss2tf(*a.loop.environment)(0, 0), tb = ss2tf(*b.loop.environment)(0, 0);
  EXPECT_TRUE(ta.num() == tb.num() && ta.den() == tb.den()) << ta.to_string() << " vs " << tb.to_string();
}

TEST(Scene, ErrorsNameFileKeyAndProblem) {
  struct Case {
    std::string from, to, key, what;
  };
  const std::vector<Case> cases = {
      {"dofs = [\"haptic\"]\nm = \"1/5\"", "dofs = [\"nope\"]\nm = \"1/5\"", "operator[0].dofs", "'nope'"},
      {"T = \"1/1000\"", "T = \"0\"", "scene.T", "must be > 0"},
      {"T = \"1/1000\"", "T = \"-1/1000\"", "scene.T", "must be > 0"},
      {"duration = \"1/2\"", "steps = 0", "simulate.steps", "must be > 0"},
      {"duration = \"1/2\"", "duration = \"0\"", "simulate.duration", "must be > 0"},
      {"m = \"1/5\"\nb = \"2\"\nk = \"500\"", "tf = \"1/(s-3)\"", "operator[0]", "unstable continuous block claimed passive"},
      {"tf = \"K + B*(z-1)/(T*z)\"", "tf = [[\"K\", \"0\"], [\"0\", \"K\"]]", "environment", "incompatible dimensions"},
      {"m = \"1/10\"", "m = 0.1", "device[0].m", "exact"},
      {"force = \"2\"", "force = \"2\"\ncolour = \"red\"", "input[0].colour", "unknown key"},
      {"tf = \"K + B*(z-1)/(T*z)\"", "tf = \"K + Q*(z-1)\"", "environment.tf", "Q"},
      {"tf = \"K + B*(z-1)/(T*z)\"", "tf = \"K*z\"", "environment.tf", "improper"},
      {"dof = \"haptic\"\nforce", "dof = 3\nforce", "input[0].dof", "does not exist"},
  };
  for (const auto& c : cases) {
    const std::string msg = error_of(replace(kWall, c.from, c.to));
    EXPECT_NE(msg.find("s.toml"), std::string::npos) << msg;
    EXPECT_NE(msg.find(c.key), std::string::npos) << "key " << c.key << " not in: " << msg;
    EXPECT_NE(msg.find(c.what), std::string::npos) << "'" << c.what << "' not in: " << msg;
  }
  EXPECT_NE(error_of("[scene]\nT = \"1/1000\"\n").find("device"), std::string::npos);
  EXPECT_NE(error_of("T = ").find("s.toml"), std::string::npos);  // TOML syntax error names the file
}

// A profile file's forces must be finite, and a line's t (t,force) the instant kT of its sample
// (to half a period): a file sampled at another rate was replayed at T with its t dropped (issue 40).
TEST(Scene, ProfileFileTimesAndForcesAreChecked) {
  const auto dir = std::filesystem::temp_directory_path() / ("hapstab_profile_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  const std::string scene = replace(kWall, "type = \"bias\"\ndof = \"haptic\"\nforce = \"2\"",
                                    "type = \"profile\"\ndof = \"haptic\"\nfile = \"p.csv\"");
  auto error = [&](const std::string& file) -> std::string {
    std::ofstream(dir / "p.csv") << file;
    try {
      const auto sc = parse_scene(scene, "s.toml", {}, dir.string());
      EXPECT_FALSE(sc.loop.profiles.empty());
    } catch (const InputError& e) {
      return e.what();
    }
    return "";
  };
  EXPECT_EQ(error("# t, force\n0,1\n0.001,2.5\n0.0020000001,-1\n"), "");  // t = kT (to half a period)
  EXPECT_EQ(error("1\n2\n-3e-2\n"), "");                                   // forces only
  EXPECT_NE(error("0,1\n0.0001,2\n").find("input[0].file: line 2: t = 0.0001 s is not this line's instant 0.001 s"),
            std::string::npos)
      << error("0,1\n0.0001,2\n");
  EXPECT_NE(error("0,1\n1e16,2\n").find("input[0].file: line 2"), std::string::npos);
  EXPECT_NE(error("1\nnan\n").find("line 2: the force nan is not finite"), std::string::npos) << error("1\nnan\n");
  EXPECT_NE(error("1\ninf\n").find("is not finite"), std::string::npos);
  EXPECT_NE(error("1\n2x\n").find("line 2: '2x' is not a number"), std::string::npos) << error("1\n2x\n");
  EXPECT_NE(error("x,1\n").find("line 1: t = 'x' is not a number"), std::string::npos);
  std::filesystem::remove_all(dir);
}

TEST(Scene, PassiveClaimCanBeWithdrawn) {
  // The same unstable operator is accepted when the scene does not claim passivity.
  auto text = replace(kWall, "m = \"1/5\"\nb = \"2\"\nk = \"500\"", "tf = \"1/(s-3)\"\npassive = false");
  EXPECT_NO_THROW(parse_scene(text, "s.toml"));
}

// Inputs the fuzzer (tests/fuzz/fuzz_scene.cpp) found: each must be an InputError naming the
// place, never a crash. A table header key starting with a character TOML does not allow
// ([[$device ]]) tripped an assertion inside toml++ 3.3's header-only parser.
TEST(Scene, FuzzerFindingsAreInputErrors) {
  for (const std::string& text : {std::string(kWall) + "\n[[$device ]]\n", std::string("[[$device ]]\n")}) {
    const std::string msg = error_of(text);
    EXPECT_NE(msg.find("s.toml:"), std::string::npos) << msg;
    EXPECT_NE(msg.find("expected bare key starting character"), std::string::npos) << msg;
  }
}

TEST(Scene, EncoderAndCoulombKeys) {
  const std::string dev = "m = \"1/10\"\nb = \"bstar\"";
  auto sc = parse_scene(replace(kWall, dev, dev + "\nquantum = \"1/4096\"\nquantizer = \"round\"\ncoulomb = \"3/10\""), "q.toml");
  ASSERT_EQ(sc.loop.quantizers.size(), 1u);
  EXPECT_EQ(sc.loop.quantizers[0].step, rational(1, 4096));
  EXPECT_TRUE(sc.loop.quantizers[0].round);
  ASSERT_EQ(sc.loop.coulomb.size(), 1u);
  EXPECT_EQ(sc.loop.coulomb[0].force, rational(3, 10));
  auto fl = parse_scene(replace(kWall, dev, dev + "\nquantum = \"1/4096\""), "q.toml");
  EXPECT_FALSE(fl.loop.quantizers.at(0).round);  // floor is the default
  struct Case {
    std::string add, key, what;
  };
  const std::vector<Case> cases = {
      {"quantum = \"0\"", "device[0].quantum", "must be > 0"},
      {"quantum = \"-1/1000\"", "device[0].quantum", "must be > 0"},
      {"quantum = 0.001", "device[0].quantum", "exact"},
      {"quantum = \"1/1000\"\nquantizer = \"ceil\"", "device[0].quantizer", "\"floor\" or \"round\""},
      {"quantum = \"1/1000\"\nquantizer = 3", "device[0].quantizer", "\"floor\" or \"round\""},
      {"quantizer = \"round\"", "device[0].quantizer", "needs quantum"},
      {"coulomb = \"-1\"", "device[0].coulomb", "must be >= 0"},
      {"coulomb = \"x\"", "device[0].coulomb", "x"},
  };
  for (const auto& c : cases) {
    const std::string msg = error_of(replace(kWall, dev, dev + "\n" + c.add));
    EXPECT_NE(msg.find(c.key), std::string::npos) << "key " << c.key << " not in: " << msg;
    EXPECT_NE(msg.find(c.what), std::string::npos) << "'" << c.what << "' not in: " << msg;
  }
  // only a mass-damper device carries them
  const std::string tf = error_of(replace(kWall, dev, "tf = \"1/(s + 1)\"\ncoulomb = \"1\""));
  EXPECT_NE(tf.find("need a mass-damper device"), std::string::npos) << tf;
}

TEST(Scene, PassivityControllerSection) {
  auto sc = parse_scene(std::string(kWall) + "[passivity_controller]\ndofs = [\"haptic\"]\n", "pc.toml");
  EXPECT_EQ(sc.loop.passivity_controller, std::vector<int>{0});
  std::string msg = error_of(std::string(kWall) + "[passivity_controller]\ndofs = [\"nope\"]\n");
  EXPECT_NE(msg.find("passivity_controller.dofs"), std::string::npos) << msg;
  msg = error_of(std::string(kWall) + "[passivity_controller]\n");
  EXPECT_NE(msg.find("passivity_controller.dofs: missing"), std::string::npos) << msg;
  msg = error_of(std::string(kWall) + "[passivity_controller]\ndofs = [\"haptic\"]\ngain = 2\n");
  EXPECT_NE(msg.find("passivity_controller.gain"), std::string::npos) << msg;
}

// ---- untrusted input ----------------------------------------------------------------------
// Scenes are untrusted (docs/security.md; issue 32): [parameters] are resolved once each, in
// dependency order, at most limits::scene_parameters of them; a cycle is named; a table header
// deeper than toml++ can take is refused before parsing; a delay beyond limits::delay_samples is
// refused by name before it is converted to a sample count.
namespace {
const std::string kHead = "[scene]\nname = \"p\"\nT = \"1/1000\"\n";
const std::string kLoop =
    "[[device]]\nname = \"d\"\nm = \"1/10\"\nb = \"1\"\n[environment]\ntf = \"100\"\n[simulate]\nsteps = 20\n";


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
  // the scene reader refuses it naming the key (issue 40), before anything converts t_d / T
  for (const std::string& key : {std::string("samples"), std::string("time")}) {
    const std::string delay = key + (key == "samples" ? " = \"200000000\"" : " = \"1e30\"");
    try {
      parse_scene(kHead + kLoop + "[delay]\n" + delay + "\n", "s.toml");
      ADD_FAILURE() << delay << " accepted";
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find("s.toml: delay." + key + ": "), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find("sample periods, more than the limit of 10000000"), std::string::npos) << e.what();
    }
  }
  auto sc = parse_scene(kHead + kLoop + "[delay]\nsamples = \"10000000\"\n", "s.toml");
  // and the simulator's own check, for a loop built without a scene
  sim::LoopSpec spec = sc.loop;
  spec.delay = rational(bmp::pow(integer(10), 30));  // 1e30 s
  try {
    sim::Simulator s(spec);
    ADD_FAILURE() << "a delay of 1e30 s accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("sample periods (t_d / T), more than the limit of 10000000"), std::string::npos)
        << e.what();
  }
  sim::Simulator s(sc.loop);
  EXPECT_EQ(s.delay_steps(), 10000000);
  sim::SimOptions o;
  o.steps = 20;
  const auto r = s.run(o);
  EXPECT_EQ(r.summary.steps_run, 20);
}

}  // namespace test_scene
