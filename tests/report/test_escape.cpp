// tests/report: the writers of report/escape.hpp, each fed crafted strings and, where the real
// tool is on the machine (scripts/install-deps installs gnuplot and python3, --test pdflatex), read
// back by that tool: gnuplot prints the literal, Python's csv module parses the cells, pdflatex
// typesets the text with shell escape off. Nothing may execute, and what comes back must be
// the text that went in (control characters replaced, as documented).
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "test_files.hpp"
#include "hapstab/report/escape.hpp"
#include "hapstab/report/process.hpp"

// Its own namespace: the module's tests compile in unity batches (tests/CMakeLists.txt),
// and other files of the batch define helpers of the same names.
namespace test_escape {

namespace {

namespace fs = std::filesystem;
using hapstab_test::slurp;

fs::path fresh_dir(const std::string& name) { return hapstab_test::fresh_dir("escape_" + name); }
using namespace hapstab::report;

const std::string kFFFD = "\xEF\xBF\xBD";

// Strings an attacker would put in a scene's name: shell, gnuplot, LaTeX, HTML, CSV and
// terminal payloads, plus text that must pass unharmed.
std::vector<std::string> crafted(const fs::path& marker_dir) {
  const std::string m = (marker_dir / "PWNED").string();
  return {
      "x'; system('touch " + m + "1'); print '",
      "`touch " + m + "2`",
      "@macro and !touch " + m + "3",
      "line one\nsystem('touch " + m + "4')",
      "it's \"quoted\" \\ back\\slash \\",
      "''''",
      "'a", "a'", "a''", "''a''", "'",
      "$(touch " + m + "5) ; | & > < * ?",
      "\\immediate\\write18{touch " + m + "6}\\input{/etc/hostname}",
      "^^5cinput{/etc/hostname} ~ # % _ { }",
      "<script>alert(1)</script> \" onload=\"x",
      "=HYPERLINK(\"http://x\",\"y\")",
      "-2+3+cmd|' /C calc'!A0",
      "@SUM(A1:A2)",
      "a,b\r\nc",
      "\x1b]0;retitled\x07\x1b[2J",
      "Fa\xC3\xA7" "ade \xE6\x97\xA5\xE6\x9C\xAC \xF0\x9F\x98\x80",  // Façade 日本 😀
      "bad utf8 \xC0\xAF \xED\xA0\x80 \xFF",
      "bidi \xE2\x80\xAE" "evil",
      "",
      " padded ",
  };
}

TEST(Text, ReplacesControlCharactersAndMalformedUtf8Only) {
  EXPECT_EQ(text("a\nb\tc"), "a" + kFFFD + "b\tc");
  EXPECT_EQ(text("a\nb", true), "a\nb");
  EXPECT_EQ(text("\x1b[2J"), kFFFD + "[2J");
  EXPECT_EQ(text("\x7f\xC2\x85"), kFFFD + kFFFD);                    // DEL, C1 NEL
  EXPECT_EQ(text("\xC0\xAF"), kFFFD + kFFFD);                        // overlong '/'
  EXPECT_EQ(text("\xED\xA0\x80"), kFFFD + kFFFD + kFFFD);            // a UTF-16 surrogate
  EXPECT_EQ(text("\xF4\x90\x80\x80"), kFFFD + kFFFD + kFFFD + kFFFD);  // > U+10FFFF
  EXPECT_EQ(text("\xE6\x97\xA5"), "\xE6\x97\xA5");                   // 日 passes
  EXPECT_EQ(text("\xE2\x80\xAE"), kFFFD);                            // RIGHT-TO-LEFT OVERRIDE
  EXPECT_EQ(text("\xE6\x97"), kFFFD + kFFFD);                        // truncated
  EXPECT_TRUE(is_clean_text("Fa\xC3\xA7" "ade 1/2"));
  EXPECT_FALSE(is_clean_text("a\nb"));
  EXPECT_FALSE(is_clean_text("\xFF"));
  EXPECT_EQ(comment("a\nb\tc"), "a" + kFFFD + "b c");
}

TEST(Gnuplot, QuoteIsASingleQuotedLiteral) {
  EXPECT_EQ(gnuplot::quote("plain"), "'plain'");
  EXPECT_EQ(gnuplot::quote("it's"), "'it'.\"'\".'s'");
  EXPECT_EQ(gnuplot::quote("'a''"), "\"'\".'a'.\"'\".\"'\"");
  EXPECT_EQ(gnuplot::quote(""), "''");
  EXPECT_EQ(gnuplot::quote("a\nb"), "'a" + kFFFD + "b'");
  EXPECT_EQ(gnuplot::quote("\\"), "'\\'");  // backslash is literal inside single quotes
}

TEST(Gnuplot, CraftedStringsReadBackThroughRealGnuplotAndRunNothing) {
  const fs::path dir = fresh_dir("gnuplot");
  const auto inputs = crafted(dir);
  {
    std::ofstream gp(dir / "t.gp");
    gp << "set print " << gnuplot::quote((dir / "printed.txt").string()) << "\n";
    for (const auto& s : inputs) gp << "print " << gnuplot::quote(s) << "\n";
    // the same strings as a plot title and a label, on the dumb terminal
    gp << "set terminal dumb\nset output " << gnuplot::quote((dir / "plot.txt").string()) << "\n";
    for (const auto& s : inputs)
      gp << "set title " << gnuplot::quote(s) << " noenhanced\nset label 1 " << gnuplot::quote(s)
         << " at 0,0 noenhanced\nplot x title " << gnuplot::quote(s) << "\n";
  }
  const auto r = run_process({"gnuplot", (dir / "t.gp").string()});
  ASSERT_TRUE(r.ok()) << r.describe() << "\n" << r.err;
  std::istringstream printed(slurp(dir / "printed.txt"));
  for (const auto& s : inputs) {
    std::string line;
    ASSERT_TRUE(std::getline(printed, line)) << "missing output for " << s;
    EXPECT_EQ(line, text(s)) << "gnuplot read back something else for: " << s;
  }
  for (int k = 1; k <= 6; ++k) EXPECT_FALSE(fs::exists(dir / ("PWNED" + std::to_string(k)))) << k;
  fs::remove_all(dir);
}

TEST(Csv, RulesOfRfc4180AndFormulaNeutralisation) {
  EXPECT_EQ(csv::cell("plain"), "plain");
  EXPECT_EQ(csv::cell("a,b"), "\"a,b\"");
  EXPECT_EQ(csv::cell("say \"hi\""), "\"say \"\"hi\"\"\"");
  EXPECT_EQ(csv::cell(" padded"), "\" padded\"");
  EXPECT_EQ(csv::cell("=1+2"), "'=1+2");
  EXPECT_EQ(csv::cell("@SUM(A1)"), "'@SUM(A1)");
  EXPECT_EQ(csv::cell("+cmd"), "'+cmd");
  EXPECT_EQ(csv::cell("-2+3+cmd|' /C calc'!A0"), "'-2+3+cmd|' /C calc'!A0");
  // numbers stay numbers
  EXPECT_EQ(csv::cell("-1/2"), "-1/2");
  EXPECT_EQ(csv::cell("-3.5e-7"), "-3.5e-7");
  EXPECT_EQ(csv::cell("+5"), "+5");
  EXPECT_TRUE(csv::is_plain_number("1/1000"));
  EXPECT_FALSE(csv::is_plain_number("-"));
  EXPECT_FALSE(csv::is_plain_number("-e"));
}

TEST(Csv, CraftedCellsParseBackWithPythonCsvInTheirColumns) {
  const fs::path dir = fresh_dir("csv");
  const auto inputs = crafted(dir);
  nlohmann::json expected = nlohmann::json::array();
  {
    std::ofstream f(dir / "t.csv", std::ios::binary);
    for (const auto& s : inputs) {
      // three columns: index, the crafted cell, a number
      f << csv::cell(std::to_string(expected.size())) << ',' << csv::cell(s) << ',' << csv::cell("-1/2") << "\r\n";
      std::string want = text(s);
      if (!want.empty() && std::string("=+-@").find(want[0]) != std::string::npos && !csv::is_plain_number(want))
        want = "'" + want;
      expected.push_back({std::to_string(expected.size()), want, "-1/2"});
    }
  }
  const auto r = run_process({"python3", "-c",
                              "import csv, json, sys\n"
                              "print(json.dumps(list(csv.reader(open(sys.argv[1], newline='', encoding='utf-8')))))",
                              (dir / "t.csv").string()});
  ASSERT_TRUE(r.ok()) << r.describe() << "\n" << r.err;
  const auto got = nlohmann::json::parse(r.out);
  ASSERT_EQ(got.size(), expected.size()) << r.out;
  for (size_t i = 0; i < got.size(); ++i) EXPECT_EQ(got[i], expected[i]) << "row " << i;
  fs::remove_all(dir);
}

// After the escape, the only control sequences are the ones it writes itself.
TEST(Latex, EscapeLeavesNoControlSequenceOfItsInput) {
  const fs::path dir = fresh_dir("latex_unit");
  for (const auto& s : crafted(dir)) {
    std::string e = latex::escape(s);
    for (const char* ok : {"\\textbackslash{}", "\\textasciicircum{}", "\\textasciitilde{}", "\\{", "\\}", "\\$", "\\&",
                           "\\#", "\\_", "\\%", "\\textless{}", "\\textgreater{}", "\\textbar{}"})
      for (size_t p; (p = e.find(ok)) != std::string::npos;) e.erase(p, std::string(ok).size());
    EXPECT_EQ(e.find_first_of("\\{}$&#^_~%"), std::string::npos) << s << " -> " << latex::escape(s);
  }
  fs::remove_all(dir);
}

TEST(Latex, CraftedTextTypesetsWithPdflatexAndRunsOrReadsNothing) {
  const fs::path dir = fresh_dir("latex");
  const auto inputs = crafted(dir);
  {
    std::ofstream f(dir / "t.tex");
    f << "\\documentclass{article}\n\\begin{document}\n";
    for (const auto& s : inputs) f << latex::escape(s) << "\\par\n";
    f << "\\end{document}\n";
  }
  ProcessOptions po;
  po.working_dir = dir;
  po.time_limit = 120;
  // Characters outside pdflatex's default set (CJK, emoji, U+FFFD) are errors it reports and
  // skips; the run must reach the end with no other error.
  const auto r = run_process({"pdflatex", "-no-shell-escape", "-interaction=nonstopmode", "t.tex"}, po);
  ASSERT_TRUE(r.started) << r.describe();
  const std::string log = slurp(dir / "t.log");
  EXPECT_NE(log.find("Output written on t.pdf"), std::string::npos) << log.substr(log.size() > 3000 ? log.size() - 3000 : 0);
  std::istringstream lines(log);
  for (std::string line; std::getline(lines, line);)
    if (line.rfind("! ", 0) == 0) { EXPECT_EQ(line.rfind("! LaTeX Error: Unicode character", 0), 0u) << line; }
  EXPECT_EQ(log.find("(/etc/hostname"), std::string::npos) << "pdflatex opened a file named in the input (the log shows an opened file as \"(path\")";
  EXPECT_TRUE(fs::exists(dir / "t.pdf"));
  for (int k = 1; k <= 6; ++k) EXPECT_FALSE(fs::exists(dir / ("PWNED" + std::to_string(k)))) << k;
  fs::remove_all(dir);
}

TEST(Html, TextAttributeAndUrl) {
  EXPECT_EQ(html::text("<script>alert('x')</script>&"), "&lt;script&gt;alert(&#39;x&#39;)&lt;/script&gt;&amp;");
  EXPECT_EQ(html::attribute("\" onload=\"x` y"), "&quot; onload=&quot;x&#96; y");
  EXPECT_EQ(html::url_component("../a b?c#d"), "..%2Fa%20b%3Fc%23d");
  EXPECT_EQ(html::url_component("javascript:alert(1)"), "javascript%3Aalert%281%29");
  EXPECT_EQ(html::url_component("sim_tightness"), "sim_tightness");
  for (const auto& s : crafted(fs::path("/nonexistent"))) {
    const std::string t = html::text(s), a = html::attribute(s);
    EXPECT_EQ(t.find_first_of("<>\"'"), std::string::npos) << s;
    EXPECT_EQ(a.find_first_of("<>\"'`"), std::string::npos) << s;
  }
}

TEST(Markdown, CellsCannotBreakTheTableOrLink) {
  EXPECT_EQ(markdown::cell("a|b"), "a\\|b");
  EXPECT_EQ(markdown::cell("<img src=x onerror=alert(1)>"), "\\<img src=x onerror=alert(1)>");
  EXPECT_EQ(markdown::cell("</td><!-- x --><?php"), "\\</td>\\<!-- x -->\\<?php");
  EXPECT_EQ(markdown::cell("<http://x.org>"), "\\<http://x.org>");  // no autolink
  EXPECT_EQ(markdown::cell("&lt; &#60; &x"), "\\&lt; \\&#60; \\&x");    // no entity
  // what cannot open HTML or an entity stays as written (report.md's claims read as the table does)
  EXPECT_EQ(markdown::cell("b* < b, K <= 2b/T, |x|<1, A & O, 3&4"), "b* < b, K <= 2b/T, \\|x\\|<1, A & O, 3&4");
  EXPECT_EQ(markdown::cell("[x](javascript:alert(1))"), "\\[x\\](javascript:alert(1))");
  EXPECT_EQ(markdown::cell("line\nbreak"), "line" + kFFFD + "break");
  EXPECT_EQ(markdown::code("plain"), "`plain`");
  EXPECT_EQ(markdown::code("a`b"), "``a`b``");
  EXPECT_EQ(markdown::code("`x"), "`` `x ``");
  EXPECT_EQ(markdown::code("a|b"), "`a\\|b`");
}

}  // namespace

}  // namespace test_escape
