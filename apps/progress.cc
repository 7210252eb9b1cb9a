#include "cbbg/apps/progress.h"

#include <cstdio>

#include <spdlog/spdlog.h>

namespace cbbg::app {

Progress::Progress(std::size_t total, bool terminal)
    : total_(total), terminal_(terminal), start_(std::chrono::steady_clock::now()) {}

void Progress::finished(const experiments::SeedRun& run) {
  const std::lock_guard<std::mutex> lock(mutex_);
  ++done_;
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  const std::string what = run.arm + " seed " + std::to_string(run.seed) + ": " +
                           std::to_string(run.trials.size()) + " trials, " +
                           (run.succeeded ? "succeeded after " : "no success in ") +
                           std::to_string(run.failures_before_success) + " failures";
  if (!terminal_) {
    spdlog::info("[{}/{}] {}", done_, total_, what);
    return;
  }
  constexpr int kWidth = 30;
  const int filled = static_cast<int>(kWidth * done_ / std::max<std::size_t>(total_, 1));
  std::fprintf(stderr, "\r[%s%s] %zu/%zu  %.0f s  %-60s", std::string(filled, '#').c_str(),
               std::string(kWidth - filled, '.').c_str(), done_, total_, seconds, what.c_str());
  std::fflush(stderr);
}

void Progress::close() {
  if (terminal_ && done_ > 0) std::fprintf(stderr, "\n");
}

}  // namespace cbbg::app
