// tests/cli: scenes are untrusted input (docs/security.md). A scene whose name carries gnuplot,
// shell, LaTeX and HTML payloads runs; its plot.gp is then run by the real gnuplot (PNG and the
// cairolatex terminal) and the LaTeX it writes by the real pdflatex: nothing executes, nothing
// is read from outside, nothing is written outside --out. Names with control characters, bad
// parameter names and profile files outside the scene's folder are refused with exit 2 and a
// message naming the field. `reproduce` escapes scene text in report.md and index.html, and runs
// a scene whose file name holds shell syntax without a shell.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <string>

#include "test_files.hpp"
#include "hapstab/report/process.hpp"

namespace {

namespace fs = std::filesystem;
using hapstab_test::slurp;

fs::path fresh_dir(const std::string& name) { return hapstab_test::fresh_dir("untrusted_" + name); }
using hapstab::report::ProcessOptions;
using hapstab::report::ProcessResult;
using hapstab::report::run_process;

ProcessResult hapstab_cli(std::vector<std::string> args, const fs::path& cwd = {}) {
  args.insert(args.begin(), HAPSTAB_CLI);
  ProcessOptions o;
  o.working_dir = cwd;
  return run_process(args, o);
}

// A TOML basic string holding s.
std::string toml_string(const std::string& s) {
  std::string o = "\"";
  for (char c : s) o += c == '"' ? std::string("\\\"") : c == '\\' ? std::string("\\\\") : std::string(1, c);
  return o + "\"";
}

// The paper-001 wall below the bound, 20 ms long, with `name` as its [scene] name and `extra`
// appended.
std::string wall_scene(const std::string& name_toml, const std::string& extra = "") {
  std::string s = slurp(fs::path(HAPSTAB_SOURCE_DIR) / "examples" / "001_tightness_below.toml");
  s = s.substr(0, s.find("[reproduce]"));
  const size_t n = s.find("name = \"001 tightness");
  s.replace(n, s.find('\n', n) - n, "name = " + name_toml);
  const size_t d = s.find("duration = \"1\"");
  s.replace(d, std::string("duration = \"1\"").size(), "duration = \"0.02\"");
  const size_t w = s.find("window = ");
  s.replace(w, s.find('\n', w) - w, "window = [\"0.01\", \"0.012\"]");
  return s + extra;
}

std::set<std::string> entries(const fs::path& dir) {
  std::set<std::string> out;
  for (const auto& e : fs::recursive_directory_iterator(dir)) out.insert(fs::relative(e.path(), dir).string());
  return out;
}

TEST(Untrusted, CraftedSceneNameRunsNothingInGnuplotOrLatex) {
  const fs::path dir = fresh_dir("name");
  const std::string payload =
      "wall x'; system('touch PWNED1'); print 'a `touch PWNED2` @m !touch PWNED3 "
      "\\immediate\\write18{touch PWNED4}\\input{/etc/hostname} ^^5cinput{/etc/hostname} $x$ 50% "
      "<script>alert(1)</script> caf\xC3\xA9";
  std::ofstream(dir / "scene.toml") << wall_scene(toml_string(payload));
  const auto before = entries(dir);
  auto r = hapstab_cli({"simulate", "--scene", (dir / "scene.toml").string(), "--out", (dir / "out").string(), "--quiet"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  // nothing outside --out
  std::set<std::string> added;
  for (const auto& e : entries(dir))
    if (!before.count(e) && e.rfind("out", 0) != 0) added.insert(e);
  EXPECT_TRUE(added.empty()) << *added.begin();
  // samples.csv parses with Python's csv module into the same columns in every row
  const auto csv = run_process({"python3", "-c",
                                "import csv, sys\n"
                                "rows = list(csv.reader(open(sys.argv[1], newline='', encoding='utf-8')))\n"
                                "print(len(rows), sorted(set(len(r) for r in rows)), rows[0][:3])",
                                (dir / "out" / "samples.csv").string()});
  ASSERT_TRUE(csv.ok()) << csv.describe() << csv.err;
  EXPECT_NE(csv.out.find(" [9] ['t [s]', 'x_0 [m]', 'v_0 [m/s]']"), std::string::npos) << csv.out;  // t + 8 columns for one DOF
  // the script draws with the real gnuplot, in PNG and in the cairolatex terminal
  ProcessOptions in_out;
  in_out.working_dir = dir / "out";
  r = run_process({"gnuplot", "plot.gp"}, in_out);
  ASSERT_TRUE(r.ok()) << r.describe() << r.err;
  r = run_process({"gnuplot", "-e", "fmt='tex'", "plot.gp"}, in_out);
  ASSERT_TRUE(r.ok()) << r.describe() << r.err;
  EXPECT_TRUE(fs::exists(dir / "out" / "position.png"));
  const std::string tex = slurp(dir / "out" / "position.tex");
  EXPECT_NE(tex.find("\\textbackslash{}immediate\\textbackslash{}write18\\{touch PWNED4\\}"), std::string::npos) << tex;
  EXPECT_EQ(tex.find("\\immediate\\write18"), std::string::npos);
  // ... and the LaTeX pair typesets without shell escape, reading no file the name names
  std::ofstream(dir / "out" / "doc.tex") << "\\documentclass{article}\n\\usepackage{graphicx}\n\\usepackage{color}\n"
                                             "\\begin{document}\n\\input{position.tex}\n\\end{document}\n";
  r = run_process({"pdflatex", "-no-shell-escape", "-interaction=nonstopmode", "doc.tex"}, in_out);
  ASSERT_TRUE(r.started) << r.describe();
  const std::string log = slurp(dir / "out" / "doc.log");
  EXPECT_NE(log.find("Output written on doc.pdf"), std::string::npos) << log.substr(log.size() > 3000 ? log.size() - 3000 : 0);
  EXPECT_EQ(log.find("(/etc/hostname"), std::string::npos);
  for (const auto& where : {dir, dir / "out", fs::current_path()})
    for (int k = 1; k <= 4; ++k) EXPECT_FALSE(fs::exists(where / ("PWNED" + std::to_string(k)))) << where << " " << k;
  fs::remove_all(dir);
}

TEST(Untrusted, NamesWithControlCharactersAndBadParameterNamesAreRefused) {
  const fs::path dir = fresh_dir("refused");
  struct Case {
    std::string scene, field, why;
  };
  const std::string ok_name = toml_string("wall");
  const Case cases[] = {
      {wall_scene("\"escape \\u001b]0;retitled\\u0007\""), "scene.name", "control characters"},
      {wall_scene("\"two\\nlines\""), "scene.name", "control characters"},
      {wall_scene("42"), "scene.name", "expected a string"},
      {wall_scene(toml_string(std::string(300, 'a'))), "scene.name", "longer than 256 bytes"},
      {[&] {
         std::string s = wall_scene(ok_name);
         const size_t p = s.find("name = \"haptic\"");
         return s.replace(p, std::string("name = \"haptic\"").size(), "name = \"hap\\rtic\"");
       }(),
       "device[0].name", "control characters"},
      {[&] {
         std::string s = wall_scene(ok_name);
         const size_t p = s.find("[parameters]\n");
         return s.insert(p + 13, "\"a b\" = \"1\"\n");
       }(),
       "parameters", "not a parameter name"},
  };
  int i = 0;
  for (const auto& c : cases) {
    const fs::path f = dir / ("case" + std::to_string(i++) + ".toml");
    std::ofstream(f) << c.scene;
    const auto r = hapstab_cli({"simulate", "--scene", f.string(), "--out", (dir / "out").string(), "--quiet"});
    EXPECT_EQ(r.exit_code, 2) << c.field << ": " << r.err;
    EXPECT_NE(r.err.find(c.field + ": "), std::string::npos) << r.err;
    EXPECT_NE(r.err.find(c.why), std::string::npos) << r.err;
    EXPECT_EQ(r.err.find('\x1b'), std::string::npos) << "a control character reached the terminal";
  }
  EXPECT_FALSE(fs::exists(dir / "out"));
  fs::remove_all(dir);
}

TEST(Untrusted, ProfileFilesOutsideTheSceneFolderAreRefused) {
  const fs::path dir = fresh_dir("profile");
  fs::create_directories(dir / "scene");
  std::ofstream(dir / "secret.csv") << "root:x:0:0\n";
  const std::pair<std::string, std::string> cases[] = {
      {"../secret.csv", "climbs out"}, {(dir / "secret.csv").string(), "absolute path"}, {"/dev/zero", "absolute path"}};
  for (const auto& [file, why] : cases) {
    const std::string profile = "\n[[input]]\ntype = \"profile\"\ndof = \"haptic\"\nfile = " + toml_string(file) + "\n";
    std::ofstream(dir / "scene" / "s.toml") << wall_scene(toml_string("wall"), profile);
    const auto r = hapstab_cli({"simulate", "--scene", (dir / "scene" / "s.toml").string(), "--out", (dir / "out").string()});
    EXPECT_EQ(r.exit_code, 2) << file << ": " << r.err;
    EXPECT_NE(r.err.find(".file: "), std::string::npos) << r.err;
    EXPECT_NE(r.err.find(why), std::string::npos) << r.err;
    EXPECT_EQ(r.err.find("root:x"), std::string::npos) << "the file's content leaked into the message";
  }
  fs::remove_all(dir);
}

TEST(Untrusted, FigureNamesCannotClimbOutOfOut) {
  const fs::path dir = fresh_dir("figure");
  for (const std::string name : {"../../escape", "/tmp/x", "sim_tightness/../../x"}) {
    const auto r = hapstab_cli({"figure", name, "--out", (dir / "out").string()});
    EXPECT_EQ(r.exit_code, 2) << name << ": " << r.err;
  }
  for (const auto& e : entries(dir)) EXPECT_EQ(e.rfind("out", 0), 0u) << e;  // nothing beside --out
  fs::remove_all(dir);
}

TEST(Untrusted, ReproduceEscapesSceneTextAndUsesNoShell) {
  const fs::path root = fresh_dir("reproduce");
  fs::create_directories(root / "examples");
  fs::copy(fs::path(HAPSTAB_SOURCE_DIR) / "plots", root / "plots");
  const std::string claim = "<script>alert(1)</script> | [x](javascript:alert(1)) `code` \" onload=\"y";
  // A file name with shell syntax: run through a shell, it would create PWNED in the working folder.
  const std::string file = "001_zz'$(touch PWNED)'.toml";
  std::ofstream(root / "examples" / file) << wall_scene(toml_string("wall"), "[reproduce]\npaper = \"001\"\nclaim = " +
                                                                               toml_string(claim) + "\n");
  const fs::path work = root / "work";
  fs::create_directories(work);
  const auto r = run_process({"env", "HAPSTAB_DATA_DIR=" + root.string(), HAPSTAB_CLI, "reproduce", "--only", "001",
                              "--format", "png", "--quiet", "--out", (root / "out").string()},
                             [&] {
                               ProcessOptions o;
                               o.working_dir = work;
                               return o;
                             }());
  ASSERT_TRUE(r.started) << r.describe();
  EXPECT_LE(r.exit_code, 1) << r.err;
  EXPECT_FALSE(fs::exists(work / "PWNED"));
  EXPECT_FALSE(fs::exists(root / "PWNED"));
  const std::string html = slurp(root / "out" / "index.html");
  const std::string md = slurp(root / "out" / "report.md");
  ASSERT_NE(html.find("&lt;script&gt;alert(1)&lt;/script&gt;"), std::string::npos) << html.substr(0, 3000);
  EXPECT_EQ(html.find("<script>"), std::string::npos);
  EXPECT_EQ(html.find("onload=\"y"), std::string::npos);
  // Markdown: a '<' that could open HTML carries CommonMark's backslash escape, every time
  EXPECT_NE(md.find("\\<script>alert(1)\\</script>"), std::string::npos) << md.substr(0, 3000);
  for (size_t at = md.find("<script>"); at != std::string::npos; at = md.find("<script>", at + 1))
    EXPECT_TRUE(at > 0 && md[at - 1] == '\\') << md.substr(at > 40 ? at - 40 : 0, 80);
  EXPECT_EQ(md.find("[x](javascript"), std::string::npos);
  // the scene ran (its row says so) through the argument vector, file name and all
  EXPECT_NE(md.find("001_zz'$(touch PWNED)'.toml"), std::string::npos);
  EXPECT_TRUE(fs::exists(root / "out" / "scenes" / "001_zz'$(touch PWNED)'.simulate.json"));
  fs::remove_all(root);
}

}  // namespace
