// The subsystems of the CB-BG controller and the closed loop: their ports, their blocks and
// their messages.

#include <cmath>
#include <memory>
#include <string>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "cbbg/blocks/pd_supervisor.h"
#include "cbbg/blocks/rbf_features.h"
#include "cbbg/diagrams/basal_ganglia.h"
#include "cbbg/diagrams/cerebellum.h"
#include "cbbg/diagrams/closed_loop.h"
#include "cbbg/diagrams/presets.h"
#include "cbbg/diagrams/validated_parameters.h"
#include "cbbg/experiments/trial_runner.h"
#include "cbbg/framework/graphviz.h"
#include "cbbg/framework/primitives/gain.h"

namespace cbbg::diagrams {
namespace {

using ::testing::HasSubstr;
using ::testing::ThrowsMessage;

config::Config analytic_config() {
  config::Config config;
  config.set("plant.kind=analytic");
  return config;
}

std::vector<std::string> port_names(const Block& block, bool inputs) {
  std::vector<std::string> names;
  const int count = inputs ? block.num_input_ports() : block.num_output_ports();
  for (int i = 0; i < count; ++i) {
    names.push_back(inputs ? block.input_port(i).name() : block.output_port(i).name());
  }
  return names;
}

std::vector<std::string> child_names(const Diagram& diagram) {
  std::vector<std::string> names;
  for (const auto& block : diagram.blocks()) names.push_back(block->name());
  return names;
}

BasalGanglia make_basal_ganglia(bool exploration) {
  BasalGangliaParams params;
  params.exploration = exploration;
  return BasalGanglia("basal_ganglia",
                      std::make_unique<blocks::RbfFeatures>("features", blocks::RbfParams{}),
                      params);
}

TEST(BasalGanglia, HasTheDocumentedPortsAndBlocks) {
  const BasalGanglia bg = make_basal_ganglia(true);
  EXPECT_EQ(port_names(bg, true),
            (std::vector<std::string>{"state", "reward", "failed", "supervisor_action", "omega"}));
  EXPECT_EQ(port_names(bg, false),
            (std::vector<std::string>{"actor_action", "exploration_action", "value", "td_error",
                                      "temperature", "entropy"}));
  EXPECT_EQ(bg.state().size(), 2);
  EXPECT_EQ(&bg.state(), &bg.input_port("state"));
  EXPECT_EQ(&bg.temperature(), &bg.output_port("temperature"));
  EXPECT_EQ(child_names(bg), (std::vector<std::string>{"features", "critic", "actor", "tropism",
                                                       "sampler", "entropy"}));
  EXPECT_EQ(dynamic_cast<const blocks::Learner&>(bg.critic()).num_features(), 49);
  ASSERT_NE(bg.tropism(), nullptr);
}

TEST(BasalGanglia, WithoutExplorationTheActorActsAloneAndTheTemperatureIsNaN) {
  const BasalGanglia bg = make_basal_ganglia(false);
  EXPECT_EQ(bg.tropism(), nullptr);
  EXPECT_EQ(child_names(bg),
            (std::vector<std::string>{"features", "critic", "actor", "no_exploration"}));
  auto context = bg.create_context(1);
  context->fix_input(bg.state(), Vector::Constant(2, 0.5));
  for (const InputPort* port : {bg.reward(), bg.failed(), bg.supervisor_action(), bg.omega()}) {
    context->fix_input(*port, Vector::Zero(1));
  }
  dynamic_cast<const blocks::Learner&>(bg.actor())
      .mutable_learnt(*context, "weights")
      .setConstant(0.25);
  const double actor_action = bg.eval_output(*context, bg.actor_action())[0];
  EXPECT_GT(actor_action, 0.0);
  EXPECT_EQ(bg.eval_output(*context, bg.exploration_action())[0], actor_action);
  EXPECT_TRUE(std::isnan(bg.eval_output(*context, bg.temperature())[0]));
  EXPECT_TRUE(std::isnan(bg.eval_output(*context, bg.entropy())[0]));
}

TEST(BasalGanglia, RefusesAFeaturesBlockWithOtherPorts) {
  EXPECT_THAT(
      [] { BasalGanglia("bg", std::make_unique<Gain>("features", 1.0, 2), BasalGangliaParams{}); },
      ThrowsMessage<std::invalid_argument>(
          "basal ganglia 'bg': the block 'features' must have one input \"x\" and one output "
          "\"features\""));
}

TEST(Cerebellum, WrapsItsSupervisor) {
  const Cerebellum cerebellum("cerebellum", std::make_unique<blocks::PdSupervisor>(
                                                "supervisor", blocks::PdSupervisorParams{}));
  EXPECT_EQ(port_names(cerebellum, true), std::vector<std::string>{"measured"});
  EXPECT_EQ(port_names(cerebellum, false), std::vector<std::string>{"action"});
  EXPECT_EQ(cerebellum.measured().size(), 6);
  EXPECT_EQ(cerebellum.supervisor().name(), "supervisor");
  auto context = cerebellum.create_context(1);
  Vector measured = Vector::Zero(6);
  measured[0] = 0.1;  // leaning forward: the PD law pushes the wheels forward
  context->fix_input(cerebellum.measured(), measured);
  EXPECT_DOUBLE_EQ(cerebellum.eval_output(*context, cerebellum.action())[0], 50.0 * 0.1);
}

TEST(Cerebellum, RefusesASupervisorWithOtherPorts) {
  EXPECT_THAT([] { Cerebellum("cb", std::make_unique<Gain>("supervisor", 1.0, 1)); },
              ThrowsMessage<std::invalid_argument>(
                  "cerebellum 'cb': the block 'supervisor' must have one input \"measured\" and "
                  "one output \"action\" of size 1"));
}

TEST(CbbgController, OffersTheDocumentedPortsWithAndWithoutBasalGanglia) {
  const config::Config config = analytic_config();
  const std::vector<std::string> outputs{
      "action",   "supervisor_action", "actor_action", "exploration_action", "omega", "value",
      "td_error", "temperature",       "entropy"};
  const CbbgController full("controller", parameters::read_parameters(config), ControllerOptions{});
  EXPECT_EQ(port_names(full, true), (std::vector<std::string>{"measured", "reward", "failed"}));
  EXPECT_EQ(port_names(full, false), outputs);
  EXPECT_EQ(child_names(full), (std::vector<std::string>{"cerebellum", "normaliser",
                                                         "basal_ganglia", "omega", "mixer"}));
  ControllerOptions alone;
  alone.basal_ganglia = false;
  const CbbgController supervisor("controller", parameters::read_parameters(config), alone);
  EXPECT_EQ(port_names(supervisor, true), std::vector<std::string>{"measured"});
  EXPECT_EQ(supervisor.reward(), nullptr);
  EXPECT_EQ(supervisor.basal_ganglia(), nullptr);
  EXPECT_EQ(port_names(supervisor, false), outputs);
}

TEST(CbbgController, RefusesOptionsWithNothingThatActs) {
  ControllerOptions nothing;
  nothing.supervisor = false;
  nothing.basal_ganglia = false;
  EXPECT_THAT(
      [&] {
        CbbgController("controller", parameters::read_parameters(analytic_config()), nothing);
      },
      ThrowsMessage<std::invalid_argument>(
          "controller options: with neither a supervisor nor basal ganglia nothing acts; "
          "keep one of them"));
}

TEST(ClosedLoop, AStartedTrialResetsPerTrialStateAndKeepsTheWeights) {
  const config::Config config = analytic_config();
  const ClosedLoop loop = build_preset("bg_only", parameters::read_parameters(config));
  experiments::TrialRunner runner(loop, 1, config.number("trial.period"));
  const experiments::TrialOutcome first = runner.run_trial(0.1744, 20.0);
  EXPECT_EQ(first.status, experiments::TrialStatus::kFailed);  // a blank actor cannot balance
  Context& context = runner.context();
  const Vector learnt = loop.learner.actor->learnt(context, "weights");
  EXPECT_GT(learnt.norm(), 0.0);
  const Block& critic = loop.learner.critic->learner_block();
  EXPECT_GT(critic.discrete_state_part("trace").of(context.discrete_state(critic)).norm(), 0.0);
  loop.start_trial(context, 0.1);
  EXPECT_EQ(loop.learner.actor->learnt(context, "weights"), learnt);
  EXPECT_EQ(critic.discrete_state_part("trace").of(context.discrete_state(critic)).norm(), 0.0);
  EXPECT_EQ(context.time(), 0.0);
  EXPECT_EQ(loop.diagram->eval_output(context, *loop.telemetry)[kTelemetryThetaB], 0.1);
}

TEST(ClosedLoop, RefusesAPlantWithoutTheRobotPorts) {
  class OneInputPlant final : public plant::RobotPlant {
   public:
    explicit OneInputPlant(std::string name) : RobotPlant(std::move(name)) {
      declare_input_port("torque", 1);
    }
    void reset(Context&, double) const override {}
  };
  ClosedLoopOptions options;
  options.plant = [](const std::string& name, const parameters::Parameters&) {
    return std::make_unique<OneInputPlant>(name);
  };
  EXPECT_THAT(
      [&] {
        closed_loop_factory("one_input", ControllerOptions{},
                            options)(parameters::read_parameters(analytic_config()));
      },
      ThrowsMessage<std::invalid_argument>(
          "plant 'plant' must have an input \"torque\" of size 2 and an output \"state\" "
          "(plant/robot_plant.h)"));
}

// A plant whose state output has `size` entries named `names`, which logs `logged`.
class NamedSignalsPlant final : public plant::RobotPlant {
 public:
  NamedSignalsPlant(std::string name, int size, std::vector<std::string> names,
                    std::vector<std::string> logged = {})
      : RobotPlant(std::move(name)), names_(std::move(names)), logged_(std::move(logged)) {
    declare_input_port("torque", plant::kTorqueSize);
    declare_output_port("state", size, [](const BlockContext&, VectorRef y) { y.setZero(); }, {});
  }
  std::vector<std::string> signals() const override { return names_; }
  std::vector<std::string> logged_signals() const override { return logged_; }
  void reset(Context&, double) const override {}

 private:
  std::vector<std::string> names_;
  std::vector<std::string> logged_;
};

TEST(ClosedLoop, RefusesAPlantWhoseSignalsDoNotFit) {
  auto loop_with = [](int size, std::vector<std::string> names) {
    ClosedLoopOptions options;
    options.plant = [=](const std::string& name, const parameters::Parameters&) {
      return std::make_unique<NamedSignalsPlant>(name, size, names);
    };
    closed_loop_factory("named", ControllerOptions{},
                        options)(parameters::read_parameters(analytic_config()));
  };
  EXPECT_THAT(
      [&] {
        loop_with(3, {"pitch", "pitch_rate"});
      },
      ThrowsMessage<std::invalid_argument>(
          "plant 'plant' names 2 signals, but its output \"state\" has size 3"));
  EXPECT_THAT(
      [&] {
        loop_with(3, {"pitch", "pitch_rate", "wheel"});
      },
      ThrowsMessage<std::invalid_argument>(
          "plant 'plant' has no signal 'wheel_left_rate' (or 'wheel_rate') in its state output; "
          "a plant names pitch, pitch_rate, wheel_left, wheel_right, wheel_left_rate and "
          "wheel_right_rate (or wheel and wheel_rate) (plant/plant_signals.h)"));
  EXPECT_THAT(
      [&] {
        loop_with(4, {"pitch", "pitch_rate", "wheel", "pitch"});
      },
      ThrowsMessage<std::invalid_argument>("plant 'plant' names its signal 'pitch' twice"));
  EXPECT_NO_THROW(loop_with(5, {"wheel_rate", "pitch", "extra", "wheel", "pitch_rate"}));
}

TEST(ClosedLoop, RefusesALoggedSignalItCannotRecord) {
  const std::vector<std::string> names{"pitch", "pitch_rate", "wheel", "wheel_rate", "x",
                                       "y",     "yaw",        "a",     "energy"};
  auto loop_logging = [&](std::vector<std::string> logged) {
    ClosedLoopOptions options;
    options.plant = [=](const std::string& name, const parameters::Parameters&) {
      return std::make_unique<NamedSignalsPlant>(name, 9, names, logged);
    };
    return closed_loop_factory("logging", ControllerOptions{},
                               options)(parameters::read_parameters(analytic_config()));
  };
  EXPECT_THAT([&] { loop_logging({"power"}); },
              ThrowsMessage<std::invalid_argument>(
                  "plant 'plant' logs 'power', which is not one of its signals (pitch, "
                  "pitch_rate, wheel, wheel_rate, x, y, yaw, a, energy)"));
  EXPECT_THAT(
      [&] {
        loop_logging({"energy", "energy"});
      },
      ThrowsMessage<std::invalid_argument>("plant 'plant' logs 'energy' twice"));
  EXPECT_THAT([&] { loop_logging({"yaw"}); },
              ThrowsMessage<std::invalid_argument>(
                  "plant 'plant' logs 'yaw', its pose, which steps.csv records anyway; log only "
                  "its other signals"));
  EXPECT_THAT([&] { loop_logging({"a"}); },
              ThrowsMessage<std::invalid_argument>(
                  "plant 'plant' logs 'a', a name steps.csv gives one of its own columns; "
                  "rename the signal"));
  const ClosedLoop loop = loop_logging({"energy", "pitch"});
  EXPECT_EQ(loop.signals.logged, (std::vector<plant::LoggedSignal>{{"energy", 8}, {"pitch", 0}}));
  EXPECT_EQ(loop.telemetry->size(), kTelemetrySize + 2);
}

TEST(ParamsFromConfig, PlantSimbodyIntegratorChoosesTheIntegrator) {
  config::Config config = analytic_config();
  EXPECT_EQ(parameters::read_parameters(config).plant.robot.simbody_integrator,
            plant::SimbodyIntegrator::kMerson);
  config.set("plant.simbody_integrator=rk3");
  EXPECT_EQ(parameters::read_parameters(config).plant.robot.simbody_integrator,
            plant::SimbodyIntegrator::kRungeKutta3);
  config.set("plant.simbody_integrator=verlet");
  EXPECT_EQ(parameters::read_parameters(config).plant.robot.simbody_integrator,
            plant::SimbodyIntegrator::kVerlet);
  EXPECT_THROW(config.set("plant.simbody_integrator=euler"), config::ConfigError);
}

TEST(ParamsFromConfig, PlantSimbodyModelChoosesTheFormulation) {
  config::Config config = analytic_config();
  EXPECT_EQ(parameters::read_parameters(config).plant.robot.simbody_model,
            plant::SimbodyModel::kRollingBase);
  config.set("plant.simbody_model=constrained");
  EXPECT_EQ(parameters::read_parameters(config).plant.robot.simbody_model,
            plant::SimbodyModel::kNoSlipConstraints);
  EXPECT_THAT([&] { config.set("plant.simbody_model=lagrange"); },
              ::testing::ThrowsMessage<config::ConfigError>(
                  "--set plant.simbody_model=lagrange: plant.simbody_model must be one of "
                  "rolling, constrained; got 'lagrange'"));
}

TEST(ClosedLoop, IsDrawnWithTheCerebellumAndTheBasalGangliaAsClusters) {
  const ClosedLoop loop = build_preset("cbbg", parameters::read_parameters(analytic_config()));
  const std::string dot = to_dot(*loop.diagram, {.hidden_blocks = {"cbbg/telemetry"}});
  EXPECT_THAT(dot, HasSubstr("subgraph \"cluster_cbbg/controller/cerebellum\""));
  EXPECT_THAT(dot, HasSubstr("subgraph \"cluster_cbbg/controller/basal_ganglia\""));
  EXPECT_THAT(dot, ::testing::Not(HasSubstr("\"cbbg/telemetry\"")));
  EXPECT_THAT(to_dot(*loop.diagram), HasSubstr("\"cbbg/telemetry\""));
}

}  // namespace
}  // namespace cbbg::diagrams
