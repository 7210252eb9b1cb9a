#pragma once
// Writes the files of a results directory (docs/commands.md): config.yaml,
// schema.json (what the results hold: the protocol's declaration), summary.json, trials.csv,
// evaluation.csv, figures.csv (the protocol's own per-seed figures), steps.csv, weights/. They
// go into a run's work directory (run_directory.h), which its commit then publishes. Every file
// is written from the results' schema (records/schema.h) alone.

#include <filesystem>
#include <string>

#include "cbbg/config/config.h"
#include "cbbg/parameters/parameters.h"
#include "cbbg/records/experiment_results.h"

namespace cbbg::store {

using records::ExperimentResults;

class TaskStore;

// `config` as a results directory records it: `arms` are the arms the protocol compared (a
// library run's own arms too), whatever the config said.
config::Config recorded_config(const ExperimentResults& results, config::Config config);

// What summary.json says of the run beside its results, from the run's typed parameters.
struct RunFacts {
  std::string plant;  // plant.kind
  long long max_trials = 0;
  long long log_decimation = 0;  // log.decimation: steps.csv when positive
};
RunFacts run_facts(const parameters::Parameters& parameters);

// Writes every data file of `results` into `directory` (which must exist), config.yaml as
// recorded_config, and each learning run's weights into weights/<arm>_seed<k>.txt. steps.csv comes
// from the store's files when one is given, else from each run's steps_csv.
void write_result_files(const ExperimentResults& results, const config::Config& config,
                        const RunFacts& facts, const std::filesystem::path& directory,
                        const TaskStore* store = nullptr);

// A text as a CSV field: quoted when it holds a comma or a quote (a list value, say).
std::string csv_field(const std::string& text);

// The median of per-seed counts (the mean of the middle two for an even count).
double median(std::vector<int> values);

std::string summary_json(const ExperimentResults& results, const RunFacts& facts);
// The results' schema, with every run's own figures (failures_before_success, succeeded) first.
std::string schema_json(const ExperimentResults& results);
std::string trials_csv(const ExperimentResults& results);
std::string evaluation_csv(const ExperimentResults& results);
// Per arm and seed, the runs' own figures (SeedRun::figures), a column each.
std::string figures_csv(const ExperimentResults& results);

}  // namespace cbbg::store
