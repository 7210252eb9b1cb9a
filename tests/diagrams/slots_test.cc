// A user's own block in each slot, from user code only: a supervisor, a feature approximator
// feeding critic and actor (one with a layout of its own, filed with its weights), and a
// plant. Each runs through the protocols as a preset does.

#include <algorithm>
#include <cmath>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "cbbg/blocks/measured_signals.h"
#include "cbbg/diagrams/presets.h"
#include "cbbg/experiments/experiments.h"
#include "cbbg/framework/block_context.h"
#include "cbbg/store/weights_file.h"
#include "tests/diagrams/slot_fixtures.h"
#include "tests/support/pendulum_robot.h"
#include "tests/support/scratch_directory.h"

namespace cbbg::diagrams {
namespace {

using ::testing::ThrowsMessage;

using testing::PitchSupervisor;
using testing::quick_config;

// Features of the user's: a bias and the two state coordinates, phi = (1, x_0, x_1).
class LinearFeatures final : public Block {
 public:
  explicit LinearFeatures(std::string name) : Block(std::move(name)) {
    const InputPort& x = declare_input_port("x", 2);
    declare_output_port("features", 3,
                        [&x](const BlockContext& context, VectorRef phi) {
                          phi[0] = 1.0;
                          phi.tail(2) = context.input(x);
                        },
                        {&x});
  }
};

using cbbg::testing::PendulumRobot;

TEST(Slots, AUsersSupervisorTakesTheCerebellumsPlace) {
  ControllerOptions options = preset("cbbg").options;
  options.slots.supervisor = [](const std::string& name, const parameters::Parameters&) {
    return std::make_unique<PitchSupervisor>(name);
  };
  const Arm mine = make_arm("cbbg_pitch", options);
  const ClosedLoop loop = mine.learner(parameters::read_parameters(quick_config()));
  auto context = loop.diagram->create_context(1);
  // theta0 = 0.1744 at rest: a_S = 40 theta0.
  EXPECT_DOUBLE_EQ(loop.diagram->eval_output(*context, *loop.telemetry)[kTelemetrySupervisorAction],
                   40.0 * 0.1744);
  const experiments::ExperimentResults results = experiments::run_exp1(
      parameters::read_parameters(quick_config()), {preset_arm("cbbg"), mine});
  ASSERT_EQ(results.arms, (std::vector<std::string>{"cbbg", "cbbg_pitch"}));
  for (std::size_t s = 0; s < results.seeds.size(); ++s) {
    const auto& run = results.run(1, s);
    EXPECT_FALSE(run.trials.empty());
    EXPECT_TRUE(run.weights.has_value());
    EXPECT_EQ(run.evaluation.size(), quick_config().numbers("evaluation.angles").size());
  }
}

TEST(Slots, AUsersFeaturesFeedCriticAndActor) {
  ControllerOptions options = preset("bg_only").options;
  options.slots.features = [](const std::string& name, const parameters::Parameters&) {
    return std::make_unique<LinearFeatures>(name);
  };
  const ClosedLoop loop =
      make_arm("bg_linear", options).learner(parameters::read_parameters(quick_config()));
  EXPECT_EQ(loop.learner.critic->num_features(), 3);
  EXPECT_EQ(loop.learner.actor->num_features(), 3);
  experiments::TrialRunner runner(loop, 1, 0.01);
  runner.run_trial(0.1744, 2.0);
  EXPECT_GT(loop.learner.critic->learnt(runner.context(), "weights").norm(), 0.0);
  EXPECT_GT(loop.learner.actor->learnt(runner.context(), "weights").norm(), 0.0);
}

// Features of the user's with a layout of their own: one-hot tiles, n x n over the grid
// [-3, 3]^2 the normaliser maps to. Its layout (tiles.per_axis) is filed with the weights.
class Tiles final : public Block, public blocks::DescribesLayout {
 public:
  Tiles(std::string name, int per_axis) : Block(std::move(name)), per_axis_(per_axis) {
    const InputPort& x = declare_input_port("x", 2);
    declare_output_port("features", per_axis * per_axis,
                        [&x, per_axis](const BlockContext& context, VectorRef phi) {
                          auto tile = [per_axis](double v) {
                            const int i = static_cast<int>((v + 3.0) / 6.0 * per_axis);
                            return std::clamp(i, 0, per_axis - 1);
                          };
                          const auto state = context.input(x);
                          phi.setZero();
                          phi[tile(state[0]) * per_axis + tile(state[1])] = 1.0;
                        },
                        {&x});
  }
  blocks::FeatureLayout layout() const override {
    return {{"tiles.per_axis", {static_cast<double>(per_axis_)}}};
  }

 private:
  int per_axis_;
};

Arm tiles_arm(int per_axis) {
  ControllerOptions options = preset("cbbg").options;
  options.slots.features = [per_axis](const std::string& name, const parameters::Parameters&) {
    return std::make_unique<Tiles>(name, per_axis);
  };
  return make_arm("cbbg_tiles", options);
}

TEST(Slots, AUsersFeaturesKeepTheirWeightsWithTheirOwnLayout) {
  const experiments::ExperimentResults results =
      experiments::run_exp1(parameters::read_parameters(quick_config()), {tiles_arm(6)});
  const experiments::SeedRun& run = results.run(0, 0);
  ASSERT_TRUE(run.weights.has_value());
  EXPECT_EQ(run.weights->num_features(), 36);
  EXPECT_FALSE(run.evaluation.empty());  // its learnt actor, with the same tiles, evaluated
  EXPECT_EQ(run.weights->layout.back(), (blocks::LayoutEntry{"tiles.per_axis", {6}}));

  // Filed, read back, and loaded only where the tiles are the same.
  const cbbg::testing::ScratchDirectory scratch;
  store::save_weights(scratch.path() / "w.txt", *run.weights);
  const experiments::LearntWeights loaded = store::load_weights(scratch.path() / "w.txt");
  EXPECT_TRUE(loaded == *run.weights);
  const parameters::Parameters parameters = parameters::read_parameters(quick_config());
  EXPECT_NO_THROW(
      experiments::check_layout(loaded, tiles_arm(6).policy(parameters).layout, "w.txt"));
  EXPECT_THAT(
      [&] { experiments::check_layout(loaded, tiles_arm(4).policy(parameters).layout, "w.txt"); },
      ThrowsMessage<config::ConfigError>(
          "weights file 'w.txt' was made for tiles.per_axis 6; this diagram has tiles.per_axis 4"));
  EXPECT_THAT(
      [&] {
        experiments::check_layout(loaded, preset_arm("cbbg").policy(parameters).layout, "w.txt");
      },
      ThrowsMessage<config::ConfigError>(
          "weights file 'w.txt' was made for tiles.per_axis 6; this diagram has rbf.centres "
          "[-3, -2, -1, 0, 1, 2, 3]"));
}

TEST(Slots, AUsersPlantLogsItsOwnSignalsIntoStepsCsv) {
  ClosedLoopOptions pendulum;
  pendulum.plant = [](const std::string& name, const parameters::Parameters&) {
    auto robot = std::make_unique<PendulumRobot>(name);
    robot->log({"pitch_rate", "wheel"});
    return robot;
  };
  const ClosedLoop loop =
      build_preset("pd_only", parameters::read_parameters(quick_config()), pendulum);
  EXPECT_EQ(experiments::steps_csv_header(loop.signals),
            "arm,seed,trial,t,theta_b,dtheta_b,phi_l,phi_r,a_S,a_A,a_E,a,omega,V,delta,T,reward,"
            "pitch_rate,wheel\n");
  std::ostringstream steps;
  experiments::TrialRunner runner(loop, 1, 0.01, {.steps = &steps, .row_prefix = "pd_only,1,"});
  runner.run_trial(0.1, 0.05);
  // The quick config's sensors are exact: the logged true signals are the measured ones.
  std::istringstream rows(steps.str());
  int count = 0;
  for (std::string row; std::getline(rows, row); ++count) {
    std::vector<std::string> fields;
    std::stringstream split(row);
    for (std::string field; std::getline(split, field, ',');) fields.push_back(field);
    ASSERT_EQ(fields.size(), 19u) << row;
    EXPECT_EQ(fields[17], fields[5]) << row;  // pitch_rate, dtheta_b
    EXPECT_EQ(fields[18], fields[6]) << row;  // wheel, phi_l
  }
  EXPECT_EQ(count, 5);
}

TEST(Slots, AUsersPlantTakesTheRobotsPlace) {
  ClosedLoopOptions pendulum;
  pendulum.plant = [](const std::string& name, const parameters::Parameters&) {
    return std::make_unique<PendulumRobot>(name);
  };
  // The paper's PD law balances the pendulum (50 > 2 * 24.5 / 2 ... stable), its absence not.
  const ClosedLoop supervised =
      build_preset("pd_only", parameters::read_parameters(quick_config()), pendulum);
  experiments::TrialRunner runner(supervised, 1, 0.01);
  const experiments::TrialOutcome balanced = runner.run_trial(0.1744, 8.0);  // past 5 s
  EXPECT_EQ(balanced.status, experiments::TrialStatus::kSuccess);
  // It does not say its wheels' radius (the config's is the two-wheeler's): no speed.
  EXPECT_TRUE(std::isnan(supervised.plant->wheel_radius()));
  EXPECT_TRUE(std::isfinite(balanced.pitch_rms));  // the span after the settle time exists
  EXPECT_TRUE(std::isnan(balanced.mean_forward_speed));
  EXPECT_EQ(
      build_preset("pd_only", parameters::read_parameters(quick_config())).plant->wheel_radius(),
      0.15);
  // Its signals by name: the loop measures its pitch and wheel, and it has no pose.
  auto context = supervised.diagram->create_context(1);
  supervised.start_trial(*context, 0.05);
  const auto telemetry = supervised.diagram->eval_output(*context, *supervised.telemetry);
  EXPECT_EQ(telemetry[kTelemetryThetaB], 0.05);
  EXPECT_EQ(telemetry[kTelemetryPhiLeft], 0.0);
  EXPECT_TRUE(std::isnan(telemetry[kTelemetryX]) && std::isnan(telemetry[kTelemetryYaw]));
  EXPECT_EQ(experiments::steps_csv_header(supervised.signals),
            "arm,seed,trial,t,theta_b,dtheta_b,phi_l,phi_r,a_S,a_A,a_E,a,omega,V,delta,T,reward\n");
  const experiments::ExperimentResults results = experiments::run_exp1(
      parameters::read_parameters(quick_config()), {preset_arm("bg_only", pendulum)});
  EXPECT_EQ(results.runs.size(), 2u);
  EXPECT_GT(results.runs[0].trials.size(), 0u);
  EXPECT_EQ(results.runs[0].trials.front().outcome.status, experiments::TrialStatus::kFailed);
  // Its evaluation on a changed robot would leave it unchanged: refused before any training.
  parameters::Parameters heavier = parameters::read_parameters(quick_config());
  heavier.evaluation.body_mass_scale = 1.3;
  EXPECT_THAT(
      [&] { experiments::run_exp1(heavier, {preset_arm("bg_only", pendulum)}); },
      ThrowsMessage<config::ConfigError>(
          "evaluation.body_mass_scale is 1.3, but plant 'bg_only/plant' is the arm's own, not "
          "plant.kind's, and would be evaluated unchanged; keep it at 1, or register the plant "
          "as a kind that applies the change (diagrams/plant_kinds.h)"));
  EXPECT_NO_THROW(experiments::run_exp1(heavier, {preset_arm("pd_only")}));  // the robot's plant
}

// A push from outside reaches a user's plant through its input "disturbance"; a plant without
// one is refused it, before any training, rather than run unpushed.
TEST(Slots, AUsersPlantTakesAPushFromOutsideThroughItsDisturbanceInput) {
  auto pendulum_arm = [](plant::DisturbanceInput disturbance) {
    ClosedLoopOptions options;
    options.plant = [disturbance](const std::string& name, const parameters::Parameters&) {
      return std::make_unique<PendulumRobot>(name, disturbance);
    };
    return options;
  };
  parameters::Parameters pushed = parameters::read_parameters(quick_config());
  pushed.push.pitch_torque = 30.0;
  pushed.push.start = 1.0;
  pushed.push.duration = 0.5;
  const ClosedLoopOptions taking = pendulum_arm(plant::DisturbanceInput::kDeclared);
  // Unpushed (the input fixed at zero) it balances; pushed harder than the motors can answer
  // (30 N m on the body against 10 N m), it falls.
  parameters::Parameters unpushed = pushed;
  unpushed.push = blocks::PushParams{};
  const ClosedLoop still = build_preset("pd_only", unpushed, taking);
  experiments::TrialRunner calm(still, 1, 0.01);
  EXPECT_EQ(calm.run_trial(0.05, 3.0).status, experiments::TrialStatus::kSuccess);
  const ClosedLoop loop = build_preset("pd_only", pushed, taking);
  auto has_block = [&loop](const char* name) {
    const auto& blocks = loop.diagram->blocks();
    return std::any_of(blocks.begin(), blocks.end(),
                       [name](const auto& block) { return block->name() == name; });
  };
  EXPECT_TRUE(has_block("external_push"));
  EXPECT_FALSE(has_block("push"));  // nothing through the motors
  experiments::TrialRunner shoved(loop, 1, 0.01);
  EXPECT_EQ(shoved.run_trial(0.05, 3.0).status, experiments::TrialStatus::kFailed);

  const ClosedLoopOptions deaf = pendulum_arm(plant::DisturbanceInput::kNone);
  EXPECT_THAT([&] { build_preset("pd_only", pushed, deaf); },
              ThrowsMessage<config::ConfigError>(
                  "push.force and push.pitch_torque push the robot from outside, but plant "
                  "'plant' has no input \"disturbance\" of size 2 (force, pitch torque); keep "
                  "them 0 for this plant, or push through the motors (push.torque)"));
  parameters::Parameters evaluated_pushed = parameters::read_parameters(quick_config());
  evaluated_pushed.evaluation.push_force = 50.0;
  EXPECT_THAT(
      [&] { experiments::run_exp1(evaluated_pushed, {preset_arm("bg_only", deaf)}); },
      ThrowsMessage<config::ConfigError>(::testing::StartsWith(
          "evaluation.push_force and evaluation.push_pitch_torque: push.force and "
          "push.pitch_torque push the robot from outside, but plant 'plant' has no input")));
}

}  // namespace
}  // namespace cbbg::diagrams
