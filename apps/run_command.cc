// cbbg run: resolve the config, run the experiment, write the results directory.

#include <cstdio>
#include <iostream>

#include <spdlog/spdlog.h>
#include <unistd.h>

#include "apps/commands.h"
#include "apps/figures.h"
#include "apps/progress.h"
#include "diagrams/params_from_config.h"
#include "diagrams/results_writer.h"

namespace cbbg::app {
namespace {

// Applies the file, the overrides and the run flags, in that order; validates everything.
config::Config resolve(const RunOptions& options) {
  config::Config config;
  if (!options.config_file.empty()) config.merge_file(options.config_file);
  for (const auto& assignment : options.sets) config.set(assignment);
  if (!options.experiment.empty()) {
    config.set("experiment=" + options.experiment, "--experiment " + options.experiment);
  }
  if (options.seeds > 0) {
    config.set("seeds=" + std::to_string(options.seeds), "--seeds");
  }
  if (options.seed >= 0) config.set("seed=" + std::to_string(options.seed), "--seed");
  diagrams::validate_all(config);
  return config;
}

void print_summary(const diagrams::ExperimentResults& results) {
  std::printf("%-14s %8s %10s %8s %s\n", "arm", "seeds", "succeeded", "median", "range");
  for (std::size_t a = 0; a < results.arms.size(); ++a) {
    int succeeded = 0;
    int low = 1 << 30;
    int high = 0;
    std::vector<int> failures;
    for (std::size_t s = 0; s < results.seeds.size(); ++s) {
      const auto& run = results.run(a, s);
      succeeded += run.succeeded ? 1 : 0;
      failures.push_back(run.failures_before_success);
      low = std::min(low, run.failures_before_success);
      high = std::max(high, run.failures_before_success);
    }
    std::sort(failures.begin(), failures.end());
    const std::size_t n = failures.size();
    const double median =
        n % 2 == 1 ? failures[n / 2] : 0.5 * (failures[n / 2 - 1] + failures[n / 2]);
    std::printf("%-14s %8zu %10d %8.1f [%d, %d]  (failures before the first success)\n",
                results.arms[a].c_str(), results.seeds.size(), succeeded, median, low, high);
  }
}

}  // namespace

int run_command(const RunOptions& options) {
  config::Config config;
  try {
    config = resolve(options);
  } catch (const config::ConfigError& error) {
    std::cerr << "cbbg: error: " << error.what() << "\n";
    return 2;
  }
  const std::size_t tasks =
      (config.text("experiment") == "exp1" ? config.names("arms").size() : 1) *
      static_cast<std::size_t>(config.integer("seeds"));
  spdlog::info("{}: {} seed(s) x {} arm(s) on the {} plant, {} thread(s)",
               config.text("experiment"), config.integer("seeds"),
               tasks / static_cast<std::size_t>(config.integer("seeds")), config.text("plant.kind"),
               options.jobs);
  try {
    Progress progress(tasks, ::isatty(STDERR_FILENO) == 1);
    const diagrams::ExperimentResults results = diagrams::run_experiment(
        config, options.jobs,
        [&progress](const diagrams::SeedRun& run) { progress.finished(run); });
    progress.close();

    diagrams::StagingDirectory staging(options.out);
    diagrams::write_result_files(results, config, staging.path());
    if (options.figures) {
      draw_figures(staging.path(), config);
    }
    staging.commit();
    print_summary(results);
    spdlog::info("results in {}", options.out.string());
  } catch (const config::ConfigError& error) {
    std::cerr << "cbbg: error: " << error.what() << "\n";
    return 2;
  } catch (const std::exception& error) {
    std::cerr << "cbbg: error: " << error.what() << "\n";
    return 1;
  }
  return 0;
}

}  // namespace cbbg::app
