#include "cbbg/experiments/experiments.h"

#include <stdexcept>

#include "cbbg/config/parameters.h"
#include "cbbg/experiments/evaluation_conditions.h"
#include "cbbg/experiments/policy_evaluation.h"
#include "cbbg/experiments/protocol_kit.h"

namespace cbbg::experiments {
namespace {

// k1 of `trial` under the annealing schedule (steps sorted by from_trial, the first at 1).
double annealed_k1(const std::vector<config::AnnealingStep>& schedule, int trial) {
  double k1 = schedule.front().k1;
  for (const auto& step : schedule) {
    if (step.from_trial <= trial) k1 = step.k1;
  }
  return k1;
}

}  // namespace

void run_until_success(const config::Parameters& p, const diagrams::Arm& arm,
                       const TelemetryOptions& telemetry, const LearntWeights* initial_weights,
                       SeedRun& run) {
  SeedLoop seed(p, arm, telemetry, initial_weights, run.seed);
  for (int trial = 1; trial <= p.run.max_trials; ++trial) {
    const TrialRecord record = next_trial(p, seed.runner, trial);
    run.trials.push_back(record);
    if (record.outcome.status == TrialStatus::kSuccess) {
      run.succeeded = true;
      break;
    }
    ++run.failures_before_success;
  }
  finish_run(p, arm, seed.loop, seed.runner.context(), run);
}

namespace {

// exp3's test after a trial: the weights learnt so far, frozen, with the actor alone, from
// each of exp3.angles in turn (stopping at the first that fails).
bool actor_alone_balances(const config::Parameters& p, const diagrams::Arm& arm,
                          const LearntWeights& weights, long long seed) {
  const config::Parameters tested = with_seed(p, seed);
  for (const double angle : p.exp3.angles) {
    EvaluationSettings settings;
    settings.angles = {angle};
    const PolicyEvaluation evaluation = evaluate_policy(tested, arm.policy, weights, settings);
    if (evaluation.angles.front().balanced() == 0) return false;
  }
  return true;
}

}  // namespace

void run_until_skill(const config::Parameters& p, const diagrams::Arm& arm,
                     const TelemetryOptions& telemetry, const LearntWeights* initial_weights,
                     SeedRun& run) {
  SeedLoop seed(p, arm, telemetry, initial_weights, run.seed);
  TrialRunner& runner = seed.runner;
  const diagrams::ClosedLoop& loop = seed.loop;
  const bool has_actor = loop.learner.learns() && static_cast<bool>(arm.policy);
  int failures = 0;
  for (int trial = 1; trial <= p.run.max_trials; ++trial) {
    TrialRecord record = next_trial(p, runner, trial);
    const bool success = record.outcome.status == TrialStatus::kSuccess;
    if (!success) ++failures;
    if (success && !run.succeeded) {
      run.succeeded = true;
      run.failures_before_success = failures;
    }
    if (has_actor) {
      const LearntWeights weights = learnt_weights(loop, runner.context(), provenance(p, run));
      record.actor_alone_passed =
          weights.actor.all_finite() && actor_alone_balances(p, arm, weights, run.seed);
    }
    run.trials.push_back(record);
    if (record.actor_alone_passed.value_or(false)) {
      run.trials_to_skill = trial;
      run.failures_to_skill = failures;
      break;
    }
    if (!has_actor && run.succeeded) break;
  }
  if (!run.succeeded) run.failures_before_success = failures;
  finish_run(p, arm, loop, runner.context(), run);
}

namespace {

void set_k1(const diagrams::ClosedLoop& loop, Context& context, double k1) {
  if (loop.learner.tropism == nullptr) {
    throw std::invalid_argument("exp2 anneals k1: the closed loop '" + loop.diagram->name() +
                                "' has no tropism");
  }
  loop.learner.tropism->set_k1(context, k1);
}

void run_annealing(const config::Parameters& p, const diagrams::Arm& coordinated,
                   const diagrams::Arm& operant, const TelemetryOptions& telemetry,
                   const LearntWeights* initial_weights, SeedRun& run) {
  const double theta0 = p.trial.theta0;
  const double duration = p.trial.duration;
  const std::vector<config::AnnealingStep>& schedule = p.annealing;
  SeedLoop first(p, coordinated, telemetry, initial_weights, run.seed);
  set_k1(first.loop, first.runner.context(), annealed_k1(schedule, 1));
  run.trials.push_back(
      {1, annealed_k1(schedule, 1), first.runner.run_trial(theta0, duration, 1), std::nullopt});

  // The operant loop carries on: weights, the omega counter and the random streams.
  const diagrams::ClosedLoop later_loop = operant.learner(p);
  TrialRunner later(later_loop, static_cast<std::uint64_t>(run.seed), p.trial.period, telemetry);
  later.context().continue_from(first.runner.context());
  for (int trial = 2; trial <= p.exp2.trials; ++trial) {
    const double k1 = annealed_k1(schedule, trial);
    set_k1(later_loop, later.context(), k1);
    run.trials.push_back({trial, k1, later.run_trial(theta0, duration, trial), std::nullopt});
  }
  for (const auto& trial : run.trials) {
    if (trial.outcome.status == TrialStatus::kSuccess && !run.succeeded) {
      run.succeeded = true;
      run.failures_before_success = trial.trial - 1;
    }
  }
  if (!run.succeeded) run.failures_before_success = static_cast<int>(run.trials.size());
  keep_weights(learnt_weights(later_loop, later.context(), provenance(p, run)), run);
}

// No training: the initial weights (an arm that learns nothing: its closed loop) evaluated.
void evaluate_only(const config::Parameters& p, const diagrams::Arm& arm, const TelemetryOptions&,
                   const LearntWeights* initial_weights, SeedRun& run) {
  const bool learns = arm.learner(p).learner.learns();
  run.evaluation = evaluate_weights(p, arm, learns ? initial_weights : nullptr, run.seed);
}

}  // namespace

void check_evaluation(const config::Parameters& parameters, const std::vector<diagrams::Arm>& arms,
                      const LearntWeights* initial_weights) {
  for (const auto& arm : arms) {
    if (initial_weights == nullptr && arm.learner(parameters).learner.learns()) {
      throw config::ConfigError("the evaluate protocol tests the weights of --load-weights; arm '" +
                                arm.name + "' learns and none were given");
    }
  }
}

ExperimentResults run_evaluation(const config::Parameters& parameters,
                                 const std::vector<diagrams::Arm>& arms,
                                 const ExperimentOptions& options) {
  check_evaluation(parameters, arms, options.initial_weights);
  return run_per_arm("evaluate", evaluate_only, parameters, arms, options);
}

ExperimentResults run_exp1(const config::Parameters& parameters,
                           const std::vector<diagrams::Arm>& arms,
                           const ExperimentOptions& options) {
  return run_per_arm("exp1", run_until_success, parameters, arms, options);
}

ExperimentResults run_exp3(const config::Parameters& parameters,
                           const std::vector<diagrams::Arm>& arms,
                           const ExperimentOptions& options) {
  return run_per_arm("exp3", run_until_skill, parameters, arms, options);
}

ExperimentResults run_exp2(const config::Parameters& parameters, const diagrams::Arm& coordinated,
                           const diagrams::Arm& operant, const ExperimentOptions& options) {
  auto body = [&](SeedRun& run, const TelemetryOptions& telemetry) {
    run_annealing(parameters, coordinated, operant, telemetry, options.initial_weights, run);
  };
  ExperimentResults results = run_tasks(parameters, {coordinated.name}, body, options);
  results.experiment = "exp2";
  return results;
}

}  // namespace cbbg::experiments
