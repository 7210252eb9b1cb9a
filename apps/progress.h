#pragma once
// Progress of a multi-seed run: a bar redrawn in place on a terminal, one log line per
// finished seed otherwise. Safe to call from worker threads.

#include <chrono>
#include <mutex>
#include <string>

#include "cbbg/experiments/seed_run.h"

namespace cbbg::app {

class Progress {
 public:
  Progress(std::size_t total, bool terminal);
  void finished(const experiments::SeedRun& run);
  void close();

 private:
  std::mutex mutex_;
  std::size_t total_;
  std::size_t done_ = 0;
  bool terminal_;
  std::chrono::steady_clock::time_point start_;
};

}  // namespace cbbg::app
