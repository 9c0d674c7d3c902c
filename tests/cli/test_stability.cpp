// `hapstab stability` end to end (in process, as sweep and Python call it): the JSON keys and
// exit codes of the verdict and of --max, and a sweep of --max over the wall's damper B.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "cli/cli_run.hpp"
#include "cli/command.hpp"
#include "test_files.hpp"

namespace {

using hapstab::cli::run_in_process;

const std::vector<std::string> kDevice{"--plant", "1/(m*s^2 + b*s)", "--set", "m=1", "--set", "b=1",
                                       "--H",     "K + B*(z-1)/(T*z)", "--T", "1/1000", "--set", "B=2"};

std::vector<std::string> with(std::vector<std::string> a, const std::vector<std::string>& more) {
  a.insert(a.begin(), "stability");
  a.insert(a.end(), more.begin(), more.end());
  a.push_back("--json");
  return a;
}

TEST(StabilityCli, MaxThenVerdictOnBothSides) {
  const auto m = run_in_process(with(kDevice, {"--max", "K", "--delay", "1", "--digits", "25"}));
  ASSERT_EQ(m.code, 0) << m.json.dump();
  EXPECT_EQ(m.json["status"], "certified");
  EXPECT_EQ(m.json["crossing"]["at"], "complex pair");
  ASSERT_EQ(m.json["enclosure"].size(), 2u);
  const std::string max = m.json["max"];
  EXPECT_EQ(max.size(), 26u) << max;  // 25 significant digits and the point
  const double K = std::stod(max);
  auto at = [&](double k) { return run_in_process(with(kDevice, {"--set", "K=" + std::to_string(k), "--delay", "1"})); };
  const auto below = at(K * 0.999), above = at(K * 1.001);
  EXPECT_EQ(below.code, 0);
  EXPECT_EQ(below.json["stable"], true);
  EXPECT_EQ(below.json["status"], "certified");
  EXPECT_EQ(above.code, 1);
  EXPECT_EQ(above.json["stable"], false);
  ASSERT_EQ(above.json["spectral_radius"].size(), 2u);
  EXPECT_GT(std::stod(above.json["spectral_radius"][0].get<std::string>()), 1.0);
}

TEST(StabilityCli, UnstableForEverySmallGainExitsOne) {
  std::vector<std::string> a = kDevice;
  a.back() = "B=-2";  // a wall that pushes harder than b damps (B = -b: a double root at z = 1, undecided)
  const auto r = run_in_process(with(a, {"--max", "K"}));
  EXPECT_EQ(r.code, 1);
  EXPECT_EQ(r.json["max"], "0");
}

// The note names the gain maximised (issue 31: `--set K=500 --max B` ended "stable at K = 414").
TEST(StabilityCli, NoteNamesTheGainMaximised) {
  std::vector<std::string> a = kDevice;
  a.back() = "K=500";  // B free
  const auto r = run_in_process(with(a, {"--max", "B", "--delay", "1"}));
  ASSERT_EQ(r.code, 0) << r.json.dump();
  EXPECT_EQ(r.json["name"], "B");
  const std::string note = r.json["note"];
  EXPECT_EQ(note.rfind("stable at B = ", 0), 0u) << note;
  EXPECT_EQ(note.find("K"), std::string::npos) << note;
}

TEST(StabilityCli, PureMassIsExact) {
  const auto r = run_in_process({"stability", "--plant", "1/s^2", "--H", "100 + 5*(z-1)/(T*z)", "--T", "1/1000", "--json"});
  EXPECT_EQ(r.json["status"], "exact");
  EXPECT_EQ(r.json["stable"], true);
  EXPECT_EQ(r.code, 0);
}

// Delays of teleoperation scale (issue 43): the long-delay path, named in the JSON; a one-DOF scene
// with [delay] gives what the same loop written as options gives; refusals name what is not modelled.
TEST(StabilityCli, LongDelayAndScenes) {
  std::vector<std::string> a = kDevice;
  a.back() = "B=1/2";
  const auto m = run_in_process(with(a, {"--max", "K", "--delay", "600", "--digits", "15"}));
  ASSERT_EQ(m.code, 0) << m.json.dump();
  EXPECT_EQ(m.json["path"], "long_delay");
  EXPECT_NE(m.json["plan"].get<std::string>().find("degree 603"), std::string::npos) << m.json.dump();
  const auto dir = hapstab_test::fresh_dir("stability_scene");
  const std::string scene = "[scene]\nname = \"wall behind a network\"\nT = \"1/1000\"\n[parameters]\nK = \"1\"\n"
                            "[[device]]\nname = \"d\"\nm = \"1\"\nb = \"1\"\n[environment]\ntf = \"K + 1/2*(z-1)/(T*z)\"\n"
                            "[delay]\nsamples = \"600\"\n";
  std::ofstream(dir / "s.toml") << scene;
  const auto s = run_in_process({"stability", "--scene", (dir / "s.toml").string(), "--max", "K", "--digits", "15", "--json"});
  ASSERT_EQ(s.code, 0) << s.json.dump();
  EXPECT_EQ(s.json["max"], m.json["max"]);
  EXPECT_EQ(s.json["path"], "long_delay");
  const auto v = run_in_process({"stability", "--scene", (dir / "s.toml").string(), "--json"});  // K = 1 < sup K
  EXPECT_EQ(v.code, 0) << v.json.dump();
  EXPECT_EQ(v.json["stable"], true);
  std::ofstream(dir / "frac.toml") << scene.substr(0, scene.find("[delay]")) << "[delay]\nsamples = \"1201/2\"\n";
  // a fractional delay: decided on the loop as written (the forces still to act are states), and
  // refused by name for --max (the one-DOF gain search takes z^-n)
  const auto fd = run_in_process({"stability", "--scene", (dir / "frac.toml").string(), "--json"});
  EXPECT_NE(fd.json["stable"], nlohmann::json(nullptr)) << fd.json.dump();
  const auto f = hapstab_test::run_cli("stability --scene " + (dir / "frac.toml").string() + " --max K");
  EXPECT_EQ(f.code, 2) << f.out;
  EXPECT_NE(f.out.find("not a whole number of samples"), std::string::npos) << f.out;
  const auto both = hapstab_test::run_cli("stability --scene " + (dir / "s.toml").string() + " --T 1/1000");
  EXPECT_EQ(both.code, 2) << both.out;
  EXPECT_NE(both.out.find("--scene replaces"), std::string::npos) << both.out;
  std::filesystem::remove_all(dir);
}

TEST(StabilityCli, SweepsMaxOverTheDamper) {
  const auto dir = hapstab_test::fresh_dir("stability_sweep");
  const auto spec = dir / "spec.toml";
  std::ofstream(spec) << "command = \"stability\"\n[args]\nplant = \"1/(s^2 + s)\"\nH = \"K + B*(z-1)/(T*z)\"\n"
                         "T = \"1/1000\"\nmax = \"K\"\ndelay = 2\ndigits = 20\n[axes]\n"
                         "B = { from = \"0\", to = \"4\", points = 3 }\n";
  const auto r = hapstab_test::run_cli("sweep " + spec.string() + " --out " + (dir / "out").string() + " --jobs 1 --quiet");
  ASSERT_EQ(r.code, 0) << r.out;
  const std::string csv = hapstab_test::slurp(dir / "out" / "points.csv");
  // B = 0, 2, 4 each give a supremum; the B = 0 one is the 400.17... of the library test
  EXPECT_NE(csv.find("400.1732410011606020"), std::string::npos) << csv;
  std::filesystem::remove_all(dir);
}

}  // namespace

// --conservatism (issue 42): the refusals by name, and on Sec. VI case ii with (27)/kc the JSON's
// two brackets -- each end a certified verdict -- and a ratio >= 1 that is what the brackets give.
TEST(StabilityCli, ConservatismRefusalsAndBrackets) {
  const std::string ex = std::string(HAPSTAB_SOURCE_DIR) + "/examples/";
  auto r = hapstab_test::run_cli("stability --scene " + ex + "multidof_case_ii_nominal.toml --max k --conservatism");
  EXPECT_EQ(r.code, 2) << r.out;
  EXPECT_NE(r.out.find("[coupling]"), std::string::npos) << r.out;  // no coupling: Theorem 5 never concludes
  r = hapstab_test::run_cli("stability --scene " + ex + "multidof_case_ii_coupling.toml --conservatism");
  EXPECT_EQ(r.code, 2) << r.out;
  EXPECT_NE(r.out.find("--max"), std::string::npos) << r.out;
  const auto m = run_in_process({"stability", "--scene", ex + "multidof_case_ii_coupling.toml", "--max", "kc", "--conservatism",
                                 "--digits", "2", "--json"});
  ASSERT_EQ(m.code, 0) << m.json.dump();
  const auto& j = m.json;
  EXPECT_EQ(j["path"], "bisection_on_verdicts");
  EXPECT_EQ(j["supremum_proven"], false);
  EXPECT_EQ(j["stable_at"]["status"], "certified");
  EXPECT_EQ(j["unstable_at"]["status"], "certified");
  EXPECT_EQ(j["theorem5"]["concludes_at"]["status"], "exact");
  ASSERT_TRUE(j["theorem5"]["not_at"].is_object());
  const double e_lo = std::stod(j["change_in"][0].get<std::string>()), e_hi = std::stod(j["change_in"][1].get<std::string>());
  const double t_lo = std::stod(j["theorem5"]["bracket"][0].get<std::string>()),
               t_hi = std::stod(j["theorem5"]["bracket"][1].get<std::string>());
  const double c_lo = std::stod(j["conservatism"][0].get<std::string>()), c_hi = std::stod(j["conservatism"][1].get<std::string>());
  EXPECT_LT(t_lo, e_hi);  // sound: Theorem 5 never concludes where the loop is NOT stable
  EXPECT_LE(c_lo, e_lo / t_hi);  // rounded outward
  EXPECT_GE(c_hi, e_hi / t_lo);
  EXPECT_GE(c_hi, 1.0);
}
