#include "cbbg/experiments/evaluation_conditions.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "cbbg/diagrams/presets.h"
#include "cbbg/experiments/experiments.h"
#include "cbbg/experiments/policy_evaluation.h"

namespace cbbg::experiments {
namespace {

config::Config analytic_config() {
  config::Config config;
  config.set("plant.kind=analytic");
  return config;
}

// The evaluation's parameters of a training config.
parameters::Parameters evaluated(const config::Config& training) {
  return evaluation_parameters(parameters::read_parameters(training));
}

TEST(EvaluationConditions, AtTheirDefaultsTheEvaluationIsTheTraining) {
  const config::Config training = analytic_config();
  config::Config evaluation;
  parameters::write_parameters(evaluated(training), evaluation);
  EXPECT_EQ(evaluation, training);
}

TEST(EvaluationConditions, AreDescribedInWordsOnlyWhenChanged) {
  config::Config config = analytic_config();
  EXPECT_EQ(describe_conditions(parameters::read_parameters(config).evaluation), "");
  config.set("evaluation.body_mass_scale=0.7");
  config.set("evaluation.com_height_scale=1.15");
  config.set("evaluation.noise_std=0.02");
  config.set("evaluation.push_torque=5");
  config.set("evaluation.push_duration=0.5");
  EXPECT_EQ(describe_conditions(parameters::read_parameters(config).evaluation),
            "body mass x0.7, CoM height x1.15, pitch noise 0.02, push 5 N m on each wheel from 5 s "
            "for 0.5 s");
  config.set("evaluation.push_torque=0");
  config.set("evaluation.push_force=40");
  config.set("evaluation.push_pitch_torque=-2");
  EXPECT_EQ(describe_conditions(parameters::read_parameters(config).evaluation),
            "body mass x0.7, CoM height x1.15, pitch noise 0.02, push 40 N at the centre of mass "
            "and -2 N m on the body from 5 s for 0.5 s");
}

TEST(EvaluationConditions, APushFromOutsideBecomesThePushOfTheEvaluation) {
  config::Config training = analytic_config();
  training.set("push.torque=1");  // the training's own push gives way to the evaluation's
  training.set("evaluation.push_force=40");
  training.set("evaluation.push_start=2");
  training.set("evaluation.push_duration=0.5");
  const blocks::PushParams push = evaluated(training).push;
  EXPECT_EQ(push.torque, 0.0);
  EXPECT_EQ(push.force, 40.0);
  EXPECT_EQ(push.pitch_torque, 0.0);
  EXPECT_EQ(push.start, 2.0);
  EXPECT_EQ(push.duration, 0.5);
  EXPECT_TRUE(pushes_from_outside(parameters::read_parameters(training).evaluation));
  training.set("evaluation.push_force=0");
  training.set("evaluation.push_pitch_torque=3");
  EXPECT_EQ(evaluated(training).push.pitch_torque, 3.0);
  training.set("evaluation.push_pitch_torque=0");
  EXPECT_EQ(evaluated(training).push.torque, 1.0);  // no evaluation push: push.* as set
  EXPECT_FALSE(pushes_from_outside(parameters::read_parameters(training).evaluation));
}

TEST(EvaluationConditions, TheMassScaleMakesTheBodyDenserAndLeavesTheWheels) {
  config::Config training = analytic_config();
  training.set("evaluation.body_mass_scale=1.3");
  const plant::RobotParams robot = evaluated(training).plant.robot;
  EXPECT_DOUBLE_EQ(robot.body_mass, 13.0);
  EXPECT_DOUBLE_EQ(robot.body_pitch_inertia, 1.5417 * 1.3);
  EXPECT_DOUBLE_EQ(robot.body_yaw_inertia, 0.5893 * 1.3);
  EXPECT_DOUBLE_EQ(robot.body_roll_inertia, 1.5417 * 1.3);
  EXPECT_EQ(robot.wheel_mass, 1.0);
  EXPECT_EQ(robot.com_height, 0.4);
}

TEST(EvaluationConditions, TheHeightScaleMovesTheCentreOfMassOnly) {
  config::Config training = analytic_config();
  training.set("evaluation.com_height_scale=0.7");
  const plant::RobotParams robot = evaluated(training).plant.robot;
  EXPECT_DOUBLE_EQ(robot.com_height, 0.28);
  EXPECT_EQ(robot.body_pitch_inertia, 1.5417);
  EXPECT_EQ(robot.body_mass, 10.0);
}

TEST(EvaluationConditions, NoiseAddsInQuadratureToThePitchAndPitchRate) {
  config::Config training = analytic_config();
  training.set("sensors.noise_std=[0.03, 0, 0.5, 0, 0, 0]");
  training.set("evaluation.noise_std=0.04");
  EXPECT_THAT(
      evaluated(training).sensors.noise_std,
      ::testing::Pointwise(::testing::DoubleEq(), std::vector<double>{0.05, 0.04, 0.5, 0, 0, 0}));
}

TEST(EvaluationConditions, APushTorqueSetsThePushOfEveryTrial) {
  config::Config training = analytic_config();
  training.set("evaluation.push_torque=-3");
  training.set("evaluation.push_start=2");
  training.set("evaluation.push_duration=0.5");
  const blocks::PushParams push = evaluated(training).push;
  EXPECT_EQ(push.torque, -3.0);
  EXPECT_EQ(push.start, 2.0);
  EXPECT_EQ(push.duration, 0.5);
  EXPECT_EQ(parameters::read_parameters(training).push.torque, 0.0);
}

bool has_push(const config::Config& config) {
  const diagrams::ClosedLoop loop =
      diagrams::build_preset("pd_only", parameters::read_parameters(config));
  const auto& blocks = loop.diagram->blocks();
  return std::any_of(blocks.begin(), blocks.end(),
                     [](const auto& block) { return block->name() == "push"; });
}

TEST(EvaluationConditions, ThePushOfTheConfigIsABlockOfTheClosedLoop) {
  config::Config config = analytic_config();
  EXPECT_FALSE(has_push(config));
  config.set("push.torque=2");
  EXPECT_TRUE(has_push(config));
}

// The supervisor alone, as evaluated, from 0.1744 rad.
TrialOutcome supervisor_alone(const config::Config& training) {
  const PolicyEvaluation evaluation =
      evaluate_controller(evaluated(training), diagrams::preset_arm("pd_only").learner,
                          EvaluationSettings{{0.1744}, 1});
  return evaluation.angles.front().runs.front();
}

TEST(EvaluationConditions, AStrongPushFellsTheSupervisorThatStandsWithoutIt) {
  config::Config training = analytic_config();
  ASSERT_EQ(supervisor_alone(training).status, TrialStatus::kSuccess);
  // Full torque on both wheels for 1.5 s from 2 s: the body is thrown back.
  training.set("evaluation.push_torque=-20");
  training.set("evaluation.push_start=2");
  training.set("evaluation.push_duration=1.5");
  const TrialOutcome pushed = supervisor_alone(training);
  EXPECT_EQ(pushed.status, TrialStatus::kFailed);
  EXPECT_GT(pushed.steps, 200);  // it stood until the push began
}

TEST(EvaluationConditions, ANoisyPitchChangesWhatTheSupervisorDoes) {
  config::Config training = analytic_config();
  const TrialOutcome clean = supervisor_alone(training);
  training.set("evaluation.noise_std=0.01");
  EXPECT_NE(supervisor_alone(training).final_theta, clean.final_theta);
}

TEST(EvaluationConditions, ALearningLoopIsEvaluatedThroughItsPolicy) {
  EXPECT_THAT(([] {
                evaluate_controller(parameters::read_parameters(analytic_config()),
                                    diagrams::preset_arm("cbbg").learner,
                                    EvaluationSettings{{0.1}, 1});
              }),
              ::testing::ThrowsMessage<std::invalid_argument>(
                  "the closed loop 'cbbg' learns: evaluate its learnt policy instead"));
}

TEST(EvaluationConditions, Exp1EvaluatesTheSupervisorAloneUnderThem) {
  config::Config config = analytic_config();
  config.set("seeds=1");
  config.set("evaluation.angles=[0.1744]");
  config.set("evaluation.push_torque=-20");
  config.set("evaluation.push_start=2");
  config.set("evaluation.push_duration=1.5");
  const ExperimentResults results =
      run_exp1(parameters::read_parameters(config), {diagrams::preset_arm("pd_only")});
  const SeedRun& run = results.run(0, 0);
  ASSERT_TRUE(run.succeeded);  // trained (here: run) unpushed
  ASSERT_EQ(run.evaluation.size(), 1u);
  EXPECT_EQ(run.evaluation[0].outcome.status, TrialStatus::kFailed);  // evaluated pushed
}

TEST(EvaluationConditions, Exp3EvaluatesTheActorItTaughtUnderThem) {
  config::Config config = analytic_config();
  config.set("seeds=1");
  config.set("evaluation.angles=[0.05, 0.25]");
  const ExperimentResults nominal =
      run_exp3(parameters::read_parameters(config), {diagrams::preset_arm("bg_only")});
  const SeedRun& run = nominal.run(0, 0);
  ASSERT_TRUE(run.figure("trials_to_skill").has_value());
  ASSERT_EQ(run.evaluation.size(), 2u);
  EXPECT_EQ(run.evaluation[1].theta0, 0.25);
  // The skill test passed from 0.25 rad after the last trial, and the evaluation's run from
  // there is the same run.
  EXPECT_EQ(run.evaluation[1].outcome.status, TrialStatus::kSuccess);

  config.set("evaluation.com_height_scale=0.5");
  const ExperimentResults lower =
      run_exp3(parameters::read_parameters(config), {diagrams::preset_arm("bg_only")});
  EXPECT_EQ(lower.run(0, 0).figures, run.figures);  // training is nominal: the same skill
  EXPECT_NE(lower.run(0, 0).evaluation[1].outcome.final_theta,
            run.evaluation[1].outcome.final_theta);
}

}  // namespace
}  // namespace cbbg::experiments
