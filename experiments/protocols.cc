#include "cbbg/experiments/protocols.h"

#include <algorithm>
#include <stdexcept>

#include "cbbg/experiments/experiments.h"
#include "cbbg/experiments/run_names.h"
#include "cbbg/experiments/transfer.h"

namespace cbbg::experiments {
namespace {

// exp2's figure: the trials that balanced.
int balanced_trials(const SeedRun& run) {
  return static_cast<int>(std::count_if(run.trials.begin(), run.trials.end(), [](const auto& t) {
    return t.outcome.status == TrialStatus::kSuccess;
  }));
}

std::vector<diagrams::Arm> named_arms(const std::vector<std::string>& names) {
  std::vector<diagrams::Arm> arms;
  for (const auto& name : names) arms.push_back(diagrams::named_arm(name));
  return arms;
}

// evaluate's figure: the evaluation runs that balanced.
int balanced_evaluations(const SeedRun& run) {
  return static_cast<int>(std::count_if(run.evaluation.begin(), run.evaluation.end(),
                                        [](const EvaluationRecord& evaluation) {
                                          return evaluation.outcome.status == TrialStatus::kSuccess;
                                        }));
}

// The paper's one run of Fig. 11: failures before the first success.
const std::vector<std::pair<std::string, int>> kPaperFailures{{"cbbg", 0}, {"bg_only", 8}};

std::vector<Protocol>& registry() {
  static std::vector<Protocol> all{
      {"exp1",
       "per arm and seed: trials until the first success (paper Fig. 11)",
       {},
       [](const config::Parameters& p, const std::vector<diagrams::Arm>& arms,
          const ExperimentOptions& options) { return run_exp1(p, arms, options); },
       {.paper = kPaperFailures}},
      {"exp2",
       "one cbbg trial, then omega = 1 with the annealing schedule (paper Figs. 12-14)",
       [](const config::RunParams&) { return std::vector<std::string>{"cbbg"}; },
       [](const config::Parameters& p, const std::vector<diagrams::Arm>& arms,
          const ExperimentOptions& options) {
         return run_exp2(p, arms.front(), diagrams::named_arm("bg_only"), options);
       },
       {.evaluates = false,
        .paired = false,
        .oscillation = true,
        .trial_table = true,
        .headline = "balanced_trials",
        .headline_of = balanced_trials}},
      {"exp3",
       "per arm and seed: trials until the learnt actor alone balances from every "
       "exp3.angles (skill acquisition)",
       {},
       [](const config::Parameters& p, const std::vector<diagrams::Arm>& arms,
          const ExperimentOptions& options) { return run_exp3(p, arms, options); },
       {.skill = true}},
      {"evaluate",
       "per arm and seed: no training; the weights of --load-weights evaluated from "
       "evaluation.angles under evaluation.*",
       {},
       [](const config::Parameters& p, const std::vector<diagrams::Arm>& arms,
          const ExperimentOptions& options) { return run_evaluation(p, arms, options); },
       {.paired = false, .headline = "balanced", .headline_of = balanced_evaluations},
       [](const config::Parameters& p, const LearntWeights* initial_weights) {
         check_evaluation(p, named_arms(p.run.arms), initial_weights);
       },
       /*learns=*/false},
      {"transfer",
       "per arm and seed: one training (transfer.training), then evaluated under each of "
       "transfer.conditions",
       {},
       [](const config::Parameters& p, const std::vector<diagrams::Arm>& arms,
          const ExperimentOptions& options) { return run_transfer(p, arms, options); },
       {.pairs_figure =
            [](const std::string& figure) {
              return figure.starts_with("balanced@") || figure == "trials_to_skill";
            }},
       [](const config::Parameters& p, const LearntWeights*) {
         check_transfer(p, named_arms(p.run.arms));
       }},
  };
  return all;
}

}  // namespace

void register_protocol(Protocol protocol) {
  std::vector<std::string> taken;
  for (const Protocol& existing : registry()) taken.push_back(existing.name);
  config::check_new_name("protocol", protocol.name, taken);
  const std::vector<std::string> arms = diagrams::arm_names();
  if (std::find(arms.begin(), arms.end(), protocol.name) != arms.end()) {
    throw std::invalid_argument("protocol '" + protocol.name + "': an arm has that name");
  }
  if (!protocol.run) throw std::invalid_argument("protocol '" + protocol.name + "' has no run");
  registry().push_back(std::move(protocol));
}

const std::vector<Protocol>& protocols() { return registry(); }

const Protocol* find_protocol(std::string_view name) {
  for (const Protocol& protocol : registry()) {
    if (protocol.name == name) return &protocol;
  }
  return nullptr;
}

const ResultsShape& results_shape(std::string_view experiment) {
  static const ResultsShape one_arm{.paper = kPaperFailures};  // exp1's, for one arm
  const Protocol* protocol = find_protocol(experiment);
  return protocol == nullptr ? one_arm : protocol->results;
}

int headline(const ResultsShape& shape, const SeedRun& run) {
  return shape.headline_of ? shape.headline_of(run) : run.failures_before_success;
}

void check_protocol(const config::Parameters& parameters, const LearntWeights* initial_weights) {
  const Protocol* protocol = find_protocol(parameters.run.experiment);
  if (protocol != nullptr && protocol->check) protocol->check(parameters, initial_weights);
}

std::vector<std::string> experiment_arms(const config::RunParams& run) {
  const Protocol* protocol = find_protocol(run.experiment);
  if (protocol == nullptr) return {run.experiment};
  return protocol->arms ? protocol->arms(run) : run.arms;
}

ExperimentResults run_experiment(const config::Parameters& parameters,
                                 const ExperimentOptions& options) {
  check_run_names(parameters.run);
  const std::vector<diagrams::Arm> arms = named_arms(experiment_arms(parameters.run));
  if (const Protocol* protocol = find_protocol(parameters.run.experiment)) {
    return protocol->run(parameters, arms, options);
  }
  ExperimentResults results = run_exp1(parameters, arms, options);  // one arm alone
  results.experiment = parameters.run.experiment;
  return results;
}

}  // namespace cbbg::experiments
