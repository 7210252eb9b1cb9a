#pragma once
// A console reporter that also prints, after all runs, each benchmark's CPU time as a ratio
// to its baseline measured in the same run. Baselines are named by the caller:
// "BM_Diagram/10" against "BM_PlainLoop/10", say.

#include <functional>
#include <map>
#include <ostream>
#include <string>
#include <vector>

#include <benchmark/benchmark.h>

namespace cbbg::bench {

class RatioReporter : public benchmark::ConsoleReporter {
 public:
  // Maps a benchmark name to the name of its baseline, or to "" when it has none.
  explicit RatioReporter(std::function<std::string(const std::string&)> baseline_of)
      : baseline_of_(std::move(baseline_of)) {}

  void ReportRuns(const std::vector<Run>& runs) override {
    for (const Run& run : runs) {
      if (run.run_type == Run::RT_Iteration && !run.error_occurred) {
        // With repetitions the last one stands; each name is listed once.
        if (cpu_ns_.count(run.benchmark_name()) == 0) order_.push_back(run.benchmark_name());
        cpu_ns_[run.benchmark_name()] = run.GetAdjustedCPUTime();
      }
    }
    ConsoleReporter::ReportRuns(runs);
  }

  void Finalize() override {
    ConsoleReporter::Finalize();
    GetOutputStream() << "\nRatios to the baseline measured in the same run (CPU time):\n";
    for (const std::string& name : order_) {
      const std::string baseline = baseline_of_(name);
      if (baseline.empty() || cpu_ns_.count(baseline) == 0) continue;
      GetOutputStream() << "  " << name << " / " << baseline << " = "
                        << cpu_ns_[name] / cpu_ns_[baseline] << "\n";
    }
  }

 private:
  std::function<std::string(const std::string&)> baseline_of_;
  std::map<std::string, double> cpu_ns_;
  std::vector<std::string> order_;
};

// The main() of a cbbg benchmark: runs the benchmarks the command line selects and prints
// each one's ratio to the baseline `baseline_of` names.
inline int run_benchmarks_with_ratios(int argc, char** argv,
                                      std::function<std::string(const std::string&)> baseline_of) {
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  RatioReporter reporter(std::move(baseline_of));
  benchmark::RunSpecifiedBenchmarks(&reporter);
  benchmark::Shutdown();
  return 0;
}

}  // namespace cbbg::bench
