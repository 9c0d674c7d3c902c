#include "hapstab/report/process.hpp"

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstring>
#include <sstream>

#include "hapstab/numeric/error.hpp"

extern char** environ;

namespace hapstab::report {

namespace {

// A pipe whose ends are closed on every exit path.
struct Pipe {
  int fd[2] = {-1, -1};
  Pipe() {
    if (pipe2(fd, O_CLOEXEC) != 0) fd[0] = fd[1] = -1;
  }
  ~Pipe() { close_both(); }
  void close_end(int i) {
    if (fd[i] >= 0) ::close(fd[i]);
    fd[i] = -1;
  }
  void close_both() { close_end(0), close_end(1); }
  bool ok() const { return fd[0] >= 0; }
};

struct SpawnSetup {
  posix_spawn_file_actions_t actions;
  SpawnSetup() { posix_spawn_file_actions_init(&actions); }
  ~SpawnSetup() { posix_spawn_file_actions_destroy(&actions); }
};

// Reads both pipes until they close or the deadline passes; false when the deadline passed.
bool drain(Pipe& out, Pipe& err, ProcessResult& r, const ProcessOptions& o) {
  using clock = std::chrono::steady_clock;
  const auto deadline = clock::now() + std::chrono::duration_cast<clock::duration>(std::chrono::duration<double>(o.time_limit));
  char buf[65536];
  while (out.fd[0] >= 0 || err.fd[0] >= 0) {
    pollfd p[2] = {{out.fd[0], POLLIN, 0}, {err.fd[0], POLLIN, 0}};
    int wait_ms = -1;
    if (o.time_limit > 0) {
      const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - clock::now()).count();
      if (left <= 0) return false;
      wait_ms = static_cast<int>(std::min<long long>(left, 1000));
    }
    const int n = ::poll(p, 2, wait_ms);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) return true;
    for (int k = 0; k < 2; ++k) {
      if (p[k].fd < 0 || !(p[k].revents & (POLLIN | POLLHUP | POLLERR))) continue;
      Pipe& pp = k == 0 ? out : err;
      std::string& dst = k == 0 ? r.out : r.err;
      const ssize_t got = ::read(pp.fd[0], buf, sizeof buf);
      if (got < 0 && errno == EINTR) continue;
      if (got <= 0) {
        pp.close_end(0);
        continue;
      }
      if (dst.size() < o.max_output) dst.append(buf, std::min<size_t>(size_t(got), o.max_output - dst.size()));
    }
  }
  return true;
}

}  // namespace

std::string ProcessResult::describe() const {
  std::ostringstream s;
  if (!started) s << "could not be run: " << err;
  else if (timed_out) s << "stopped at the time limit of " << time_limit << " s";
  else if (signal) s << "killed by signal " << signal << " (" << strsignal(signal) << ")";
  else s << "exit code " << exit_code;
  return s.str();
}

ProcessResult run_process(const std::vector<std::string>& argv, const ProcessOptions& o) {
  ProcessResult r;
  r.time_limit = o.time_limit;
  if (argv.empty() || argv[0].empty()) {
    r.err = "no program named";
    return r;
  }
  Pipe out, err;
  if (!out.ok() || !err.ok()) {
    r.err = std::string("cannot create a pipe: ") + std::strerror(errno);
    return r;
  }
  SpawnSetup setup;
  auto* fa = &setup.actions;
  posix_spawn_file_actions_addopen(fa, 0, "/dev/null", O_RDONLY, 0);
  posix_spawn_file_actions_adddup2(fa, out.fd[1], 1);
  posix_spawn_file_actions_adddup2(fa, err.fd[1], 2);
  if (!o.working_dir.empty()) posix_spawn_file_actions_addchdir_np(fa, o.working_dir.c_str());
  std::vector<char*> args;
  for (const auto& a : argv) args.push_back(const_cast<char*>(a.c_str()));
  args.push_back(nullptr);
  pid_t pid = -1;
  const bool search = argv[0].find('/') == std::string::npos;
  const int rc = search ? posix_spawnp(&pid, args[0], fa, nullptr, args.data(), environ)
                        : posix_spawn(&pid, args[0], fa, nullptr, args.data(), environ);
  out.close_end(1);
  err.close_end(1);
  if (rc != 0) {
    std::error_code ec;
    r.err = !o.working_dir.empty() && !std::filesystem::is_directory(o.working_dir, ec)
                ? "the working folder '" + o.working_dir.string() + "' does not exist"
                : "'" + argv[0] + "': " + std::strerror(rc);
    return r;
  }
  r.started = true;
  if (!drain(out, err, r, o)) {
    r.timed_out = true;
    ::kill(pid, SIGKILL);
  }
  int status = 0;
  while (::waitpid(pid, &status, 0) < 0 && errno == EINTR) {
  }
  if (WIFEXITED(status)) r.exit_code = WEXITSTATUS(status);
  if (WIFSIGNALED(status)) r.signal = WTERMSIG(status);
  if (r.timed_out) r.exit_code = -1;
  return r;
}

ProcessResult run_checked(const std::vector<std::string>& argv, const std::string& what, const ProcessOptions& o) {
  ProcessResult r = run_process(argv, o);
  if (!r.ok())
    throw NumericalError(what + " failed (" + r.describe() + ")" + (r.err.empty() && r.out.empty() ? "" : ":\n") +
                         r.err + r.out);
  return r;
}

}  // namespace hapstab::report
