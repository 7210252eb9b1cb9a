// evaluate: no training; the weights of --load-weights (an arm that learns nothing: its closed
// loop) evaluated per arm and seed as exp1 evaluates what it learnt.

#include <algorithm>

#include "cbbg/experiments/builtin_protocols.h"
#include "cbbg/experiments/experiments.h"
#include "cbbg/experiments/protocol_kit.h"

namespace cbbg::experiments {
namespace {

void evaluate_only(const parameters::Parameters& p, const diagrams::Arm& arm,
                   const TelemetryOptions&, const LearntWeights* initial_weights, SeedRun& run) {
  const bool learns = arm.learner(p).learner.learns();
  run.evaluation = evaluate_weights(p, arm, learns ? initial_weights : nullptr, run.seed);
  const auto balanced = std::count_if(run.evaluation.begin(), run.evaluation.end(),
                                      [](const EvaluationRecord& record) {
                                        return record.outcome.status == TrialStatus::kSuccess;
                                      });
  run.figures.push_back({"balanced", static_cast<double>(balanced)});
}

}  // namespace

void check_evaluation(const parameters::Parameters& parameters,
                      const std::vector<diagrams::Arm>& arms,
                      const LearntWeights* initial_weights) {
  for (const auto& arm : arms) {
    if (initial_weights == nullptr && arm.learner(parameters).learner.learns()) {
      throw config::ConfigError("the evaluate protocol tests the weights of --load-weights; arm '" +
                                arm.name + "' learns and none were given");
    }
  }
}

ExperimentResults run_evaluation(const parameters::Parameters& parameters,
                                 const std::vector<diagrams::Arm>& arms,
                                 const ExperimentOptions& options) {
  check_evaluation(parameters, arms, options.initial_weights);
  return run_per_arm("evaluate", evaluate_only, parameters, arms, options);
}

Protocol evaluate_protocol() {
  return {.name = "evaluate",
          .meaning =
              "per arm and seed: no training; the weights of --load-weights evaluated from "
              "evaluation.angles under evaluation.*",
          .run = [](const parameters::Parameters& p, const std::vector<diagrams::Arm>& arms,
                    const ExperimentOptions& options) { return run_evaluation(p, arms, options); },
          .schema =
              [](const parameters::Parameters&) {
                return ResultsSchema{.figures = {{.name = "balanced",
                                                  .type = ValueType::kInteger,
                                                  .meaning = "the evaluation runs that balanced",
                                                  .summary = FigureSummary::kNone}},
                                     .pairs_failures = false,
                                     .headline = "balanced",
                                     .plots = {"evaluation"}};
              },
          .check =
              [](const parameters::Parameters& p, const LearntWeights* initial_weights) {
                check_evaluation(p, diagrams::named_arms(p.run.arms), initial_weights);
              },
          .learns = false};
}

}  // namespace cbbg::experiments
