#pragma once
// Writes a results directory (README "Results directory"): config.yaml, summary.json,
// trials.csv, steps.csv, figures/. Everything goes into a staging directory beside the
// target, renamed onto it at the end, so an interrupted run never leaves a directory that
// looks finished.

#include <filesystem>
#include <string>

#include "config/config.h"
#include "diagrams/experiments.h"

namespace cbbg::diagrams {

// The paper's failures before the first success (Fig. 11), for summary.json.
struct PaperReference {
  const char* arm;
  int failures;
};

// Writes every data file of `results` into `directory` (which must exist).
void write_result_files(const ExperimentResults& results, const config::Config& config,
                        const std::filesystem::path& directory);

std::string summary_json(const ExperimentResults& results, const config::Config& config);
std::string trials_csv(const ExperimentResults& results);
std::string evaluation_csv(const ExperimentResults& results);

// A directory that becomes `target` only when commit() is called; destroyed uncommitted,
// it is removed.
class StagingDirectory {
 public:
  explicit StagingDirectory(std::filesystem::path target);
  ~StagingDirectory();
  StagingDirectory(const StagingDirectory&) = delete;
  StagingDirectory& operator=(const StagingDirectory&) = delete;

  const std::filesystem::path& path() const { return staging_; }
  // Replaces `target` (and whatever was there) with the staging directory.
  void commit();

 private:
  std::filesystem::path target_;
  std::filesystem::path staging_;
  bool committed_ = false;
};

}  // namespace cbbg::diagrams
