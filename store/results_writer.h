#pragma once
// Writes a results directory (README "Results directory"): config.yaml, summary.json,
// trials.csv, evaluation.csv, steps.csv, figures/. Everything goes into a work directory
// beside the target, renamed onto it at the end, so an interrupted run never leaves a
// directory that looks finished.

#include <filesystem>
#include <string>

#include "config/config.h"
#include "experiments/seed_run.h"

namespace cbbg::store {

using experiments::ExperimentResults;

class TaskStore;

// Writes every data file of `results` into `directory` (which must exist), and each learning
// run's weights into weights/<arm>_seed<k>.txt. steps.csv comes from the store's files when
// one is given, else from each run's steps_csv.
void write_result_files(const ExperimentResults& results, const config::Config& config,
                        const std::filesystem::path& directory, const TaskStore* store = nullptr);

// The median of per-seed counts (the mean of the middle two for an even count).
double median(std::vector<int> values);

std::string summary_json(const ExperimentResults& results, const config::Config& config);
std::string trials_csv(const ExperimentResults& results);
std::string evaluation_csv(const ExperimentResults& results);

// Where a run works before its results are final: "<target>.partial", holding the resolved
// config (config.yaml) and the finished tasks (tasks/). commit() renames it onto `target`.
// A run killed midway leaves only the .partial directory, which --resume continues.
class RunDirectory {
 public:
  // Starts a run into `target`, writing `config` into the work directory. Throws
  // config::ConfigError when an interrupted run's work directory is in the way.
  static RunDirectory create(const std::filesystem::path& target, const config::Config& config);
  // Continues the interrupted run into `target`; its config comes from the work directory.
  // Throws config::ConfigError when there is nothing to resume.
  static RunDirectory resume(const std::filesystem::path& target);

  const std::filesystem::path& work() const { return work_; }
  const std::filesystem::path& target() const { return target_; }
  std::filesystem::path tasks() const { return work_ / "tasks"; }
  // Where the weights learning started from are kept (cbbg run --load-weights), for resume.
  std::filesystem::path initial_weights() const { return work_ / "initial_weights.txt"; }
  const config::Config& config() const { return config_; }
  // Removes the task files and replaces `target` (and whatever was there) with the results.
  void commit();

 private:
  RunDirectory(std::filesystem::path target, config::Config config);

  std::filesystem::path target_;
  std::filesystem::path work_;
  config::Config config_;
};

}  // namespace cbbg::store
