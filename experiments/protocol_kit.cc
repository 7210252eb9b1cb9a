#include "cbbg/experiments/protocol_kit.h"

#include <memory>
#include <stdexcept>
#include <string>

#include "cbbg/config/config.h"
#include "cbbg/experiments/evaluation_conditions.h"
#include "cbbg/experiments/policy_evaluation.h"
#include "cbbg/experiments/training_disturbances.h"
#include "cbbg/framework/number_text.h"

namespace cbbg::experiments {
namespace {

std::vector<std::string> names_of(const std::vector<diagrams::Arm>& arms) {
  std::vector<std::string> names;
  for (const auto& arm : arms) names.push_back(arm.name);
  return names;
}

}  // namespace

parameters::Parameters with_seed(parameters::Parameters parameters, long long seed) {
  parameters.run.seed = seed;
  return parameters;
}

WeightsProvenance provenance(const parameters::Parameters& p, const SeedRun& run) {
  return {run.arm, run.seed, static_cast<long long>(run.trials.size()), p.plant.kind};
}

void keep_weights(LearntWeights weights, SeedRun& run) {
  if (weights.actor.all_finite() && weights.critic.all_finite()) {
    run.weights = std::move(weights);
  } else {
    run.weights_diverged = true;
  }
}

SeedEvaluation evaluate_seed(const parameters::Parameters& training, const diagrams::Arm& arm,
                             const LearntWeights* weights, long long seed) {
  const parameters::Parameters p = with_seed(evaluation_parameters(training), seed);
  EvaluationSettings settings;
  settings.angles = p.evaluation.angles;
  PolicyEvaluation evaluation;
  if (weights == nullptr) {
    evaluation = evaluate_controller(p, arm.learner, settings);
  } else if (arm.policy) {
    evaluation = evaluate_policy(p, arm.policy, *weights, settings);
  }
  SeedEvaluation result;
  result.seed_free = evaluation.seed_free;
  for (const AngleEvaluation& angle : evaluation.angles) {
    result.records.push_back({angle.theta0, angle.runs.front()});
  }
  return result;
}

std::vector<EvaluationRecord> evaluate_weights(const parameters::Parameters& training,
                                               const diagrams::Arm& arm,
                                               const LearntWeights* weights, long long seed) {
  return evaluate_seed(training, arm, weights, seed).records;
}

std::vector<EvaluationRecord> evaluate_run(const parameters::Parameters& training,
                                           const diagrams::Arm& arm, const SeedRun& run) {
  if (run.weights_diverged) return {};
  return evaluate_weights(training, arm, run.weights ? &*run.weights : nullptr, run.seed);
}

void keep_learnt(const parameters::Parameters& p, const diagrams::ClosedLoop& loop,
                 const Context& context, SeedRun& run) {
  if (loop.learner.learns()) keep_weights(learnt_weights(loop, context, provenance(p, run)), run);
}

void finish_run(const parameters::Parameters& p, const diagrams::Arm& arm,
                const diagrams::ClosedLoop& loop, const Context& context, SeedRun& run) {
  keep_learnt(p, loop, context, run);
  run.evaluation = evaluate_run(p, arm, run);
}

diagrams::ClosedLoop learning_loop(const parameters::Parameters& p, const diagrams::Arm& arm) {
  const TrainingParams training = training_params(p);
  try {
    return arm.learner(training_loop_parameters(p));
  } catch (const config::ConfigError& error) {
    const std::string what = error.what();
    if (training.push_force == 0.0 ||
        what.find("push the robot from outside") == std::string::npos) {
      throw;
    }
    // The push block is training.push_force's: say so rather than name push.force.
    throw config::ConfigError("training.push_force is " + format_number(training.push_force) +
                              ", but arm '" + arm.name +
                              "' has a plant without the input \"disturbance\" that a push "
                              "from outside needs; keep training.push_force 0 for it");
  }
}

void meet_training(TrialRunner& runner, const diagrams::ClosedLoop& loop,
                   const std::shared_ptr<TrainingDisturbances>& disturbances) {
  if (!disturbances) return;
  disturbances->check(loop);
  runner.set_before_trial([&loop, disturbances](Context& context, int trial, double theta0) {
    return disturbances->before_trial(loop, context, trial, theta0);
  });
}

SeedLoop::SeedLoop(const parameters::Parameters& p, const diagrams::Arm& arm,
                   const TelemetryOptions& telemetry, const LearntWeights* initial_weights,
                   long long seed)
    : loop(learning_loop(p, arm)),
      runner(loop, static_cast<std::uint64_t>(seed), p.trial.period, telemetry),
      parameters_(p),
      arm_(arm),
      telemetry_(telemetry),
      seed_(seed) {
  if (initial_weights != nullptr && loop.learner.learns()) {
    load_learnt_weights(loop, runner.context(), *initial_weights);
  }
  if (training_params(p).disturbs()) {
    disturbances = std::make_shared<TrainingDisturbances>(p, static_cast<std::uint64_t>(seed));
  }
  meet_disturbances();
}

SeedLoop::SeedLoop(const parameters::Parameters& p, const diagrams::Arm& arm,
                   const TelemetryOptions& telemetry, const SeedLoop& before)
    : loop(learning_loop(p, arm)),
      runner(loop, static_cast<std::uint64_t>(before.seed_), p.trial.period, telemetry),
      disturbances(before.disturbances),
      parameters_(p),
      arm_(arm),
      telemetry_(telemetry),
      seed_(before.seed_) {
  runner.context().continue_from(before.runner.context());
  meet_disturbances();
}

void SeedLoop::meet_disturbances() {
  if (!disturbances) return;
  if (!disturbances->varies_robot()) {
    meet_training(runner, loop, disturbances);
    return;
  }
  disturbances->check(loop);
  // Every trial has a robot of its own, which run_trial builds: none runs in `loop`.
  runner.set_before_trial([](Context&, int, double) -> double {
    throw std::logic_error(
        "training.body_mass_spread gives each trial a robot of its own: run the trials "
        "through SeedLoop::run_trial (or next_trial with the SeedLoop), not its runner");
  });
}

TrialOutcome SeedLoop::run_trial(double theta0, double duration, int trial) {
  if (disturbances && disturbances->varies_robot()) {
    return run_on_trial_robot(theta0, duration, trial);
  }
  return runner.run_trial(theta0, duration, trial);
}

TrialOutcome SeedLoop::run_on_trial_robot(double theta0, double duration, int trial) {
  const diagrams::ClosedLoop robot =
      learning_loop(disturbances->trial_robot(parameters_, trial), arm_);
  TrialRunner trial_runner(robot, static_cast<std::uint64_t>(seed_), parameters_.trial.period,
                           telemetry_);
  Context& context = trial_runner.context();
  context.continue_from(runner.context());
  context.copy_parameters_from(runner.context(), robot.plant);
  meet_training(trial_runner, robot, disturbances);
  const TrialOutcome outcome = trial_runner.run_trial(theta0, duration, trial);
  runner.context().continue_from(context);
  return outcome;
}

TrialRecord next_trial(const parameters::Parameters& p, SeedLoop& seed, int trial) {
  return next_trial(p, seed, trial, p.trial.theta0);
}

TrialRecord next_trial(const parameters::Parameters& p, SeedLoop& seed, int trial, double theta0) {
  return {trial, p.tropism.k1, seed.run_trial(theta0, p.trial.duration, trial)};
}

TrialRecord next_trial(const parameters::Parameters& p, TrialRunner& runner, int trial) {
  return next_trial(p, runner, trial, p.trial.theta0);
}

TrialRecord next_trial(const parameters::Parameters& p, TrialRunner& runner, int trial,
                       double theta0) {
  return {trial, p.tropism.k1, runner.run_trial(theta0, p.trial.duration, trial)};
}

ExperimentResults run_per_arm(const std::string& experiment, const PerSeed& protocol,
                              const parameters::Parameters& p,
                              const std::vector<diagrams::Arm>& arms,
                              const ExperimentOptions& options) {
  check_training(p);
  for (std::size_t a = 0; a < arms.size(); ++a) {
    if (!config::is_name(arms[a].name)) {
      throw std::invalid_argument(experiment + ": arm name '" + arms[a].name + "' is not a name (" +
                                  config::kNameRule +
                                  "): it names files and columns of the results");
    }
    for (std::size_t b = 0; b < a; ++b) {
      if (arms[a].name == arms[b].name) {
        throw std::invalid_argument(experiment + ": two arms are named '" + arms[a].name +
                                    "'; an arm's name must be unique");
      }
    }
  }
  // Before any training: every arm's plant sees the robot its evaluation changes and takes
  // its push, and the weights learning starts from fit its robot and layout.
  for (const auto& arm : arms) {
    if (changes_robot(p.evaluation)) {
      check_plant_takes_conditions(p.evaluation, arm.learner(p));
    }
    check_plant_takes_push(p, arm.learner);
    if (options.initial_weights != nullptr) {
      const diagrams::ClosedLoop loop = arm.learner(p);
      if (loop.learner.learns()) {
        check_weights_fit(*options.initial_weights, p.plant.kind, loop, "the initial weights");
      }
    }
  }
  // Tasks are arm-major: the arm of a run is found by its name.
  auto body = [&](SeedRun& run, const TelemetryOptions& telemetry) {
    for (const auto& arm : arms) {
      if (arm.name == run.arm) {
        protocol(p, arm, telemetry, options.initial_weights, run);
        return;
      }
    }
  };
  ExperimentResults results = run_tasks(p, names_of(arms), body, options);
  results.experiment = experiment;
  results.compares_arms = true;
  if (!arms.empty()) results.steps_header = steps_csv_header(arms.front().learner(p).signals);
  return results;
}

}  // namespace cbbg::experiments
