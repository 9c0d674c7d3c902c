// cli/reproduce_certificates.cpp -- see reproduce_certificates.hpp.
#include "cli/reproduce_certificates.hpp"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdlib>
#include <fstream>
#include <functional>
#include <iterator>
#include <iostream>
#include <map>
#include <optional>
#include <sstream>
#include <thread>

#include <nlohmann/json.hpp>

#include "cli/command.hpp"
#include "cli/figure.hpp"
#include "hapstab/numeric/decimal.hpp"
#include "hapstab/numeric/error.hpp"
#include "hapstab/report/process.hpp"

namespace hapstab::cli {

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

using clock_type = std::chrono::steady_clock;
double since(clock_type::time_point t0) { return std::chrono::duration<double>(clock_type::now() - t0).count(); }

// The command as a user types it: arguments with a space or a shell character in single quotes.
std::string command_text(const std::vector<std::string>& args) {
  std::string s = "hapstab";
  for (const auto& a : args) {
    const bool plain = !a.empty() && a.find_first_not_of("abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789"
                                                         "-_=./+,:") == std::string::npos;
    s += " " + (plain ? a : "'" + a + "'");
  }
  return s;
}

rational number(const json& claim, const char* key) {
  if (!claim.contains(key) || !claim[key].is_string()) throw InputError(std::string("claim.") + key + " missing");
  return parse_rational(claim[key].get<std::string>(), key);
}

// "" when the certificate's claim is the instance's (CertificateRequest), else what differs.
std::string expectation_fails(const json& c, const proofs::CertificateRequest& r) {
  if (!c.is_object() || !c.contains("claim") || !c["claim"].is_object()) return "the certificate has no claim";
  const json& claim = c["claim"];
  try {
    const bool exact = claim.contains("value");
    if (!r.contains.empty()) {
      const rational x = parse_rational(r.contains, "contains");
      if (exact ? number(claim, "value") != x : !(number(claim, "lo") <= x && x <= number(claim, "hi")))
        return "the certificate's claim " + claim.dump() + " is not the claim's value " + r.contains;
    }
    if (!r.at_most.empty()) {
      const rational x = parse_rational(r.at_most, "at_most");
      if (number(claim, exact ? "value" : "hi") > x)
        return "the certificate's claim " + claim.dump() + " is not at most the claim's bound " + r.at_most;
    }
    if (!r.at_least_value.empty()) {
      const rational x = parse_rational(r.at_least_value, "at_least_value");
      if (number(claim, exact ? "value" : "lo") < x)
        return "the certificate's claim " + claim.dump() + " is not at least the claim's bound " + r.at_least_value;
    }
  } catch (const std::exception& e) {
    return std::string("the certificate's claim cannot be compared with the claim's: ") + e.what();
  }
  for (const auto& [a, b] : r.at_least) {
    // a >= b proven: a = +inf, or b finite and a's lower end >= b's upper end
    const auto infinite = [&](const std::string& key) {
      return claim.contains(key) && claim[key].is_object() && claim[key].contains("infinite") &&
             claim[key]["infinite"] == true;
    };
    if (!claim.contains(a) || !claim.contains(b) || !claim[a].is_object() || !claim[b].is_object())
      return "the certificate's claim has no " + (claim.contains(a) ? b : a) + " to compare";
    if (infinite(a)) continue;
    try {
      if (infinite(b) || number(claim[a], "lo") < number(claim[b], "hi"))
        return "the certificate's claim does not prove " + a + " >= " + b + ": " + claim[a].dump() + " against " +
               claim[b].dump();
    } catch (const std::exception& e) {
      return "claim." + a + " or claim." + b + " is not an enclosure: " + e.what();
    }
  }
  for (const auto& [key, want] : r.flags)
    if (!claim.contains(key) || !claim[key].is_boolean() || claim[key].get<bool>() != want)
      return "claim." + key + " of the certificate is " + (claim.contains(key) ? claim[key].dump() : "missing") +
             ", the claim's is " + (want ? "true" : "false");
  return "";
}

// Writes one instance's certificate: its command run in this process with --certificate FILE.
CertificateEntry produce_one(const proofs::ClaimResult& c, size_t k, const fs::path& dir) {
  const size_t n = c.certificates.size();
  const proofs::CertificateRequest& req = c.certificates[k];
  CertificateEntry e;
  e.claim = c.id;
  e.file = "certificates/" + c.id + (n > 1 ? "." + std::to_string(k + 1) : std::string()) + ".json";
  const fs::path path = dir / e.file;
  std::vector<std::string> args = req.args;
  if (!req.input.empty()) {  // the file the command reads, beside the certificates
    const std::string input = "certificates/inputs/" + fs::path(e.file).filename().string();
    fs::create_directories(dir / "certificates" / "inputs");
    std::ofstream(dir / input) << req.input << "\n";
    for (auto& a : args)
      if (a == "{input}") a = (dir / input).string();
    auto shown = req.args;
    for (auto& a : shown)
      if (a == "{input}") a = input;
    e.command = command_text(shown);
  } else {
    e.command = command_text(req.args);
  }
  args.insert(args.end(), {"--certificate", path.string(), "--json"});
  const auto t0 = clock_type::now();
  try {
    const InProcessRun run = run_in_process(args);
    e.produce_seconds = since(t0);
    if (run.code != exit_ok && run.code != exit_property_fails)
      e.error = "the command exited with code " + std::to_string(run.code);
    else if (!fs::exists(path))
      e.error = "the command wrote no certificate";
  } catch (const std::exception& ex) {
    e.produce_seconds = since(t0);
    e.error = std::string("the command failed (") + exit_code_for(ex).kind + "): " + ex.what();
  }
  if (!fs::exists(path)) return e;
  e.bytes = fs::file_size(path);
  try {
    std::ifstream in(path);
    const json j = json::parse(in);
    e.kind = j.is_object() && j.contains("kind") && j["kind"].is_string() ? j["kind"].get<std::string>() : "";
    if (e.error.empty()) e.error = expectation_fails(j, req);
  } catch (const std::exception& ex) {
    if (e.error.empty()) e.error = std::string("the certificate is not JSON: ") + ex.what();
  }
  return e;
}

// python3 (/usr/bin/python3, else the first in PATH), "" when there is none.
std::string find_python() {
  if (fs::exists("/usr/bin/python3")) return "/usr/bin/python3";
  const char* path = std::getenv("PATH");
  std::istringstream dirs(path ? path : "");
  for (std::string d; std::getline(dirs, d, ':');)
    if (!d.empty() && fs::exists(fs::path(d) / "python3")) return (fs::path(d) / "python3").string();
  return "";
}

std::string first_line(const std::string& s) {
  std::string line = s.substr(0, s.find('\n'));
  return line.size() > 2000 ? line.substr(0, 2000) + "..." : line;
}

// One `hapstab check --batch` process on `files` (indices into entries): each certificate's file as
// one line (its newlines made spaces: JSON has none inside a string, so the line parses as the file
// does), one JSON verdict per line with the check's own time. One process per certificate cost
// 100 times more, all of it start-up (docs/certificates.md, Sizes and times).
void check_with_hapstab(std::vector<CertificateEntry>& entries, const std::vector<size_t>& files, const fs::path& dir,
                        const fs::path& exe, int part) {
  const fs::path list = dir / "certificates" / (".check-" + std::to_string(part) + ".jsonl");
  {
    std::ofstream out(list);
    for (size_t i : files) {
      std::ifstream in(dir / entries[i].file);
      std::string text((std::istreambuf_iterator<char>(in)), {});
      for (char& c : text)
        if (c == '\n' || c == '\r') c = ' ';
      out << (text.find_first_not_of(" \t") == std::string::npos ? "{}" : text) << "\n";  // an empty file: malformed
    }
  }
  report::ProcessOptions po;
  po.time_limit = 1800;
  const auto r = report::run_process({exe.string(), "check", "--batch", list.string()}, po);
  std::error_code ec;
  fs::remove(list, ec);
  std::map<long, json> by_line;
  std::istringstream lines(r.out);
  for (std::string line; std::getline(lines, line);) {
    try {
      const json j = json::parse(line);
      if (j.is_object() && j.contains("line") && j["line"].is_number_integer()) by_line[j["line"].get<long>()] = j;
    } catch (const std::exception&) {  // not a verdict line: a certificate without one fails below
    }
  }
  for (size_t k = 0; k < files.size(); ++k) {
    CertificateCheck& c = entries[files[k]].hapstab;
    const auto it = by_line.find(static_cast<long>(k) + 1);
    if (it == by_line.end() || !it->second.contains("exit") || !it->second["exit"].is_number_integer()) {
      c.exit = -1;
      c.reason = "hapstab check --batch reported nothing on it (" + r.describe() + "): " + first_line(r.err);
      continue;
    }
    c.exit = it->second["exit"].get<int>();
    const std::string verdict = it->second.value("verdict", std::string());
    c.reason = (c.exit == 0 ? std::string() : verdict + ": ") + it->second.value("reason", std::string());
    c.seconds = it->second.value("seconds", 0.0);
  }
}

// One process of the independent checker on `files` (indices into entries): one JSON line each.
void check_independently(std::vector<CertificateEntry>& entries, const std::vector<size_t>& files,
                         const std::string& python, const fs::path& script, const fs::path& dir) {
  std::vector<std::string> argv{python, script.string(), "--files"};
  for (size_t i : files) argv.push_back((dir / entries[i].file).string());
  report::ProcessOptions po;
  po.time_limit = 1800;
  const auto r = report::run_process(argv, po);
  std::map<std::string, json> by_file;
  std::istringstream lines(r.out);
  for (std::string line; std::getline(lines, line);) {
    try {
      const json j = json::parse(line);
      if (j.is_object() && j.contains("file") && j["file"].is_string()) by_file[j["file"].get<std::string>()] = j;
    } catch (const std::exception&) {  // not a result line: ignored; a certificate without one fails below
    }
  }
  for (size_t i : files) {
    CertificateCheck& c = entries[i].independent;
    const auto it = by_file.find((dir / entries[i].file).string());
    if (it == by_file.end() || !it->second.contains("exit") || !it->second["exit"].is_number_integer()) {
      c.exit = -1;
      c.reason = "the independent checker reported nothing on it (" + r.describe() + "): " + first_line(r.err);
      continue;
    }
    c.exit = it->second["exit"].get<int>();
    c.reason = it->second.value("reason", std::string());
    c.seconds = it->second.value("seconds", 0.0);
  }
}

// Runs the jobs on two workers (the machine's 2 cores), each job writing only its own entries.
void run_jobs(const std::vector<std::function<void()>>& jobs) {
  std::atomic<size_t> next{0};
  auto worker = [&] {
    for (size_t i = next++; i < jobs.size(); i = next++) jobs[i]();
  };
  std::thread other(worker);
  worker();
  other.join();
}

json check_json(const CertificateCheck& c) {
  static const char* const words[] = {"verified", "refuted", "malformed", "not checked"};
  return {{"exit", c.exit},
          {"verdict", c.exit >= 0 && c.exit <= 3 ? words[c.exit] : "not run"},
          {"reason", c.reason},
          {"seconds", c.seconds}};
}

}  // namespace

std::vector<CertificateEntry> produce_certificates(const std::vector<proofs::ClaimResult>& claims, const fs::path& dir,
                                                   bool quiet) {
  const fs::path cdir = dir / "certificates";
  fs::create_directories(cdir);
  std::vector<fs::path> stale;  // a previous run's: removed after the listing, not while it runs
  for (const auto& e : fs::directory_iterator(cdir))
    if (e.path().extension() == ".json") stale.push_back(e.path());
  for (const auto& p : stale) fs::remove(p);
  std::vector<CertificateEntry> out;  // a failure is printed by check_certificates, with the checkers'
  for (const auto& c : claims)
    for (size_t k = 0; k < c.certificates.size(); ++k) out.push_back(produce_one(c, k, dir));
  if (!quiet) std::cerr << "reproduce: " << out.size() << " certificates written\n";
  return out;
}

std::string scene_claim_id(const SceneRun& r) {
  return "examples/" + r.file + (r.command == "multidof design" ? " (design)" : "");
}

namespace {

// The certificate of `stability --scene` for a scene (kind stability for a one-DOF loop, stability-loop
// beyond), beside what the scene's own run shows: a simulated trend (001's tightness scenes: decaying
// must be stable, growing NOT stable) or `multidof analyze`'s loop as written (`expected`). nullopt
// when the loop has no certificate (contact, friction, a coupling, an ss block: refused by name; the
// row says what it has).
std::optional<CertificateEntry> stability_scene_certificate(const SceneRun& r, const fs::path& dir, std::optional<bool> expected) {
  CertificateEntry e;
  e.claim = scene_claim_id(r);
  e.file = "certificates/scene." + fs::path(r.file).stem().string() + ".stability.json";
  e.command = command_text({"stability", "--scene", "examples/" + r.file, "--certificate", e.file});
  const fs::path path = dir / e.file;
  fs::create_directories(path.parent_path());
  const auto t0 = clock_type::now();
  try {
    run_in_process({"stability", "--scene", (examples_dir() / r.file).string(), "--json", "--certificate", path.string()});
  } catch (const InputError&) {  // a loop of no certificate kind
    return std::nullopt;
  } catch (const std::exception& ex) {
    e.error = std::string("the command failed (") + exit_code_for(ex).kind + "): " + ex.what();
  }
  e.produce_seconds = since(t0);
  if (!fs::exists(path)) {
    if (e.error.empty()) e.error = "the command wrote no certificate";
    return e;
  }
  e.bytes = fs::file_size(path);
  if (!expected && r.expected.find("trend = decaying") != std::string::npos) expected = true;
  if (!expected && r.expected.find("trend = growing") != std::string::npos) expected = false;
  try {
    std::ifstream in(path);
    const json j = json::parse(in);
    e.kind = j.value("kind", std::string());
    const bool stable = j.at("claim").at("stable").get<bool>();
    if (e.error.empty() && expected && stable != *expected)
      e.error = std::string("the certificate claims the loop ") + (stable ? "stable" : "NOT stable") + ", the scene's run shows it " +
                (*expected ? "stable" : "NOT stable");
  } catch (const std::exception& ex) {
    if (e.error.empty()) e.error = std::string("the certificate has no claim.stable: ") + ex.what();
  }
  return e;
}

// One scene command run in process, writing its certificate at `path`: the run (its JSON), the
// certificate read back, or `refused` (why) when the command refused by name ("no certificate").
// e gets the error, production time, size and kind.
struct SceneCertificateRun {
  InProcessRun run{exit_ok, json()};
  std::optional<json> certificate;
  std::string refused;
};
SceneCertificateRun run_scene_certificate(CertificateEntry& e, const std::vector<std::string>& args, const fs::path& path) {
  SceneCertificateRun out;
  const auto t0 = clock_type::now();
  try {
    out.run = run_in_process(args);
  } catch (const InputError& ex) {
    const std::string why = ex.what();
    if (why.find("no certificate") != std::string::npos) {
      out.refused = why;
      return out;
    }
    e.error = "the command failed (bad input): " + why;
  } catch (const std::exception& ex) {
    e.error = std::string("the command failed (") + exit_code_for(ex).kind + "): " + ex.what();
  }
  e.produce_seconds = since(t0);
  if (e.error.empty() && !fs::exists(path)) e.error = "the command wrote no certificate";
  if (fs::exists(path)) {
    e.bytes = fs::file_size(path);
    try {
      std::ifstream in(path);
      out.certificate = json::parse(in);
      e.kind = out.certificate->value("kind", std::string());
    } catch (const std::exception& ex) {
      if (e.error.empty()) e.error = std::string("the certificate is not JSON: ") + ex.what();
    }
  }
  return out;
}

// `multidof analyze --premise-certificate` on the scene of r (written as scene.STEM.premise.json), or
// nullopt where the failing premise has no certificate kind (refused by name).
std::optional<CertificateEntry> premise_certificate(const SceneRun& r, const fs::path& dir) {
  CertificateEntry e;
  e.claim = scene_claim_id(r);
  e.file = "certificates/scene." + fs::path(r.file).stem().string() + ".premise.json";
  e.command = command_text({"multidof", "analyze", "--scene", "examples/" + r.file, "--premise-certificate", e.file});
  const fs::path path = dir / e.file;
  const SceneCertificateRun c = run_scene_certificate(
      e, {"multidof", "analyze", "--scene", (examples_dir() / r.file).string(), "--quiet", "--json", "--premise-certificate", path.string()},
      path);
  if (!c.refused.empty()) return std::nullopt;
  return e;
}

}  // namespace

std::vector<CertificateEntry> produce_scene_certificates(std::vector<SceneRun>& runs, const fs::path& dir) {
  std::vector<CertificateEntry> out;
  for (SceneRun& r : runs) {
    if (r.command == "simulate") {
      if (auto e = stability_scene_certificate(r, dir, std::nullopt)) out.push_back(std::move(*e));
      continue;
    }
    if (r.command != "multidof analyze" && r.command != "multidof design") continue;
    const std::string sub = r.command == "multidof design" ? "design" : "analyze";
    CertificateEntry e;
    e.claim = scene_claim_id(r);
    e.file = "certificates/scene." + fs::path(r.file).stem().string() + (sub == "design" ? ".design" : "") + ".json";
    e.command = command_text({"multidof", sub, "--scene", "examples/" + r.file, "--certificate", e.file});
    const fs::path path = dir / e.file;
    fs::create_directories(path.parent_path());
    const SceneCertificateRun c = run_scene_certificate(
        e, {"multidof", sub, "--scene", (examples_dir() / r.file).string(), "--quiet", "--json", "--certificate", path.string()}, path);
    if (!c.refused.empty()) {  // a verdict of no certificate kind: said in its row
      r.no_certificate = c.refused.rfind("--certificate: ", 0) == 0 ? c.refused.substr(15) : c.refused;
      continue;
    }
    const InProcessRun& run = c.run;
    if (c.certificate) {
      // analyze: the claim's `feasible` is the verdict printed; design: a certificate (V meets
      // Theorem 4) is written only beside a printed, verified V
      const json& j = *c.certificate;
      const json printed = run.json.is_object() && run.json.contains("feasible") ? run.json["feasible"] : json();
      const char* key = sub == "design" ? "theorem4" : "feasible";
      if (e.error.empty() && (!j.contains("claim") || !j["claim"].is_object() || j["claim"].value(key, json()) != printed))
        e.error = std::string("the certificate's claim.") + key + " is not the verdict the command printed (" + printed.dump() + ")";
    }
    out.push_back(std::move(e));
    // analyze, (16) feasible and no conclusion: the failing premise's certificate where it has a kind
    // (an operator given by tf not passive: paper 000 case i's H1)
    if (sub == "analyze" && run.json.is_object() && run.json.value("feasible", json()) == json(true) &&
        run.json.value("stability_concluded", json()) == json(false))
      if (auto p = premise_certificate(r, dir)) out.push_back(std::move(*p));
    // analyze: the loop as written's verdict too (paper 000 Fig. 6(a): without a coupling it is NOT stable)
    const json* loop = run.json.is_object() && run.json.contains("loop_as_written") ? &run.json["loop_as_written"] : nullptr;
    if (sub == "analyze" && loop && loop->is_object() && loop->contains("stable") && (*loop)["stable"].is_boolean())
      if (auto l = stability_scene_certificate(r, dir, (*loop)["stable"].get<bool>())) out.push_back(std::move(*l));
  }
  return out;
}

std::vector<CertificateEntry> certificates_in_folder(const fs::path& dir) {
  std::vector<CertificateEntry> out;
  if (!fs::is_directory(dir / "certificates")) return out;
  for (const auto& f : fs::directory_iterator(dir / "certificates")) {
    if (f.path().extension() != ".json" || f.path().filename() == "index.json") continue;
    CertificateEntry e;
    e.claim = f.path().stem().string();
    e.file = "certificates/" + f.path().filename().string();
    e.bytes = fs::file_size(f.path());
    try {
      std::ifstream in(f.path());
      const json j = json::parse(in);
      if (j.is_object() && j.contains("kind") && j["kind"].is_string()) e.kind = j["kind"].get<std::string>();
    } catch (const std::exception&) {  // the checkers say what is wrong with it
    }
    out.push_back(e);
  }
  std::sort(out.begin(), out.end(), [](const CertificateEntry& a, const CertificateEntry& b) { return a.file < b.file; });
  return out;
}

CertificateSummary check_certificates(std::vector<CertificateEntry>& entries, const fs::path& dir, bool quiet,
                                      const fs::path& hapstab) {
  const fs::path exe = hapstab.empty() ? self_exe() : hapstab;
  CertificateSummary s;
  const auto t0 = clock_type::now();
  std::vector<size_t> written;
  for (size_t i = 0; i < entries.size(); ++i)
    if (fs::exists(dir / entries[i].file)) written.push_back(i);
  const std::string python = find_python();
  const fs::path script = plots_dir().parent_path() / "checks" / "hapstab_check.py";
  if (python.empty()) s.independent_missing = "python3 not found";
  else if (!fs::exists(script)) s.independent_missing = script.string() + " not found";
  s.independent_ran = s.independent_missing.empty() && !written.empty();
  // each checker in two processes, on halves of the certificates; every job writes its own entries
  const size_t half = (written.size() + 1) / 2;
  const std::vector<size_t> parts[2] = {std::vector<size_t>(written.begin(), written.begin() + half),
                                        std::vector<size_t>(written.begin() + half, written.end())};
  std::vector<std::function<void()>> jobs;
  for (int k = 0; k < 2; ++k) {
    if (parts[k].empty()) continue;
    jobs.push_back([&entries, &parts, k, dir, exe] { check_with_hapstab(entries, parts[k], dir, exe, k + 1); });
    if (s.independent_ran)
      jobs.push_back([&entries, &parts, k, python, script, dir] { check_independently(entries, parts[k], python, script, dir); });
  }
  run_jobs(jobs);
  s.wall_seconds = since(t0);
  for (auto& e : entries) {
    const bool written_ = fs::exists(dir / e.file);
    s.total += written_;
    s.produce_seconds += e.produce_seconds;
    s.check_seconds += e.hapstab.seconds;
    s.independent_seconds += e.independent.seconds;
    s.verified += written_ && e.hapstab.exit == 0;
    s.independent_verified += s.independent_ran && e.independent.exit == 0;
    s.beyond_limit += s.independent_ran && e.independent.exit == 3;
    std::string why = e.error;
    if (why.empty() && e.hapstab.exit != 0) why = "hapstab check: " + (e.hapstab.reason.empty() ? "exit " + std::to_string(e.hapstab.exit) : e.hapstab.reason);
    if (why.empty() && s.independent_ran && e.independent.exit != 0 && e.independent.exit != 3)
      why = std::string("independent checker: ") +
            (e.independent.exit == 1 ? "refuted: " : e.independent.exit == 2 ? "malformed: " : "") + e.independent.reason;
    e.failure = why;
    if (!why.empty()) s.failures.push_back(e.file + ": " + why);
  }
  s.failed = s.failures.size();
  if (!quiet)
    for (const auto& f : s.failures) std::cerr << "reproduce: certificate " << f << "\n";
  return s;
}

void write_certificate_index(const std::vector<CertificateEntry>& entries, const CertificateSummary& s, const fs::path& dir) {
  json list = json::array();
  for (const auto& e : entries)
    list.push_back({{"file", e.file},
                    {"claim", e.claim},
                    {"command", e.command},
                    {"kind", e.kind},
                    {"bytes", e.bytes},
                    {"production_seconds", e.produce_seconds},
                    {"hapstab_check", check_json(e.hapstab)},
                    {"independent_checker", check_json(e.independent)},
                    {"error", e.error.empty() ? json(nullptr) : json(e.error)}});
  const json summary = {{"certificates", s.total},
                        {"verified_by_hapstab_check", s.verified},
                        {"verified_by_independent_checker", s.independent_verified},
                        {"beyond_independent_size_limit", s.beyond_limit},
                        {"failed", s.failed},
                        {"independent_checker", s.independent_missing.empty() ? json("ran") : json(s.independent_missing)},
                        {"production_seconds", s.produce_seconds},
                        {"hapstab_check_seconds", s.check_seconds},
                        {"independent_checker_seconds", s.independent_seconds},
                        {"checks_wall_seconds", s.wall_seconds},
                        {"failures", s.failures}};
  fs::create_directories(dir / "certificates");
  std::ofstream out(dir / "certificates" / "index.json");
  if (!out) throw InputError("--out: cannot write " + (dir / "certificates" / "index.json").string());
  out << json{{"summary", summary}, {"certificates", list}}.dump(2) << "\n";
}

std::string certificate_counts(const CertificateSummary& s, bool code) {
  std::ostringstream o;
  o << s.total << " certificates, " << s.verified << " verified by " << (code ? "`hapstab check`" : "hapstab check") << ", "
    << s.independent_verified << " by the independent checker";
  if (s.independent_missing.empty())
    o << " (" << s.beyond_limit << " beyond its size limit)";
  else
    o << " (not run: " << s.independent_missing << ")";
  if (s.failed) o << ", " << s.failed << " FAILING";
  return o.str();
}

}  // namespace hapstab::cli
