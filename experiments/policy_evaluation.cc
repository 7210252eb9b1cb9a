#include "cbbg/experiments/policy_evaluation.h"

#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <string>

#include "cbbg/parameters/parameters.h"

namespace cbbg::experiments {

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
}

int AngleEvaluation::balanced() const {
  int count = 0;
  for (const auto& run : runs) count += run.status == TrialStatus::kSuccess ? 1 : 0;
  return count;
}

namespace {

// The runs of evaluate_policy, or of evaluate_controller when `weights` is null.
PolicyEvaluation evaluate(const parameters::Parameters& parameters,
                          const diagrams::ClosedLoopFactory& factory, const LearntWeights* weights,
                          const EvaluationSettings& settings) {
  settings.validate();
  const diagrams::ClosedLoop loop = factory(parameters);
  if (weights == nullptr && loop.learner.learns()) {
    throw std::invalid_argument("the closed loop '" + loop.diagram->name() +
                                "' learns: evaluate its learnt policy instead");
  }
  PolicyEvaluation result;
  result.first_seed = parameters.run.seed;
  TelemetryOptions telemetry;
  telemetry.keep_in_memory = false;
  TrialRunner runner(loop, static_cast<std::uint64_t>(result.first_seed), parameters.trial.period,
                     telemetry);
  Context& context = runner.context();
  for (const double theta0 : settings.angles) {
    AngleEvaluation angle;
    angle.theta0 = theta0;
    for (int repeat = 0; repeat < settings.repeats; ++repeat) {
      // A clean context with this run's seed: a run does not depend on the runs before it.
      context.reset_all_state();
      context.reseed(static_cast<std::uint64_t>(result.first_seed + repeat));
      if (weights != nullptr) load_learnt_weights(loop, context, *weights);
      angle.runs.push_back(runner.run_trial(theta0, parameters.trial.duration));
      result.seed_free = result.seed_free && context.generators_at_seed();
    }
    result.angles.push_back(std::move(angle));
  }
  return result;
}

}  // namespace

PolicyEvaluation evaluate_policy(const parameters::Parameters& parameters,
                                 const diagrams::ClosedLoopFactory& policy,
                                 const LearntWeights& weights, const EvaluationSettings& settings) {
  return evaluate(parameters, policy, &weights, settings);
}

PolicyEvaluation evaluate_controller(const parameters::Parameters& parameters,
                                     const diagrams::ClosedLoopFactory& controller,
                                     const EvaluationSettings& settings) {
  return evaluate(parameters, controller, nullptr, settings);
}

}  // namespace cbbg::experiments
