// transfer: one training per arm and seed, evaluated under each condition; a condition's
// figures are those of exp3 run with that setting, and its record and results keep them.

#include "cbbg/experiments/transfer.h"

#include <atomic>
#include <memory>
#include <string>
#include <vector>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "cbbg/blocks/measured_signals.h"
#include "cbbg/diagrams/validated_parameters.h"
#include "cbbg/experiments/experiments.h"
#include "cbbg/experiments/protocols.h"
#include "cbbg/framework/block_context.h"
#include "cbbg/framework/diagram_builder.h"
#include "cbbg/framework/number_text.h"
#include "cbbg/records/paired_statistics.h"
#include "cbbg/store/results_writer.h"
#include "cbbg/store/task_store.h"

namespace cbbg::experiments {
namespace {

using ::testing::ContainsRegex;
using ::testing::HasSubstr;
using ::testing::Not;
using ::testing::ThrowsMessage;

config::Config small_transfer() {
  config::Config config;
  config.set("plant.kind=analytic");
  config.set("experiment=transfer");
  config.set("arms=[bg_only, pd_only]");
  config.set("seeds=2");
  config.set("max_trials=6");
  config.set("evaluation.angles=[0.1, 0.2]");
  config.set(
      "transfer.conditions=[evaluation.body_mass_scale=1.3, evaluation.noise_std=0.05; "
      "evaluation.push_torque=2]");
  return config;
}

int balanced(const std::vector<EvaluationRecord>& records) {
  int count = 0;
  for (const auto& record : records) count += record.outcome.status == TrialStatus::kSuccess;
  return count;
}

TEST(Transfer, AConditionsFiguresAreThoseOfExp3RunWithItsSetting) {
  const config::Config config = small_transfer();
  const ExperimentResults transfer = run_experiment(diagrams::validated_parameters(config));
  ASSERT_EQ(transfer.runs.size(), 4U);
  const std::vector<std::pair<std::string, std::vector<std::string>>> conditions{
      {"evaluation.body_mass_scale=1.3", {"evaluation.body_mass_scale=1.3"}},
      {"evaluation.noise_std=0.05; evaluation.push_torque=2",
       {"evaluation.noise_std=0.05", "evaluation.push_torque=2"}}};
  for (std::size_t c = 0; c < conditions.size(); ++c) {
    config::Config alone = config;
    alone.set("experiment=exp3");
    for (const std::string& setting : conditions[c].second) alone.set(setting);
    const ExperimentResults exp3 = run_experiment(diagrams::validated_parameters(alone));
    for (std::size_t task = 0; task < transfer.runs.size(); ++task) {
      const SeedRun& run = transfer.runs[task];
      ASSERT_EQ(run.figures.size(), 6U);
      EXPECT_EQ(run.figures[2 * c].name, "balanced@" + conditions[c].first);
      EXPECT_EQ(run.figures[2 * c].value, balanced(exp3.runs[task].evaluation)) << task;
      EXPECT_EQ(run.figures[2 * c + 1].name, "evaluated@" + conditions[c].first);
      EXPECT_EQ(run.figures[2 * c + 1].value, double(exp3.runs[task].evaluation.size()));
      // The training is exp3's, whatever the evaluation, and so are its figures.
      EXPECT_EQ(run.trials.size(), exp3.runs[task].trials.size());
      EXPECT_EQ(run.figures[4].name, "skilled");
      const std::optional<double> skill = exp3.runs[task].figure("trials_to_skill");
      EXPECT_EQ(run.figures[4].value, skill ? 1.0 : 0.0);
      EXPECT_EQ(run.figures[5].name, "trials_to_skill");
      EXPECT_EQ(run.figures[5].value, skill);
    }
  }
}

TEST(Transfer, ItsRecordAndResultsKeepTheFigures) {
  const config::Config config = small_transfer();
  const ExperimentResults results = run_experiment(diagrams::validated_parameters(config));
  const SeedRun back = store::parse_run(store::serialize_run(results.runs[0]), "record");
  EXPECT_EQ(back.figures, results.runs[0].figures);
  const std::string csv = store::figures_csv(results);
  EXPECT_THAT(csv, HasSubstr("arm,seed,balanced@evaluation.body_mass_scale=1.3,"
                             "evaluated@evaluation.body_mass_scale=1.3,"
                             "balanced@evaluation.noise_std=0.05; evaluation.push_torque=2,"));
  // The supervisor alone copes; it has no actor to come to balance alone.
  EXPECT_THAT(csv, HasSubstr("\npd_only,1,2,2,2,2,0,\n"));
  const std::string summary =
      store::summary_json(results, store::run_facts(parameters::read_parameters(config)));
  EXPECT_THAT(summary, HasSubstr("\"figures\": {\"balanced@evaluation.body_mass_scale=1.3\": 4"));
  // Paired over the balanced figures, not over how many ran.
  EXPECT_THAT(summary, HasSubstr("\"figure\": \"balanced@evaluation.body_mass_scale=1.3\""));
  EXPECT_THAT(summary, Not(HasSubstr("\"figure\": \"evaluated@")));
}

// A condition that sets the run's own values takes the run's evaluation, the same records.
TEST(Transfer, AConditionThatChangesNothingTakesTheRunsOwnEvaluation) {
  config::Config config = small_transfer();
  config.set("transfer.conditions=[evaluation.noise_std=0, evaluation.noise_std=0.05]");
  const parameters::Parameters p = diagrams::validated_parameters(config);
  const std::vector<TransferCondition> conditions = transfer_conditions(p);
  ASSERT_EQ(conditions.size(), 2U);
  EXPECT_TRUE(conditions[0].changes_nothing);
  EXPECT_FALSE(conditions[1].changes_nothing);
  const ExperimentResults results = run_experiment(p);
  for (const SeedRun& run : results.runs) {
    EXPECT_EQ(run.figures[0].value, balanced(run.evaluation));
    EXPECT_EQ(run.figures[1].value, double(run.evaluation.size()));
  }
}

TEST(Transfer, AConditionSetsOnlyWhatTheEvaluationSees) {
  config::Config config = small_transfer();
  config.set("transfer.conditions=[critic.gamma=0.5]");
  EXPECT_THAT([&] { transfer_conditions(diagrams::validated_parameters(config)); },
              ThrowsMessage<config::ConfigError>(
                  "transfer.conditions[0]: a condition sets what the evaluation sees: keys of "
                  "evaluation.*, plant.* (not plant.kind), sensors.*, push.* or a registered "
                  "section; got 'critic.gamma'"));
  // A protocol's own keys are how it runs, not what the evaluation sees.
  config.set("transfer.conditions=[exp2.trials=5]");
  EXPECT_THAT([&] { transfer_conditions(diagrams::validated_parameters(config)); },
              ThrowsMessage<config::ConfigError>(HasSubstr("got 'exp2.trials'")));
  config.set("transfer.conditions=[evaluation.body_mass_scale=1e308]");
  EXPECT_THAT([&] { transfer_conditions(diagrams::validated_parameters(config)); },
              ThrowsMessage<config::ConfigError>(
                  HasSubstr("transfer.conditions[0] 'evaluation.body_mass_scale=1e308': ")));
}

TEST(Transfer, TheConfigChecksEachSettingAsItArrives) {
  config::Config config;
  EXPECT_THAT([&] { config.set("transfer.conditions=[evaluation.body_mas_scale=2]"); },
              ThrowsMessage<config::ConfigError>(
                  "--set transfer.conditions=[evaluation.body_mas_scale=2]: "
                  "transfer.conditions[0]: unknown key 'evaluation.body_mas_scale'; did you mean "
                  "'evaluation.body_mass_scale'?"));
  EXPECT_THAT([&] { config.set("transfer.conditions=[evaluation.noise_std=-1]"); },
              ThrowsMessage<config::ConfigError>(
                  "--set transfer.conditions=[evaluation.noise_std=-1]: transfer.conditions[0]: "
                  "evaluation.noise_std must be >= 0; got -1"));
  EXPECT_THAT([&] { config.set("transfer.conditions=[evaluation.noise_std]"); },
              ThrowsMessage<config::ConfigError>(
                  HasSubstr("transfer.conditions[0] must be key=value (several joined by ';')")));
  EXPECT_THAT([&] { config.set("transfer.conditions=[]"); },
              ThrowsMessage<config::ConfigError>(
                  HasSubstr("transfer.conditions must be a non-empty list of settings")));
  config.set("transfer.conditions=[push.torque=1; evaluation.noise_std=0.1]");
  EXPECT_EQ(config::split_settings(config.names("transfer.conditions")[0]),
            (std::vector<std::pair<std::string, std::string>>{{"push.torque", "1"},
                                                              {"evaluation.noise_std", "0.1"}}));
  config::Config back;
  back.merge_yaml(config.to_yaml(), "config.yaml");
  EXPECT_EQ(back, config);
}

// A user's control law on the pitch; with `dither`, plus a small random action drawn from its
// generator every tick.
class PitchLaw final : public Block {
 public:
  PitchLaw(std::string name, bool dither) : Block(std::move(name)) {
    const InputPort& measured = declare_input_port("measured", blocks::kMeasuredSize);
    declare_discrete_state("dither", Vector::Zero(1), StateLifetime::kPerTrial);
    declare_output_port("action", 1,
                        [&measured](const BlockContext& context, VectorRef action) {
                          const auto y = context.input(measured);
                          action[0] = 40.0 * y[blocks::kMeasuredThetaB] +
                                      8.0 * y[blocks::kMeasuredThetaBDot] +
                                      context.discrete_state()[0];
                        },
                        {&measured});
    if (!dither) return;
    declare_periodic_update(0.01, 0.0, [](BlockContext& context, VectorRef next) {
      next[0] = 0.5 * draw_standard_normal(context.random_generator());
      return EventStatus::succeeded();
    });
  }
};

// An arm of the user's that learns nothing, counting the closed loops it builds.
diagrams::Arm pitch_law_arm(bool dither, std::atomic<int>& builds) {
  const diagrams::ControllerFactory controller = [dither, &builds](const parameters::Parameters&) {
    ++builds;
    DiagramBuilder builder("pitch_law");
    auto& law = builder.emplace<PitchLaw>("law", dither);
    builder.export_input(law.input_port("measured"));
    builder.export_output(law.output_port("action"));
    return std::shared_ptr<Diagram>(builder.build());
  };
  return {"pitch_law", diagrams::closed_loop_factory("pitch_law", controller), {}};
}

// The seeds of an arm that learns nothing share a condition's evaluation when it drew no
// random number, with the figures each seed would have alone; one that drew is each seed's.
TEST(Transfer, SeedsShareTheEvaluationsThatDrewNoRandomNumber) {
  config::Config config = small_transfer();
  config.set("seeds=3");
  config.set(
      "transfer.conditions=[evaluation.body_mass_scale=1.3, evaluation.com_height_scale=1.3]");
  const parameters::Parameters p = diagrams::validated_parameters(config);
  std::vector<int> builds_of;
  for (const bool dither : {false, true}) {
    std::atomic<int> builds{0};
    const std::vector<diagrams::Arm> arms{pitch_law_arm(dither, builds)};
    const ExperimentResults transfer = run_transfer(p, arms, {.jobs = 2});
    builds_of.push_back(builds.load());
    for (const std::string setting :
         {"evaluation.body_mass_scale=1.3", "evaluation.com_height_scale=1.3"}) {
      config::Config alone = config;
      alone.set(setting);
      const ExperimentResults exp3 = run_exp3(diagrams::validated_parameters(alone), arms);
      const std::size_t c = setting.starts_with("evaluation.body") ? 0 : 1;
      for (std::size_t task = 0; task < 3; ++task) {
        EXPECT_EQ(transfer.runs[task].figures[2 * c].value, balanced(exp3.runs[task].evaluation))
            << setting << " dither " << dither << " task " << task;
      }
    }
  }
  // Two conditions, three seeds: the dithering law runs each condition for the two seeds
  // that the other takes from the first.
  EXPECT_EQ(builds_of[1] - builds_of[0], 2 * 2);
}

TEST(Transfer, IsARegisteredProtocolWhoseResultsPairTheBalancedFigures) {
  const Protocol* transfer = find_protocol("transfer");
  ASSERT_NE(transfer, nullptr);
  config::Config config = small_transfer();
  config.set("transfer.conditions=[evaluation.noise_std=0.1]");
  const ResultsSchema schema = transfer->schema(diagrams::validated_parameters(config));
  ASSERT_NE(schema.figure("balanced@evaluation.noise_std=0.1"), nullptr);
  EXPECT_TRUE(schema.figure("balanced@evaluation.noise_std=0.1")->paired);
  EXPECT_FALSE(schema.figure("evaluated@evaluation.noise_std=0.1")->paired);
  EXPECT_TRUE(schema.figure("trials_to_skill")->paired);
}

// A seed that never comes to the skill has no trials_to_skill, wherever it is read: an empty
// cell in figures.csv, null in summary.json's list, none in its task record; the paired
// comparison and the median count it as beyond max_trials.
TEST(Transfer, TrialsToSkillIsOneValueWhereverItAppears) {
  config::Config config = small_transfer();
  config.set("arms=[cbbg, bg_only]");
  config.set("max_trials=3");
  const ExperimentResults results = run_experiment(diagrams::validated_parameters(config));
  std::vector<std::vector<double>> paired(2);  // per arm, per seed, as the comparison counts
  const SeedRun* never = nullptr;
  for (std::size_t arm = 0; arm < 2; ++arm) {
    for (std::size_t seed = 0; seed < 2; ++seed) {
      const SeedRun& run = results.run(arm, seed);
      const std::optional<double> trials = run.figure("trials_to_skill");
      EXPECT_EQ(run.figure("skilled"), trials ? 1.0 : 0.0);
      if (!trials) never = &run;
      paired[arm].push_back(trials.value_or(3 + 1));
    }
  }
  ASSERT_NE(never, nullptr) << "a seed that never comes to the skill in 3 trials";
  EXPECT_FALSE(store::parse_run(store::serialize_run(*never), "record")
                   .figure("trials_to_skill")
                   .has_value());
  EXPECT_THAT(store::figures_csv(results),
              HasSubstr("\n" + never->arm + "," + std::to_string(never->seed) + ","));
  EXPECT_THAT(store::figures_csv(results), HasSubstr(",0,\n"));  // skilled 0, no trials
  const std::string summary =
      store::summary_json(results, store::run_facts(parameters::read_parameters(config)));
  EXPECT_THAT(summary, HasSubstr("\"trials_to_skill\": ["));  // per seed, null for none
  EXPECT_THAT(summary, Not(ContainsRegex("\"trials_to_skill\": [0-9]")));  // never summed
  const records::PairedComparison comparison = records::compare_paired(paired[0], paired[1]);
  EXPECT_THAT(summary, HasSubstr("\"figure\": \"trials_to_skill\", \"mean_b_minus_a\": " +
                                 format_number(comparison.mean) + ","));
}

}  // namespace
}  // namespace cbbg::experiments
