#include "cbbg/experiments/transfer.h"

#include <string_view>

#include "cbbg/config/config.h"
#include "cbbg/config/declared_keys.h"
#include "cbbg/diagrams/validated_parameters.h"
#include "cbbg/experiments/builtin_protocols.h"
#include "cbbg/experiments/evaluation_conditions.h"
#include "cbbg/experiments/experiments.h"
#include "cbbg/experiments/protocol_kit.h"
#include "cbbg/experiments/shared_evaluations.h"
#include "cbbg/experiments/transfer_params.h"

namespace cbbg::experiments {
namespace {

TransferParams transfer_params(const parameters::Parameters& p) {
  return config::read_section<TransferParams>(p.own, TransferParams::kSection);
}

// What a condition may change: what the evaluation sees, never what is learnt or how.
bool condition_may_set(const std::string& key, const parameters::Parameters& p) {
  for (const char* section : {"evaluation.", "sensors.", "push."}) {
    if (key.starts_with(section)) return true;
  }
  if (key.starts_with("plant.")) return key != "plant.kind";
  return p.own.values.contains(key) && !is_protocol_key(key);
}

TransferCondition applied(const parameters::Parameters& p, const std::string& entry,
                          const std::string& label) {
  for (const auto& [key, value] : config::split_settings(entry)) {
    if (!condition_may_set(key, p)) {
      throw config::ConfigError(label +
                                ": a condition sets what the evaluation sees: keys of "
                                "evaluation.*, plant.* (not plant.kind), sensors.*, "
                                "push.* or a registered section; got '" +
                                key + "'");
    }
  }
  const std::string source = label + " '" + entry + "'";
  try {
    TransferCondition condition{entry, diagrams::validated_with_settings(p, entry, source),
                                !diagrams::settings_change(p, entry)};
    check_evaluation_conditions(condition.parameters);
    return condition;
  } catch (const config::ConfigError& error) {
    if (std::string_view(error.what()).starts_with(source)) throw;
    throw config::ConfigError(source + ": " + error.what());
  }
}

int balanced(const std::vector<EvaluationRecord>& records) {
  int count = 0;
  for (const auto& record : records) count += record.outcome.status == TrialStatus::kSuccess;
  return count;
}

// What `run` left, evaluated under each condition. An arm that learns nothing is evaluated
// as it is, the same under every seed unless a block draws a random number: the seeds share
// such an evaluation.
std::vector<std::vector<EvaluationRecord>> evaluate_conditions(
    const std::vector<TransferCondition>& conditions, const diagrams::Arm& arm, const SeedRun& run,
    SharedEvaluations& shared) {
  const bool learns_nothing = !run.weights && !run.weights_diverged;
  const SharedEvaluations::Evaluate evaluate = [&](std::size_t c) -> SeedEvaluation {
    const TransferCondition& condition = conditions[c];
    if (condition.changes_nothing) return {run.evaluation, false};  // this seed's own, at hand
    if (learns_nothing) return evaluate_seed(condition.parameters, arm, nullptr, run.seed);
    return {evaluate_run(condition.parameters, arm, run), false};
  };
  if (learns_nothing) return shared.evaluate(arm.name, conditions.size(), evaluate);
  std::vector<std::vector<EvaluationRecord>> evaluations;
  for (std::size_t c = 0; c < conditions.size(); ++c) evaluations.push_back(evaluate(c).records);
  return evaluations;
}

}  // namespace

std::vector<TransferCondition> transfer_conditions(const parameters::Parameters& p) {
  std::vector<TransferCondition> conditions;
  const std::vector<std::string> entries = transfer_params(p).conditions;
  for (std::size_t i = 0; i < entries.size(); ++i) {
    conditions.push_back(applied(p, entries[i], "transfer.conditions[" + std::to_string(i) + "]"));
  }
  return conditions;
}

std::vector<TransferCondition> check_transfer(const parameters::Parameters& p,
                                              const std::vector<diagrams::Arm>& arms) {
  if (transfer_params(p).training == TransferTraining::kUntilSkill) check_skill_angles(p);
  std::vector<TransferCondition> conditions = transfer_conditions(p);
  for (const auto& condition : conditions) {
    for (const auto& arm : arms) {
      if (changes_robot(condition.parameters.evaluation)) {
        check_plant_takes_conditions(condition.parameters.evaluation,
                                     arm.learner(condition.parameters));
      }
      check_plant_takes_push(condition.parameters, arm.learner);
    }
  }
  return conditions;
}

ExperimentResults run_transfer(const parameters::Parameters& p,
                               const std::vector<diagrams::Arm>& arms,
                               const ExperimentOptions& options) {
  const std::vector<TransferCondition> conditions = check_transfer(p, arms);
  const bool until_skill = transfer_params(p).training == TransferTraining::kUntilSkill;
  SharedEvaluations shared;
  const PerSeed per_seed = [&](const parameters::Parameters& q, const diagrams::Arm& arm,
                               const TelemetryOptions& telemetry,
                               const LearntWeights* initial_weights, SeedRun& run) {
    std::optional<SkillTest> skill;
    if (until_skill) {
      skill = train_until_skill(q, arm, telemetry, initial_weights, run);
    } else {
      run_until_success(q, arm, telemetry, initial_weights, run);
    }
    const std::vector<std::vector<EvaluationRecord>> evaluations =
        evaluate_conditions(conditions, arm, run, shared);
    for (std::size_t c = 0; c < conditions.size(); ++c) {
      run.figures.push_back({"balanced@" + conditions[c].name, double(balanced(evaluations[c]))});
      run.figures.push_back({"evaluated@" + conditions[c].name, double(evaluations[c].size())});
    }
    if (skill) {
      // exp3's own figure, so that one run answers "how fast" beside "how robust": the trial
      // after which the actor came to balance alone (none, for an arm without one or when
      // max_trials came first).
      run.figures.push_back({"skilled", skill->trials ? 1.0 : 0.0});
      std::optional<double> trials;
      if (skill->trials) trials = *skill->trials;
      run.figures.push_back({"trials_to_skill", trials});
    }
  };
  return run_per_arm("transfer", per_seed, p, arms, options);
}

ResultsSchema transfer_schema(const parameters::Parameters& p) {
  ResultsSchema schema{.plots = {"pitch", "failures", "figures"}};
  for (const std::string& condition : transfer_params(p).conditions) {
    schema.figures.push_back({.name = "balanced@" + condition,
                              .type = ValueType::kInteger,
                              .meaning = "evaluation runs that balanced under " + condition,
                              .paired = true});
    schema.figures.push_back({.name = "evaluated@" + condition,
                              .type = ValueType::kInteger,
                              .meaning = "evaluation runs under " + condition});
  }
  if (transfer_params(p).training == TransferTraining::kUntilSkill) {
    schema.figures.push_back({.name = "skilled",
                              .type = ValueType::kInteger,
                              .meaning = "1 when the actor alone came to balance, else 0"});
    schema.figures.push_back({.name = "trials_to_skill",
                              .type = ValueType::kInteger,
                              .meaning = "the trial after which the actor alone first balanced",
                              .summary = FigureSummary::kList,
                              .statistics = {"", "skill_median", "skill_min", "skill_max"},
                              .paired = true,
                              .missing = Missing::kBeyondMaxTrials,
                              .console = "trials until the actor alone balances; of the seeds "
                                         "that got there"});
  }
  return schema;
}

Protocol transfer_protocol() {
  return {
      .name = "transfer",
      .meaning =
          "per arm and seed: one training (transfer.training), then evaluated under "
          "each of transfer.conditions",
      .run = [](const parameters::Parameters& p, const std::vector<diagrams::Arm>& arms,
                const ExperimentOptions& options) { return run_transfer(p, arms, options); },
      .schema = transfer_schema,
      .check = [](const parameters::Parameters& p,
                  const LearntWeights*) { check_transfer(p, diagrams::named_arms(p.run.arms)); },
      .keys = config::declared_keys(TransferParams{}, TransferParams::kSection),
      .keys_after = TransferParams::kKeysAfter};
}

}  // namespace cbbg::experiments
