#include "cbbg/experiments/training_disturbances.h"

#include <algorithm>
#include <cmath>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "cbbg/diagrams/presets.h"
#include "cbbg/experiments/experiments.h"
#include "cbbg/experiments/protocol_kit.h"
#include "cbbg/experiments/protocols.h"
#include "tests/support/pendulum_robot.h"

namespace cbbg::experiments {
namespace {

using ::testing::ThrowsMessage;

config::Config analytic_config() {
  config::Config config;
  config.set("plant.kind=analytic");
  config.set("seeds=1");
  config.set("log.decimation=0");
  return config;
}

parameters::Parameters with(std::vector<std::string> settings) {
  config::Config config = analytic_config();
  for (const std::string& setting : settings) config.set(setting);
  return parameters::read_parameters(config);
}

// The measured pitch at each trial's first tick, for trials 1..n of one seed of `arm`: the
// initial pitch, plus the sensors' noise.
std::vector<double> first_pitches(const parameters::Parameters& p, const std::string& arm,
                                  int trials) {
  SeedLoop seed(p, diagrams::preset_arm(arm), {}, nullptr, 7);
  std::vector<double> pitches;
  for (int trial = 1; trial <= trials; ++trial) {
    seed.runner.run_trial(p.trial.theta0, 0.05, trial);
    pitches.push_back(seed.runner.telemetry().sample(0)[diagrams::kTelemetryThetaB]);
  }
  return pitches;
}

TEST(TrainingDisturbances, TheSectionIsDeclaredAfterTheEvaluationsAndDisturbsNothingByDefault) {
  const TrainingParams training = training_params(with({}));
  EXPECT_FALSE(training.disturbs());
  EXPECT_EQ(training.push_duration, 0.5);
  const parameters::Parameters nominal = with({});
  EXPECT_EQ(training_loop_parameters(nominal).sensors.noise_std, nominal.sensors.noise_std);
  EXPECT_FALSE(training_loop_parameters(nominal).push.any());
  EXPECT_THAT([] { with({"training.noise_std=-1"}); },
              ThrowsMessage<config::ConfigError>(::testing::HasSubstr("training.noise_std")));
}

TEST(TrainingDisturbances, InitialPitchesSpreadAroundTheta0AndAreTheSameForEveryArmOfASeed) {
  const parameters::Parameters p = with({"training.pitch_spread=0.08"});
  const std::vector<double> cbbg = first_pitches(p, "cbbg", 4);
  EXPECT_EQ(cbbg, first_pitches(p, "bg_only", 4));  // common random numbers
  for (const double pitch : cbbg) {
    EXPECT_GE(pitch, 0.1744 - 0.08);
    EXPECT_LE(pitch, 0.1744 + 0.08);
    EXPECT_NE(pitch, 0.1744);
  }
  EXPECT_NE(cbbg[0], cbbg[1]);
  // Without a spread every trial starts at trial.theta0.
  EXPECT_EQ(first_pitches(with({}), "cbbg", 2), (std::vector<double>{0.1744, 0.1744}));
}

TEST(TrainingDisturbances, TheCurriculumGrowsThemFromNoneAtTheFirstTrial) {
  const parameters::Parameters p =
      with({"training.pitch_spread=0.08", "training.curriculum_trials=2"});
  const TrainingDisturbances disturbances(p, 7);
  EXPECT_EQ(disturbances.share(1), 0.0);
  EXPECT_EQ(disturbances.share(2), 0.5);
  EXPECT_EQ(disturbances.share(3), 1.0);
  EXPECT_EQ(disturbances.share(9), 1.0);
  const std::vector<double> pitches = first_pitches(p, "cbbg", 3);
  EXPECT_EQ(pitches[0], 0.1744);
  EXPECT_LE(std::abs(pitches[1] - 0.1744), 0.04);
  EXPECT_NE(pitches[1], 0.1744);
}

TEST(TrainingDisturbances, TheNoiseGrowsWithTheCurriculumOnThePitchAndItsRate) {
  const parameters::Parameters p =
      with({"training.noise_std=0.05", "training.curriculum_trials=1"});
  const parameters::Parameters loop = training_loop_parameters(p);
  EXPECT_EQ(loop.sensors.noise_std[0], 0.05);
  EXPECT_EQ(loop.sensors.noise_std[1], 0.05);
  EXPECT_EQ(loop.sensors.noise_std[2], 0.0);
  const std::vector<double> pitches = first_pitches(p, "cbbg", 2);
  EXPECT_EQ(pitches[0], 0.1744);  // trial 1: none yet
  EXPECT_NE(pitches[1], 0.1744);  // trial 2: all of it
  EXPECT_LT(std::abs(pitches[1] - 0.1744), 0.05 * 6);
}

TEST(TrainingDisturbances, EachTrialIsPushedOnceWithinTheTrialAndTheForce) {
  const parameters::Parameters p = with({"training.push_force=80", "training.push_duration=0.4"});
  SeedLoop seed(p, diagrams::preset_arm("cbbg"), {}, nullptr, 7);
  const Block* push = nullptr;
  for (const auto& block : seed.loop.diagram->blocks()) {
    if (block->name() == "external_push") push = block.get();
  }
  ASSERT_NE(push, nullptr);
  std::vector<double> forces;
  for (int trial = 1; trial <= 5; ++trial) {
    seed.runner.run_trial(p.trial.theta0, 0.02, trial);
    const auto pulse = seed.runner.context().parameter(*push, "pulse");
    EXPECT_GE(pulse[0], 0.0);
    EXPECT_LE(pulse[0], p.trial.duration - 0.4);
    EXPECT_EQ(pulse[1], 0.4);
    EXPECT_LE(std::abs(pulse[2]), 80.0);
    EXPECT_EQ(pulse[3], 0.0);
    forces.push_back(pulse[2]);
  }
  EXPECT_NE(forces[0], forces[1]);
  EXPECT_TRUE(std::any_of(forces.begin(), forces.end(), [](double f) { return f < 0; }) &&
              std::any_of(forces.begin(), forces.end(), [](double f) { return f > 0; }));
}

TEST(TrainingDisturbances, WhatCannotBeAppliedIsRefusedNamingTheKey) {
  EXPECT_THAT(
      [] {
        check_training(with({"training.push_force=50", "push.torque=1"}));
      },
      ThrowsMessage<config::ConfigError>(
          "training.push_force is 50, but push.* pushes every trial already; a learning trial "
          "takes one push: set push.torque, push.force and push.pitch_torque to 0, or "
          "training.push_force to 0"));
  for (const std::string protocol : {"exp1", "exp2", "exp3", "transfer"}) {
    EXPECT_THAT(
        [&] {
          check_protocol(
              with({"training.push_force=50", "push.torque=1", "experiment=" + protocol}), nullptr);
        },
        ThrowsMessage<config::ConfigError>(::testing::StartsWith("training.push_force is 50")))
        << protocol;
  }
  EXPECT_THAT(
      [] {
        run_exp2(with({"training.push_force=50", "push.torque=1"}), diagrams::preset_arm("cbbg"),
                 diagrams::preset_arm("bg_only"));
      },
      ThrowsMessage<config::ConfigError>(::testing::StartsWith("training.push_force is 50")));
  EXPECT_THAT([] { check_training(with({"training.pitch_spread=0.4"})); },
              ThrowsMessage<config::ConfigError>(
                  "trial.theta0 + training.pitch_spread (0.5744 rad) must lie inside "
                  "trial.failure_angle (0.5236 rad): a trial from there fails at once"));
  diagrams::ClosedLoopOptions pendulum;
  pendulum.plant = [](const std::string& name, const parameters::Parameters&) {
    return std::make_unique<testing::PendulumRobot>(name);
  };
  EXPECT_THAT(
      [&] {
        learning_loop(with({"training.push_force=50"}), diagrams::preset_arm("cbbg", pendulum));
      },
      ThrowsMessage<config::ConfigError>(
          "training.push_force is 50, but arm 'cbbg' has a plant without the input "
          "\"disturbance\" that a push from outside needs; keep training.push_force 0 for it"));
}

TEST(TrainingDisturbances, EachTrialHasABodyMassOfItsOwnWithinTheSpreadCommonToTheArms) {
  const parameters::Parameters p = with({"training.body_mass_spread=0.3"});
  TrainingDisturbances one(p, 7);
  TrainingDisturbances another(p, 7);
  std::vector<double> scales;
  for (int trial = 1; trial <= 6; ++trial) {
    const double mass = one.trial_robot(p, trial).plant.robot.body_mass;
    EXPECT_EQ(another.trial_robot(p, trial).plant.robot.body_mass, mass);
    const double scale = mass / p.plant.robot.body_mass;
    EXPECT_GE(scale, 0.7);
    EXPECT_LE(scale, 1.3);
    scales.push_back(scale);
  }
  EXPECT_TRUE(std::any_of(scales.begin(), scales.end(), [](double s) { return s < 1.0; }) &&
              std::any_of(scales.begin(), scales.end(), [](double s) { return s > 1.0; }));
  const parameters::Parameters grown =
      with({"training.body_mass_spread=0.3", "training.curriculum_trials=4"});
  TrainingDisturbances curriculum(grown, 7);
  EXPECT_EQ(curriculum.trial_robot(grown, 1).plant.robot.body_mass, p.plant.robot.body_mass);
}

// Every trial of a seed with `settings`: its status, steps and final pitch, then the learnt
// weights, for the protocol `protocol`.
std::vector<double> trials_and_weights(const std::string& protocol,
                                       std::vector<std::string> settings) {
  settings.insert(settings.end(), {"experiment=" + protocol, "max_trials=4", "exp2.trials=4",
                                   "trial.duration=4", "arms=[cbbg]"});
  const SeedRun run = run_experiment(with(settings)).run(0, 0);
  std::vector<double> figures;
  for (const TrialRecord& trial : run.trials) {
    figures.insert(figures.end(),
                   {static_cast<double>(trial.outcome.status),
                    static_cast<double>(trial.outcome.steps), trial.outcome.final_theta});
  }
  EXPECT_TRUE(run.weights.has_value()) << protocol;
  if (run.weights) {
    const Vector& actor = run.weights->actor.parts.front().values;
    figures.insert(figures.end(), actor.begin(), actor.end());
  }
  return figures;
}

// A trial's own robot is a loop of its own: the learning, the protocol's parameters (exp2's
// annealed k1) and the random streams go into it and come back, so a spread too small to
// move the robot learns what the nominal robot does.
TEST(TrainingDisturbances, ARobotOfItsOwnCarriesTheLearningFromTrialToTrial) {
  for (const std::string protocol : {"exp1", "exp2", "exp3"}) {
    const std::vector<double> nominal = trials_and_weights(protocol, {});
    const std::vector<double> tiny =
        trials_and_weights(protocol, {"training.body_mass_spread=1e-12"});
    ASSERT_EQ(nominal.size(), tiny.size()) << protocol;
    for (std::size_t i = 0; i < nominal.size(); ++i) {
      EXPECT_NEAR(tiny[i], nominal[i], 1e-6 * (1.0 + std::abs(nominal[i]))) << protocol << " " << i;
    }
    EXPECT_NE(trials_and_weights(protocol, {"training.body_mass_spread=0.5"}), nominal) << protocol;
  }
}

TEST(TrainingDisturbances, ASpreadOfBodyMassesRefusesARunnerOfItsLoopAndAPlantOfTheArmsOwn) {
  const parameters::Parameters p = with({"training.body_mass_spread=0.2"});
  SeedLoop seed(p, diagrams::preset_arm("cbbg"), {}, nullptr, 7);
  EXPECT_THAT([&] { seed.runner.run_trial(p.trial.theta0, 0.05, 1); },
              ThrowsMessage<std::logic_error>(
                  "training.body_mass_spread gives each trial a robot of its own: run the trials "
                  "through SeedLoop::run_trial (or next_trial with the SeedLoop), not its runner"));
  EXPECT_EQ(seed.run_trial(p.trial.theta0, 0.05, 1).status, TrialStatus::kSuccess);
  diagrams::ClosedLoopOptions pendulum;
  pendulum.plant = [](const std::string& name, const parameters::Parameters&) {
    return std::make_unique<testing::PendulumRobot>(name);
  };
  EXPECT_THAT(
      [&] { SeedLoop own(p, diagrams::preset_arm("cbbg", pendulum), {}, nullptr, 7); },
      ThrowsMessage<config::ConfigError>(
          "training.body_mass_spread is 0.2, but plant 'cbbg/plant' is the arm's own, not "
          "plant.kind's, and would learn unchanged; keep training.body_mass_spread 0 for it, or "
          "register the plant as a kind (diagrams/plant_kinds.h)"));
  EXPECT_THAT(
      [] { with({"training.body_mass_spread=1"}); },
      ThrowsMessage<config::ConfigError>(::testing::HasSubstr("training.body_mass_spread")));
}

// The first trial's outcome of every arm and seed of `protocol`.
std::vector<TrialOutcome> first_trials(const std::string& protocol,
                                       std::vector<std::string> settings) {
  settings.insert(settings.end(),
                  {"experiment=" + protocol, "max_trials=2", "exp2.trials=2", "trial.duration=3"});
  std::vector<TrialOutcome> outcomes;
  for (const SeedRun& run : run_experiment(with(settings)).runs) {
    outcomes.push_back(run.trials.front().outcome);
  }
  return outcomes;
}

TEST(TrainingDisturbances, EveryProtocolsLearningTrialsMeetThem) {
  const std::vector<std::string> disturbed{"training.noise_std=0.05", "training.push_force=60",
                                           "training.pitch_spread=0.05",
                                           "training.body_mass_spread=0.3"};
  for (const std::string protocol : {"exp1", "exp2", "exp3", "transfer"}) {
    const std::vector<TrialOutcome> plain = first_trials(protocol, {});
    const std::vector<TrialOutcome> learnt = first_trials(protocol, disturbed);
    ASSERT_EQ(plain.size(), learnt.size()) << protocol;
    for (std::size_t i = 0; i < plain.size(); ++i) {
      EXPECT_FALSE(plain[i].steps == learnt[i].steps &&
                   plain[i].final_theta == learnt[i].final_theta)
          << protocol << " run " << i << ": its first trial met no disturbance";
    }
  }
}

TEST(TrainingDisturbances, TheEvaluationOfWhatWasLearntDoesNotMeetThem) {
  const parameters::Parameters nominal = with({"max_trials=2"});
  const parameters::Parameters disturbed =
      with({"max_trials=2", "training.noise_std=0.05", "training.push_force=60"});
  const diagrams::Arm arm = diagrams::preset_arm("cbbg");
  const SeedRun run = run_exp1(disturbed, {arm}).run(0, 0);
  ASSERT_TRUE(run.weights.has_value());
  const std::vector<EvaluationRecord> under_training = evaluate_run(disturbed, arm, run);
  const std::vector<EvaluationRecord> plain = evaluate_run(nominal, arm, run);
  ASSERT_EQ(under_training.size(), plain.size());
  for (std::size_t i = 0; i < plain.size(); ++i) {
    EXPECT_EQ(under_training[i].outcome.steps, plain[i].outcome.steps);
    EXPECT_EQ(under_training[i].outcome.final_theta, plain[i].outcome.final_theta);
  }
}

}  // namespace
}  // namespace cbbg::experiments
