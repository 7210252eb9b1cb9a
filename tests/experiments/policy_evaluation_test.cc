#include "cbbg/experiments/policy_evaluation.h"
#include "tests/support/scratch_directory.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <limits>
#include <optional>
#include <sstream>
#include <string>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "cbbg/apps/eval_command.h"
#include "cbbg/blocks/torque_push.h"
#include "cbbg/diagrams/plant_kinds.h"
#include "cbbg/diagrams/presets.h"
#include "cbbg/experiments/trial_runner.h"
#include "cbbg/framework/diagram_builder.h"
#include "cbbg/framework/primitives/constant_source.h"
#include "cbbg/framework/simulator.h"
#include "cbbg/store/weights_file.h"

namespace cbbg::experiments {
namespace {

using namespace cbbg::diagrams;
using namespace cbbg::experiments;
using namespace cbbg::store;
using blocks::PushParams;

using ::testing::HasSubstr;
namespace fs = std::filesystem;

// The analytic plant keeps these tests quick.
config::Config analytic_config() {
  config::Config config;
  config.set("plant.kind=analytic");
  return config;
}

// Weights learnt by bg_only (seed 1, analytic plant) up to its first balanced trial.
const LearntWeights& bg_only_weights() {
  static const LearntWeights weights = [] {
    const config::Config config = analytic_config();
    const ClosedLoop learner = build_preset("bg_only", parameters::read_parameters(config));
    TrialRunner runner(learner, 1, config.number("trial.period"));
    int trials = 0;
    bool balanced = false;
    while (!balanced && trials < 30) {
      ++trials;
      balanced =
          runner.run_trial(config.number("trial.theta0"), config.number("trial.duration")).status ==
          TrialStatus::kSuccess;
    }
    EXPECT_TRUE(balanced) << "bg_only did not balance within 30 trials";
    return learnt_weights(learner, runner.context(), {"bg_only", 1, trials, "analytic"});
  }();
  return weights;
}

LearntWeights zero_weights() {
  LearntWeights weights = bg_only_weights();
  weights.actor.weights("actor").setZero();
  weights.critic.weights("critic").setZero();
  return weights;
}

EvaluationSettings from(std::vector<double> angles, int repeats = 1) {
  return EvaluationSettings{std::move(angles), repeats};
}

// The learnt-actor preset, pushed or not.
PolicyEvaluation evaluate(const config::Config& config, const LearntWeights& weights,
                          const EvaluationSettings& settings,
                          std::optional<PushParams> push = std::nullopt) {
  const ClosedLoopFactory policy =
      closed_loop_factory(kLearntActor, preset(kLearntActor).options, {.push = push});
  return evaluate_policy(parameters::read_parameters(config), policy, weights, settings);
}

bool same_bits(double a, double b) {
  return std::bit_cast<std::uint64_t>(a) == std::bit_cast<std::uint64_t>(b);
}

TEST(PolicyEvaluation, ZeroWeightsFallFromTheTrialAngle) {
  const PolicyEvaluation evaluation = evaluate(analytic_config(), zero_weights(), from({0.1744}));
  ASSERT_EQ(evaluation.angles.size(), 1u);
  const TrialOutcome& run = evaluation.angles[0].runs.at(0);
  EXPECT_EQ(run.status, TrialStatus::kFailed);
  EXPECT_EQ(evaluation.angles[0].balanced(), 0);
  // No torque at all: the body falls past pi/6 well within two seconds.
  EXPECT_LT(run.steps, 200);
  EXPECT_GT(std::abs(run.final_theta), 0.5236);
}

TEST(PolicyEvaluation, WeightsLearntByAShortBgOnlyRunBalanceFromASmallAngle) {
  const PolicyEvaluation evaluation = evaluate(analytic_config(), bg_only_weights(), from({0.05}));
  ASSERT_EQ(evaluation.angles.size(), 1u);
  const AngleEvaluation& angle = evaluation.angles[0];
  EXPECT_EQ(angle.theta0, 0.05);
  ASSERT_EQ(angle.runs.size(), 1u);
  EXPECT_EQ(angle.balanced(), 1);
  EXPECT_EQ(angle.runs[0].status, TrialStatus::kSuccess);
  EXPECT_EQ(angle.runs[0].steps, 2000);  // 20 s at 10 ms
}

TEST(PolicyEvaluation, MatchesTheLearntActorDiagramRunByTrialRunner) {
  config::Config config = analytic_config();
  config.set("sensors.noise_std=[0.002, 0.01, 0, 0, 0, 0]");
  config.set("seed=5");
  for (const double theta0 : {0.05, 0.2}) {
    const ClosedLoop policy = build_preset(kLearntActor, parameters::read_parameters(config));
    TrialRunner runner(policy, 5, config.number("trial.period"));
    load_learnt_weights(policy, runner.context(), bg_only_weights());
    const TrialOutcome expected = runner.run_trial(theta0, config.number("trial.duration"));
    const TrialOutcome got = evaluate(config, bg_only_weights(), from({theta0})).angles[0].runs[0];
    EXPECT_EQ(got.status, expected.status) << "from " << theta0;
    EXPECT_EQ(got.steps, expected.steps) << "from " << theta0;
    EXPECT_TRUE(same_bits(got.final_theta, expected.final_theta))
        << "from " << theta0 << ": " << got.final_theta << " vs " << expected.final_theta;
  }
}

TEST(PolicyEvaluation, RepeatsDifferOnlyWithSensorNoise) {
  config::Config config = analytic_config();
  const AngleEvaluation quiet = evaluate(config, bg_only_weights(), from({0.1}, 3)).angles[0];
  ASSERT_EQ(quiet.runs.size(), 3u);
  for (const TrialOutcome& run : quiet.runs) {
    EXPECT_TRUE(same_bits(run.final_theta, quiet.runs[0].final_theta));
    EXPECT_EQ(run.steps, quiet.runs[0].steps);
  }

  config.set("sensors.noise_std=[0.002, 0.01, 0, 0, 0, 0]");
  const AngleEvaluation noisy = evaluate(config, bg_only_weights(), from({0.1}, 3)).angles[0];
  EXPECT_NE(noisy.runs[0].final_theta, noisy.runs[1].final_theta);
  EXPECT_NE(noisy.runs[1].final_theta, noisy.runs[2].final_theta);
  EXPECT_NE(noisy.runs[0].final_theta, noisy.runs[2].final_theta);
  // Repeat r is seed + r, whatever ran before it.
  config.set("seed=2");
  const TrialOutcome second = evaluate(config, bg_only_weights(), from({0.1})).angles[0].runs[0];
  EXPECT_TRUE(same_bits(second.final_theta, noisy.runs[1].final_theta));
  EXPECT_EQ(second.steps, noisy.runs[1].steps);
}

TEST(PolicyEvaluation, AStrongPushFellsABalancingPolicy) {
  const config::Config config = analytic_config();
  const TrialOutcome still = evaluate(config, bg_only_weights(), from({0.05})).angles[0].runs[0];
  ASSERT_EQ(still.status, TrialStatus::kSuccess);

  // A push of nothing changes nothing, bit for bit.
  const TrialOutcome nothing =
      evaluate(config, bg_only_weights(), from({0.05}), PushParams{1.0, 0.0, 1.0})
          .angles[0]
          .runs[0];
  EXPECT_EQ(nothing.steps, still.steps);
  EXPECT_TRUE(same_bits(nothing.final_theta, still.final_theta));

  // The full torque limit on both wheels for a second, from t = 1 s.
  const TrialOutcome pushed =
      evaluate(config, bg_only_weights(), from({0.05}), PushParams{1.0, 5.0, 1.0})
          .angles[0]
          .runs[0];
  EXPECT_EQ(pushed.status, TrialStatus::kFailed);
  EXPECT_GT(pushed.steps, 100);  // it stood until the push began
}

TEST(PolicyEvaluation, APushActsTheSameOnBothPlants) {
  // The push switches at ticks only, so both plants integrate the same piecewise-constant
  // torque: they agree as closely as without a push (docs/model.md §1.4: 1e-6 rad over 3 s).
  config::Config config = analytic_config();
  config.set("trial.duration=1.0");
  const EvaluationSettings settings = from({0.05});
  const PushParams push{0.305, 1.5, 0.2};
  const TrialOutcome analytic =
      evaluate(config, bg_only_weights(), settings, push).angles[0].runs[0];
  config.set("plant.kind=simbody");
  const TrialOutcome simbody =
      evaluate(config, bg_only_weights(), settings, push).angles[0].runs[0];
  ASSERT_EQ(analytic.status, TrialStatus::kSuccess);
  ASSERT_EQ(simbody.status, TrialStatus::kSuccess);
  EXPECT_NEAR(simbody.final_theta, analytic.final_theta, 1e-6);
  const TrialOutcome unpushed = evaluate(config, bg_only_weights(), from({0.05})).angles[0].runs[0];
  EXPECT_GT(std::abs(unpushed.final_theta - simbody.final_theta), 1e-3);  // the push mattered
}

TEST(PolicyEvaluation, RefusesWeightsOfAnotherGrid) {
  config::Config config = analytic_config();
  config.set("rbf.centres=[-1, 0, 1]");
  EXPECT_THAT(([&] { evaluate(config, bg_only_weights(), from({0.1})); }),
              ::testing::ThrowsMessage<std::invalid_argument>(
                  "the weights were made for rbf.centres [-3, -2, -1, 0, 1, 2, 3]; diagram "
                  "'learnt_actor' has rbf.centres [-1, 0, 1]"));
  EXPECT_THAT(
      ([&] { evaluate(analytic_config(), bg_only_weights(), from({})); }),
      ::testing::ThrowsMessage<std::invalid_argument>("evaluation angles: at least one is needed"));
  EXPECT_THAT(
      ([&] { evaluate(analytic_config(), bg_only_weights(), from({0.1}, 0)); }),
      ::testing::ThrowsMessage<std::invalid_argument>("evaluation repeats must be >= 1; got 0"));
}

// cbbg eval, called as the command line calls it.
class EvalCommand : public ::testing::Test {
 protected:
  void SetUp() override {
    scratch_directory_.emplace();
    directory_ = scratch_directory_->path();
    weights_file_ = directory_ / "w.txt";
    save_weights(weights_file_, bg_only_weights());
  }

  app::EvalOptions options() const {
    app::EvalOptions result;
    result.weights_file = weights_file_;
    result.sets = {"plant.kind=analytic"};
    result.angles = "0.05";
    return result;
  }

  struct Outcome {
    int exit_code;
    std::string out;
    std::string err;
  };
  static Outcome run(const app::EvalOptions& options) {
    ::testing::internal::CaptureStdout();
    ::testing::internal::CaptureStderr();
    const int code = app::eval_command(options);
    std::string out = ::testing::internal::GetCapturedStdout();
    return {code, std::move(out), ::testing::internal::GetCapturedStderr()};
  }
  // Runs options that must be refused: exit 2, nothing on stdout; returns stderr.
  static std::string refused(const app::EvalOptions& options) {
    const Outcome outcome = run(options);
    EXPECT_EQ(outcome.exit_code, 2) << outcome.err;
    EXPECT_EQ(outcome.out, "");
    return outcome.err;
  }

  std::optional<cbbg::testing::ScratchDirectory> scratch_directory_;
  fs::path directory_;
  fs::path weights_file_;
};

TEST_F(EvalCommand, BadWeightsOrConfigExitTwoWithOneLine) {
  app::EvalOptions bad = options();
  bad.weights_file.clear();
  EXPECT_EQ(refused(bad), "cbbg: error: --load-weights FILE is required\n");
  bad = options();
  bad.weights_file = directory_ / "missing.txt";
  EXPECT_EQ(refused(bad),
            "cbbg: error: weights file '" + bad.weights_file.string() + "' does not exist\n");
  std::ofstream(directory_ / "broken.txt") << "cbbg-weights 1\narm bg_only\nseed one\n";
  bad.weights_file = directory_ / "broken.txt";
  EXPECT_EQ(refused(bad), "cbbg: error: weights file '" + bad.weights_file.string() +
                              "' line 3: seed 'one' is not an integer\n");
  bad = options();
  bad.sets.push_back("rbf.centres=[-2, -1, 0, 1, 2]");
  EXPECT_EQ(refused(bad), "cbbg: error: weights file '" + weights_file_.string() +
                              "' was made for rbf.centres [-3, -2, -1, 0, 1, 2, 3]; this diagram "
                              "has rbf.centres [-2, -1, 0, 1, 2]\n");
  bad = options();
  bad.sets.push_back("critic.gama=0.5");
  EXPECT_THAT(refused(bad), HasSubstr("unknown key 'critic.gama'; did you mean 'critic.gamma'?"));
}

// plant.kind own_robot: a user's robot, built here as the analytic two-wheeler is, but a robot
// of its own to the weights (diagrams::PlantKind::robot).
void register_own_robot() {
  static const bool done = [] {
    register_plant_kind({.name = "own_robot",
                         .description = "a user's robot",
                         .make = [](const std::string& name, const parameters::Parameters& p) {
                           return plant_kind("analytic").make(name, p);
                         }});
    return true;
  }();
  (void)done;
}

TEST_F(EvalCommand, RunsOnThePlantTheWeightsWereLearntOnUnlessOneIsNamed) {
  register_own_robot();
  LearntWeights own = bg_only_weights();
  own.provenance.plant = "own_robot";
  const fs::path own_file = directory_ / "own.txt";
  save_weights(own_file, own);
  app::EvalOptions unset = options();
  unset.weights_file = own_file;
  unset.sets.clear();  // the default plant.kind is simbody; the weights' own_robot wins
  Outcome outcome = run(unset);
  ASSERT_EQ(outcome.exit_code, 0) << outcome.err;
  EXPECT_THAT(outcome.out, HasSubstr("trial(s) on the own_robot plant\npolicy alone on the "
                                     "own_robot plant for 20 s"));
  EXPECT_THAT(outcome.out, HasSubstr("      0.05        1/1\n"));

  // Named by --set or the config file, another plant of the same robot is evaluated.
  app::EvalOptions named = options();
  named.sets = {"plant.kind=simbody", "trial.duration=0.5"};
  outcome = run(named);
  ASSERT_EQ(outcome.exit_code, 0) << outcome.err;
  EXPECT_THAT(outcome.out, HasSubstr("on the analytic plant\npolicy alone on the simbody plant"));
  const fs::path config = directory_ / "simbody.yaml";
  std::ofstream(config) << "plant:\n  kind: simbody\ntrial:\n  duration: 0.5\n";
  named.sets.clear();
  named.config_file = config;
  outcome = run(named);
  ASSERT_EQ(outcome.exit_code, 0) << outcome.err;
  EXPECT_THAT(outcome.out, HasSubstr("policy alone on the simbody plant for 0.5 s"));
}

TEST_F(EvalCommand, WeightsOfAnotherRobotExitTwoNamingTheFileAndBothPlants) {
  register_own_robot();
  LearntWeights own = bg_only_weights();
  own.provenance.plant = "own_robot";
  const fs::path own_file = directory_ / "own.txt";
  save_weights(own_file, own);
  app::EvalOptions bad = options();  // plant.kind=analytic
  bad.weights_file = own_file;
  EXPECT_EQ(refused(bad), "cbbg: error: weights file '" + own_file.string() +
                              "' was made on plant kind 'own_robot' and cannot be loaded onto "
                              "plant kind 'analytic' (plant.kind): another robot\n");
  // Weights of a plant kind this program does not have: refused on the default plant.
  LearntWeights other = bg_only_weights();
  other.provenance.plant = "cartpole";
  const fs::path other_file = directory_ / "cartpole.txt";
  save_weights(other_file, other);
  bad.weights_file = other_file;
  bad.sets.clear();
  EXPECT_EQ(refused(bad), "cbbg: error: weights file '" + other_file.string() +
                              "' was made on plant kind 'cartpole' and cannot be loaded onto "
                              "plant kind 'simbody' (plant.kind): another robot\n");
}

TEST_F(EvalCommand, BadOptionsExitTwoWithOneLine) {
  app::EvalOptions bad = options();
  bad.repeats = 0;
  EXPECT_EQ(refused(bad), "cbbg: error: --repeats must be from 1 to 10000; got 0\n");
  bad = options();
  for (const char* angles : {"0.05,inf", "0.1,,0.2", "0.1,", ",0.1", "0.1;0.2", "0.1 ,0.2"}) {
    bad.angles = angles;
    EXPECT_EQ(refused(bad), std::string("cbbg: error: --angles must be finite numbers separated by "
                                        "commas (rad), e.g. 0.1,0.2; got '") +
                                angles + "'\n");
  }
  bad = options();
  bad.out = weights_file_;
  EXPECT_EQ(refused(bad),
            "cbbg: error: --out '" + weights_file_.string() + "' is a file, not a directory\n");
  bad = options();
  bad.push_time = 1.0;
  EXPECT_EQ(refused(bad),
            "cbbg: error: a push needs --push-time, --push-duration and at least one of "
            "--push-torque, --push-force and --push-pitch-torque; missing --push-duration and "
            "--push-torque, --push-force or --push-pitch-torque\n");
  bad.push_torque = 2.0;
  bad.push_duration = 0.0;
  EXPECT_EQ(refused(bad), "cbbg: error: --push-duration must be a finite number > 0 (s); got 0\n");
  bad.push_duration = 0.5;
  bad.push_time = -1.0;
  EXPECT_EQ(refused(bad), "cbbg: error: --push-time must be a finite number >= 0 (s); got -1\n");
  bad.push_time = 1.0;
  bad.push_torque = std::numeric_limits<double>::quiet_NaN();
  EXPECT_EQ(refused(bad), "cbbg: error: --push-torque must be a finite number (N m); got nan\n");
}

TEST_F(EvalCommand, PrintsBalancedRunsPerAngleAndWritesTheCsv) {
  app::EvalOptions good = options();
  // 0.05 rad the learnt policy balances; from 0.5 rad gravity's torque on the body (M g L
  // sin 0.5 = 18.8 N m) beats what both motors can push back (10 N m): every policy falls.
  good.angles = "0.05,0.5";
  good.repeats = 2;
  good.out = directory_ / "eval";
  const Outcome outcome = run(good);
  ASSERT_EQ(outcome.exit_code, 0) << outcome.err;
  EXPECT_EQ(outcome.err, "");
  EXPECT_THAT(outcome.out, HasSubstr("    theta0   balanced\n"
                                     "      0.05        2/2\n"
                                     "       0.5        0/2\n"));
  std::ifstream csv(good.out / "evaluation.csv");
  std::string header;
  std::getline(csv, header);
  EXPECT_EQ(header, "theta0,seed,balanced,steps,final_theta,status");
  std::vector<std::string> rows;
  for (std::string row; std::getline(csv, row);) rows.push_back(row);
  ASSERT_EQ(rows.size(), 4u);
  EXPECT_THAT(rows[0], ::testing::StartsWith("0.05,1,1,2000,"));
  EXPECT_THAT(rows[1], ::testing::StartsWith("0.05,2,1,2000,"));
  EXPECT_THAT(rows[3], ::testing::StartsWith("0.5,2,0,"));
  EXPECT_THAT(rows[3], ::testing::EndsWith(",failed"));
  std::vector<std::string> files;
  for (const auto& entry : fs::directory_iterator(good.out)) {
    files.push_back(entry.path().filename().string());
  }
  std::sort(files.begin(), files.end());
  // evaluation.csv and the manifest that names it as cbbg's: no temporary file left.
  EXPECT_EQ(files, (std::vector<std::string>{".cbbg-written", "evaluation.csv"}));
}

TEST_F(EvalCommand, AFallIsAResultNotAnError) {
  app::EvalOptions pushed = options();
  pushed.push_time = 1.0;
  pushed.push_torque = 5.0;
  pushed.push_duration = 1.0;
  const Outcome outcome = run(pushed);
  EXPECT_EQ(outcome.exit_code, 0) << outcome.err;
  EXPECT_THAT(outcome.out, HasSubstr("push 5 N m on each wheel from 1 s for 1 s"));
  EXPECT_THAT(outcome.out, HasSubstr("      0.05        0/1\n"));
}

// Through the motors a push is bounded by their limit; from outside it is not: 150 N at the
// centre of mass for 0.5 s fells what a 5 N m push through the motors only nudges.
TEST_F(EvalCommand, APushFromOutsideIsNotBoundedByTheMotors) {
  app::EvalOptions through_motors = options();
  through_motors.push_time = 1.0;
  through_motors.push_torque = 1.0;
  through_motors.push_duration = 0.5;
  Outcome outcome = run(through_motors);
  ASSERT_EQ(outcome.exit_code, 0) << outcome.err;
  EXPECT_THAT(outcome.out, HasSubstr("      0.05        1/1\n"));
  app::EvalOptions from_outside = options();
  from_outside.push_time = 1.0;
  from_outside.push_force = 150.0;
  from_outside.push_pitch_torque = 2.0;
  from_outside.push_duration = 0.5;
  outcome = run(from_outside);
  ASSERT_EQ(outcome.exit_code, 0) << outcome.err;
  EXPECT_THAT(outcome.out, HasSubstr("push 150 N at the centre of mass and 2 N m on the body from "
                                     "1 s for 0.5 s"));
  EXPECT_THAT(outcome.out, HasSubstr("      0.05        0/1\n"));
}

TEST_F(EvalCommand, LinearisesTheActorOnRequest) {
  app::EvalOptions linearised = options();
  linearised.linearise = true;
  const Outcome outcome = run(linearised);
  ASSERT_EQ(outcome.exit_code, 0) << outcome.err;
  EXPECT_THAT(outcome.out, HasSubstr("\nthe actor near rest: slopes of its action at x = 0 (N m "
                                     "per rad, per rad/s)\n   theta_b "));
  EXPECT_THAT(outcome.out, HasSubstr("\n       phi            0\n"));
  EXPECT_THAT(outcome.out, HasSubstr("the robot upright closed by those slopes, the action held "
                                     "for 0.01 s: its modes\n"));
}

TEST_F(EvalCommand, SaysWhenTheRobotIsNotTheOneTrained) {
  app::EvalOptions changed = options();
  EXPECT_THAT(run(changed).out, ::testing::Not(HasSubstr("changed robot")));
  changed.sets.push_back("evaluation.body_mass_scale=1.3");
  changed.sets.push_back("evaluation.push_torque=-2");
  const Outcome outcome = run(changed);
  EXPECT_EQ(outcome.exit_code, 0) << outcome.err;
  EXPECT_THAT(outcome.out, HasSubstr("; evaluated on a changed robot: body mass x1.3, push -2 N m "
                                     "on each wheel from 5 s for 0.2 s\n"));
}

}  // namespace
}  // namespace cbbg::experiments
