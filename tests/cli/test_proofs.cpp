// tests/cli: the claim table (proofs/README.md) is compared with the claims column by column
// (`hapstab proofs --table`), and a claimed bound is accepted only from the right end of its
// enclosure and a claim over instances holds only on enough non-trivial ones (proofs/proof.hpp)
// -- issue 30.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "cli/cli_run.hpp"
#include "cli/reproduce.hpp"
#include "hapstab/numeric/scalar.hpp"
#include "proofs/proof.hpp"

namespace {

namespace fs = std::filesystem;
using hapstab::rational;
using hapstab::Status;
using hapstab::proofs::ClaimResult;

std::vector<ClaimResult> two_claims() {
  return {{"001.x.upper", "001", "(1)", "b* at most 3 | abs", Status::certified, true, "e"},
          {"001.y.identity", "001", "(2) -> (3)", "an identity [in t]", Status::exact, true, "e"}};
}

std::string table_of(const std::vector<ClaimResult>& cs) {
  std::string t = "# The claim table\n\n" + hapstab::cli::claim_table_header();
  for (const auto& c : cs) t += hapstab::cli::claim_table_row(c) + "\n";
  return t;
}

bool names(const std::vector<std::string>& msgs, const std::string& a, const std::string& b) {
  for (const auto& m : msgs)
    if (m.find(a) != std::string::npos && m.find(b) != std::string::npos) return true;
  return false;
}

}  // namespace

TEST(ProofBounds, AnUpperBoundIsProvenOnlyByTheUpperEnd) {
  using hapstab::Enclosure;
  using hapstab::proofs::proves_lower_bound;
  using hapstab::proofs::proves_upper_bound;
  const rational v(1);
  // an enclosure straddling v: neither bound is proven (the old `lo <= v` accepted it as an upper bound)
  const Enclosure<rational> straddle{rational(99, 100), rational(101, 100)};
  EXPECT_FALSE(proves_upper_bound(straddle, v));
  EXPECT_FALSE(proves_lower_bound(straddle, v));
  EXPECT_TRUE(proves_upper_bound(Enclosure<rational>{rational(1, 2), rational(1)}, v));
  EXPECT_FALSE(proves_upper_bound(Enclosure<rational>{rational(1, 2), rational(1000001, 1000000)}, v));
  EXPECT_TRUE(proves_lower_bound(Enclosure<rational>{rational(1), rational(2)}, v));
  EXPECT_FALSE(proves_lower_bound(Enclosure<rational>{rational(999999, 1000000), rational(2)}, v));
}

// A claim over instances whose premise never holds (issue 30, item 5: 002.wedge_contains_tsypkin
// could pass on 40 H none of which satisfied Tsypkin's condition) fails, and its evidence names
// the counts and the minimum; at the minimum it holds; a failed check stays failed.
TEST(ProofInstances, TooFewNonTrivialInstancesFailTheClaim) {
  using hapstab::proofs::Checker;
  using hapstab::proofs::Instances;
  auto run = [](long nontrivial, bool check_holds) {
    Instances tsypkin{"H satisfying Tsypkin's condition", 3};
    for (long i = 0; i < 40; ++i) tsypkin.count(i < nontrivial);
    Checker c("002");
    const bool holds = c.claim("002.wedge_contains_tsypkin", "(25) vs (21)", "Tsypkin => wedge", Status::exact,
                               check_holds, "0 with Tsypkin but not wedge", {tsypkin});
    EXPECT_EQ(c.results().size(), 1u);
    EXPECT_EQ(c.results()[0].holds, holds);
    return c.results()[0];
  };
  const ClaimResult none = run(0, true);  // the implication holds vacuously on every H
  EXPECT_FALSE(none.holds);
  EXPECT_EQ(none.id, "002.wedge_contains_tsypkin");
  EXPECT_NE(none.evidence.find("0 of 40 instances non-trivial (H satisfying Tsypkin's condition), minimum 3: TOO FEW"),
            std::string::npos)
      << none.evidence;
  EXPECT_FALSE(run(2, true).holds);
  const ClaimResult three = run(3, true);
  EXPECT_TRUE(three.holds);
  EXPECT_EQ(three.evidence,
            "0 with Tsypkin but not wedge; 3 of 40 instances non-trivial (H satisfying Tsypkin's condition), minimum 3");
  EXPECT_FALSE(run(40, false).holds);
  // every family must reach its minimum
  Instances a{"a", 1}, b{"b", 1};
  a.count(true);
  b.count(false);
  Checker c("001");
  EXPECT_FALSE(c.claim("001.x", "(1)", "s", Status::exact, true, "e", {a, b}));
  EXPECT_NE(c.results()[0].evidence.find("1 of 1 instances non-trivial (a), minimum 1; 0 of 1 instances non-trivial (b), "
                                         "minimum 1: TOO FEW"),
            std::string::npos)
      << c.results()[0].evidence;
}

TEST(ProofTable, EveryColumnIsCompared) {
  const auto cs = two_claims();
  const std::string good = table_of(cs);
  EXPECT_TRUE(hapstab::cli::compare_claim_table(cs, good, "").empty());
  // '|' and '[' in a cell are escaped (report/escape.hpp, markdown::cell) and read back
  EXPECT_NE(good.find("b* at most 3 \\| abs"), std::string::npos) << good;
  EXPECT_NE(good.find("an identity \\[in t\\]"), std::string::npos) << good;

  // one method cell changed: named with its claim and column
  std::string t = good;
  const std::string row = hapstab::cli::claim_table_row(cs[0]);
  std::string changed = row;
  changed.replace(changed.find("| certified |"), 13, "| exact |");
  t.replace(t.find(row), row.size(), changed);
  auto msgs = hapstab::cli::compare_claim_table(cs, t, "");
  ASSERT_EQ(msgs.size(), 1u);
  EXPECT_TRUE(names(msgs, "`001.x.upper`", "column method")) << msgs[0];

  // the verdict, the equation, the statement
  auto fails = cs;
  fails[1].holds = false;
  EXPECT_TRUE(names(hapstab::cli::compare_claim_table(fails, good, ""), "`001.y.identity`", "column verdict"));
  auto eq = cs;
  eq[1].equation = "(2)";
  EXPECT_TRUE(names(hapstab::cli::compare_claim_table(eq, good, ""), "`001.y.identity`", "column equation"));
  auto st = cs;
  st[0].statement = "b* at most 4";
  EXPECT_TRUE(names(hapstab::cli::compare_claim_table(st, good, ""), "`001.x.upper`", "column statement"));

  // a claim without a row; a row without a claim (only for the papers run)
  auto more = cs;
  more.push_back({"002.z.new", "002", "(9)", "s", Status::numeric, true, "e"});
  EXPECT_TRUE(names(hapstab::cli::compare_claim_table(more, good, ""), "`002.z.new`", "no row"));
  const std::vector<ClaimResult> first{cs[0]};
  EXPECT_TRUE(names(hapstab::cli::compare_claim_table(first, good, ""), "`001.y.identity`", "no such claim"));
  EXPECT_TRUE(hapstab::cli::compare_claim_table(first, good, "002").empty());
}

// End to end: `hapstab proofs --only ext --table T` with one method cell of the real table
// changed exits 1 and names the claim and the column.
TEST(ProofTable, CommandFailsOnAChangedMethodCell) {
  std::ifstream in(fs::path(HAPSTAB_SOURCE_DIR) / "proofs" / "README.md");
  std::string table((std::istreambuf_iterator<char>(in)), {});
  const std::string key = "| `ext.friction.spring_damper` |";
  const size_t at = table.find(key);
  ASSERT_NE(at, std::string::npos);
  const size_t end = table.find('\n', at);
  const size_t m = table.rfind("| exact |", end);
  ASSERT_TRUE(m != std::string::npos && m > at);
  table.replace(m, 9, "| numeric |");
  const fs::path f = fs::path(::testing::TempDir()) / "claim_table_changed.md";
  {
    std::ofstream out(f);
    out << table;
  }
  const auto r = hapstab_test::run_cli("proofs --quiet --only ext --table " + f.string());
  EXPECT_EQ(r.code, 1) << r.out;
  EXPECT_NE(r.out.find("claim `ext.friction.spring_damper`: column method: the table says 'numeric', the claim 'exact'"),
            std::string::npos)
      << r.out;
}

// `hapstab proofs > file` keeps the layout README shows: each "[proof k/N]" header on stdout with
// its claims (stderr is left out here), and a statement with "<" reads as written in report.md.
TEST(ProofOutput, HeadersAndClaimsOnStdoutAndReadableCells) {
  const std::string cmd = std::string(HAPSTAB_CLI) + " proofs --only 001 2>/dev/null";
  FILE* p = popen(cmd.c_str(), "r");
  ASSERT_NE(p, nullptr);
  std::string out;
  char buf[4096];
  for (size_t n; (n = fread(buf, 1, sizeof buf, p)) > 0;) out.append(buf, n);
  pclose(p);
  const size_t header = out.find("[proof 1/"), claim = out.find("  holds  001.");
  ASSERT_NE(header, std::string::npos) << out.substr(0, 400);
  ASSERT_NE(claim, std::string::npos);
  EXPECT_LT(header, claim);  // the header precedes its claims, in one stream
  ClaimResult c{"001.x", "001", "(1)", "b* < b when K <= 2(b - B)/T", Status::exact, true, "e"};
  EXPECT_NE(hapstab::cli::claim_table_row(c).find("b* < b when K <= 2(b - B)/T"), std::string::npos);
}
