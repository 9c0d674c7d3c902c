// `hapstab plot nyquist|bode`: the figures are written in every format, the b* they mark is the
// number `hapstab bound` prints, the Nyquist curve's largest real part is b* (the curve whose
// maximum defines it), the window is cut and said so when Im G -> inf as w -> 0, titles that
// hold hostile names draw, and bad input exits 2.
#include <gtest/gtest.h>

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "cli/cli_run.hpp"
#include "cli/mat_fixture.hpp"

namespace fs = std::filesystem;
using hapstab_test::json_of;
using hapstab_test::run_cli;

namespace {

fs::path tmp(const std::string& name) { return hapstab_test::temp_path("plot", name); }

bool nonempty(const fs::path& p) { return fs::exists(p) && fs::file_size(p) > 100; }

const std::string wall = "--T 1/1000 --H \"K + B*(z-1)/(T*z)\" --set K=1000 --set B=5 --delay 1";

}  // namespace

TEST(CmdPlot, NyquistMarksTheBoundOfHapstabBound) {
  const auto out = tmp("nyq");
  const auto j = json_of("plot nyquist --json --format png,svg " + wall + " --out " + out.string());
  const auto b = json_of("bound --json " + wall);
  ASSERT_FALSE(j.is_null());
  EXPECT_EQ(j["bound"], b["bound"]);
  EXPECT_EQ(j["omega"], b["omega"]);
  EXPECT_EQ(j["status"], b["status"]);
  EXPECT_TRUE(nonempty(out / "figures" / "nyquist.png"));
  EXPECT_TRUE(nonempty(out / "figures" / "nyquist.svg"));
  EXPECT_FALSE(j["clip_omega"].is_null()) << "H(1) = K != 0: Im G -> inf as w -> 0";
  // the title shows the parameter values the expression was drawn at (the labels reach gnuplot
  // as -e values, not as a file: docs/security.md; the drawn SVG holds the title's text)
  std::stringstream svg;
  svg << std::ifstream(out / "figures" / "nyquist.svg").rdbuf();
  EXPECT_NE(svg.str().find("H = K + B*(z-1)/(T*z), K = 1000, B = 5, T = 0.001 s, n = 1"), std::string::npos);
  // the curve's largest real part is b* (to the plot's double evaluation), the mark sits on it
  std::ifstream d(out / "data" / "nyquist.dat");
  std::string line;
  double max_re = -1e300, mark_re = 0;
  int index = 0;
  bool blank = false;
  while (std::getline(d, line)) {
    if (line.empty()) {
      if (!blank) ++index;
      blank = true;
      continue;
    }
    blank = false;
    if (line[0] == '#') continue;
    std::stringstream ss(line);
    double a, w, re;
    if (index == 0 && (ss >> a >> w >> re)) max_re = std::max(max_re, re);
    if (index == 1 && (ss >> a)) mark_re = a;
  }
  const double bstar = std::stod(b["bound"].get<std::string>());
  EXPECT_NEAR(mark_re, bstar, 1e-12 * bstar);
  EXPECT_NEAR(max_re, bstar, 1e-6 * bstar);
  EXPECT_LE(max_re, bstar * (1 + 1e-12));
}

TEST(CmdPlot, BodeAndTheWedgeInPaperFormats) {
  const auto out = tmp("bode");
  const auto j = json_of("plot bode --json --format pdf,tex --num \"0.3 0.3\" --den \"1 -0.5 0.1\" --T 1/1000 --out " + out.string());
  EXPECT_TRUE(nonempty(out / "figures" / "bode.pdf"));
  EXPECT_TRUE(nonempty(out / "figures" / "tex" / "bode.tex"));
  EXPECT_TRUE(j["clip_omega"].is_null());
  const auto w = json_of("plot nyquist --json --wedge --name mine --H \"0.3*(z+1)/(z^2-0.5*z+0.1)\" --T 1/1000 --out " + out.string());
  EXPECT_TRUE(nonempty(out / "figures" / "mine.png"));
  EXPECT_TRUE(nonempty(out / "figures" / "mine_wedge.png"));
  EXPECT_EQ(w["figures"].size(), 2u);
}

// --wedge draws the loop gain k*H at the wedge gain, as contact_nyquist does: the wedges' apex is
// -1, a criterion on k H (issue 31: it drew H, thousands across, against them). H = 0.9 (z+1)/
// (z^2 - z/2) has k*_wedge = 10/9 (`hapstab wedge`), so the curve starts at k* H(1) = 10/9 * 3.6 = 4.
TEST(CmdPlot, WedgeDrawsTheLoopGainAtTheWedgeGain) {
  const auto out = tmp("wedge");
  json_of("plot nyquist --json --wedge --format png,svg --H \"0.9*(z+1)/(z^2-0.5*z)\" --T 1/1000 --out " + out.string());
  std::ifstream d(out / "data" / "nyquist_wedge.dat");
  std::string line, header;
  double re = 0, im = 1, theta = 1;
  while (std::getline(d, line)) {
    if (line.rfind("# index 0:", 0) == 0) header = line;
    if (!line.empty() && line[0] != '#') {
      std::stringstream(line) >> re >> im >> theta;
      break;
    }
  }
  EXPECT_NE(header.find("k H(e^{j theta})"), std::string::npos) << header;
  EXPECT_NE(header.find("(k*_wedge)"), std::string::npos) << header;
  EXPECT_EQ(theta, 0.0);
  EXPECT_NEAR(re, 4.0, 1e-12);  // k*_wedge to 17 digits times H(1) in double
  EXPECT_NEAR(im, 0.0, 1e-12);
  // the legend and axes name the curve k*H (the drawn SVG's text)
  std::stringstream svg;
  svg << std::ifstream(out / "figures" / "nyquist_wedge.svg").rdbuf();
  EXPECT_NE(svg.str().find("k*H at the wedge"), std::string::npos);
}

TEST(CmdPlot, HostileNamesInTitlesDraw) {
  // the --mat file name reaches the title: quotes, backslashes, LaTeX and gnuplot syntax
  const auto dir = tmp("hostile");
  fs::create_directories(dir);
  const fs::path f = dir / "a'b\"c\\$x`id`@m{}%_^.mat";
  hapstab_test::write_mat_file(f, {hapstab_test::mat_double("num", 1, 2, {1, -0.5}), hapstab_test::mat_double("den", 1, 2, {1, -0.25})});
  std::string quoted = "'";
  for (char c : f.string()) quoted += c == '\'' ? std::string("'\\''") : std::string(1, c);
  quoted += "'";
  const auto r = run_cli("plot nyquist --format png,tex --T 1/100 --mat " + quoted + " --out " + (dir / "out").string());
  EXPECT_EQ(r.code, 0) << r.out;
  EXPECT_TRUE(nonempty(dir / "out" / "figures" / "nyquist.png"));
  EXPECT_TRUE(nonempty(dir / "out" / "figures" / "tex" / "nyquist.tex"));
}

TEST(CmdPlot, BadInputExits2) {
  const auto out = tmp("bad").string();
  auto bad = [&](const std::string& args, const std::string& says) {
    const auto r = run_cli(args);
    EXPECT_EQ(r.code, 2) << args << "\n" << r.out;
    EXPECT_NE(r.out.find(says), std::string::npos) << args << "\n" << r.out;
  };
  bad("plot polar " + wall + " --out " + out, "expected nyquist or bode");
  bad("plot bode --wedge " + wall + " --out " + out, "--wedge: only with plot nyquist");
  bad("plot bode --format gif " + wall + " --out " + out, "--format");
  bad("plot bode --name ../x " + wall + " --out " + out, "--name");
  bad("plot nyquist --T 1/1000 --H \"1/(z-2)\" --out " + out, "unstable");
  bad("plot nyquist --T 1/1000 --out " + out, "--H is required");
}
