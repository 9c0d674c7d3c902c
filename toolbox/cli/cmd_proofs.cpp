// `hapstab proofs` runs every checked derivation in proofs/ and prints the claim table;
// `hapstab reproduce` is the main job: it runs them and writes DIR/report.md.
#include <chrono>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>
#include <set>
#include <sstream>

#include "cli/command.hpp"
#include "hapstab/numeric/error.hpp"
#include "proofs/proof.hpp"

namespace hapstab::cli {
namespace {

namespace fs = std::filesystem;
using proofs::ClaimResult;

const char* paper_title(const std::string& p) {
  if (p == "000") return "Bianchini, Orlandesi, Prattichizzo: An LMI framework for multi-dimensional haptic systems";
  if (p == "001") return "Roberts, Moore, Colgate: A new expression for the passivity bound";
  if (p == "002") return "Tsai, Colgate: Stability of discrete time systems with unilateral nonlinearities";
  return "other";
}

std::vector<ClaimResult> run_all(const std::string& only, bool quiet, double& seconds) {
  std::vector<ClaimResult> all;
  auto t0 = std::chrono::steady_clock::now();
  const auto& reg = proofs::registry();
  size_t i = 0;
  for (const auto& p : reg) {
    ++i;
    if (!only.empty() && only != p.paper) continue;
    proofs::Checker check(p.paper);
    auto s0 = std::chrono::steady_clock::now();
    try {
      p.run(check);
    } catch (const std::exception& e) {
      check.claim(std::string(p.paper) + "." + p.id + ".completes", "-", std::string("proof ran to the end: ") + p.title,
                  proofs::Method::exact, false, std::string("threw: ") + e.what());
    }
    double dt = std::chrono::duration<double>(std::chrono::steady_clock::now() - s0).count();
    if (!quiet) {
      std::cerr << "[" << i << "/" << reg.size() << "] " << p.paper << " " << p.id << " (" << check.results().size()
                << " claims, " << dt << " s)\n";
      for (const auto& c : check.results())
        std::cout << (c.holds ? "  holds  " : "  FAILS  ") << c.id << "  " << c.equation << "  ["
                  << proofs::to_string(c.method) << "]  " << c.evidence << "\n";
    }
    all.insert(all.end(), check.results().begin(), check.results().end());
  }
  seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return all;
}

std::string md_escape(std::string s) {
  std::string o;
  for (char c : s) {
    if (c == '|') o += "\\|";
    else if (c == '\n') o += ' ';
    else o += c;
  }
  return o;
}

void write_report(const std::vector<ClaimResult>& claims, const fs::path& dir, double seconds) {
  fs::create_directories(dir);
  std::ofstream md(dir / "report.md");
  if (!md) throw InputError("--out: cannot write " + (dir / "report.md").string());
  size_t fails = 0;
  for (const auto& c : claims) fails += !c.holds;
  md << "# hapstab reproduction report\n\n"
     << claims.size() << " claims checked in " << seconds << " s; " << (claims.size() - fails) << " hold, " << fails
     << " fail.\n\nStatus: `exact` = proven in rational arithmetic; `certified` = proven by an enclosure; "
        "`numeric` = floating-point evidence with the stated error.\n";
  for (std::string paper : {"001", "002", "000"}) {
    bool any = false;
    for (const auto& c : claims) any |= c.paper == paper;
    if (!any) continue;
    md << "\n## Paper " << paper << ": " << paper_title(paper) << "\n\n"
       << "| claim | equation | statement | method | verdict | evidence |\n|---|---|---|---|---|---|\n";
    for (const auto& c : claims)
      if (c.paper == paper)
        md << "| `" << c.id << "` | " << md_escape(c.equation) << " | " << md_escape(c.statement) << " | "
           << proofs::to_string(c.method) << " | " << (c.holds ? "holds" : "**FAILS**") << " | "
           << md_escape(c.evidence) << " |\n";
  }
}

// Every claim id must stand in the claim table (proofs/README.md) in backquotes.
int check_table(const std::vector<ClaimResult>& claims, const std::string& table) {
  std::ifstream in(table);
  if (!in) throw InputError("--table: cannot read '" + table + "'");
  std::stringstream ss;
  ss << in.rdbuf();
  const std::string text = ss.str();
  int missing = 0;
  for (const auto& c : claims)
    if (text.find("`" + c.id + "`") == std::string::npos) {
      std::cerr << "hapstab proofs: claim `" << c.id << "` has no row in " << table << "\n";
      ++missing;
    }
  return missing;
}

struct Opts {
  std::string only, out, table;
  bool quiet = false, json = false;
};

int run(const Opts& o, bool reproduce) {
  static const std::set<std::string> papers{"", "000", "001", "002"};
  if (!papers.count(o.only)) throw InputError("--only: unknown paper '" + o.only + "' (expected 000, 001 or 002)");
  double seconds = 0;
  auto claims = run_all(o.only, o.quiet || o.json, seconds);
  size_t fails = 0;
  for (const auto& c : claims) fails += !c.holds;
  if (reproduce || !o.out.empty()) write_report(claims, o.out.empty() ? "out" : o.out, seconds);
  int missing = o.table.empty() ? 0 : check_table(claims, o.table);
  if (o.json) {
    nlohmann::json j = nlohmann::json::array();
    for (const auto& c : claims)
      j.push_back({{"id", c.id},
                   {"paper", c.paper},
                   {"equation", c.equation},
                   {"statement", c.statement},
                   {"method", proofs::to_string(c.method)},
                   {"holds", c.holds},
                   {"evidence", c.evidence}});
    print_json(j);
  } else {
    std::cout << claims.size() - fails << " passed, " << fails << " failed\n";
    if (reproduce || !o.out.empty())
      std::cout << "report: " << (fs::path(o.out.empty() ? "out" : o.out) / "report.md").string() << "\n";
  }
  return (fails || missing) ? exit_property_fails : exit_ok;
}

Runner setup(CLI::App& app, bool reproduce) {
  auto o = std::make_shared<Opts>();
  app.add_option("--only", o->only, "Only this paper: 000, 001 or 002");
  app.add_option("--out", o->out, reproduce ? "Output folder (default: out)" : "Also write DIR/report.md");
  app.add_flag("--quiet", o->quiet, "Print only the summary line");
  if (!reproduce) {
    app.add_flag("--json", o->json, "Print the claims as JSON");
    app.add_option("--table", o->table, "Fail unless every claim id has a row in this claim table (proofs/README.md)");
  }
  return [o, reproduce]() { return run(*o, reproduce); };
}

const Register proofs_cmd({"proofs", "Run every checked derivation (proofs/) and print the claim verdicts",
                           [](CLI::App& app) { return setup(app, false); }});
const Register reproduce_cmd({"reproduce",
                              "The main job: run every proof and write DIR/report.md (one section per paper)",
                              [](CLI::App& app) { return setup(app, true); }});

}  // namespace
}  // namespace hapstab::cli
