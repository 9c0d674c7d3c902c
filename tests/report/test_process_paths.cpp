// tests/report: running programs without a shell (report/process.hpp) and keeping file names
// from input inside their folder (report/paths.hpp).
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "hapstab/numeric/error.hpp"
#include "test_files.hpp"
#include "hapstab/report/paths.hpp"
#include "hapstab/report/process.hpp"

// Its own namespace: the module's tests compile in unity batches (tests/CMakeLists.txt),
// and other files of the batch define helpers of the same names.
namespace test_process_paths {

namespace {

namespace fs = std::filesystem;
using hapstab_test::slurp;

fs::path fresh_dir(const std::string& name) { return hapstab_test::fresh_dir("report_" + name); }
using namespace hapstab::report;
using hapstab::InputError;
using hapstab::NumericalError;

TEST(Process, ArgumentsAreNeverReadByAShell) {
  const fs::path dir = fresh_dir("noshell");
  const std::string payload = "x; touch " + (dir / "PWNED").string() + " $(touch " + (dir / "PWNED2").string() + ") `id`";
  const auto r = run_process({"printf", "%s", payload});
  ASSERT_TRUE(r.ok()) << r.describe();
  EXPECT_EQ(r.out, payload);  // printed as one argument, byte for byte
  EXPECT_FALSE(fs::exists(dir / "PWNED"));
  EXPECT_FALSE(fs::exists(dir / "PWNED2"));
  fs::remove_all(dir);
}

TEST(Process, ExitCodesSignalsAndStderrAreReported) {
  auto r = run_process({"sh", "-c", "echo out; echo err >&2; exit 3"});
  EXPECT_TRUE(r.started);
  EXPECT_EQ(r.exit_code, 3);
  EXPECT_EQ(r.out, "out\n");
  EXPECT_EQ(r.err, "err\n");
  EXPECT_EQ(r.describe(), "exit code 3");
  r = run_process({"sh", "-c", "kill -9 $$"});
  EXPECT_EQ(r.exit_code, -1);
  EXPECT_EQ(r.signal, 9);
  EXPECT_NE(r.describe().find("killed by signal 9"), std::string::npos);
  try {
    run_checked({"sh", "-c", "echo why >&2; exit 4"}, "the child");
    FAIL() << "no exception";
  } catch (const NumericalError& e) {
    EXPECT_NE(std::string(e.what()).find("the child failed (exit code 4)"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("why"), std::string::npos) << e.what();
  }
}

TEST(Process, AMissingProgramIsNamed) {
  const auto r = run_process({"hapstab-no-such-program-xyz", "a"});
  EXPECT_FALSE(r.started);
  EXPECT_FALSE(r.ok());
  EXPECT_NE(r.describe().find("hapstab-no-such-program-xyz"), std::string::npos) << r.describe();
  EXPECT_FALSE(run_process({}).started);
  ProcessOptions o;
  o.working_dir = "/nonexistent-hapstab-folder";
  EXPECT_NE(run_process({"true"}, o).describe().find("working folder '/nonexistent-hapstab-folder' does not exist"),
            std::string::npos);
}

TEST(Process, StdinIsEmptyAndWorkingDirIsHonoured) {
  const fs::path dir = fresh_dir("cwd");
  ProcessOptions o;
  o.working_dir = dir;
  const auto r = run_process({"sh", "-c", "cat; pwd"}, o);  // cat reads /dev/null: returns at once
  ASSERT_TRUE(r.ok()) << r.describe();
  EXPECT_EQ(r.out, fs::canonical(dir).string() + "\n");
  fs::remove_all(dir);
}

TEST(Process, TimeLimitStopsTheChild) {
  ProcessOptions o;
  o.time_limit = 0.3;
  const auto r = run_process({"sleep", "60"}, o);
  EXPECT_TRUE(r.timed_out);
  EXPECT_FALSE(r.ok());
  EXPECT_NE(r.describe().find("time limit of 0.3 s"), std::string::npos) << r.describe();
}

TEST(Process, OutputBeyondTheLimitIsDroppedWithoutBlockingTheChild) {
  ProcessOptions o;
  o.max_output = 1000;
  const auto r = run_process({"head", "-c", "3000000", "/dev/zero"}, o);  // far more than a pipe buffer
  ASSERT_TRUE(r.ok()) << r.describe();
  EXPECT_EQ(r.out.size(), 1000u);
}

TEST(Paths, FileComponentAcceptsNamesAndRefusesPaths) {
  EXPECT_EQ(file_component("sim_tightness", "figure"), "sim_tightness");
  EXPECT_EQ(file_component("001 wall \xC3\xA9", "scene"), "001 wall \xC3\xA9");
  for (const std::string bad : {"", ".", "..", "a/b", "../x", "/etc/passwd", "a\\b", "-rf", "a\nb", "\xFF"}) {
    try {
      file_component(bad, "figure name");
      ADD_FAILURE() << "accepted '" << bad << "'";
    } catch (const InputError& e) {
      EXPECT_EQ(std::string(e.what()).rfind("figure name: ", 0), 0u) << e.what();
    }
  }
  EXPECT_THROW(file_component(std::string(256, 'a'), "x"), InputError);
}

TEST(Paths, InputFilesStayInsideTheirFolder) {
  const fs::path root = fresh_dir("inside");
  const fs::path scene = root / "scene";
  fs::create_directories(scene / "data");
  std::ofstream(scene / "data" / "f.csv") << "1\n2\n";
  std::ofstream(root / "secret.txt") << "secret\n";
  fs::create_symlink(root / "secret.txt", scene / "link.csv");
  fs::create_symlink(scene / "data" / "f.csv", scene / "ok_link.csv");
  EXPECT_EQ(input_file_inside(scene, "data/f.csv", "input[0].file", 1000), fs::canonical(scene / "data" / "f.csv"));
  EXPECT_EQ(input_file_inside(scene, "ok_link.csv", "input[0].file", 1000), fs::canonical(scene / "data" / "f.csv"));
  const std::pair<std::string, std::string> refused[] = {
      {"../secret.txt", "climbs out"},
      {"data/../../secret.txt", "climbs out"},
      {(root / "secret.txt").string(), "absolute path"},
      {"link.csv", "symbolic link"},
      {"data", "not a regular file"},
      {"missing.csv", "no such file"},
      {"", "empty file name"},
      {"a\nb", "control characters"},
  };
  for (const auto& [name, why] : refused) {
    try {
      input_file_inside(scene, name, "input[0].file", 1000);
      ADD_FAILURE() << "accepted '" << name << "'";
    } catch (const InputError& e) {
      EXPECT_EQ(std::string(e.what()).rfind("input[0].file: ", 0), 0u) << e.what();
      EXPECT_NE(std::string(e.what()).find(why), std::string::npos) << e.what();
    }
  }
  try {
    input_file_inside(scene, "data/f.csv", "input[0].file", 3);
    ADD_FAILURE() << "size limit not applied";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("more than the limit of 3"), std::string::npos) << e.what();
  }
  fs::remove_all(root);
}

}  // namespace

}  // namespace test_process_paths
