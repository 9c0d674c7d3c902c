// tests/report: the second hardening pass over files (issue 32). The depth check every TOML text
// passes before toml++ (report/toml_limits.hpp): a header of 50,000 dotted keys overflowed
// toml++'s stack; the check refuses it by name and never counts less than toml++ builds. The
// private folder and the checked copy into a folder someone else may have prepared
// (report/paths.hpp): planted symbolic links are refused or replaced, never followed. Input files
// are regular files of bounded size, checked before they are opened (a FIFO would block).
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <string>
#include <toml++/toml.h>
#include <utility>
#include <vector>

#include "hapstab/numeric/error.hpp"
#include "hapstab/numeric/limits.hpp"
#include "hapstab/report/paths.hpp"
#include "hapstab/report/toml_limits.hpp"
#include "test_files.hpp"

namespace {

namespace fs = std::filesystem;
using hapstab::InputError;
using hapstab::report::toml_depth;
using hapstab_test::slurp;

std::string error_of(const std::string& text) {
  try {
    hapstab::report::check_toml_depth(text, "f.toml");
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

// The depth of the tree toml++ builds (its keys one deeper than a table, elements than an array).
int tree_depth(const toml::node& n) {
  int d = 0;
  if (const auto* t = n.as_table())
    for (auto&& [k, v] : *t) d = std::max(d, 1 + tree_depth(v));
  if (const auto* a = n.as_array())
    for (const auto& v : *a) d = std::max(d, 1 + tree_depth(v));
  return d;
}

std::string dotted(int parts) {
  std::string s = "a";
  for (int i = 1; i < parts; ++i) s += ".a";
  return s;
}

}  // namespace

TEST(TomlDepth, AHeaderOf50000DottedKeysIsRefusedBeforeParsing) {
  const std::string text = "[scene]\nT = \"1/1000\"\n[" + dotted(50000) + "]\nx = 1\n";  // 100 KB: SIGSEGV in toml++
  const std::string msg = error_of(text);
  EXPECT_NE(msg.find("f.toml:3:"), std::string::npos) << msg;  // the header, not the key under it
  EXPECT_NE(msg.find("nested 50001 levels deep"), std::string::npos) << msg;
  EXPECT_NE(msg.find("more than the limit of 64"), std::string::npos) << msg;
  // the same as a dotted key, in an inline table, and as nested arrays
  EXPECT_NE(error_of(dotted(50000) + " = 1\n").find("limit of 64"), std::string::npos);
  EXPECT_NE(error_of("x = { " + dotted(50000) + " = 1 }\n").find("limit of 64"), std::string::npos);
  EXPECT_NE(error_of("x = " + std::string(50000, '[') + "\n").find("limit of 64"), std::string::npos);
  // at the limit toml++ parses it; one more is refused
  EXPECT_EQ(error_of("[" + dotted(63) + "]\nx = 1\n"), "");
  EXPECT_EQ(tree_depth(toml::parse("[" + dotted(63) + "]\nx = 1\n")), 64);
  EXPECT_NE(error_of("[" + dotted(64) + "]\nx = 1\n").find("nested 65 levels"), std::string::npos);
}

TEST(TomlDepth, CountsWhatTomlBuildsAndNothingInsideStringsOrComments) {
  const std::vector<std::pair<std::string, int>> cases = {
      {"", 0},
      {"x = 1", 1},
      {"[a]\nx = 1", 2},
      {"[a.b.c]", 3},
      {"[ a . \"b.c\" . 'd.e' ]\nx = 1", 4},
      {"a.b.c = 1", 3},
      {"\"a.b.c\" = 1", 1},
      {"x = [1, [2, [3]]]", 4},
      {"x = {y = {z = 1}}", 3},
      {"x = {y.z = [ {w = 1} ]}", 5},
      {"x = \"a.b.c[[[{{{\"\ny = 'a.b.c.d'", 1},
      {"x = \"\"\"\n[a.b.c.d]\n\\\"\"\"\"\"\"\ny = 1", 1},
      {"x = '''\n[a.b.c.d.e]\n'''''\ny = 1", 1},
      {"# [a.b.c.d]\nx = 1 # a.b.c", 1},
      {"x = [\n  1, # [[[[\n  2,\n]\n[t]\ny = 2", 2},
      {"[[a]]\nx = 1\n[[a]]\ny = 2", 3},
      {"[[a]]\n[a.b]\nx = 1", 4},
      {"[[a]]\n[[a.b]]\nx = 1", 5},
  };
  for (const auto& [text, depth] : cases) {
    const int scanned = toml_depth(text).depth;
    EXPECT_GE(scanned, depth) << text;
    EXPECT_LE(scanned, depth + 1) << text;  // an empty array's element level, an [[a]] path: counted as if there
    int built = 0;
    EXPECT_NO_THROW(built = tree_depth(toml::parse(text))) << text;
    EXPECT_EQ(built, depth) << text;
  }
}

// Every example scene and spec: far below the limit, and never less than toml++'s tree.
TEST(TomlDepth, ExampleScenesAreShallow) {
  int files = 0;
  for (const fs::path dir : {fs::path(HAPSTAB_SOURCE_DIR) / "examples", fs::path(HAPSTAB_SOURCE_DIR) / "docs"})
    for (const auto& e : fs::directory_iterator(dir)) {
      if (e.path().extension() != ".toml") continue;
      const std::string text = slurp(e.path());
      const int scanned = toml_depth(text).depth;
      EXPECT_GE(scanned, tree_depth(toml::parse(text))) << e.path();
      EXPECT_LE(scanned, 10) << e.path();
      ++files;
    }
  EXPECT_GT(files, 10);
}

TEST(PrivateFolder, IsFreshPrivateAndRemoved) {
  fs::path p;
  {
    const hapstab::report::PrivateFolder f("hapstab-test");
    p = f.path();
    struct stat st {};
    ASSERT_EQ(::lstat(p.c_str(), &st), 0);
    EXPECT_TRUE(S_ISDIR(st.st_mode));
    EXPECT_EQ(st.st_mode & 0777, 0700u);
    EXPECT_TRUE(fs::is_empty(p));
    std::ofstream(p / "x") << "data";
  }
  EXPECT_FALSE(fs::exists(p));
}

// A folder someone else prepared: a symbolic link at the file's name is replaced, not followed;
// a symbolic link as the folder is refused; nothing outside is written.
TEST(InstallFile, PlantedLinksAreReplacedOrRefusedNeverFollowed) {
  const fs::path d = hapstab_test::fresh_dir("report_install");
  std::ofstream(d / "src.png") << "the figure";
  fs::create_directories(d / "outside");
  std::ofstream(d / "outside" / "victim") << "keep me";
  fs::create_directories(d / "dir");
  fs::create_symlink(d / "outside" / "victim", d / "dir" / "map.png");
  const fs::path out = hapstab::report::install_file(d / "src.png", d / "dir", "map.png", "test");
  EXPECT_EQ(out, d / "dir" / "map.png");
  EXPECT_FALSE(fs::is_symlink(d / "dir" / "map.png"));
  EXPECT_EQ(slurp(d / "dir" / "map.png"), "the figure");
  EXPECT_EQ(slurp(d / "outside" / "victim"), "keep me");
  // the folder itself a link out: refused by name
  fs::create_directory_symlink(d / "outside", d / "linked");
  try {
    hapstab::report::install_file(d / "src.png", d / "linked", "map.png", "sweep plot");
    ADD_FAILURE() << "wrote through a symbolic link";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("sweep plot: '" + (d / "linked").string() + "' is a symbolic link"), std::string::npos)
        << e.what();
  }
  EXPECT_FALSE(fs::exists(d / "outside" / "map.png"));
  // a missing folder is created; a new file appears; no temporary is left behind
  hapstab::report::install_file(d / "src.png", d / "new", "map.png", "test");
  EXPECT_EQ(slurp(d / "new" / "map.png"), "the figure");
  EXPECT_EQ(std::distance(fs::directory_iterator(d / "new"), fs::directory_iterator()), 1);
  fs::remove_all(d);
}

TEST(ReadInputFile, RegularFilesOfBoundedSizeOnly) {
  const fs::path d = hapstab_test::fresh_dir("report_read_input");
  std::ofstream(d / "ok.toml") << "x = 1\n";
  EXPECT_EQ(hapstab::report::read_input_file(d / "ok.toml", "the scene", 100), "x = 1\n");
  auto error = [](const fs::path& p, std::uintmax_t max) {
    try {
      hapstab::report::read_input_file(p, "the scene", max);
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  EXPECT_NE(error(d / "ok.toml", 5).find("has 6 bytes, more than the limit of 5"), std::string::npos);
  EXPECT_NE(error("/dev/zero", 100).find("is not a regular file"), std::string::npos);
  ASSERT_EQ(::mkfifo((d / "fifo.toml").c_str(), 0600), 0);
  EXPECT_NE(error(d / "fifo.toml", 100).find("is not a regular file"), std::string::npos);  // returns: no open, no block
  EXPECT_NE(error(d / "missing.toml", 100).find("no such file"), std::string::npos);
  fs::remove_all(d);
}
