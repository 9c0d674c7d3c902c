// tests/cli: what a user sees when a scene holds a name the schema does not know, or a part the
// command does not model (issue 29): exit 2 and one line naming the file, the line, the wrong
// name and the right one (or the command that models it). Before, each of these ran a different
// model than the one written, with exit 0. Scene files: tests/scene/data/.
#include <gtest/gtest.h>

#include <string>

#include "cli/cli_run.hpp"

namespace {

const std::string kDir = std::string(HAPSTAB_SOURCE_DIR) + "/tests/scene/data/";

hapstab_test::CliRun simulate(const std::string& file) {
  return hapstab_test::run_cli("simulate --quiet --scene " + kDir + file + " --out " +
                               hapstab_test::temp_path("refusals", file).string());
}

hapstab_test::CliRun analyze(const std::string& file) {
  return hapstab_test::run_cli("multidof analyze --scene " + kDir + file);
}

}  // namespace

TEST(SceneRefusals, MisspelledSectionsExitTwoNamingLineAndNearestName) {
  auto r = simulate("bias_wall_contacts.toml");  // ran a two-sided wall: 1.6e7 J, exit 0
  EXPECT_EQ(r.code, 2) << r.out;
  EXPECT_EQ(r.out, "hapstab: error: " + kDir + "bias_wall_contacts.toml:41: unknown section [contacts]; did you mean [contact]?\n");
  r = simulate("misspelled_delays.toml");
  EXPECT_EQ(r.code, 2) << r.out;
  EXPECT_NE(r.out.find("misspelled_delays.toml:31: unknown section [delays]; did you mean [delay]?"), std::string::npos) << r.out;
  r = analyze("misspelled_delays.toml");
  EXPECT_EQ(r.code, 2) << r.out;
  EXPECT_NE(r.out.find("unknown section [delays]; did you mean [delay]?"), std::string::npos) << r.out;
  r = simulate("misspelled_passivity_controler.toml");
  EXPECT_EQ(r.code, 2) << r.out;
  EXPECT_NE(r.out.find("unknown section [passivity_controler]; did you mean [passivity_controller]?"), std::string::npos) << r.out;
  r = simulate("misspelled_input_field.toml");
  EXPECT_EQ(r.code, 2) << r.out;
  EXPECT_NE(r.out.find("misspelled_input_field.toml:27: unknown key input[0].tme; did you mean input[0].time?"), std::string::npos)
      << r.out;
}

TEST(SceneRefusals, MisspelledMultidofKeysExitTwo) {
  auto r = analyze("multidof_ops.toml");
  EXPECT_EQ(r.code, 2) << r.out;
  EXPECT_EQ(r.out, "hapstab: error: " + kDir + "multidof_ops.toml:32: unknown key multidof.ops; did you mean multidof.osp?\n");
  r = analyze("multidof_misspelled_subtable.toml");
  EXPECT_EQ(r.code, 2) << r.out;
  EXPECT_NE(r.out.find("multidof_misspelled_subtable.toml:34: unknown section [multidof.coupl]; did you mean [multidof.coupling]?"),
            std::string::npos)
      << r.out;
}

// multidof analyze analysed 002_bias_wall.toml as a two-sided linear wall; now it refuses
// [contact] and names the command that models it; simulate runs the same file.
TEST(SceneRefusals, ContactIsRefusedByMultidofNamingSimulate) {
  for (const char* cmd : {"analyze", "design"}) {
    const auto r = hapstab_test::run_cli(std::string("multidof ") + cmd + " --scene " + kDir + "multidof_contact.toml");
    EXPECT_EQ(r.code, 2) << r.out;
    EXPECT_NE(r.out.find("multidof_contact.toml:31: multidof " + std::string(cmd) +
                         " does not model [contact] (a unilateral wall; Theorems 5 and 6 model a two-sided linear wall); "
                         "`hapstab simulate` does"),
              std::string::npos)
        << r.out;
  }
  const auto r = hapstab_test::run_cli("multidof analyze --scene " + std::string(HAPSTAB_SOURCE_DIR) + "/examples/002_bias_wall.toml");
  EXPECT_EQ(r.code, 2) << r.out;
  EXPECT_NE(r.out.find("does not model [contact]"), std::string::npos) << r.out;
  EXPECT_EQ(simulate("multidof_contact.toml").code, 0);
}
