#include "cli/process.hpp"

#include <sys/wait.h>

#include <array>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>

#include "hapstab/numeric/error.hpp"

namespace hapstab::cli {

namespace fs = std::filesystem;

std::string shell_quote(const std::string& s) {
  std::string o = "'";
  for (char c : s) o += (c == '\'') ? std::string("'\\''") : std::string(1, c);
  return o + "'";
}

void run_logged(const std::string& cmd, const fs::path& log, const std::string& what) {
  const std::string full = cmd + " > " + shell_quote(log.string()) + " 2>&1";
  if (std::system(full.c_str()) != 0) {
    std::ifstream in(log);
    std::stringstream ss;
    ss << in.rdbuf();
    throw NumericalError(what + " failed:\n" + ss.str());
  }
  fs::remove(log);
}

int run_capture(const std::vector<std::string>& argv, std::string& out, const fs::path& errfile) {
  std::string cmd;
  for (const auto& a : argv) cmd += shell_quote(a) + " ";
  cmd += "2> " + shell_quote(errfile.string());
  FILE* p = popen(cmd.c_str(), "r");
  if (!p) return -1;
  std::array<char, 4096> buf;
  size_t n;
  out.clear();
  while ((n = fread(buf.data(), 1, buf.size(), p)) > 0) out.append(buf.data(), n);
  const int status = pclose(p);
  return (status != -1 && WIFEXITED(status)) ? WEXITSTATUS(status) : -1;
}

fs::path self_exe() {
  std::error_code ec;
  fs::path p = fs::read_symlink("/proc/self/exe", ec);
  if (ec) throw NumericalError("cannot find the hapstab executable (/proc/self/exe): " + ec.message());
  return p;
}

}  // namespace hapstab::cli
