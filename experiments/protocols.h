#pragma once
// The protocols `experiment` may name: exp1, exp2, exp3, evaluate, transfer, and any a user
// registers, each a name, what it measures, the arms it runs and how it runs them. `cbbg run`
// (and a user's program through apps/cli.h) runs whichever the config names; a protocol of
// the user's is written with protocol_kit.h and gets the results directory, resume, sweeps
// and merge.
//
//   experiments::register_protocol({
//       .name = "curriculum",
//       .meaning = "trials from 0.05 rad until a success, then from trial.theta0",
//       .run = [](const config::Parameters& p, const std::vector<diagrams::Arm>& arms,
//                 const experiments::ExperimentOptions& options) {
//         return experiments::run_per_arm("curriculum", curriculum_seed, p, arms, options);
//       }});

#include <functional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "cbbg/config/parameters.h"
#include "cbbg/diagrams/arms.h"
#include "cbbg/experiments/parallel_runs.h"
#include "cbbg/experiments/seed_run.h"

namespace cbbg::experiments {

// What a protocol's results hold, which the generic writers (results directory, sweep.csv,
// the console) show: exp1's by default.
struct ResultsShape {
  bool evaluates = true;     // evaluation.csv: each run evaluated from evaluation.angles
  bool paired = true;        // summary.json compares the first arm with each other, seed by seed
  bool skill = false;        // trials to skill (exp3): trials.csv's actor_alone, its summaries
  bool oscillation = false;  // trials.csv's pitch_rms, pitch_peak_to_peak, mean_forward_speed
  bool trial_table = false;  // the console shows each trial (k1, T, E, balanced), not failures
  // sweep.csv's figure of a run, and its column; empty: failures_before_success.
  std::string headline = "failures_before_success";
  std::function<int(const SeedRun&)> headline_of{};
  // Which of the runs' own figures (SeedRun::figures) summary.json compares seed by seed, the
  // first arm against each other, when `paired`; none by default.
  std::function<bool(const std::string& figure)> pairs_figure{};
  // The paper's failures before the first success per arm (Fig. 11), which summary.json
  // shows for the arms that ran on the paper's robot (the two-wheeler); none by default.
  std::vector<std::pair<std::string, int>> paper{};
};

struct Protocol {
  std::string name{};
  std::string meaning{};  // one line, for `cbbg list` and the help
  // The arms it runs, by name, from the run's parameters; empty: the `arms` key's.
  std::function<std::vector<std::string>(const config::RunParams&)> arms{};
  // Runs it over those arms (diagrams::named_arm of each), its results named after it.
  std::function<ExperimentResults(const config::Parameters&, const std::vector<diagrams::Arm>&,
                                  const ExperimentOptions&)>
      run{};
  ResultsShape results{};
  // Before any work, given the weights learning starts from (none: nullptr): a user's mistake
  // in the parameters, as a config::ConfigError; none by default.
  std::function<void(const config::Parameters&, const LearntWeights* initial_weights)> check{};
  // Whether its runs learn weights (what --save-weights keeps); evaluate's only use them.
  bool learns = true;
};

// Adds `protocol` (its name a config::is_name word no protocol or arm has). Register before
// running the command line. Throws std::invalid_argument.
void register_protocol(Protocol protocol);

// exp1, exp2, exp3, evaluate, transfer, then the registered protocols.
const std::vector<Protocol>& protocols();
// The protocol named `name`, or nullptr (an arm's name: that arm alone under exp1).
const Protocol* find_protocol(std::string_view name);

// The shape of results named `experiment`: its protocol's, or exp1's (an arm alone).
const ResultsShape& results_shape(std::string_view experiment);
// sweep.csv's figure of `run` under `shape`.
int headline(const ResultsShape& shape, const SeedRun& run);

// The check of the protocol `parameters` name, if it has one (Protocol::check).
void check_protocol(const config::Parameters& parameters, const LearntWeights* initial_weights);

// The arms `run.experiment` runs, by name: its protocol's, or the one arm it names.
std::vector<std::string> experiment_arms(const config::RunParams& run);

// The experiment the parameters name, over its arms (what `cbbg run` runs).
ExperimentResults run_experiment(const config::Parameters& parameters,
                                 const ExperimentOptions& options = {});

}  // namespace cbbg::experiments
