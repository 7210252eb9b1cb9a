#include "diagrams/policy_evaluation.h"

#include <cmath>
#include <cstdint>
#include <functional>
#include <limits>
#include <memory>
#include <stdexcept>
#include <string>

#include "diagrams/controller_diagram.h"

namespace cbbg::diagrams {

void EvaluationSettings::validate() const {
  if (angles.empty()) throw std::invalid_argument("evaluation angles: at least one is needed");
  for (std::size_t i = 0; i < angles.size(); ++i) {
    if (!std::isfinite(angles[i])) {
      throw std::invalid_argument("evaluation angle [" + std::to_string(i) +
                                  "] must be finite; got " + std::to_string(angles[i]));
    }
  }
  if (repeats < 1) {
    throw std::invalid_argument("evaluation repeats must be >= 1; got " + std::to_string(repeats));
  }
  if (push) push->validate();
}

int AngleEvaluation::balanced() const {
  int count = 0;
  for (const auto& run : runs) count += run.status == TrialStatus::kSuccess ? 1 : 0;
  return count;
}

PolicyEvaluation evaluate_policy(const config::Config& config, const LearntWeights& weights,
                                 const EvaluationSettings& settings) {
  settings.validate();
  const ControllerDiagram policy =
      build_controller_diagram(kLearntActorDiagram, config, DiagramOptions{settings.push});
  if (weights.actor.size() != policy.actor->num_features()) {
    throw std::invalid_argument("the weights have " + std::to_string(weights.actor.size()) +
                                " actor weights; the config's RBF grid has " +
                                std::to_string(policy.actor->num_features()) + " features");
  }
  PolicyEvaluation result;
  result.first_seed = config.integer("seed");
  TelemetryOptions telemetry;
  telemetry.keep_in_memory = false;
  TrialRunner runner(policy, static_cast<std::uint64_t>(result.first_seed),
                     config.number("trial.period"), telemetry);
  Context& context = runner.context();
  for (const double theta0 : settings.angles) {
    AngleEvaluation angle;
    angle.theta0 = theta0;
    for (int repeat = 0; repeat < settings.repeats; ++repeat) {
      // A clean context with this run's seed: a run does not depend on the runs before it.
      context.reset_all_state();
      context.reseed(static_cast<std::uint64_t>(result.first_seed + repeat));
      policy.actor->mutable_weights(context) = weights.actor;
      angle.runs.push_back(runner.run_trial(theta0, config.number("trial.duration")));
    }
    result.angles.push_back(std::move(angle));
  }
  return result;
}

}  // namespace cbbg::diagrams
