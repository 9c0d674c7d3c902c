// `hapstab proofs`: runs every checked derivation in proofs/ and prints the claim verdicts.
#include <fstream>
#include <iostream>
#include <memory>
#include <set>

#include "cli/command.hpp"
#include "cli/reproduce.hpp"
#include "hapstab/numeric/error.hpp"

namespace hapstab::cli::cmd_proofs {  // its own namespace: the commands compile in unity batches
namespace {

struct Opts {
  std::string only, out, table;
  bool quiet = false, json = false, print_table = false;
};

int run(const Opts& o) {
  static const std::set<std::string> papers{"", "000", "001", "002", "ext"};
  if (!papers.count(o.only)) throw InputError("--only: unknown paper '" + o.only + "' (expected 000, 001, 002 or ext)");
  // Inputs and outputs are checked before the proofs run (they take a while).
  if (!o.out.empty()) output_folder(o.out, "--out");
  if (!o.table.empty() && !std::ifstream(o.table)) throw InputError("--table: cannot read '" + o.table + "'");
  double seconds = 0;
  auto claims = run_proofs(o.only, o.quiet || o.json || o.print_table, seconds);
  size_t fails = 0;
  for (const auto& c : claims) fails += !c.holds;
  if (!o.out.empty()) {
    ReportInput rep;
    rep.claims = claims;
    rep.seconds = seconds;
    write_report_md(rep, o.out);
  }
  // every claim must stand in the claim table with the row it states, each column compared
  int missing = o.table.empty() ? 0 : claim_table_differences(claims, o.table, o.only, "proofs");
  if (o.print_table) {
    std::cout << claim_table_header();
    for (const auto& c : claims) std::cout << claim_table_row(c) << "\n";
  } else if (o.json) {
    nlohmann::json j = nlohmann::json::array();
    for (const auto& c : claims)
      j.push_back({{"id", c.id},
                   {"paper", c.paper},
                   {"equation", c.equation},
                   {"statement", c.statement},
                   {"method", to_string(c.status)},
                   {"holds", c.holds},
                   {"evidence", c.evidence}});
    print_json(j);
  } else {
    std::cout << "proofs: " << claims.size() - fails << " passed, " << fails << " failed";
    if (missing) std::cout << ", " << missing << " difference" << (missing == 1 ? "" : "s") << " from " << o.table;
    std::cout << "\n";
  }
  return (fails || missing) ? exit_property_fails : exit_ok;
}

const Register reg({"proofs", "Run every checked derivation (proofs/) and print the claim verdicts", [](CLI::App& app) {
                      auto o = std::make_shared<Opts>();
                      app.add_option("--only", o->only, "Only this part: a paper (000, 001, 002) or ext (beyond the papers)");
                      app.add_option("--out", o->out, "Also write DIR/report.md");
                      app.add_flag("--quiet", o->quiet, "Print only the summary line");
                      app.add_flag("--json", o->json, "Print the claims as JSON");
                      app.add_option("--table", o->table,
                                     "Fail unless every claim has its row, every column equal, in this claim table "
                                     "(proofs/README.md); each difference is named");
                      app.add_flag("--print-table", o->print_table,
                                   "Print the claim table's rows as the claims state them (to regenerate proofs/README.md)");
                      return [o]() { return run(*o); };
                    }});

}  // namespace
}  // namespace hapstab::cli::cmd_proofs
