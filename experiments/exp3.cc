// exp3 (skill acquisition): per arm and seed, trials past the first success until the learnt
// actor alone balances from every exp3.angles, then the run's learnt actor evaluated.

#include "cbbg/config/declared_keys.h"
#include "cbbg/experiments/builtin_protocols.h"
#include "cbbg/experiments/exp3_params.h"
#include "cbbg/experiments/experiments.h"
#include "cbbg/experiments/policy_evaluation.h"
#include "cbbg/experiments/protocol_kit.h"

namespace cbbg::experiments {
namespace {

std::vector<double> skill_angles(const parameters::Parameters& p) {
  return config::read_section<Exp3Params>(p.own, Exp3Params::kSection).angles;
}

// The test after a trial: the weights learnt so far, frozen, with the actor alone, from each of
// exp3.angles in turn (stopping at the first that fails).
bool actor_alone_balances(const parameters::Parameters& p, const diagrams::Arm& arm,
                          const LearntWeights& weights, long long seed) {
  const parameters::Parameters tested = with_seed(p, seed);
  for (const double angle : skill_angles(p)) {
    EvaluationSettings settings;
    settings.angles = {angle};
    const PolicyEvaluation evaluation = evaluate_policy(tested, arm.policy, weights, settings);
    if (evaluation.angles.front().balanced() == 0) return false;
  }
  return true;
}

}  // namespace

void check_skill_angles(const parameters::Parameters& p) {
  const std::vector<double> angles = skill_angles(p);
  for (std::size_t i = 0; i < angles.size(); ++i) {
    p.check_inside_failure_angle("exp3.angles[" + std::to_string(i) + "]", angles[i]);
  }
}

SkillTest train_until_skill(const parameters::Parameters& p, const diagrams::Arm& arm,
                            const TelemetryOptions& telemetry, const LearntWeights* initial_weights,
                            SeedRun& run) {
  SeedLoop seed(p, arm, telemetry, initial_weights, run.seed);
  TrialRunner& runner = seed.runner;
  const diagrams::ClosedLoop& loop = seed.loop;
  const bool has_actor = loop.learner.learns() && static_cast<bool>(arm.policy);
  SkillTest test;
  int failures = 0;
  for (int trial = 1; trial <= p.run.max_trials; ++trial) {
    run.trials.push_back(next_trial(p, seed, trial));
    const bool success = run.trials.back().outcome.status == TrialStatus::kSuccess;
    if (!success) ++failures;
    if (success && !run.succeeded) {
      run.succeeded = true;
      run.failures_before_success = failures;
    }
    std::optional<bool> passed;
    if (has_actor) {
      const LearntWeights weights = learnt_weights(loop, runner.context(), provenance(p, run));
      passed = weights.actor.all_finite() && actor_alone_balances(p, arm, weights, run.seed);
    }
    test.passed.push_back(passed);
    if (passed.value_or(false)) {
      test.trials = trial;
      test.failures = failures;
      break;
    }
    if (!has_actor && run.succeeded) break;
  }
  if (!run.succeeded) run.failures_before_success = failures;
  finish_run(p, arm, loop, runner.context(), run);
  return test;
}

void run_until_skill(const parameters::Parameters& p, const diagrams::Arm& arm,
                     const TelemetryOptions& telemetry, const LearntWeights* initial_weights,
                     SeedRun& run) {
  const SkillTest test = train_until_skill(p, arm, telemetry, initial_weights, run);
  for (std::size_t t = 0; t < test.passed.size(); ++t) {
    if (test.passed[t])
      run.trials[t].values.push_back({"actor_alone", *test.passed[t] ? 1.0 : 0.0});
  }
  const auto count = [](std::optional<int> value) -> std::optional<double> {
    if (value) return *value;
    return std::nullopt;
  };
  run.figures.push_back({"trials_to_skill", count(test.trials)});
  run.figures.push_back({"failures_to_skill", count(test.failures)});
}

ExperimentResults run_exp3(const parameters::Parameters& parameters,
                           const std::vector<diagrams::Arm>& arms,
                           const ExperimentOptions& options) {
  return run_per_arm("exp3", run_until_skill, parameters, arms, options);
}

Protocol exp3_protocol() {
  return {
      .name = "exp3",
      .meaning =
          "per arm and seed: trials until the learnt actor alone balances from every "
          "exp3.angles (skill acquisition)",
      .run = [](const parameters::Parameters& p, const std::vector<diagrams::Arm>& arms,
                const ExperimentOptions& options) { return run_exp3(p, arms, options); },
      .schema =
          [](const parameters::Parameters&) {
            return ResultsSchema{
                .trial_columns = {{"actor_alone", ValueType::kFlag,
                                   "whether the learnt actor alone balanced from every exp3.angles "
                                   "after this trial (empty for an arm without an actor)"}},
                .figures = {{.name = "trials_to_skill",
                             .type = ValueType::kInteger,
                             .meaning = "the trial after which the actor alone first balanced",
                             .summary = FigureSummary::kList,
                             .statistics = {"num_skilled", "skill_median", "skill_min",
                                            "skill_max"},
                             .paired = true,
                             .missing = Missing::kBeyondMaxTrials,
                             .console = "trials until the actor alone balances; of the seeds that "
                                        "got there"},
                            {.name = "failures_to_skill",
                             .type = ValueType::kInteger,
                             .meaning = "the failed trials before trials_to_skill",
                             .summary = FigureSummary::kList}},
                .plots = {"pitch", "failures", "skill"}};
          },
      .check = [](const parameters::Parameters& p, const LearntWeights*) { check_skill_angles(p); },
      .keys = config::declared_keys(Exp3Params{}, Exp3Params::kSection),
      .keys_after = Exp3Params::kKeysAfter};
}

}  // namespace cbbg::experiments
