#include "cli/scenes.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <fstream>
#include <iostream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <toml++/toml.h>

#include "cli/figure.hpp"
#include "hapstab/numeric/error.hpp"
#include "hapstab/report/escape.hpp"
#include "hapstab/report/paths.hpp"
#include "hapstab/report/process.hpp"
#include "hapstab/scene/schema.hpp"
#include "hapstab/report/toml_limits.hpp"

namespace hapstab::cli {

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

std::string show(const json& j) { return j.is_string() ? j.get<std::string>() : j.dump(); }

std::string show(const toml::node& v) {
  if (v.is_boolean()) return *v.value<bool>() ? "true" : "false";
  if (v.is_string()) return *v.value<std::string>();
  if (auto d = v.value<double>()) return json(*d).dump();
  return "(a table or array)";
}

// "true (a boolean)", "\"growing\" (a string)", "null": what the command printed, typed.
std::string typed(const json& j) {
  if (j.is_null()) return "null";
  const char* kind = j.is_boolean() ? "a boolean" : j.is_number() ? "a number" : j.is_string() ? "a string"
                     : j.is_array() ? "a list" : "an object";
  std::string v = j.dump();
  if (v.size() > 80) v = v.substr(0, 77) + "...";
  return v + " (" + kind + ")";
}

// Checks one expectation (TOML value) against the command's JSON value; "" when it holds,
// else the reason. Types must match: a boolean against a boolean, a string against a string,
// a comparison or a number against a number; "!= null" / "== null" against anything.
std::string check(const std::string& key, const toml::node& want, const json& got) {
  if (want.is_boolean()) {
    const bool b = *want.value<bool>();
    if (!got.is_boolean())
      return key + " is " + typed(got) + ", expected a boolean (" + (b ? "true" : "false") + ")";
    return got.get<bool>() == b ? "" : key + " is " + show(got) + ", expected " + (b ? "true" : "false");
  }
  if (auto s = want.value<std::string>(); s && want.is_string()) {
    if (*s == "!= null" || *s == "== null") {
      const bool holds = (*s == "== null") == got.is_null();
      return holds ? "" : key + " is " + typed(got) + ", expected " + *s;
    }
    for (const char* op : {">=", "<=", "==", ">", "<"}) {
      const std::string o = op;
      if (s->rfind(o, 0) != 0) continue;
      double x;
      try {
        x = std::stod(s->substr(o.size()));
      } catch (const std::exception&) {
        return key + ": cannot read the number in '" + *s + "'";
      }
      if (!got.is_number()) return key + " is " + typed(got) + ", expected a number " + *s;
      const double g = got.get<double>();
      const bool holds = o == ">=" ? g >= x : o == "<=" ? g <= x : o == "==" ? g == x : o == ">" ? g > x : g < x;
      return holds ? "" : key + " = " + show(got) + ", expected " + *s;
    }
    if (!got.is_string()) return key + " is " + typed(got) + ", expected the string '" + *s + "'";
    return got.get<std::string>() == *s ? "" : key + " is " + show(got) + ", expected " + *s;
  }
  if (want.is_integer() || want.is_floating_point()) {
    const double d = *want.value<double>();
    if (!got.is_number()) return key + " is " + typed(got) + ", expected the number " + show(want);
    return got.get<double>() == d ? "" : key + " is " + show(got) + ", expected " + show(want);
  }
  return key + ": unsupported expectation (use true/false, a string, a number, or \"> x\"-style comparisons)";
}

SceneRun run_one(const fs::path& file, const std::string& command, const std::vector<std::string>& args,
                 const toml::table* expect, const fs::path& outdir) {
  SceneRun r;
  r.file = file.filename().string();
  r.command = command;
  auto t0 = std::chrono::steady_clock::now();
  std::vector<std::string> argv{self_exe().string()};
  argv.insert(argv.end(), args.begin(), args.end());
  fs::create_directories(outdir);
  // NAME.analyze: the scene's file stem is a name from a folder listing; it must still be one
  // clean file name (report/paths.hpp) before it names outputs.
  std::string base;
  try {
    base = report::file_component(file.stem().string(), "examples/" + report::text(r.file)) + "." +
           command.substr(command.rfind(' ') + 1);
  } catch (const InputError& e) {
    r.ok = false;
    r.error = e.what();
    return r;
  }
  const fs::path errfile = outdir / (base + ".stderr");
  const auto run = report::run_process(argv);
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  std::ofstream(outdir / (base + ".json")) << run.out;
  if (!run.err.empty()) std::ofstream(errfile) << run.err;
  if (!run.started || (run.exit_code != 0 && run.exit_code != 1)) {  // 1 = the property does not hold: a result
    r.ok = false;
    r.error = run.describe() + ": " + run.err;
    return r;
  }
  const std::string& out = run.out;
  json j;
  try {
    j = json::parse(out);
  } catch (const std::exception& e) {
    r.ok = false;
    r.error = std::string("unreadable JSON output: ") + e.what();
    return r;
  }
  // every command a scene runs states what it expects (no silent pass on exit 0 or 1)
  if (!expect || expect->empty()) {
    const std::string cmd = command.substr(command.rfind(' ') + 1);
    r.ok = false;
    r.error = "the scene states no expectation for " + command + ": add [reproduce] " + cmd +
              " = { KEY = VALUE, ... } (docs/scene.md)";
    return r;
  }
  for (const auto& [k, v] : *expect) {
    const std::string key(k.str());
    if (!j.is_object() || !j.contains(key)) {
      r.ok = false;
      r.expected += (r.expected.empty() ? "" : "; ") + key + " = " + show(v);
      r.got += (r.got.empty() ? "" : "; ") + key + " not printed";
      r.error += (r.error.empty() ? "" : "; ") + key + ": " + command + " does not print it";
      continue;
    }
    const json got = j[key];
    const std::string w = show(v);
    const bool op = v.is_string() && w.find_first_of("<>=!") == 0;  // "> 1" reads as "key > 1"
    r.expected += (r.expected.empty() ? "" : "; ") + key + (op ? " " : " = ") + w;
    r.got += (r.got.empty() ? "" : "; ") + key + " = " + show(got);
    const std::string why = check(key, v, got);
    if (!why.empty()) {
      r.ok = false;
      r.error += (r.error.empty() ? "" : "; ") + why;
    }
  }
  return r;
}

}  // namespace

std::vector<SceneRun> run_scenes(const std::string& paper, const fs::path& outdir, bool quiet) {
  std::vector<fs::path> files;
  for (const auto& e : fs::directory_iterator(examples_dir()))
    if (e.path().extension() == ".toml") files.push_back(e.path());
  std::sort(files.begin(), files.end());
  std::vector<SceneRun> runs;
  for (const auto& f : files) {
    toml::table root;
    try {
      // a regular file of at most 64 MB (not a FIFO, which would block), no deeper than toml++ can take
      const std::string text = report::read_input_file(f, "the scene", 64u << 20);
      report::check_toml_depth(text, f.filename().string());
      root = toml::parse(text, f.string());
    } catch (const std::exception& e) {
      SceneRun r;
      r.file = f.filename().string();
      r.paper = "toolbox";
      r.ok = false;
      const auto* pe = dynamic_cast<const toml::parse_error*>(&e);
      r.error = "cannot read the scene: " + (pe ? std::string(pe->description()) : std::string(e.what()));
      runs.push_back(r);
      continue;
    }
    try {  // the schema refuses unknown sections and keys, expectation keys included
      scene::check_schema(root, f.string());
    } catch (const InputError& e) {
      SceneRun r;
      r.file = f.filename().string();
      r.paper = "toolbox";
      r.command = "scene load";
      r.ok = false;
      r.error = e.what();
      runs.push_back(r);
      continue;
    }
    const toml::table* rep = root["reproduce"].as_table();
    const std::string p = rep ? (*rep)["paper"].value_or(std::string("toolbox")) : std::string("toolbox");
    if (!paper.empty() && paper != p) continue;
    std::string claim = rep ? (*rep)["claim"].value_or(std::string()) : std::string();
    if (claim.empty()) claim = root["scene"]["name"].value_or(f.stem().string());
    auto expect = [&](const char* cmd) { return rep ? (*rep)[cmd].as_table() : nullptr; };
    std::vector<SceneRun> these;
    const std::string sf = f.string();
    if (root.contains("multidof")) {
      these.push_back(run_one(f, "multidof analyze", {"multidof", "analyze", "--scene", sf, "--json"}, expect("analyze"),
                              outdir / "scenes"));
      these.push_back(run_one(f, "multidof design", {"multidof", "design", "--scene", sf, "--json"}, expect("design"),
                              outdir / "scenes"));
    } else if (root.contains("simulate")) {
      these.push_back(run_one(f, "simulate",
                              {"simulate", "--scene", sf, "--out", (outdir / "scenes" / f.stem()).string(), "--json",
                               "--quiet"},
                              expect("simulate"), outdir / "scenes"));
    } else {
      SceneRun r;
      r.file = f.filename().string();
      r.ok = false;
      r.error = "the scene has neither [simulate] nor [multidof]: nothing to run";
      these.push_back(r);
    }
    for (auto& r : these) {
      r.paper = p;
      r.claim = claim;
      if (!quiet)
        std::cerr << "reproduce: [scene] " << r.file << " (" << r.command << "): " << (r.ok ? "ok" : "FAILS " + r.error)
                  << " (" << r.seconds << " s)\n";
      runs.push_back(r);
    }
  }
  return runs;
}

}  // namespace hapstab::cli
