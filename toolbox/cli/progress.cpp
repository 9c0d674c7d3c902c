// Stage progress on stderr for long runs (see progress.hpp).
#include "cli/progress.hpp"

#include <cmath>
#include <cstdlib>
#include <iomanip>
#include <iostream>
#include <sstream>

namespace hapstab::cli {

namespace {

std::string seconds(double s) {
  std::ostringstream o;
  o << std::fixed << std::setprecision(s < 10 ? 2 : 1) << s << " s";
  return o.str();
}

}  // namespace

double StageProgress::delay_seconds() {
  const char* env = std::getenv("HAPSTAB_PROGRESS_AFTER");
  if (!env || !*env) return 2;
  char* end = nullptr;
  const double v = std::strtod(env, &end);
  return (end && *end == '\0' && std::isfinite(v) && v >= 0) ? v : 2;
}

StageProgress::StageProgress(std::string command, std::vector<std::string> stages, bool quiet)
    : command_(std::move(command)), names_(std::move(stages)), start_(Clock::now()), stage_start_(start_), quiet_(quiet) {
  if (quiet_) return;
  if (delay_seconds() == 0) live_ = true;  // from the start, deterministically (no thread to wait for)
  else watcher_ = std::thread([this] { watch(); });
}

StageProgress::~StageProgress() { finish(); }

void StageProgress::finish() {
  {
    std::lock_guard<std::mutex> lock(mu_);
    if (finished_) return;
    finished_ = true;
    if (current_ > 0) done_.push_back({names_[current_ - 1], std::chrono::duration<double>(Clock::now() - stage_start_).count()});
    if (live_) {
      const double total = since_start();
      std::cerr << command_ << ": done in " << seconds(total) << ":";
      for (size_t k = 0; k < done_.size(); ++k)
        std::cerr << (k ? ", " : " ") << done_[k].name << " "
                  << (total > 0 ? static_cast<int>(std::lround(100 * done_[k].seconds / total)) : 0) << "%";
      std::cerr << "\n" << std::flush;
    }
  }
  cv_.notify_all();
  if (watcher_.joinable()) watcher_.join();
}

double StageProgress::since_start() const { return std::chrono::duration<double>(Clock::now() - start_).count(); }

std::string StageProgress::line(size_t k) const {
  return command_ + ": [" + std::to_string(k + 1) + "/" + std::to_string(std::max(names_.size(), k + 1)) + "] " + names_[k];
}

void StageProgress::stage(const std::string& name) {
  std::lock_guard<std::mutex> lock(mu_);
  const auto now = Clock::now();
  if (current_ > 0) done_.push_back({names_[current_ - 1], std::chrono::duration<double>(now - stage_start_).count()});
  if (current_ >= names_.size()) names_.push_back(name.empty() ? "stage " + std::to_string(current_ + 1) : name);
  else if (!name.empty()) names_[current_] = name;
  ++current_;
  stage_start_ = now;
  if (live_) std::cerr << line(current_ - 1) << " ... (from " << seconds(since_start()) << ")\n" << std::flush;
}

void StageProgress::replan(const std::vector<std::string>& rest) {
  std::lock_guard<std::mutex> lock(mu_);
  names_.resize(current_);
  names_.insert(names_.end(), rest.begin(), rest.end());
}

void StageProgress::go_live() {
  live_ = true;
  for (size_t k = 0; k < done_.size(); ++k) std::cerr << line(k) << ": " << seconds(done_[k].seconds) << "\n";
  if (current_ > 0)
    std::cerr << line(current_ - 1) << " ... (from " << seconds(std::chrono::duration<double>(stage_start_ - start_).count())
              << ", running)\n";
  std::cerr << std::flush;
}

void StageProgress::watch() {
  std::unique_lock<std::mutex> lock(mu_);
  const auto when = start_ + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(delay_seconds()));
  if (cv_.wait_until(lock, when, [this] { return finished_; })) return;
  go_live();
}

}  // namespace hapstab::cli
