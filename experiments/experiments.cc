#include "experiments/experiments.h"

#include <stdexcept>

#include "config/parameters.h"
#include "experiments/evaluation_conditions.h"
#include "experiments/policy_evaluation.h"

namespace cbbg::experiments {
namespace {

// `config` with the root seed `seed`: an evaluation after a seed's training uses its streams.
config::Config with_seed(config::Config config, long long seed) {
  config::Parameters parameters = config::read_parameters(config);
  parameters.run.seed = seed;
  config::write_parameters(parameters, config);
  return config;
}

// k1 of `trial` under the annealing schedule (steps sorted by from_trial, the first at 1).
double annealed_k1(const std::vector<config::AnnealingStep>& schedule, int trial) {
  double k1 = schedule.front().k1;
  for (const auto& step : schedule) {
    if (step.from_trial <= trial) k1 = step.k1;
  }
  return k1;
}

// What the run leaves to be tested, from each evaluation angle under the evaluation's
// conditions (evaluation_conditions.h), with the run's seed: the learnt actor alone (no
// exploration, no supervisor, frozen), as `cbbg eval` runs it, or the closed loop of an arm
// that learns nothing (pd_only: the supervisor alone) as it is.
void evaluate_run(const config::Config& training, const diagrams::Arm& arm, bool learns,
                  SeedRun& run) {
  const config::Config config = with_seed(evaluation_config(training), run.seed);
  EvaluationSettings settings;
  settings.angles = config::read_parameters(config).evaluation.angles;
  PolicyEvaluation evaluation;
  if (!learns) {
    evaluation = evaluate_controller(config, arm.learner, settings);
  } else if (arm.policy && run.weights) {
    evaluation = evaluate_policy(config, arm.policy, *run.weights, settings);
  }
  for (const AngleEvaluation& angle : evaluation.angles) {
    run.evaluation.push_back({angle.theta0, angle.runs.front()});
  }
}

WeightsProvenance provenance(const config::Config& config, const SeedRun& run) {
  return {run.arm, run.seed, static_cast<long long>(run.trials.size()),
          config::read_parameters(config).plant.kind};
}

// Keeps what was learnt, unless it stopped being finite (a diverged learner): then the run
// says so instead, and nothing evaluates or saves it.
void keep_weights(LearntWeights weights, SeedRun& run) {
  if (weights.actor.allFinite() && weights.critic.allFinite()) {
    run.weights = std::move(weights);
  } else {
    run.weights_diverged = true;
  }
}

// The end of an exp1 or exp3 run: what was learnt is kept and the run evaluated.
void finish_run(const config::Config& config, const diagrams::Arm& arm,
                const diagrams::ClosedLoop& loop, const Context& context, SeedRun& run) {
  if (loop.learner.learns()) {
    keep_weights(learnt_weights(loop, context, config, provenance(config, run)), run);
  }
  evaluate_run(config, arm, loop.learner.learns(), run);
}

// One seed of an arm: its learning closed loop and the runner of its trials, started from
// the initial weights when there are some.
struct SeedLoop {
  SeedLoop(const config::Config& config, const diagrams::Arm& arm,
           const TelemetryOptions& telemetry, const LearntWeights* initial_weights, long long seed)
      : loop(arm.learner(config)),
        runner(loop, static_cast<std::uint64_t>(seed), config::read_parameters(config).trial.period,
               telemetry) {
    if (initial_weights != nullptr && loop.learner.learns()) {
      load_learnt_weights(loop, runner.context(), *initial_weights);
    }
  }
  diagrams::ClosedLoop loop;
  TrialRunner runner;  // runs `loop`: declared after it
};

// The next trial of exp1's protocol (exp3's too): from trial.theta0, k1 fixed.
TrialRecord next_trial(const config::Parameters& p, TrialRunner& runner, int trial) {
  return {trial, p.tropism.k1, runner.run_trial(p.trial.theta0, p.trial.duration, trial),
          std::nullopt};
}

void run_until_success(const config::Config& config, const diagrams::Arm& arm,
                       const TelemetryOptions& telemetry, const LearntWeights* initial_weights,
                       SeedRun& run) {
  SeedLoop seed(config, arm, telemetry, initial_weights, run.seed);
  const config::Parameters p = config::read_parameters(config);
  for (int trial = 1; trial <= p.run.max_trials; ++trial) {
    const TrialRecord record = next_trial(p, seed.runner, trial);
    run.trials.push_back(record);
    if (record.outcome.status == TrialStatus::kSuccess) {
      run.succeeded = true;
      break;
    }
    ++run.failures_before_success;
  }
  finish_run(config, arm, seed.loop, seed.runner.context(), run);
}

// exp3's test after a trial: the weights learnt so far, frozen, with the actor alone, from
// each of exp3.angles in turn (stopping at the first that fails).
bool actor_alone_balances(const config::Config& config, const diagrams::Arm& arm,
                          const LearntWeights& weights, long long seed) {
  const config::Config evaluation_config = with_seed(config, seed);
  for (const double angle : config::read_parameters(config).exp3.angles) {
    EvaluationSettings settings;
    settings.angles = {angle};
    const PolicyEvaluation evaluation =
        evaluate_policy(evaluation_config, arm.policy, weights, settings);
    if (evaluation.angles.front().balanced() == 0) return false;
  }
  return true;
}

// exp3: trials go on past the first success until the learnt actor alone passes the test
// (or max_trials). An arm that learns nothing has no actor: it stops at its first success.
void run_until_skill(const config::Config& config, const diagrams::Arm& arm,
                     const TelemetryOptions& telemetry, const LearntWeights* initial_weights,
                     SeedRun& run) {
  SeedLoop seed(config, arm, telemetry, initial_weights, run.seed);
  TrialRunner& runner = seed.runner;
  const diagrams::ClosedLoop& loop = seed.loop;
  const bool has_actor = loop.learner.learns() && static_cast<bool>(arm.policy);
  int failures = 0;
  const config::Parameters p = config::read_parameters(config);
  for (int trial = 1; trial <= p.run.max_trials; ++trial) {
    TrialRecord record = next_trial(p, runner, trial);
    const bool success = record.outcome.status == TrialStatus::kSuccess;
    if (!success) ++failures;
    if (success && !run.succeeded) {
      run.succeeded = true;
      run.failures_before_success = failures;
    }
    if (has_actor) {
      const LearntWeights weights =
          learnt_weights(loop, runner.context(), config, provenance(config, run));
      record.actor_alone_passed =
          weights.actor.allFinite() && actor_alone_balances(config, arm, weights, run.seed);
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
  finish_run(config, arm, loop, runner.context(), run);
}

void set_k1(const diagrams::ClosedLoop& loop, Context& context, double k1) {
  if (loop.learner.tropism == nullptr) {
    throw std::invalid_argument("exp2 anneals k1: the closed loop '" + loop.diagram->name() +
                                "' has no tropism");
  }
  loop.learner.tropism->set_k1(context, k1);
}

void run_annealing(const config::Config& config, const diagrams::Arm& coordinated,
                   const diagrams::Arm& operant, const TelemetryOptions& telemetry,
                   const LearntWeights* initial_weights, SeedRun& run) {
  const config::Parameters p = config::read_parameters(config);
  const double theta0 = p.trial.theta0;
  const double duration = p.trial.duration;
  const std::vector<config::AnnealingStep>& schedule = p.annealing;
  SeedLoop first(config, coordinated, telemetry, initial_weights, run.seed);
  set_k1(first.loop, first.runner.context(), annealed_k1(schedule, 1));
  run.trials.push_back(
      {1, annealed_k1(schedule, 1), first.runner.run_trial(theta0, duration, 1), std::nullopt});

  // The operant loop carries on: weights, the omega counter and the random streams.
  const diagrams::ClosedLoop later_loop = operant.learner(config);
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
  keep_weights(learnt_weights(later_loop, later.context(), config, provenance(config, run)), run);
}

std::vector<std::string> names_of(const std::vector<diagrams::Arm>& arms) {
  std::vector<std::string> names;
  for (const auto& arm : arms) names.push_back(arm.name);
  return names;
}

// One seed of one arm under a protocol (exp1's, exp3's).
using ArmProtocol = void (*)(const config::Config&, const diagrams::Arm&, const TelemetryOptions&,
                             const LearntWeights*, SeedRun&);

// `protocol` for every (arm, seed), the arms' names unique.
ExperimentResults run_per_arm(const char* experiment, ArmProtocol protocol,
                              const config::Config& config, const std::vector<diagrams::Arm>& arms,
                              const ExperimentOptions& options) {
  for (std::size_t a = 0; a < arms.size(); ++a) {
    for (std::size_t b = 0; b < a; ++b) {
      if (arms[a].name == arms[b].name) {
        throw std::invalid_argument(std::string(experiment) + ": two arms are named '" +
                                    arms[a].name + "'; an arm's name must be unique");
      }
    }
  }
  // Tasks are arm-major: the arm of a run is found by its name.
  auto body = [&](SeedRun& run, const TelemetryOptions& telemetry) {
    for (const auto& arm : arms) {
      if (arm.name == run.arm) {
        protocol(config, arm, telemetry, options.initial_weights, run);
        return;
      }
    }
  };
  ExperimentResults results = run_tasks(config, names_of(arms), body, options);
  results.experiment = experiment;
  return results;
}

}  // namespace

ExperimentResults run_exp1(const config::Config& config, const std::vector<diagrams::Arm>& arms,
                           const ExperimentOptions& options) {
  return run_per_arm("exp1", run_until_success, config, arms, options);
}

ExperimentResults run_exp3(const config::Config& config, const std::vector<diagrams::Arm>& arms,
                           const ExperimentOptions& options) {
  return run_per_arm("exp3", run_until_skill, config, arms, options);
}

ExperimentResults run_exp2(const config::Config& config, const diagrams::Arm& coordinated,
                           const diagrams::Arm& operant, const ExperimentOptions& options) {
  auto body = [&](SeedRun& run, const TelemetryOptions& telemetry) {
    run_annealing(config, coordinated, operant, telemetry, options.initial_weights, run);
  };
  ExperimentResults results = run_tasks(config, {coordinated.name}, body, options);
  results.experiment = "exp2";
  return results;
}

std::vector<std::string> experiment_arms(const config::Config& config) {
  const config::RunParams run = config::read_parameters(config).run;
  const std::string& experiment = run.experiment;
  if (experiment == "exp1" || experiment == "exp3") return run.arms;
  if (experiment == "exp2") return {"cbbg"};
  return {experiment};
}

ExperimentResults run_experiment(const config::Config& config, const ExperimentOptions& options) {
  const std::string experiment = config::read_parameters(config).run.experiment;
  if (experiment == "exp2") {
    return run_exp2(config, diagrams::preset_arm("cbbg"), diagrams::preset_arm("bg_only"), options);
  }
  std::vector<diagrams::Arm> arms;
  for (const auto& name : experiment_arms(config)) arms.push_back(diagrams::preset_arm(name));
  if (experiment == "exp3") return run_exp3(config, arms, options);
  ExperimentResults results = run_exp1(config, arms, options);
  results.experiment = experiment;
  return results;
}

}  // namespace cbbg::experiments
