// The fork()ed workers of a sweep, their checkpoint files and the progress line (run.hpp).
// A worker dies with the process that forked it (PR_SET_PDEATHSIG): no sweep leaves orphans.
#include "hapstab/study/run.hpp"

#include <fcntl.h>
#include <sched.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <thread>

#include "hapstab/numeric/error.hpp"

namespace hapstab::study {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

namespace {

bool write_all(int fd, const std::string& s) {
  size_t off = 0;
  while (off < s.size()) {
    const ssize_t n = ::write(fd, s.data() + off, s.size() - off);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return false;
    off += static_cast<size_t>(n);
  }
  return true;
}

/// Test hook (tests/cli/test_sweep.cpp, KilledRunResumesToTheSameBytes): with the environment
/// variable HAPSTAB_TEST_SWEEP_KILL_AFTER=N, worker 0 writes and syncs its first N records, then
/// SIGKILLs the sweep's process group -- a kill at a known point, not at a wall-clock moment.
long kill_after_points() {
  const char* v = std::getenv("HAPSTAB_TEST_SWEEP_KILL_AFTER");
  if (!v || !*v) return -1;
  char* end = nullptr;
  const long n = std::strtol(v, &end, 10);
  return *end == '\0' && n >= 0 ? n : -1;
}

/// The body of worker w: its points, one record line each, then _exit (never returns).
[[noreturn]] void worker(const RunPlan& plan, const std::vector<uint64_t>& pending, unsigned w, unsigned jobs,
                         int progress_fd, const PointRunner& run_point, long kill_after) {
  const int null = ::open("/dev/null", O_WRONLY);
  if (null >= 0) ::dup2(null, STDOUT_FILENO);  // a command's human output must not reach the sweep's
  const fs::path file = plan.dir / "checkpoints" / ("part-" + std::to_string(::getpid()) + ".txt");
  const int fd = ::open(file.c_str(), O_WRONLY | O_CREAT | O_APPEND | O_CLOEXEC, 0644);
  if (fd < 0) ::_exit(4);
  // Records and progress ticks leave in batches: a write(2) and a wakeup of the parent per fast
  // point cost as much system time as the point's computation.
  std::string records;
  size_t ticks = 0;
  auto synced = Clock::now(), flushed = synced;
  const auto flush = [&] {
    if (!write_all(fd, records)) ::_exit(4);
    write_all(progress_fd, std::string(ticks, '.'));
    records.clear();
    ticks = 0;
    flushed = Clock::now();
  };
  for (size_t p = w; p < pending.size(); p += jobs) {
    const uint64_t index = plan.range.index(pending[p]);
    nlohmann::json rec;
    try {
      rec = run_point(index);
    } catch (const std::exception& e) {
      rec = {{"exit", 3}, {"error", std::string("internal error: ") + e.what()}};
    }
    records += record_line(index, rec) + "\n";
    ++ticks;
    if (w == 0 && kill_after >= 0 && static_cast<long>(p / jobs + 1) == kill_after) {
      flush();
      ::fdatasync(fd);
      ::kill(0, SIGKILL);
    }
    const auto now = Clock::now();
    if (now - flushed > std::chrono::milliseconds(100) || records.size() > (64u << 10)) flush();
    if (now - synced > std::chrono::seconds(1)) {
      ::fdatasync(fd);
      synced = now;
    }
  }
  flush();
  ::fdatasync(fd);
  ::_exit(0);
}

std::string clock_text(double s) {
  const long t = static_cast<long>(s + 0.5);
  char buf[32];
  std::snprintf(buf, sizeof buf, "%ld:%02ld:%02ld", t / 3600, t / 60 % 60, t % 60);
  return buf;
}

/// The progress line on stderr: a bar redrawn in place on a terminal, a line per 10% otherwise.
class Progress {
 public:
  Progress(uint64_t total, bool quiet) : total_(total), quiet_(quiet), tty_(::isatty(STDERR_FILENO)) {}
  void advance(uint64_t n) {
    done_ += n;
    if (quiet_ || total_ == 0) return;
    const auto now = Clock::now();
    const uint64_t decile = done_ * 10 / total_;
    if (tty_ ? now - drawn_ < std::chrono::milliseconds(200) && done_ < total_ : decile == decile_) return;
    drawn_ = now, decile_ = decile;
    const double s = std::chrono::duration<double>(now - start_).count();
    const double rate = s > 0 ? static_cast<double>(done_) / s : 0;
    const int width = 30, filled = static_cast<int>(width * done_ / total_);
    char buf[200];
    std::snprintf(buf, sizeof buf, "[%s%s] %llu/%llu  %.1f points/s  ETA %s", std::string(filled, '#').c_str(),
                  std::string(width - filled, '.').c_str(), static_cast<unsigned long long>(done_),
                  static_cast<unsigned long long>(total_), rate,
                  rate > 0 ? clock_text(static_cast<double>(total_ - done_) / rate).c_str() : "?");
    std::cerr << (tty_ ? "\r" : "") << buf << (tty_ && done_ < total_ ? "" : "\n") << std::flush;
  }

 private:
  uint64_t total_, done_ = 0, decile_ = 0;
  bool quiet_, tty_;
  Clock::time_point start_ = Clock::now(), drawn_{};
};

}  // namespace

std::vector<fs::path> checkpoint_files(const fs::path& dir) {
  std::vector<fs::path> out;
  std::error_code ec;
  for (const auto& e : fs::directory_iterator(dir / "checkpoints", ec))
    if (e.is_regular_file() && e.path().extension() == ".txt") out.push_back(e.path());
  std::sort(out.begin(), out.end());
  return out;
}

unsigned available_cpus() {
  cpu_set_t set;
  if (sched_getaffinity(0, sizeof set, &set) == 0) return std::max(1, CPU_COUNT(&set));
  return std::max(1u, std::thread::hardware_concurrency());
}

RunResult run_pending(const RunPlan& plan, const RecordStore& done, const PointRunner& run_point) {
  std::vector<uint64_t> pending;
  for (uint64_t k = 0; k < plan.range.count; ++k)
    if (!done.has(k)) pending.push_back(k);
  RunResult result;
  if (pending.empty()) return result;
  fs::create_directories(plan.dir / "checkpoints");
  const unsigned jobs = static_cast<unsigned>(std::min<uint64_t>(std::max(1u, plan.jobs), pending.size()));
  int pipe_fd[2];
  if (::pipe2(pipe_fd, O_CLOEXEC) != 0) throw NumericalError("sweep: cannot create a pipe");
  std::cout.flush(), std::cerr.flush(), std::fflush(nullptr);
  const long kill_after = kill_after_points();
  std::vector<pid_t> workers;
  const pid_t parent = ::getpid();
  for (unsigned w = 0; w < jobs; ++w) {
    const pid_t pid = ::fork();
    if (pid < 0) throw NumericalError("sweep: cannot start a worker process");
    if (pid == 0) {
      // a worker ends with the sweep: SIGKILL when the process that forked it dies (issue 49), and
      // at once if that happened before this line
      ::prctl(PR_SET_PDEATHSIG, SIGKILL);
      if (::getppid() != parent) ::_exit(4);
      ::close(pipe_fd[0]);
      worker(plan, pending, w, jobs, pipe_fd[1], run_point, kill_after);
    }
    workers.push_back(pid);
  }
  ::close(pipe_fd[1]);
  Progress progress(pending.size(), plan.quiet);
  char buf[4096];
  for (;;) {
    const ssize_t n = ::read(pipe_fd[0], buf, sizeof buf);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) break;
    progress.advance(static_cast<uint64_t>(n));
    result.ran += static_cast<uint64_t>(n);
  }
  ::close(pipe_fd[0]);
  for (pid_t pid : workers) {
    int status = 0;
    while (::waitpid(pid, &status, 0) < 0 && errno == EINTR) {
    }
    if (WIFEXITED(status) && WEXITSTATUS(status) == 0) continue;
    result.workers_ok = false;
    result.worker_error = WIFSIGNALED(status) ? "a worker was killed by signal " + std::to_string(WTERMSIG(status))
                                              : "a worker could not write its checkpoint file (exit " +
                                                    std::to_string(WEXITSTATUS(status)) + ")";
  }
  return result;
}

}  // namespace hapstab::study
