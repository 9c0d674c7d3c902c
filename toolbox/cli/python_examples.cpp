// cli/python_examples.cpp -- see python_examples.hpp.
#include "cli/python_examples.hpp"

#include <algorithm>
#include <chrono>
#include <fstream>
#include <iostream>
#include <sstream>

#include "cli/figure.hpp"
#include "hapstab/report/process.hpp"

namespace hapstab::cli {
namespace fs = std::filesystem;

namespace {

/// The first paragraph of the script's docstring, on one line: the figures' caption.
std::string caption_of(const fs::path& script) {
  std::ifstream f(script);
  std::string line, text;
  bool in_doc = false;
  while (std::getline(f, line) && text.size() < 2000) {
    if (!in_doc) {
      const auto q = line.find("\"\"\"");
      if (q == std::string::npos) continue;
      in_doc = true;
      line = line.substr(q + 3);
    }
    const auto end = line.find("\"\"\"");
    if (line.find_first_not_of(" ") == std::string::npos) break;  // the paragraph ends
    text += (text.empty() ? "" : " ") + line.substr(line.find_first_not_of(" "), end);
    if (end != std::string::npos) break;
  }
  return text;
}

FigureEntry skipped(const std::string& name, const std::string& caption, const std::string& why) {
  FigureEntry e{name, "python", caption};
  e.ok = false;
  e.skipped = true;
  e.error = why;
  return e;
}

/// "" when `dir` holds the package with its C++ extension, else what is missing. The folder alone
/// proves nothing: CMake creates it when it configures, and without __init__.py and _core an empty
/// folder imports as a namespace package without attributes.
std::string built_package(const fs::path& dir) {
  const std::string how = " (cmake --build build --target hapstab_python)";
  if (!fs::is_regular_file(dir / "__init__.py"))
    return "the Python package is not built next to this hapstab: no " + (dir / "__init__.py").string() + how;
  std::error_code ec;
  for (const auto& e : fs::directory_iterator(dir, ec))
    if (e.path().filename().string().rfind("_core.", 0) == 0) return "";
  return "the Python package's C++ extension is not built next to this hapstab: no " + (dir / "_core*.so").string() + how;
}

}  // namespace

std::vector<FigureEntry> run_python_examples(const fs::path& figures_dir, bool quiet) {
  std::vector<FigureEntry> out;
  const fs::path examples = examples_dir() / "python";
  if (!fs::is_directory(examples)) return out;
  std::vector<fs::path> scripts;
  for (const auto& e : fs::directory_iterator(examples))
    if (e.path().extension() == ".py" && e.path().filename().string().front() != '_') scripts.push_back(e.path());
  std::sort(scripts.begin(), scripts.end());
  const fs::path package = self_exe().parent_path() / "python";
  const std::string python = fs::exists("/usr/bin/python3") ? "/usr/bin/python3" : "python3";
  const std::string missing = built_package(package / "hapstab");
  for (const auto& script : scripts) {
    const std::string stem = script.stem().string(), caption = caption_of(script);
    if (!missing.empty()) {
      out.push_back(skipped("python_" + stem, caption, missing));
      continue;
    }
    const auto t0 = std::chrono::steady_clock::now();
    report::ProcessOptions po;
    po.time_limit = 600;
    // env(1) sets the variables: still an argument vector, no shell
    const auto r = report::run_process({"/usr/bin/env", "PYTHONPATH=" + package.string(), "MPLBACKEND=Agg",
                                        "HAPSTAB_CLI=" + self_exe().string(), python, script.string(), "--out",
                                        figures_dir.string()},
                                       po);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    if (!r.ok()) {
      FigureEntry e{"python_" + stem, "python", caption};
      e.ok = false;
      e.error = "examples/python/" + script.filename().string() + " failed (" + r.describe() + "): " + r.err.substr(0, 2000);
      std::cerr << "reproduce: " << e.error << "\n";
      out.push_back(e);
      continue;
    }
    std::istringstream printed(r.out);
    std::string path;
    while (std::getline(printed, path)) {
      const fs::path p(path);
      if (p.extension() != ".png" || p.parent_path() != figures_dir) continue;  // its PDF twin, or noise
      FigureEntry e{p.stem().string(), "python", caption + " (examples/python/" + script.filename().string() + ")"};
      e.matplotlib = true;
      e.seconds = seconds;
      out.push_back(e);
    }
    if (!quiet) std::cerr << "reproduce: [python] " << script.filename().string() << " (" << seconds << " s)\n";
  }
  return out;
}

}  // namespace hapstab::cli
