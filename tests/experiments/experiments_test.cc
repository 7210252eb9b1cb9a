#include "cbbg/experiments/experiments.h"
#include "cbbg/experiments/run_names.h"

#include <algorithm>
#include <cmath>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "cbbg/diagrams/presets.h"
#include "cbbg/diagrams/telemetry.h"
#include "cbbg/plant/plant_ports.h"
#include "cbbg/store/results_writer.h"
#include "cbbg/store/task_store.h"

namespace cbbg::experiments {
namespace {

using namespace cbbg::diagrams;
using namespace cbbg::experiments;
using namespace cbbg::store;

using ::testing::HasSubstr;

// The analytic plant keeps these tests quick.
config::Config quick_config() {
  config::Config config;
  config.set("plant.kind=analytic");
  config.set("seeds=2");
  return config;
}

TEST(TrialRunner, ATrialReachingItsDurationSucceeds) {
  const config::Config config = quick_config();
  const auto controller = build_preset("pd_only", parameters::read_parameters(config));
  TrialRunner runner(controller, 1, config.number("trial.period"));
  const TrialOutcome outcome = runner.run_trial(0.1744, 2.0);
  EXPECT_EQ(outcome.status, TrialStatus::kSuccess);
  EXPECT_EQ(outcome.steps, 200);  // ticks at 0, 0.01, ..., 1.99
}

// The telemetry's pose is the plant's: on a straight run the axle rolls R (phi_l + phi_r) / 2
// along x, on both plants.
TEST(TrialRunner, RecordsThePoseTheWheelsRolledTo) {
  for (const char* kind : {"analytic", "simbody"}) {
    config::Config config = quick_config();
    config.set(std::string("plant.kind=") + kind);
    const auto controller = build_preset("pd_only", parameters::read_parameters(config));
    TrialRunner runner(controller, 1, config.number("trial.period"));
    ASSERT_EQ(runner.run_trial(0.1744, 2.0).status, TrialStatus::kSuccess);
    const auto values = runner.telemetry().values();
    const Eigen::Index last = values.cols() - 1;
    const double rolled = config.number("plant.wheel_radius") *
                          (values(kTelemetryPhiLeft, last) + values(kTelemetryPhiRight, last)) / 2;
    EXPECT_GT(std::abs(rolled), 0.05) << kind;  // it moved
    EXPECT_NEAR(values(kTelemetryX, last), rolled, 1e-6) << kind;
    EXPECT_NEAR(values(kTelemetryY, last), 0.0, 1e-9) << kind;
    EXPECT_NEAR(values(kTelemetryYaw, last), 0.0, 1e-9) << kind;
    EXPECT_EQ(values(kTelemetryX, 0), 0.0) << kind;
  }
}

// The oscillation figures are the telemetry's, from the settle time on: recomputed here
// from the kept log.
TEST(TrialRunner, MeasuresTheOscillationAfterTheSettleTime) {
  const config::Config config = quick_config();
  const auto controller = build_preset("pd_only", parameters::read_parameters(config));
  TelemetryOptions telemetry;
  telemetry.settle_time = 2.0;
  TrialRunner runner(controller, 1, config.number("trial.period"), telemetry);
  const TrialOutcome outcome = runner.run_trial(0.1744, 6.0);
  ASSERT_EQ(outcome.status, TrialStatus::kSuccess);
  const auto& times = runner.telemetry().times();
  const auto values = runner.telemetry().values();
  double sum = 0.0;
  double squares = 0.0;
  double low = 1e9;
  double high = -1e9;
  long long n = 0;
  std::size_t first = 0;
  std::size_t last = 0;
  for (std::size_t k = 0; k < times.size(); ++k) {
    if (times[k] < 2.0) continue;
    const double pitch = values(diagrams::kTelemetryThetaB, static_cast<Eigen::Index>(k));
    if (n == 0) first = k;
    last = k;
    sum += pitch;
    squares += pitch * pitch;
    low = std::min(low, pitch);
    high = std::max(high, pitch);
    ++n;
  }
  ASSERT_EQ(n, 400);  // ticks at 2.00, 2.01, ..., 5.99
  auto wheels = [&values](std::size_t k) {
    const auto column = static_cast<Eigen::Index>(k);
    return 0.5 * (values(diagrams::kTelemetryPhiLeft, column) +
                  values(diagrams::kTelemetryPhiRight, column));
  };
  const double mean = sum / 400.0;
  EXPECT_NEAR(outcome.pitch_rms, std::sqrt(squares / 400.0 - mean * mean), 1e-12);
  EXPECT_DOUBLE_EQ(outcome.pitch_peak_to_peak, high - low);
  EXPECT_DOUBLE_EQ(outcome.mean_forward_speed, config.number("plant.wheel_radius") *
                                                   (wheels(last) - wheels(first)) /
                                                   (times[last] - times[first]));
  // A trial that ends before the settle time has none.
  EXPECT_TRUE(std::isnan(runner.run_trial(0.1744, 1.5).pitch_rms));
}

TEST(Experiments, Exp1CountsFailuresBeforeTheFirstSuccess) {
  config::Config config = quick_config();
  config.set("arms=[cbbg, bg_only]");
  ExperimentOptions two_threads;
  two_threads.jobs = 2;
  const ExperimentResults results =
      run_experiment(parameters::read_parameters(config), two_threads);
  ASSERT_EQ(results.runs.size(), 4u);
  EXPECT_EQ(results.seeds, (std::vector<long long>{1, 2}));
  for (const SeedRun& run : results.runs) {
    ASSERT_FALSE(run.trials.empty());
    EXPECT_TRUE(run.succeeded);
    EXPECT_EQ(run.trials.back().outcome.status, TrialStatus::kSuccess);
    EXPECT_EQ(run.failures_before_success, static_cast<int>(run.trials.size()) - 1);
    EXPECT_EQ(run.evaluation.size(), config.numbers("evaluation.angles").size());
  }
  EXPECT_EQ(results.run(0, 0).arm, "cbbg");
  EXPECT_EQ(results.run(1, 1).arm, "bg_only");
  EXPECT_EQ(results.run(1, 1).seed, 2);
}

// exp3 goes on past the first success until the frozen actor alone balances from every
// exp3.angles; each trial records the test, and the run ends at the first one passed.
TEST(Experiments, Exp3RunsUntilTheActorAloneBalancesFromEveryAngle) {
  config::Config config = quick_config();
  config.set("experiment=exp3");
  config.set("arms=[cbbg, bg_only, pd_only]");
  const ExperimentResults results = run_experiment(parameters::read_parameters(config));
  EXPECT_EQ(results.experiment, "exp3");
  for (std::size_t arm : {0u, 1u}) {
    for (std::size_t seed = 0; seed < 2; ++seed) {
      const SeedRun& run = results.run(arm, seed);
      ASSERT_TRUE(run.figure("trials_to_skill").has_value()) << run.arm << " seed " << run.seed;
      EXPECT_EQ(*run.figure("trials_to_skill"), static_cast<double>(run.trials.size()));
      EXPECT_EQ(run.trials.back().value("actor_alone"), 1.0);
      int failures = 0;
      for (std::size_t t = 0; t < run.trials.size(); ++t) {
        ASSERT_TRUE(run.trials[t].value("actor_alone").has_value());
        if (t + 1 < run.trials.size()) {
          EXPECT_EQ(*run.trials[t].value("actor_alone"), 0.0);
        }
        failures += run.trials[t].outcome.status == TrialStatus::kSuccess ? 0 : 1;
      }
      EXPECT_EQ(*run.figure("failures_to_skill"), failures);
      EXPECT_TRUE(run.succeeded);
      EXPECT_LE(run.failures_before_success, failures);
    }
  }
  // The PD supervisor alone learns nothing: it stops at its first success, with no skill.
  const SeedRun& pd = results.run(2, 0);
  EXPECT_EQ(pd.trials.size(), 1u);
  EXPECT_FALSE(pd.figure("trials_to_skill").has_value());
  EXPECT_FALSE(pd.trials.front().value("actor_alone").has_value());
}

TEST(Experiments, Exp3ReportsASeedThatNeverGetsThereAsSuch) {
  config::Config config = quick_config();
  config.set("experiment=exp3");
  config.set("arms=[bg_only]");
  config.set("max_trials=2");
  const ExperimentResults results = run_experiment(parameters::read_parameters(config));
  for (const SeedRun& run : results.runs) {
    EXPECT_EQ(run.trials.size(), 2u);
    EXPECT_FALSE(run.figure("trials_to_skill").has_value());
    EXPECT_FALSE(run.figure("failures_to_skill").has_value());
  }
  // Its record keeps every test for a resume, and its skill: none.
  const SeedRun back = parse_run(serialize_run(results.runs[0]), "record");
  EXPECT_EQ(back.trials[1].value("actor_alone"), results.runs[0].trials[1].value("actor_alone"));
  EXPECT_FALSE(back.figure("trials_to_skill").has_value());
  EXPECT_THAT(figures_csv(results), HasSubstr("bg_only,1,,\n"));
  EXPECT_THAT(summary_json(results, run_facts(parameters::read_parameters(config))),
              HasSubstr("\"trials_to_skill\": [null, null],\n      \"failures_to_skill\": "
                        "[null, null],\n      \"num_skilled\": 0,\n      \"skill_median\": "
                        "null"));
}

TEST(Experiments, ASeedThatNeverSucceedsCountsAllItsTrials) {
  config::Config config = quick_config();
  config.set("experiment=bg_only");
  config.set("seeds=1");
  config.set("max_trials=3");
  config.set("trial.failure_angle=0.1");  // below theta0: every trial fails at once
  const ExperimentResults results = run_experiment(parameters::read_parameters(config));
  ASSERT_EQ(results.runs.size(), 1u);
  EXPECT_FALSE(results.runs[0].succeeded);
  EXPECT_EQ(results.runs[0].failures_before_success, 3);
  EXPECT_EQ(results.runs[0].trials.size(), 3u);
  EXPECT_THAT(summary_json(results, run_facts(parameters::read_parameters(config))),
              HasSubstr("\"succeeded\": [false]"));
}

TEST(Experiments, ADivergingTrialIsRecordedAndTheRunGoesOn) {
  config::Config config = quick_config();
  config.set("experiment=bg_only");
  config.set("seeds=1");
  config.set("max_trials=3");
  config.set("critic.beta=1e300");  // the critic's weights overflow within a few ticks
  const ExperimentResults results = run_experiment(parameters::read_parameters(config));
  const auto& trials = results.runs.at(0).trials;
  ASSERT_EQ(trials.size(), 3u);
  for (const TrialRecord& record : trials) {
    EXPECT_EQ(record.outcome.status, TrialStatus::kDiverged) << "trial " << record.trial;
    EXPECT_THAT(record.outcome.message,
                HasSubstr("block 'bg_only/controller/basal_ganglia/critic': "));
  }
  EXPECT_FALSE(results.runs[0].succeeded);
  EXPECT_THAT(trials_csv(results), HasSubstr("bg_only,1,3,1,1,"));
  EXPECT_THAT(trials_csv(results), HasSubstr(",nan,diverged\n"));
  // Weights that stopped being finite are marked, neither saved nor evaluated.
  EXPECT_TRUE(results.runs[0].weights_diverged);
  EXPECT_FALSE(results.runs[0].weights.has_value());
  EXPECT_TRUE(results.runs[0].evaluation.empty());
  EXPECT_THAT(summary_json(results, run_facts(parameters::read_parameters(config))),
              HasSubstr("\"weights_diverged\": [true]"));
}

TEST(Experiments, ATemperatureTooLargeToAverageEndsTheTrialAsDiverged) {
  // k1 = 1e308 keeps every tick's T = k1 / (1 + exp(k2 V)) finite, but their sum overflows
  // within a handful of ticks: no trial's mean of them is finite, however soon it falls.
  config::Config config = quick_config();
  config.set("experiment=bg_only");
  config.set("seeds=1");
  config.set("max_trials=2");
  config.set("tropism.k1=1e308");
  const ExperimentResults results = run_experiment(parameters::read_parameters(config));
  const auto& trials = results.runs.at(0).trials;
  ASSERT_EQ(trials.size(), 2u);
  for (const TrialRecord& record : trials) {
    EXPECT_EQ(record.outcome.status, TrialStatus::kDiverged) << "trial " << record.trial;
    EXPECT_EQ(record.outcome.message, "the trial's mean temperature or entropy is not finite")
        << "trial " << record.trial;
  }
  EXPECT_FALSE(results.runs[0].succeeded);
}

TEST(Experiments, Exp2AnnealsK1TrialByTrial) {
  config::Config config = quick_config();
  config.set("experiment=exp2");
  config.set("seeds=1");
  config.set("exp2.trials=12");
  config.set("trial.duration=1");
  const ExperimentResults results = run_experiment(parameters::read_parameters(config));
  ASSERT_EQ(results.runs.size(), 1u);
  const auto& trials = results.runs[0].trials;
  ASSERT_EQ(trials.size(), 12u);
  EXPECT_EQ(trials[0].k1, 10.0);
  EXPECT_EQ(trials[9].k1, 10.0);  // trial 10
  EXPECT_EQ(trials[10].k1, 5.0);  // trial 11
  // T = k1 / (1 + exp(k2 V)) <= k1: the schedule shows in the mean temperature.
  EXPECT_LE(trials[10].outcome.mean_temperature, 5.0);
  EXPECT_GT(trials[9].outcome.mean_temperature, 5.0 * 0.5);
}

TEST(Experiments, Exp1GivesEveryArmOfASeedTheSameRandomStreams) {
  // Two arms with the same options under other names: paired seed by seed, bit for bit.
  config::Config config = quick_config();
  config.set("log.decimation=0");
  const ControllerOptions options = preset("bg_only").options;
  const ExperimentResults results =
      run_exp1(parameters::read_parameters(config),
               {make_arm("first", options), make_arm("second", options)});
  for (std::size_t s = 0; s < results.seeds.size(); ++s) {
    const SeedRun& first = results.run(0, s);
    const SeedRun& second = results.run(1, s);
    ASSERT_EQ(first.trials.size(), second.trials.size()) << "seed " << results.seeds[s];
    for (std::size_t t = 0; t < first.trials.size(); ++t) {
      EXPECT_EQ(first.trials[t].outcome.final_theta, second.trials[t].outcome.final_theta);
      EXPECT_EQ(first.trials[t].outcome.mean_temperature,
                second.trials[t].outcome.mean_temperature);
    }
    EXPECT_EQ(first.weights->actor, second.weights->actor);
  }
  EXPECT_NE(results.run(0, 0).weights->actor, results.run(0, 1).weights->actor);
  EXPECT_THAT(
      [&] {
        run_exp1(parameters::read_parameters(config), {preset_arm("cbbg"), preset_arm("cbbg")});
      },
      ::testing::ThrowsMessage<std::invalid_argument>(
          "exp1: two arms are named 'cbbg'; an arm's name must be unique"));
  EXPECT_THAT(
      [&] { run_exp1(parameters::read_parameters(config), {make_arm("mine/v2", options)}); },
      ::testing::ThrowsMessage<std::invalid_argument>(
          "exp1: arm name 'mine/v2' is not a name (1 to 100 letters, digits, '_', '-' and '.', "
          "not starting with '-' or '.'): it names files and columns of the results"));
}

TEST(Experiments, Exp2CarriesTheCoordinatedTrialsLearningIntoOperantLearning) {
  config::Config config = quick_config();
  config.set("experiment=exp2");
  config.set("seeds=1");
  config.set("exp2.trials=2");
  config.set("log.decimation=0");
  const ExperimentResults results = run_experiment(parameters::read_parameters(config));
  ASSERT_EQ(results.runs.front().trials.size(), 2u);
  // By hand: one cbbg trial, then bg_only continuing from its context.
  const ClosedLoop coordinated = build_preset("cbbg", parameters::read_parameters(config));
  const ClosedLoop operant = build_preset("bg_only", parameters::read_parameters(config));
  TrialRunner first(coordinated, 1, 0.01);
  first.run_trial(0.1744, 20.0);
  TrialRunner later(operant, 1, 0.01);
  later.context().continue_from(first.context());
  EXPECT_EQ(operant.learner.actor->learnt(later.context(), "weights"),
            coordinated.learner.actor->learnt(first.context(), "weights"));
  EXPECT_EQ(operant.learner.critic->learnt(later.context(), "weights"),
            coordinated.learner.critic->learnt(first.context(), "weights"));
  operant.learner.tropism->set_k1(later.context(), 10.0);
  const TrialOutcome second = later.run_trial(0.1744, 20.0);
  EXPECT_EQ(results.runs.front().trials[1].outcome.final_theta, second.final_theta);
  EXPECT_EQ(results.runs.front().trials[1].outcome.steps, second.steps);
}

TEST(Experiments, TheRunsNamesComeFromTheProtocolAndPresetTables) {
  parameters::RunParams run;
  EXPECT_NO_THROW(check_run_names(run));
  run.arms = {"cbbg", "nope"};
  EXPECT_THAT([&] { check_run_names(run); },
              ::testing::ThrowsMessage<config::ConfigError>(
                  "arms[1] must be one of cbbg, cbbg_weighted, bg_only, cb_only, pd_only; got "
                  "'nope'"));
  run.arms = {"cbbg"};
  run.experiment = "learnt_actor";
  EXPECT_THAT([&] { check_run_names(run); },
              ::testing::ThrowsMessage<config::ConfigError>(
                  "experiment must be one of exp1, exp2, exp3, evaluate, transfer, realtime, cbbg, "
                  "cbbg_weighted, bg_only, "
                  "cb_only, pd_only; got 'learnt_actor'"));
  std::vector<std::string> protocols;
  for (const auto& protocol : protocol_names()) protocols.push_back(protocol.name);
  EXPECT_EQ(protocols,
            (std::vector<std::string>{"exp1", "exp2", "exp3", "evaluate", "transfer", "realtime"}));
}

TEST(ResultsWriter, ConfigYamlRecordsTheArmsTheProtocolCompared) {
  config::Config config = quick_config();
  config.set("seeds=1");
  config.set("max_trials=1");
  config.set("trial.duration=0.5");
  config.set("log.decimation=0");
  const ExperimentResults mine =
      run_exp1(parameters::read_parameters(config), {make_arm("mine", preset("bg_only").options)});
  const config::Config recorded = recorded_config(mine, config);
  EXPECT_EQ(recorded.names("arms"), std::vector<std::string>{"mine"});
  EXPECT_THAT(recorded.to_yaml(), HasSubstr("\narms: [mine]\n"));
  // exp2's one arm is not what the arms key means: the config stands as given.
  ExperimentResults one_arm = mine;
  one_arm.compares_arms = false;
  EXPECT_EQ(recorded_config(one_arm, config), config);
}

TEST(ResultsWriter, TrialsCsvHasOneRowPerTrial) {
  ExperimentResults results;
  results.experiment = "exp1";
  results.arms = {"cbbg"};
  results.seeds = {7};
  SeedRun run;
  run.arm = "cbbg";
  run.seed = 7;
  TrialOutcome failed{TrialStatus::kFailed, 53, 5.5, 2.75, 0.53, ""};
  TrialOutcome diverged{TrialStatus::kDiverged, 10, 1.0, 0.0, std::nan(""), "boom"};
  run.trials = {{1, 10.0, failed}, {2, 10.0, diverged}};
  results.runs = {run};
  EXPECT_EQ(trials_csv(results),
            "arm,seed,trial,failed,steps,mean_temperature,mean_entropy,final_theta,status\n"
            "cbbg,7,1,1,53,5.5,2.75,0.53,failed\n"
            "cbbg,7,2,1,10,1,0,nan,diverged\n");
}

}  // namespace
}  // namespace cbbg::experiments
