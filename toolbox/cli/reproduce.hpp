// cli/reproduce.hpp -- running the proofs, and writing the report (report.md, index.html)
// that `hapstab reproduce` produces: per paper the claim table (each claim linked to its
// certificates, cli/reproduce_certificates.hpp), the example scenes and the figures.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "cli/reproduce_certificates.hpp"
#include "cli/scenes.hpp"
#include "proofs/proof.hpp"

namespace hapstab::cli {

/// Runs every registered proof of `paper` ("" = all); prints per-claim lines unless quiet.
std::vector<proofs::ClaimResult> run_proofs(const std::string& paper, bool quiet, double& seconds);

/// One drawn figure of the report (files relative to the report folder).
struct FigureEntry {
  std::string name, paper, caption;
  bool ok = true;
  bool skipped = false;  ///< not reproduced on this build, not a failure (e.g. bench programs not built)
  bool matplotlib = false;  ///< drawn by a Python example (examples/python): PNG and PDF only
  std::string error{};   ///< why it was not drawn (empty when it was)
  double seconds = 0;
};

struct ReportInput {
  std::vector<proofs::ClaimResult> claims;
  std::vector<FigureEntry> figures;
  std::vector<SceneRun> scenes;
  std::vector<CertificateEntry> certificates;  ///< in the claims' order
  CertificateSummary certificate_summary;
  double seconds = 0;
};

/// The report's certificate cell of claim `c`: its certificates (links relative to the report
/// folder) and what the checkers said, or why it has none ("no certificate kind yet (issue 47)").
/// `html`: HTML, else markdown.
std::string certificate_cell(const proofs::ClaimResult& c, const std::vector<CertificateEntry>& entries, bool html);

/// DIR/report.md: one section per paper, each claim with its equation, status and verdict,
/// then the paper's example scenes and its figures.
void write_report_md(const ReportInput& in, const std::filesystem::path& dir);
/// DIR/index.html: the same report, static, with the PNG figures inline.
void write_index_html(const ReportInput& in, const std::filesystem::path& dir);

const char* paper_title(const std::string& paper);

/// The claim table (proofs/README.md): one row per claim, its cells (`id`, equation, statement,
/// method, verdict) as the claim states them, a '|' in a cell escaped as "\|".
std::vector<std::string> claim_table_cells(const proofs::ClaimResult& c);
std::string claim_table_row(const proofs::ClaimResult& c);
/// The header and separator lines of the claim table.
std::string claim_table_header();
/// Compares every claim with its row of the claim table `text`, cell by cell; one message per
/// difference, naming the claim and the column ("claim `001.eq51`: column method: the table says
/// 'numeric', the claim 'exact'"), a claim without a row, and a row of the papers `papers_run`
/// ("" = all) without a claim. Empty when they agree.
std::vector<std::string> compare_claim_table(const std::vector<proofs::ClaimResult>& claims, const std::string& text,
                                             const std::string& papers_run);
/// compare_claim_table against the file `table` (InputError when it cannot be read): prints each
/// difference on stderr as "hapstab WHO: TABLE: message" and returns their number (`proofs --table`,
/// `reproduce --table`).
int claim_table_differences(const std::vector<proofs::ClaimResult>& claims, const std::string& table,
                            const std::string& papers_run, const std::string& who);

}  // namespace hapstab::cli
