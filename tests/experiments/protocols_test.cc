// Protocols by name: the built-in three and one of the user's, run by run_experiment.

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "cbbg/config/declared_keys.h"
#include "cbbg/diagrams/validated_parameters.h"
#include "cbbg/experiments/protocol_kit.h"
#include "cbbg/experiments/protocols.h"
#include "cbbg/experiments/run_names.h"

namespace cbbg::experiments {
namespace {

using ::testing::ThrowsMessage;

// Two trials per seed, whatever happens: from 0.05 rad, then from trial.theta0.
void two_trials(const parameters::Parameters& p, const diagrams::Arm& arm,
                const TelemetryOptions& telemetry, const LearntWeights* initial, SeedRun& run) {
  SeedLoop seed(p, arm, telemetry, initial, run.seed);
  run.trials.push_back(next_trial(p, seed, 1, 0.05));
  run.trials.push_back(next_trial(p, seed, 2));
  finish_run(p, arm, seed.loop, seed.runner.context(), run);
}

TEST(Protocols, TheBuiltInThreeComeFirst) {
  ASSERT_GE(protocols().size(), 3U);
  EXPECT_EQ(protocols()[0].name, "exp1");
  EXPECT_EQ(protocols()[1].name, "exp2");
  EXPECT_EQ(protocols()[2].name, "exp3");
  parameters::RunParams run;
  run.experiment = "exp2";
  EXPECT_EQ(experiment_arms(run), (std::vector<std::string>{"cbbg"}));
  run.experiment = "exp3";
  run.arms = {"bg_only", "pd_only"};
  EXPECT_EQ(experiment_arms(run), run.arms);
  run.experiment = "cb_only";  // an arm alone
  EXPECT_EQ(experiment_arms(run), (std::vector<std::string>{"cb_only"}));
  EXPECT_EQ(find_protocol("cb_only"), nullptr);
}

TEST(Protocols, ARegisteredProtocolRunsByItsName) {
  register_protocol(
      {.name = "two_trials",
       .meaning = "two trials per seed",
       .run = [](const parameters::Parameters& p, const std::vector<diagrams::Arm>& arms,
                 const ExperimentOptions& options) {
         return run_per_arm("two_trials", two_trials, p, arms, options);
       }});
  EXPECT_EQ(protocol_names().back().name, "two_trials");
  EXPECT_NO_THROW(check_experiment_name("two_trials"));

  config::Config config;
  config.set("plant.kind=analytic");
  config.set("experiment=two_trials");
  config.set("arms=[pd_only,bg_only]");
  config.set("seeds=2");
  config.set("trial.duration=0.2");
  config.set("evaluation.angles=[0.1]");
  const ExperimentResults results = run_experiment(diagrams::validated_parameters(config));
  EXPECT_EQ(results.experiment, "two_trials");
  EXPECT_TRUE(results.compares_arms);
  EXPECT_EQ(results.arms, (std::vector<std::string>{"pd_only", "bg_only"}));
  ASSERT_EQ(results.runs.size(), 4U);
  for (const SeedRun& run : results.runs) EXPECT_EQ(run.trials.size(), 2U);
  EXPECT_EQ(results.run(0, 0).evaluation.size(), 1U);  // finished as exp1's are

  EXPECT_THAT([] { register_protocol({.name = "two_trials", .run = {}}); },
              ThrowsMessage<std::invalid_argument>("protocol 'two_trials' is registered twice"));
  EXPECT_THAT([] { register_protocol({.name = "cbbg", .run = {}}); },
              ThrowsMessage<std::invalid_argument>("protocol 'cbbg': an arm has that name"));
  EXPECT_THAT([] { register_protocol({.name = "no run", .run = {}}); },
              ThrowsMessage<std::invalid_argument>(
                  "protocol 'no run': a name is letters, digits, '_', '-' and '.'"));
  EXPECT_THAT([] { register_protocol({.name = "norun", .run = {}}); },
              ThrowsMessage<std::invalid_argument>("protocol 'norun' has no run"));
}

// A protocol's own section, registered with it: placed where it asked in every config made
// after, read back from the tree's registered values, and never registered twice.
struct WarmUpParams {
  double first_angle = 0.05;

  template <class Archive>
  void describe(Archive& a) {
    a.number("first_angle", first_angle, "warm_up: the first trial's pitch, rad", kFinite);
  }
};

TEST(Protocols, AProtocolsOwnKeysAreRegisteredWithItWhereItPlacesThem) {
  double first_angle = 0.0;
  register_protocol(
      {.name = "warm_up",
       .run =
           [&first_angle](const parameters::Parameters& p, const std::vector<diagrams::Arm>&,
                          const ExperimentOptions&) {
             first_angle = config::read_section<WarmUpParams>(p.own, "warm_up").first_angle;
             return ExperimentResults{};
           },
       .keys = config::declared_keys(WarmUpParams{}, "warm_up"),
       .keys_after = "trial"});
  std::vector<std::string> paths;
  for (const config::KeySpec& key : config::schema()) paths.push_back(key.path);
  const auto placed = std::find(paths.begin(), paths.end(), "warm_up.first_angle");
  ASSERT_NE(placed, paths.end());
  EXPECT_EQ(*(placed - 1), "trial.settle_time");  // the trial section's last key
  EXPECT_TRUE(is_protocol_key("warm_up.first_angle"));
  EXPECT_TRUE(is_protocol_key("exp3.angles"));
  EXPECT_FALSE(is_protocol_key("trial.theta0"));

  config::Config config;
  config.set("experiment=warm_up");
  config.set("warm_up.first_angle=0.07");
  run_experiment(diagrams::validated_parameters(config));
  EXPECT_EQ(first_angle, 0.07);

  EXPECT_THAT(
      [] {
        register_protocol(
            {.name = "warm_up_again",
             .run = [](const parameters::Parameters&, const std::vector<diagrams::Arm>&,
                       const ExperimentOptions&) { return ExperimentResults{}; },
             .keys = config::declared_keys(WarmUpParams{}, "warm_up")});
      },
      ThrowsMessage<std::invalid_argument>("config key 'warm_up.first_angle' is declared twice"));
  EXPECT_EQ(find_protocol("warm_up_again"), nullptr);
}

// evaluate: no training, the given weights evaluated per seed as exp1 evaluates what it
// learnt; without weights, an arm that learns is refused before any work.
TEST(Protocols, EvaluateTestsTheGivenWeightsAsExp1EvaluatesWhatItLearnt) {
  config::Config config;
  config.set("plant.kind=analytic");
  config.set("arms=[bg_only]");
  config.set("seeds=1");
  config.set("max_trials=3");
  const ExperimentResults exp1 = run_experiment(diagrams::validated_parameters(config));
  ASSERT_TRUE(exp1.runs[0].weights.has_value());
  config.set("experiment=evaluate");
  ExperimentOptions options;
  options.initial_weights = &*exp1.runs[0].weights;
  const ExperimentResults evaluated =
      run_experiment(diagrams::validated_parameters(config), options);
  EXPECT_EQ(evaluated.experiment, "evaluate");
  ASSERT_EQ(evaluated.runs.size(), 1U);
  EXPECT_TRUE(evaluated.runs[0].trials.empty());
  ASSERT_EQ(evaluated.runs[0].evaluation.size(), exp1.runs[0].evaluation.size());
  for (std::size_t e = 0; e < exp1.runs[0].evaluation.size(); ++e) {
    EXPECT_EQ(evaluated.runs[0].evaluation[e].outcome.steps,
              exp1.runs[0].evaluation[e].outcome.steps);
    EXPECT_EQ(evaluated.runs[0].evaluation[e].outcome.final_theta,
              exp1.runs[0].evaluation[e].outcome.final_theta);
  }
  EXPECT_THAT([&] { run_experiment(diagrams::validated_parameters(config)); },
              ThrowsMessage<config::ConfigError>(
                  "the evaluate protocol tests the weights of --load-weights; arm 'bg_only' "
                  "learns and none were given"));
}

// The results directory, sweeps, the console and the checks read a protocol's schema; only its
// own files (and the parameters it declares) spell its name, and only they and the library's
// study scripts its figures' names: store/ and apps/ never.
TEST(Protocols, NoCodeOutsideAProtocolsFilesNamesIt) {
  const std::filesystem::path source = CBBG_SOURCE_DIR;
  const std::filesystem::path experiments = source / "experiments";
  const std::vector<std::filesystem::path> own{experiments / "exp1.cc",
                                               experiments / "exp2.cc",
                                               experiments / "exp2_params.h",
                                               experiments / "exp3.cc",
                                               experiments / "exp3_params.h",
                                               experiments / "evaluate.cc",
                                               experiments / "transfer.h",
                                               experiments / "transfer.cc",
                                               experiments / "transfer_params.h",
                                               experiments / "realtime.cc",
                                               experiments / "realtime_params.h",
                                               experiments / "experiments.h",
                                               source / "parameters" / "parameters.h"};
  int files = 0;
  for (const char* folder : {"apps", "blocks", "config", "diagrams", "experiments", "parameters",
                             "plant", "records", "replay", "store"}) {
    for (const auto& entry : std::filesystem::recursive_directory_iterator(source / folder)) {
      const std::string ending = entry.path().extension().string();
      if (ending != ".cc" && ending != ".h") continue;
      if (std::find(own.begin(), own.end(), entry.path()) != own.end()) continue;
      ++files;
      std::ifstream in(entry.path());
      std::stringstream text;
      text << in.rdbuf();
      for (const char* name :
           {"\"exp1\"", "\"exp2\"", "\"exp3\"", "\"evaluate\"", "\"transfer\"", "\"realtime\""}) {
        EXPECT_EQ(text.str().find(name), std::string::npos) << entry.path() << ": " << name;
      }
      if (std::string(folder) == "store") {  // below the protocols: it knows their schema alone
        EXPECT_EQ(text.str().find("cbbg/experiments/"), std::string::npos) << entry.path();
      }
      if (std::string(folder) == "config") {  // a generic engine: whoever declares keys is above
        for (const char* above : {"cbbg/blocks/", "cbbg/plant/", "cbbg/parameters/",
                                  "cbbg/diagrams/", "cbbg/experiments/"}) {
          EXPECT_EQ(text.str().find(above), std::string::npos) << entry.path() << ": " << above;
        }
      }
      if (std::string(folder) != "store" && std::string(folder) != "apps") continue;
      for (const char* figure :
           {"trials_to_skill", "failures_to_skill", "actor_alone", "skill_", "\"pitch_rms\"",
            "\"pitch_peak_to_peak\"", "\"mean_forward_speed\"", "balanced_trials", "balanced@",
            "evaluated@", "\"skilled\""}) {
        EXPECT_EQ(text.str().find(figure), std::string::npos) << entry.path() << ": " << figure;
      }
    }
  }
  EXPECT_GE(files, 100);
}

}  // namespace
}  // namespace cbbg::experiments
