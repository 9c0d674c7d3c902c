// cli/cmd_check.cpp -- `hapstab check FILE`: verifies a certificate written by --certificate
// (issue 47) with the checkers of check/, which never call the code that produced it.
//   hapstab check c.json           prints "verified" (exit 0), "refuted: <what failed>" (exit 1);
//                                  a malformed certificate is an error naming the field (exit 2)
//   hapstab check --explain c.json also says what was verified
//   hapstab check --batch FILE     one certificate (JSON) per line; one JSON line each:
//                                  {"line", "verdict": "verified|refuted|malformed", "exit", "reason",
//                                   "seconds": the check's own time}
// docs/certificates.md has the format and each checker's theorem.
#include <algorithm>
#include <chrono>
#include <sstream>
#include <iostream>
#include <memory>

#include "cli/command.hpp"
#include "hapstab/check/certificate.hpp"
#include "hapstab/numeric/error.hpp"
#include "hapstab/report/paths.hpp"

namespace hapstab::cli::cmd_check {  // its own namespace: the commands compile in unity batches
namespace {

struct Opts {
  std::string file, batch;
  bool explain = false;
};

int run_batch(const std::string& file) {
  // a regular file of at most 256 MB (not /dev/zero or a FIFO), as bound --batch reads its file
  std::istringstream in(report::read_input_file(file, "--batch", 256u << 20));
  std::string line;
  int worst = 0, lineno = 0;
  while (std::getline(in, line)) {
    ++lineno;
    if (line.find_first_not_of(" \t\r") == std::string::npos) continue;
    nlohmann::json out;
    const auto t0 = std::chrono::steady_clock::now();
    try {
      nlohmann::json c;
      try {
        c = nlohmann::json::parse(line);
      } catch (const nlohmann::json::exception& e) {
        throw InputError(std::string("not JSON (") + e.what() + ")");
      }
      const check::Verdict v = check::check_certificate(c);
      out = {{"verdict", v.verified ? "verified" : "refuted"}, {"exit", v.verified ? 0 : 1}, {"reason", v.reason}};
    } catch (const std::exception& e) {
      const int code = exit_code_for(e).code;
      out = {{"verdict", code == exit_bad_input ? "malformed" : "error"}, {"exit", code}, {"reason", std::string(e.what())}};
    }
    worst = std::max(worst, out["exit"].get<int>());
    out["line"] = lineno;
    out["seconds"] = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    std::cout << out.dump() << std::endl;
  }
  return worst;
}

int run(const Opts& o) {
  if (!o.batch.empty()) {
    if (!o.file.empty()) throw InputError("give a certificate FILE or --batch FILE, not both");
    return run_batch(o.batch);
  }
  if (o.file.empty()) throw InputError("FILE is required (a certificate written by --certificate)");
  const check::Verdict v = check::check_file(o.file);
  if (v.verified) {
    std::cout << "verified" << (o.explain ? ": " + v.reason : std::string()) << "\n";
    return exit_ok;
  }
  std::cout << "refuted: " << v.reason << "\n";
  return exit_property_fails;
}

const Register reg({"check",
                    "Verify a certificate written by --certificate (any of the 18 kinds of docs/certificates.md: bound, stability, "
                    "multidof-feasible, ...) without trusting the code that produced it: exit 0 verified, 1 refuted, 2 malformed",
                    [](CLI::App& app) {
                      auto o = std::make_shared<Opts>();
                      app.add_option("FILE", o->file, "the certificate (JSON)");
                      app.add_flag("--explain", o->explain, "say what was verified, and how");
                      app.add_option("--batch", o->batch, "FILE with one certificate per line; one JSON verdict per line");
                      return [o]() { return run(*o); };
                    }});

}  // namespace
}  // namespace hapstab::cli::cmd_check
