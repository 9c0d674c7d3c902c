// Tests of `hapstab sweep`: a whole run = shards + merge = a run killed (SIGKILL) and resumed,
// byte for byte, whatever --jobs; sampled rows equal single `hapstab bound` runs; a failing
// point is a row with its error (exit 1); merge names missing and duplicate points and refuses
// shards of different specs; bad specs exit 2 naming the key; the Slurm scripts and the map.
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>

#include "cli/cli_run.hpp"
#include "cli/sweep_cli.hpp"

namespace fs = std::filesystem;
using hapstab_test::run_cli;

namespace {

fs::path unique_dir(const std::string& tag) {
  std::string t = (fs::temp_directory_path() / ("hapstab-sweep-" + tag + "-XXXXXX")).string();
  EXPECT_NE(::mkdtemp(t.data()), nullptr);
  return t;
}

std::string read(const fs::path& p) {
  std::ifstream f(p, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(f), {});
}

void write(const fs::path& p, const std::string& s) { std::ofstream(p, std::ios::binary) << s; }

// The delayed backward-difference wall over an exact (K, B) grid.
std::string wall_spec(int k_points, int b_points) {
  return "command = \"bound\"\n[args]\nH = \"K + B*(z-1)/(T*z)\"\nT = \"1/1000\"\ndelay = 1\ndigits = 30\n[axes]\n"
         "K = { from = \"0\", to = \"30000\", points = " + std::to_string(k_points) + " }\n"
         "B = { from = \"0\", to = \"20\", points = " + std::to_string(b_points) + " }\n";
}

std::vector<std::vector<std::string>> csv_rows(const fs::path& p) {  // fields without quotes (none here)
  std::vector<std::vector<std::string>> rows;
  std::istringstream in(read(p));
  for (std::string line; std::getline(in, line);) {
    std::vector<std::string> f;
    std::string cell;
    bool q = false;
    for (char c : line) {
      if (c == '"') q = !q;
      else if (c == ',' && !q) f.push_back(cell), cell.clear();
      else cell += c;
    }
    f.push_back(cell);
    rows.push_back(f);
  }
  return rows;
}

size_t column(const std::vector<std::string>& head, const std::string& name) {
  for (size_t k = 0; k < head.size(); ++k)
    if (head[k] == name) return k;
  ADD_FAILURE() << "no column " << name;
  return 0;
}

/// A command run by the shell (not hapstab): its exit code.
int shell(const std::string& cmd) {
  const int st = std::system((cmd + " >/dev/null 2>&1").c_str());
  return WIFEXITED(st) ? WEXITSTATUS(st) : -1;
}

size_t checkpoint_lines(const fs::path& dir) {
  size_t n = 0;
  std::error_code ec;
  for (const auto& e : fs::directory_iterator(dir / "checkpoints", ec)) {
    const std::string s = read(e.path());
    n += static_cast<size_t>(std::count(s.begin(), s.end(), '\n'));
  }
  return n;
}

}  // namespace

TEST(Sweep, ShardsMergeAndJobsGiveTheSameBytes) {
  const fs::path d = unique_dir("shards");
  write(d / "spec.toml", wall_spec(6, 5));
  const std::string spec = (d / "spec.toml").string();
  auto r = run_cli("sweep " + spec + " --out " + (d / "whole").string() + " --jobs 1 --quiet");
  ASSERT_EQ(r.code, 0) << r.out;
  r = run_cli("sweep " + spec + " --out " + (d / "jobs3").string() + " --jobs 3 --quiet");
  ASSERT_EQ(r.code, 0) << r.out;
  for (int k = 0; k < 4; ++k) {
    r = run_cli("sweep " + spec + " --out " + (d / ("s" + std::to_string(k))).string() + " --shard " +
                std::to_string(k) + "/4 --jobs 2 --quiet");
    ASSERT_EQ(r.code, 0) << r.out;
  }
  // Shards given in any order.
  r = run_cli("sweep merge " + (d / "s2").string() + " " + (d / "s0").string() + " " + (d / "s3").string() + " " +
              (d / "s1").string() + " --out " + (d / "merged").string() + " --quiet");
  ASSERT_EQ(r.code, 0) << r.out;
  const std::string whole = read(d / "whole" / "points.csv");
  EXPECT_EQ(csv_rows(d / "whole" / "points.csv").size(), 31u);
  EXPECT_EQ(whole, read(d / "jobs3" / "points.csv"));
  EXPECT_EQ(whole, read(d / "merged" / "points.csv"));
  EXPECT_EQ(read(d / "whole" / "results.txt"), read(d / "merged" / "results.txt"));
  const auto m = nlohmann::json::parse(read(d / "s1" / "manifest.json"));
  EXPECT_EQ(m["shard"], "1/4");
  EXPECT_EQ(m["points"]["here"], 8);  // indices 1, 5, ..., 29 of 0..29
  EXPECT_EQ(m["spec_sha256"].get<std::string>().size(), 64u);
  EXPECT_FALSE(fs::exists(d / "whole" / "checkpoints"));
  fs::remove_all(d);
}

TEST(Sweep, KilledRunResumesToTheSameBytes) {
  const fs::path d = unique_dir("resume");
  write(d / "spec.toml", wall_spec(30, 30));
  const std::string spec = (d / "spec.toml").string();
  ASSERT_EQ(run_cli("sweep " + spec + " --out " + (d / "whole").string() + " --jobs 2 --quiet").code, 0);

  // The kill comes from the sweep itself at a known point (run.cpp's test hook): worker 0 kills
  // the process group once its first 40 records are written and synced. No clock, no race.
  const pid_t pid = ::fork();
  ASSERT_GE(pid, 0);
  if (pid == 0) {
    ::setpgid(0, 0);  // the workers join this group: the hook's kill stops them all, not the test
    ::setenv("HAPSTAB_TEST_SWEEP_KILL_AFTER", "40", 1);
    const std::string out = (d / "killed").string();
    ::execl(HAPSTAB_CLI, HAPSTAB_CLI, "sweep", spec.c_str(), "--out", out.c_str(), "--jobs", "2", "--quiet",
            static_cast<char*>(nullptr));
    ::_exit(127);
  }
  ::setpgid(pid, pid);
  int status = 0;
  ASSERT_EQ(::waitpid(pid, &status, 0), pid);
  ASSERT_TRUE(WIFSIGNALED(status)) << "the sweep was not killed (exit " << WEXITSTATUS(status) << ")";
  EXPECT_EQ(WTERMSIG(status), SIGKILL);
  ASSERT_FALSE(fs::exists(d / "killed" / "points.csv"));
  const size_t kept = checkpoint_lines(d / "killed");
  EXPECT_GE(kept, 40u);   // worker 0's 40, synced before the kill
  EXPECT_LT(kept, 900u);  // worker 0 had 410 of its points left
  // A torn last write, as a kill in the middle of write(2) would leave it.
  write(d / "killed" / "checkpoints" / "part-torn.txt", "899 {\"exit\":0,\"json\":{\"bou");

  auto r = run_cli("sweep " + spec + " --out " + (d / "killed").string() + " --quiet");
  EXPECT_EQ(r.code, 2) << r.out;  // without --resume a started folder is refused
  EXPECT_NE(r.out.find("--resume"), std::string::npos);
  r = run_cli("sweep " + spec + " --out " + (d / "killed").string() + " --resume --jobs 2");
  ASSERT_EQ(r.code, 0) << r.out;
  EXPECT_NE(r.out.find("(" + std::to_string(900 - kept) + " run now)"), std::string::npos) << r.out;
  EXPECT_EQ(read(d / "whole" / "points.csv"), read(d / "killed" / "points.csv"));
  // Resuming a finished folder redoes nothing and writes the same bytes.
  r = run_cli("sweep " + spec + " --out " + (d / "killed").string() + " --resume");
  EXPECT_NE(r.out.find("(0 run now)"), std::string::npos) << r.out;
  EXPECT_EQ(read(d / "whole" / "points.csv"), read(d / "killed" / "points.csv"));
  // --resume with another spec is refused.
  write(d / "other.toml", wall_spec(30, 31));
  r = run_cli("sweep " + (d / "other.toml").string() + " --out " + (d / "killed").string() + " --resume");
  EXPECT_EQ(r.code, 2) << r.out;
  fs::remove_all(d);
}

TEST(Sweep, SampledRowsEqualSingleBoundRuns) {
  const fs::path d = unique_dir("sample");
  write(d / "spec.toml", wall_spec(4, 3));
  ASSERT_EQ(run_cli("sweep " + (d / "spec.toml").string() + " --out " + d.string() + "/o --quiet").code, 0);
  const auto rows = csv_rows(d / "o" / "points.csv");
  const auto& head = rows[0];
  for (size_t i : {2u, 7u, 11u}) {
    const auto& row = rows[i + 1];
    ASSERT_EQ(row[0], std::to_string(i));
    const auto r = run_cli("bound --H \"K + B*(z-1)/(T*z)\" --T 1/1000 --delay 1 --digits 30 --json --set K=" +
                           row[column(head, "K")] + " --set B=" + row[column(head, "B")]);
    ASSERT_EQ(r.code, 0) << r.out;
    const auto j = nlohmann::json::parse(r.out);
    EXPECT_EQ(j["bound"], row[column(head, "bound")]);
    EXPECT_EQ(j["enclosure"][0], row[column(head, "enclosure_lo")]);
    EXPECT_EQ(j["enclosure"][1], row[column(head, "enclosure_hi")]);
    EXPECT_EQ(j["status"], row[column(head, "status")]);
  }
  EXPECT_EQ(rows[3][column(head, "K")], "0");
  EXPECT_EQ(rows[4][column(head, "K")], "10000");  // exact grid values as decimals
  fs::remove_all(d);
}

TEST(Sweep, FailingPointIsARowNotTheEnd) {
  const fs::path d = unique_dir("fail");
  write(d / "spec.toml",
        "command = \"bound\"\n[args]\nH = \"K + 1/(z-c)\"\nT = \"1/1000\"\n[axes]\nK = { values = [\"1\"] }\n"
        "c = { values = [\"1/2\", \"2\", \"-1/4\"] }\n");
  const auto r = run_cli("sweep " + (d / "spec.toml").string() + " --out " + d.string() + "/o --quiet");
  EXPECT_EQ(r.code, 1) << r.out;
  const auto rows = csv_rows(d / "o" / "points.csv");
  ASSERT_EQ(rows.size(), 4u);
  const size_t err = column(rows[0], "error"), bound = column(rows[0], "bound");
  EXPECT_EQ(rows[1][err], "");
  EXPECT_NE(rows[2][err].find("unstable"), std::string::npos) << rows[2][err];
  // the cell is the message: its column is named "error" and exit 2 says bad input (issue 31: the
  // rows read "error: error: ...")
  EXPECT_EQ(rows[2][err].rfind("H is unstable", 0), 0u) << rows[2][err];
  EXPECT_EQ(rows[2][column(rows[0], "exit")], "2");
  EXPECT_EQ(rows[2][bound], "");
  EXPECT_EQ(rows[3][err], "");
  EXPECT_NE(rows[3][bound], "");
  EXPECT_EQ(nlohmann::json::parse(read(d / "o" / "manifest.json"))["points"]["failed"], 1);
  fs::remove_all(d);
}

TEST(Sweep, MergeNamesMissingAndDuplicatePointsAndForeignSpecs) {
  const fs::path d = unique_dir("merge");
  write(d / "a.toml", wall_spec(3, 2));
  write(d / "b.toml", wall_spec(3, 3));
  for (int k = 0; k < 3; ++k)
    ASSERT_EQ(run_cli("sweep " + (d / "a.toml").string() + " --out " + d.string() + "/s" + std::to_string(k) +
                      " --shard " + std::to_string(k) + "/3 --quiet")
                  .code,
              0);
  ASSERT_EQ(run_cli("sweep " + (d / "b.toml").string() + " --out " + d.string() + "/b0 --shard 0/3 --quiet").code, 0);
  const std::string s = d.string() + "/s";
  auto r = run_cli("sweep merge " + s + "0 " + s + "2 --out " + d.string() + "/m");
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.out.find("2 points missing: 1, 4"), std::string::npos) << r.out;
  r = run_cli("sweep merge " + s + "0 " + s + "1 " + s + "2 " + s + "1 --out " + d.string() + "/m");
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.out.find("more than one shard: 1, 4"), std::string::npos) << r.out;
  r = run_cli("sweep merge " + s + "0 " + d.string() + "/b0 --out " + d.string() + "/m");
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.out.find("another spec"), std::string::npos) << r.out;
  fs::remove_all(d);
}

TEST(Sweep, BadSpecsExit2NamingTheKey) {
  const fs::path d = unique_dir("bad");
  const std::string axes = "[axes]\nK = { values = [\"1\"] }\n";
  const std::vector<std::pair<std::string, std::string>> cases{
      {"command = \"bound\"\n[args]\nH = \"K\"\nT = \"1/1000\"\nwrong = 1\n" + axes, "args.wrong"},
      {"command = \"bound\"\n[args]\ncurve = \"/etc/x\"\n" + axes, "args.curve"},
      {"command = \"bound\"\n[args]\nset = \"K=1\"\n" + axes, "args.set"},
      {"command = \"reproduce\"\n" + axes, "command"},
      {"command = \"sweep\"\n" + axes, "command"},
      {"command = \"nope\"\n" + axes, "command"},
      {"command = \"bound\"\n[axes]\nK = { values = [1.5] }\n", "axes.K.values[0]"},
      {"command = \"bound\"\n[axes]\nK = { from = \"0\", to = \"1\", points = 0 }\n", "axes.K.points"}};
  for (const auto& [text, key] : cases) {
    write(d / "s.toml", text);
    const auto r = run_cli("sweep " + (d / "s.toml").string() + " --out " + d.string() + "/o --quiet");
    EXPECT_EQ(r.code, 2) << text << r.out;
    EXPECT_NE(r.out.find(key), std::string::npos) << key << ": " << r.out;
  }
  EXPECT_FALSE(fs::exists(d / "o" / "points.csv"));
  write(d / "s.toml", wall_spec(2, 2));
  const auto r = run_cli("sweep " + (d / "s.toml").string() + " --out " + d.string() + "/o --shard 4/4");
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.out.find("--shard"), std::string::npos);
  fs::remove_all(d);
}

TEST(Sweep, SlurmScriptsRunEachShardAndMerge) {
  const fs::path d = unique_dir("slurm");
  write(d / "s.toml", wall_spec(2, 2));
  const auto r = run_cli("sweep slurm " + (d / "s.toml").string() + " --shards 3 --cpus 2 --time 00:10:00 --out " +
                         d.string() + "/run");
  ASSERT_EQ(r.code, 0) << r.out;
  const std::string array = read(d / "run" / "sweep.sbatch"), merge = read(d / "run" / "merge.sbatch");
  EXPECT_NE(array.find("#SBATCH --array=0-2\n"), std::string::npos) << array;
  EXPECT_NE(array.find("#SBATCH --cpus-per-task=2\n"), std::string::npos);
  EXPECT_NE(array.find("#SBATCH --time=00:10:00\n"), std::string::npos);
  EXPECT_NE(array.find("--shard \"$SLURM_ARRAY_TASK_ID\"/3"), std::string::npos);
  EXPECT_NE(merge.find("sweep merge '" + d.string() + "/run/shards/0' '" + d.string() + "/run/shards/1' '"),
            std::string::npos)
      << merge;
  // The array script runs as written when the task id is set, as Slurm sets it.
  for (int k = 0; k < 3; ++k)
    EXPECT_EQ(shell("SLURM_ARRAY_TASK_ID=" + std::to_string(k) + " bash " + (d / "run" / "sweep.sbatch").string()), 0);
  ASSERT_EQ(shell("bash " + (d / "run" / "merge.sbatch").string()), 0);
  ASSERT_EQ(run_cli("sweep " + (d / "s.toml").string() + " --out " + d.string() + "/one --quiet").code, 0);
  EXPECT_EQ(read(d / "run" / "points.csv"), read(d / "one" / "points.csv"));
  EXPECT_EQ(run_cli("sweep slurm " + (d / "s.toml").string() + " --shards 2 --partition 'a b' --out " + d.string() + "/x").code, 2);
  fs::remove_all(d);
}

TEST(Sweep, PlotDrawsTheMap) {
  const fs::path d = unique_dir("plot");
  write(d / "s.toml", wall_spec(3, 3));
  ASSERT_EQ(run_cli("sweep " + (d / "s.toml").string() + " --out " + d.string() + "/o --quiet").code, 0);
  auto r = run_cli("sweep plot " + d.string() + "/o --x K --y B --z bound --format svg");
  ASSERT_EQ(r.code, 0) << r.out;
  EXPECT_NE(read(d / "o" / "figures" / "sweep_map.svg").find("certified / exact"), std::string::npos);
  EXPECT_FALSE(fs::exists(d / "o" / "plot-data"));  // the data goes to a private folder, never into DIR
  r = run_cli("sweep plot " + d.string() + "/o --x K --y B --z nothing");
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.out.find("--z 'nothing'"), std::string::npos);
  fs::remove_all(d);
}

// README's wall.toml: K linear, B listed (0, 1/2, 5, 20), a constant in [set], units in [units].
const char* const readme_wall =
    "command = \"bound\"\n[args]\nH = \"K + B*(z-1)/(T*z) + c\"\nT = \"1/1000\"\ndelay = 1\n[set]\nc = \"0\"\n[axes]\n"
    "K = { from = \"0\", to = \"40000\", points = 7 }\nB = { values = [\"0\", \"1/2\", \"5\", \"20\"] }\n"
    "[units]\nK = \"N/m\"\nB = \"N s/m\"\nbound = \"N s/m\"\n";

TEST(Sweep, PlotCellsOnUnevenAxesAndTheColourRangeCoverTheData) {
  using hapstab::cli::sweep::cell_edges;
  // B = 0, 1/2, 5, 20: each cell reaches halfway to its neighbours, the outer ones as far out
  const auto e = cell_edges({20, 0, 5, 0.5, 5}, false);
  ASSERT_EQ(e.size(), 4u);
  EXPECT_EQ(e.at(0), std::make_pair(-0.25, 0.25));
  EXPECT_EQ(e.at(0.5), std::make_pair(0.25, 2.75));
  EXPECT_EQ(e.at(5), std::make_pair(2.75, 12.5));
  EXPECT_EQ(e.at(20), std::make_pair(12.5, 27.5));
  // log: geometric halfway (1, 10, 100 -> edges 10^-0.5 .. 10^2.5)
  const auto l = cell_edges({1, 10, 100}, true);
  EXPECT_NEAR(l.at(1).first, 1 / std::sqrt(10.0), 1e-15);
  EXPECT_NEAR(l.at(10).first, std::sqrt(10.0), 1e-14);
  EXPECT_NEAR(l.at(100).second, 100 * std::sqrt(10.0), 1e-12);
  // the README map: b* from 0 (K = 0, B = 0) to 60 (K = 40000, B = 0), the colour bar exactly that;
  // B listed: four equal rows at 0..3 labelled with the values, so 0 and 1/2 stay apart
  const fs::path d = unique_dir("uneven");
  write(d / "wall.toml", readme_wall);
  ASSERT_EQ(run_cli("sweep " + (d / "wall.toml").string() + " --out " + (d / "o").string() + " --quiet").code, 0);
  const auto spec = hapstab::cli::sweep::spec_of(d / "o");
  ASSERT_TRUE(spec);
  EXPECT_EQ(spec->constants.size(), 1u);
  const auto data = hapstab::cli::sweep::read_plot_data(d / "o", "K", "B", "bound", spec, true);
  EXPECT_EQ(data.zmin, 0);
  EXPECT_EQ(data.zmax, 60);
  EXPECT_EQ(data.ytics, "(\"0\" 0, \"0.5\" 1, \"5\" 2, \"20\" 3)");
  EXPECT_TRUE(data.full_grid);
  std::set<double> ys;
  for (const auto& r : data.rows) ys.insert(r.y);
  EXPECT_EQ(ys, (std::set<double>{0, 1, 2, 3}));
  // without --y: one line per B
  const auto lines = hapstab::cli::sweep::read_plot_data(d / "o", "K", "", "bound", spec);
  EXPECT_EQ(lines.groups, (std::vector<std::string>{"B = 0", "B = 1/2", "B = 5", "B = 20"}));
  fs::remove_all(d);
}

TEST(Sweep, PlotForAPaperLabelsUnitsLevelsSizeFormatsAndLines) {
  const fs::path d = unique_dir("paper");
  write(d / "wall.toml", readme_wall);
  const std::string o = (d / "o").string();
  ASSERT_EQ(run_cli("sweep " + (d / "wall.toml").string() + " --out " + o + " --quiet").code, 0);
  // default labels: the column and its unit from [units]; --levels over the map; every format
  auto r = run_cli("sweep plot " + o + " --x K --y B --z bound --levels 10,20,40 --size 8.5,6 --format png,pdf,svg,tex");
  ASSERT_EQ(r.code, 0) << r.out;
  for (const char* f : {"sweep_map.png", "sweep_map.pdf", "sweep_map.svg", "tex/sweep_map.tex", "tex/sweep_map.pdf"})
    EXPECT_TRUE(fs::exists(d / "o" / "figures" / f)) << f;
  const std::string svg = read(d / "o" / "figures" / "sweep_map.svg");
  for (const char* t : {"K [N/m]", "B [N s/m]", "bound [N s/m]", "level lines", ">20<"}) EXPECT_NE(svg.find(t), std::string::npos) << t;
  EXPECT_NE(svg.find("width=\"669\""), std::string::npos);  // 8.5 cm = 3.35 in at 1200 px per 6 in
  EXPECT_NE(read(d / "o" / "figures" / "tex" / "sweep_map.tex").find("N/m"), std::string::npos);
  // labels given; a title; a line plot with one line per B, under its own name
  r = run_cli("sweep plot " + o + " --x K --z bound --xlabel \"stiffness K (N/m)\" --zlabel \"b* (N s/m)\" --title \"delayed wall\" "
              "--format svg --name bound_lines");
  ASSERT_EQ(r.code, 0) << r.out;
  const std::string line = read(d / "o" / "figures" / "bound_lines.svg");
  for (const char* t : {"stiffness K (N/m)", "b* (N s/m)", "delayed wall", "B = 1/2", "B = 20"}) EXPECT_NE(line.find(t), std::string::npos) << t;
  // contour lines with chosen levels
  ASSERT_EQ(run_cli("sweep plot " + o + " --x K --y B --z bound --contour --levels 3 --format svg").code, 0);
  // refused by name
  const std::vector<std::pair<std::string, std::string>> bad = {
      {"--x K --z bound --contour", "--contour needs --y"},
      {"--x B --y K --z bound --contour", "full grid"},
      {"--x K --y B --z bound --levels 1,x", "--levels"},
      {"--x K --y B --z bound --size 1,1", "--size"},
      {"--x K --y B --z bound --format gif", "--format"}};
  for (const auto& [args, says] : bad) {
    r = run_cli("sweep plot " + o + " " + args);
    EXPECT_EQ(r.code, 2) << args << "\n" << r.out;
    EXPECT_NE(r.out.find(says), std::string::npos) << args << "\n" << r.out;
  }
  fs::remove_all(d);
}

// bound --max K as a sweep column: the largest passive K over B, each row the closed form
// 2(b - B)/T of (46) exactly (b = 3/2, T = 1 ms), and a line plot of it.
TEST(Sweep, MaxGainIsAColumn) {
  const fs::path d = unique_dir("maxgain");
  write(d / "k.toml", "command = \"bound\"\n[args]\nH = \"K + B*(z-1)/(T*z)\"\nT = \"1/1000\"\nmax = \"K\"\ndamping = \"3/2\"\n"
                      "[axes]\nB = { values = [\"0\", \"1/2\", \"1\", \"2\"] }\n[units]\nB = \"N s/m\"\nmax = \"N/m\"\n");
  // B = 2: K_max = 0 (the row's exit 1, a result: the sweep exits 0)
  ASSERT_EQ(run_cli("sweep " + (d / "k.toml").string() + " --out " + (d / "o").string() + " --quiet").code, 0);
  const auto rows = csv_rows(d / "o" / "points.csv");
  ASSERT_EQ(rows.size(), 5u);
  const size_t cmax = column(rows[0], "max"), cexact = column(rows[0], "exact"), cexit = column(rows[0], "exit");
  EXPECT_EQ(rows[1][cexact], "3000");
  EXPECT_EQ(rows[2][cexact], "2000");
  EXPECT_EQ(rows[3][cexact], "1000");
  EXPECT_EQ(rows[4][cmax], "0");  // not passive at K = 0: b*(0) = B = 2 >= 3/2
  EXPECT_EQ(rows[4][cexit], "1");
  ASSERT_EQ(run_cli("sweep plot " + (d / "o").string() + " --x B --z max --format svg").code, 0);
  EXPECT_NE(read(d / "o" / "figures" / "sweep_line.svg").find("max [N/m]"), std::string::npos);
  fs::remove_all(d);
}

// The README's recipe for machines without Slurm: GNU parallel runs the shards, then merge.
TEST(Sweep, GnuParallelRecipe) {
  if (shell("command -v parallel") != 0) GTEST_SKIP() << "GNU parallel is not installed";
  const fs::path d = unique_dir("parallel");
  write(d / "spec.toml", wall_spec(4, 4));
  const std::string h = HAPSTAB_CLI, dir = d.string();
  ASSERT_EQ(shell("cd " + dir + " && parallel --halt now,fail=1 " + h +
                  " sweep spec.toml --out shard-{} --shard {}/4 --jobs 1 --quiet ::: 0 1 2 3 && " + h +
                  " sweep merge shard-0 shard-1 shard-2 shard-3 --out all --quiet"),
            0);
  ASSERT_EQ(run_cli("sweep " + dir + "/spec.toml --out " + dir + "/one --quiet").code, 0);
  EXPECT_EQ(read(d / "all" / "points.csv"), read(d / "one" / "points.csv"));
  fs::remove_all(d);
}

// The multi-DOF `stability --scene S --max NAME --conservatism` (issue 42) as a sweep command: its
// nested JSON flattens into columns (theorem5_bracket_lo, conservatism_hi, ...) that equal a single
// run's, here over the environment gain g of Sec. VI case ii with the coupling (27)/kc.
TEST(Sweep, MultiDofMaxWithConservatismRowsEqualASingleRun) {
  const fs::path d = unique_dir("conservatism");
  fs::copy_file(fs::path(HAPSTAB_SOURCE_DIR) / "examples" / "multidof_case_ii_coupling.toml", d / "coupled.toml");
  write(d / "spec.toml", "command = \"stability\"\n[args]\nscene = \"coupled.toml\"\nmax = \"kc\"\nconservatism = true\n"
                         "digits = 1\n[axes]\ng = { values = [\"1\", \"10\"] }\n");
  const auto s = run_cli("sweep " + (d / "spec.toml").string() + " --out " + d.string() + "/o --quiet");
  ASSERT_EQ(s.code, 0) << s.out;
  const auto rows = csv_rows(d / "o" / "points.csv");
  ASSERT_EQ(rows.size(), 3u);
  const auto& head = rows[0];
  const auto& row = rows[2];  // g = 10
  EXPECT_EQ(row[column(head, "g")], "10");
  const auto r = run_cli("stability --scene " + (d / "coupled.toml").string() + " --max kc --conservatism --digits 1 --json --set g=10");
  ASSERT_EQ(r.code, 0) << r.out;
  const auto j = nlohmann::json::parse(r.out);
  for (const auto& [key, col] : std::vector<std::pair<nlohmann::json, std::string>>{
           {j["change_in"][0], "change_in_lo"},
           {j["change_in"][1], "change_in_hi"},
           {j["theorem5"]["bracket"][0], "theorem5_bracket_lo"},
           {j["theorem5"]["bracket"][1], "theorem5_bracket_hi"},
           {j["conservatism"][0], "conservatism_lo"},
           {j["conservatism"][1], "conservatism_hi"}}) {
    ASSERT_TRUE(key.is_string()) << col << ": " << r.out;
    EXPECT_EQ(key.get<std::string>(), row[column(head, col)]) << col;
  }
  EXPECT_EQ(row[column(head, "path")], "bisection_on_verdicts");
  EXPECT_GE(std::stod(row[column(head, "conservatism_hi")]), 1.0);  // Theorem 5 is sufficient only
  fs::remove_all(d);
}
