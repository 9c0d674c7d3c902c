// cli/reproduce.hpp -- running the proofs, and writing the report (report.md, index.html)
// that `hapstab reproduce` produces.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

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
  std::string error;     ///< why it was not drawn
  double seconds = 0;
};

struct ReportInput {
  std::vector<proofs::ClaimResult> claims;
  std::vector<FigureEntry> figures;
  std::vector<SceneRun> scenes;
  double seconds = 0;
};

/// DIR/report.md: one section per paper, each claim with its equation, status and verdict,
/// then the paper's example scenes and its figures.
void write_report_md(const ReportInput& in, const std::filesystem::path& dir);
/// DIR/index.html: the same report, static, with the PNG figures inline.
void write_index_html(const ReportInput& in, const std::filesystem::path& dir);

const char* paper_title(const std::string& paper);

}  // namespace hapstab::cli
