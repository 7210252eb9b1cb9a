#pragma once
// The protocols `experiment` may name: exp1, exp2, exp3, evaluate, transfer, and any a user
// registers, each a name, what it measures, the arms it runs, how it runs them and what its
// results hold (records/schema.h). `cbbg run` (and a user's program through apps/cli.h) runs
// whichever the config names; a protocol of the user's is written with protocol_kit.h and gets
// the results directory, resume, sweeps, merge, the plots and Python, as the built-in ones
// (builtin_protocols.h) do.
//
//   experiments::register_protocol({
//       .name = "curriculum",
//       .meaning = "trials from 0.05 rad until a success, then from trial.theta0",
//       .run = [](const parameters::Parameters& p, const std::vector<diagrams::Arm>& arms,
//                 const experiments::ExperimentOptions& options) {
//         return experiments::run_per_arm("curriculum", curriculum_seed, p, arms, options);
//       },
//       .schema = [](const parameters::Parameters&) {
//         return experiments::ResultsSchema{.figures = {{.name = "warm_up_trials",
//                                                        .type = ValueType::kInteger,
//                                                        .paired = true}}};
//       },
//       .keys = config::declared_keys(CurriculumParams{}, "curriculum")});
//   // and in its run: config::read_section<CurriculumParams>(p.own, "curriculum")

#include <functional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "cbbg/config/declared_keys.h"
#include "cbbg/diagrams/arms.h"
#include "cbbg/experiments/parallel_runs.h"
#include "cbbg/experiments/seed_run.h"
#include "cbbg/parameters/parameters.h"
#include "cbbg/records/schema.h"

namespace cbbg::experiments {

struct Protocol {
  std::string name{};
  std::string meaning{};  // one line, for `cbbg list` and the help
  // The arms it runs, by name, from the run's parameters; empty: the `arms` key's.
  std::function<std::vector<std::string>(const parameters::RunParams&)> arms{};
  // Runs it over those arms (diagrams::named_arm of each), its results named after it.
  std::function<ExperimentResults(const parameters::Parameters&, const std::vector<diagrams::Arm>&,
                                  const ExperimentOptions&)>
      run{};
  // What its results hold (records/schema.h), from the run's parameters (transfer names its
  // figures after its conditions); none: exp1's, without the paper's figures.
  std::function<ResultsSchema(const parameters::Parameters&)> schema{};
  // Before any work, given the weights learning starts from (none: nullptr): a user's mistake
  // in the parameters, as a config::ConfigError; none by default.
  std::function<void(const parameters::Parameters&, const LearntWeights* initial_weights)> check{};
  // Whether its runs learn weights (what --save-weights keeps); evaluate's only use them.
  bool learns = true;
  // Its own keys (config::declared_keys of its params structs), registered with it and read
  // from the run's parameters.own (config::read_section); placed in config.yaml after the key
  // or section `keys_after` names, else at the end. A transfer condition never sets them.
  std::vector<config::KeySpec> keys{};
  std::string keys_after{};
};

// Adds `protocol` (its name a config::is_name word no protocol or arm has) and its keys.
// Register before making the config (the command line makes it). Throws
// std::invalid_argument.
void register_protocol(Protocol protocol);
// Removes a protocol register_protocol added, and its keys (a notebook registering it
// again). Throws std::invalid_argument for another name (the library's protocols stay).
void unregister_protocol(std::string_view name);

// exp1, exp2, exp3, evaluate, transfer, then the registered protocols.
const std::vector<Protocol>& protocols();
// Every program that includes this header has the library's protocols, and their keys, before
// main; after the tree's (parameters/parameters.h, included above), which they follow.
[[maybe_unused]] inline const bool kLibraryProtocolsRegistered = !protocols().empty();

// Whether a protocol's own keys (Protocol::keys) declare `key`.
bool is_protocol_key(std::string_view key);
// The protocol named `name`, or nullptr (an arm's name: that arm alone under exp1).
const Protocol* find_protocol(std::string_view name);

// The schema of the results of the experiment `parameters` name: its protocol's, or exp1's (an
// arm alone). Throws std::invalid_argument when a protocol declares one that cannot be written.
ResultsSchema results_schema(const parameters::Parameters& parameters);

// Throws std::runtime_error naming the run when one of `results`' runs records a figure its
// schema does not declare (it would be lost).
void check_recorded_figures(const ExperimentResults& results);

// The checks before any work of the protocol `parameters` name: training.*'s, which every
// protocol's learning trials meet (check_training), then the protocol's own (Protocol::check).
void check_protocol(const parameters::Parameters& parameters, const LearntWeights* initial_weights);

// The arms `run.experiment` runs, by name: its protocol's, or the one arm it names.
std::vector<std::string> experiment_arms(const parameters::RunParams& run);

// The experiment the parameters name, over its arms (what `cbbg run` runs).
ExperimentResults run_experiment(const parameters::Parameters& parameters,
                                 const ExperimentOptions& options = {});

}  // namespace cbbg::experiments
