// exp1 (paper Fig. 11): per arm and seed, trials until the first success, then the run's learnt
// actor evaluated.

#include "cbbg/diagrams/plant_kinds.h"
#include "cbbg/experiments/builtin_protocols.h"
#include "cbbg/experiments/experiments.h"
#include "cbbg/experiments/protocol_kit.h"

namespace cbbg::experiments {

void run_until_success(const parameters::Parameters& p, const diagrams::Arm& arm,
                       const TelemetryOptions& telemetry, const LearntWeights* initial_weights,
                       SeedRun& run) {
  SeedLoop seed(p, arm, telemetry, initial_weights, run.seed);
  for (int trial = 1; trial <= p.run.max_trials; ++trial) {
    const TrialRecord record = next_trial(p, seed, trial);
    run.trials.push_back(record);
    if (record.outcome.status == TrialStatus::kSuccess) {
      run.succeeded = true;
      break;
    }
    ++run.failures_before_success;
  }
  finish_run(p, arm, seed.loop, seed.runner.context(), run);
}

ExperimentResults run_exp1(const parameters::Parameters& parameters,
                           const std::vector<diagrams::Arm>& arms,
                           const ExperimentOptions& options) {
  return run_per_arm("exp1", run_until_success, parameters, arms, options);
}

ResultsSchema exp1_schema(const parameters::Parameters& parameters) {
  ResultsSchema schema;
  // The paper's one run of Fig. 11 per arm, a reference only on the paper's robot.
  if (diagrams::same_robot(parameters.plant.kind, "simbody")) {
    schema.reference = {{"cbbg", 0}, {"bg_only", 8}};
  }
  return schema;
}

Protocol exp1_protocol() {
  return {.name = "exp1",
          .meaning = "per arm and seed: trials until the first success (paper Fig. 11)",
          .run = [](const parameters::Parameters& p, const std::vector<diagrams::Arm>& arms,
                    const ExperimentOptions& options) { return run_exp1(p, arms, options); },
          .schema = exp1_schema};
}

}  // namespace cbbg::experiments
