#include "cbbg/experiments/experiments.h"

#include <stdexcept>

#include "cbbg/config/parameters.h"
#include "cbbg/experiments/evaluation_conditions.h"
#include "cbbg/experiments/policy_evaluation.h"
#include "cbbg/experiments/run_names.h"

namespace cbbg::experiments {
namespace {

// `parameters` with the root seed `seed`: an evaluation after a seed's training uses its
// streams.
config::Parameters with_seed(config::Parameters parameters, long long seed) {
  parameters.run.seed = seed;
  return parameters;
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
void evaluate_run(const config::Parameters& training, const diagrams::Arm& arm, bool learns,
                  SeedRun& run) {
  const config::Parameters p = with_seed(evaluation_parameters(training), run.seed);
  EvaluationSettings settings;
  settings.angles = p.evaluation.angles;
  PolicyEvaluation evaluation;
  if (!learns) {
    evaluation = evaluate_controller(p, arm.learner, settings);
  } else if (arm.policy && run.weights) {
    evaluation = evaluate_policy(p, arm.policy, *run.weights, settings);
  }
  for (const AngleEvaluation& angle : evaluation.angles) {
    run.evaluation.push_back({angle.theta0, angle.runs.front()});
  }
}

WeightsProvenance provenance(const config::Parameters& p, const SeedRun& run) {
  return {run.arm, run.seed, static_cast<long long>(run.trials.size()), p.plant.kind};
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
void finish_run(const config::Parameters& p, const diagrams::Arm& arm,
                const diagrams::ClosedLoop& loop, const Context& context, SeedRun& run) {
  if (loop.learner.learns()) {
    keep_weights(learnt_weights(loop, context, provenance(p, run)), run);
  }
  evaluate_run(p, arm, loop.learner.learns(), run);
}

// One seed of an arm: its learning closed loop and the runner of its trials, started from
// the initial weights when there are some.
struct SeedLoop {
  SeedLoop(const config::Parameters& p, const diagrams::Arm& arm, const TelemetryOptions& telemetry,
           const LearntWeights* initial_weights, long long seed)
      : loop(arm.learner(p)),
        runner(loop, static_cast<std::uint64_t>(seed), p.trial.period, telemetry) {
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

// exp3: trials go on past the first success until the learnt actor alone passes the test
// (or max_trials). An arm that learns nothing has no actor: it stops at its first success.
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
          weights.actor.allFinite() && actor_alone_balances(p, arm, weights, run.seed);
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

std::vector<std::string> names_of(const std::vector<diagrams::Arm>& arms) {
  std::vector<std::string> names;
  for (const auto& arm : arms) names.push_back(arm.name);
  return names;
}

// One seed of one arm under a protocol (exp1's, exp3's).
using ArmProtocol = void (*)(const config::Parameters&, const diagrams::Arm&,
                             const TelemetryOptions&, const LearntWeights*, SeedRun&);

// `protocol` for every (arm, seed), the arms' names unique.
ExperimentResults run_per_arm(const char* experiment, ArmProtocol protocol,
                              const config::Parameters& p, const std::vector<diagrams::Arm>& arms,
                              const ExperimentOptions& options) {
  for (std::size_t a = 0; a < arms.size(); ++a) {
    if (!config::is_name(arms[a].name)) {
      throw std::invalid_argument(std::string(experiment) + ": arm name '" + arms[a].name +
                                  "' is not a name (" + config::kNameRule +
                                  "): it names files and columns of the results");
    }
    for (std::size_t b = 0; b < a; ++b) {
      if (arms[a].name == arms[b].name) {
        throw std::invalid_argument(std::string(experiment) + ": two arms are named '" +
                                    arms[a].name + "'; an arm's name must be unique");
      }
    }
  }
  // Before any training: every arm's plant sees the robot its evaluation changes.
  for (const auto& arm : arms) {
    if (changes_robot(p.evaluation)) {
      check_plant_takes_conditions(p.evaluation, arm.learner(p));
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
  return results;
}

}  // namespace

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

std::vector<std::string> experiment_arms(const config::RunParams& run) {
  const std::string& experiment = run.experiment;
  if (experiment == "exp1" || experiment == "exp3") return run.arms;
  if (experiment == "exp2") return {"cbbg"};
  return {experiment};
}

ExperimentResults run_experiment(const config::Parameters& parameters,
                                 const ExperimentOptions& options) {
  check_run_names(parameters.run);
  const std::string& experiment = parameters.run.experiment;
  if (experiment == "exp2") {
    return run_exp2(parameters, diagrams::preset_arm("cbbg"), diagrams::preset_arm("bg_only"),
                    options);
  }
  std::vector<diagrams::Arm> arms;
  for (const auto& name : experiment_arms(parameters.run)) {
    arms.push_back(diagrams::named_arm(name));
  }
  if (experiment == "exp3") return run_exp3(parameters, arms, options);
  ExperimentResults results = run_exp1(parameters, arms, options);
  results.experiment = experiment;
  return results;
}

}  // namespace cbbg::experiments
