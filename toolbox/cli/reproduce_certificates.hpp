// cli/reproduce_certificates.hpp -- the certificates `hapstab reproduce` writes and checks (issue 47
// item 4, docs/certificates.md "In reproduce"). For every instance of a claim that a proof asks for
// (proofs/proof.hpp, CertificateRequest) the certificate is what its command writes with
// --certificate, run in this process through cli::run_in_process (the command's own code, as
// `hapstab sweep` runs it), into DIR/certificates/<claim-id>.json (<claim-id>.<k>.json when the
// claim has several instances); reproduce then checks that the certificate's claim is the claim's
// (CertificateRequest's expectations). Each certificate is then checked by both checkers, in
// processes of their own (neither shares state with the producer):
//   - `hapstab check --batch LIST` (this binary), each certificate's file one line of LIST, with
//     each check's own time: one process per certificate (`hapstab check FILE`) cost 100 times as
//     much, all of it the process's start-up;
//   - the independent checker `python3 checks/hapstab_check.py --files FILE...` (when python3 and
//     the script are present; exit 3 = not checked beyond its size limit, counted apart).
// Each checker runs as two processes on halves of the certificates, on two workers (the machine's
// 2 cores); the results keep the certificates' order.
// DIR/certificates/index.json records each certificate's size, production and check times.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "cli/scenes.hpp"
#include "proofs/proof.hpp"

namespace hapstab::cli {

/// One checker's verdict on one certificate.
struct CertificateCheck {
  int exit = -1;        ///< 0 verified, 1 refuted, 2 malformed, 3 not checked (the independent checker's size limit); -1 not run
  std::string reason;   ///< what it printed (the reason of a refutation, ...)
  double seconds = 0;   ///< the check itself (without its process's start-up), as the checker measured it
};

struct CertificateEntry {
  std::string claim;    ///< the claim's id
  std::string file;     ///< relative to the report folder: "certificates/<claim-id>.json"
  std::string command;  ///< the command that wrote it, as a user types it ("hapstab bound --H ...")
  std::string kind;     ///< the certificate's `kind` ("" when none was written)
  std::string error;    ///< why it was not written, or why it is not the claim's ("" when it is)
  std::uintmax_t bytes = 0;
  double produce_seconds = 0;  ///< the command run in this process, the certificate written
  CertificateCheck hapstab, independent;
  std::string failure;  ///< set by check_certificates: why it fails ("" when it is verified, or only beyond the size limit)
};

/// The counts of the report's and the console's certificate line.
struct CertificateSummary {
  size_t total = 0, verified = 0, independent_verified = 0, beyond_limit = 0;
  size_t failed = 0;                ///< not written, not the claim's, refuted or malformed by either checker
  bool independent_ran = false;
  std::string independent_missing;  ///< why the independent checker did not run ("" when it ran)
  double produce_seconds = 0, check_seconds = 0, independent_seconds = 0, wall_seconds = 0;
  std::vector<std::string> failures;  ///< "certificates/<file>: <what failed>"
};

/// Writes the certificates every claim of `claims` asks for into dir/certificates/ (emptied of
/// *.json first), in the claims' order; their count on stderr unless quiet.
std::vector<CertificateEntry> produce_certificates(const std::vector<proofs::ClaimResult>& claims,
                                                   const std::filesystem::path& dir, bool quiet);

/// The certificates of the example scenes' `multidof analyze` and `multidof design` runs (issue 47
/// items 1, 4): for each such run of `runs`, `hapstab multidof analyze|design --scene examples/F
/// --certificate dir/certificates/scene.<stem>[.design].json` in this process (claim =
/// scene_claim_id), its certificate's claim required to be the verdict the command printed (analyze:
/// claim.feasible; design: claim.theorem4 beside a printed, verified V). A verdict of no certificate
/// kind writes none: the refusal goes to the run's no_certificate, for the report's row. Call after
/// run_scenes and before check_certificates.
std::vector<CertificateEntry> produce_scene_certificates(std::vector<SceneRun>& runs, const std::filesystem::path& dir);
/// A scene run's claim id in the certificate index: "examples/F", with " (design)" for design's run.
std::string scene_claim_id(const SceneRun& r);

/// The certificates dir/certificates/*.json as entries (sorted by file; claim = the file's stem,
/// kind as written): what check_certificates checks of a folder written before, or edited.
std::vector<CertificateEntry> certificates_in_folder(const std::filesystem::path& dir);

/// Checks every written entry (dir/<entry.file>) with both checkers and counts them; `hapstab` is
/// the binary that runs `check` (empty: this one). Each failure on stderr unless quiet.
CertificateSummary check_certificates(std::vector<CertificateEntry>& entries, const std::filesystem::path& dir,
                                      bool quiet, const std::filesystem::path& hapstab = {});

/// dir/certificates/index.json: every entry (file, claim, command, kind, bytes, production and
/// check times, both verdicts) and the summary.
void write_certificate_index(const std::vector<CertificateEntry>& entries, const CertificateSummary& s,
                             const std::filesystem::path& dir);

/// "N certificates, N verified by `hapstab check`, M by the independent checker (K beyond its size
/// limit)" (`code` false: without the backquotes), with the independent checker's absence or the
/// failures appended when there are any.
std::string certificate_counts(const CertificateSummary& s, bool code = true);

}  // namespace hapstab::cli
