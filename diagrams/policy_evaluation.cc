#include "diagrams/policy_evaluation.h"

#include <cmath>
#include <cstdint>
#include <functional>
#include <limits>
#include <memory>
#include <stdexcept>
#include <string>

#include "blocks/actor.h"
#include "blocks/failure_detector.h"
#include "blocks/normaliser.h"
#include "blocks/rbf_features.h"
#include "blocks/sensors.h"
#include "diagrams/controller_diagram.h"
#include "diagrams/params_from_config.h"
#include "framework/diagram_builder.h"
#include "framework/primitives/constant_source.h"
#include "framework/primitives/multiplexer.h"
#include "framework/primitives/zero_order_hold.h"
#include "framework/simulator.h"
#include "plant/analytic_plant.h"
#include "plant/plant_ports.h"
#include "plant/simbody_plant.h"

namespace cbbg::diagrams {
namespace {

// The learnt_actor diagram of controller_diagram.h, without telemetry and reward, with an
// optional TorquePush between the hold and the wheels.
struct EvaluationDiagram {
  std::unique_ptr<Diagram> diagram;
  const Block* plant = nullptr;
  std::function<void(Context&, double)> reset_plant;
  const blocks::Sensors* sensors = nullptr;
  const blocks::Actor* actor = nullptr;
};

const Block& add_plant(DiagramBuilder& builder, const config::Config& config,
                       EvaluationDiagram& result) {
  const plant::RobotParams params = robot_params(config);
  const double theta0 = config.number("trial.theta0");
  if (config.text("plant.kind") == "analytic") {
    const auto& robot = builder.emplace<plant::AnalyticPlant>("plant", params, theta0);
    result.reset_plant = [&robot](Context& context, double pitch) { robot.reset(context, pitch); };
    return robot;
  }
  const auto& robot = builder.emplace<plant::SimbodyPlant>("plant", params, theta0);
  result.reset_plant = [&robot](Context& context, double pitch) { robot.reset(context, pitch); };
  return robot;
}

const OutputPort& constant(DiagramBuilder& builder, const std::string& name, double value) {
  return builder.emplace<ConstantSource>(name, Vector::Constant(1, value)).output_port("y");
}

EvaluationDiagram build_evaluation_diagram(const config::Config& config,
                                           const std::optional<PushParams>& push) {
  const double period = config.number("trial.period");
  EvaluationDiagram result;
  // The learnt_actor diagram's name and block names: the same seed draws the same noise.
  DiagramBuilder builder(kLearntActorDiagram);
  const Block& robot = add_plant(builder, config, result);
  result.plant = &robot;
  auto& sensors = builder.emplace<blocks::Sensors>("sensors", sensors_params(config), period);
  auto& failure =
      builder.emplace<blocks::FailureDetector>("failure", failure_params(config), period);
  auto& normaliser = builder.emplace<blocks::Normaliser>("normaliser", normaliser_params(config));
  auto& rbf = builder.emplace<blocks::RbfFeatures>("rbf", rbf_params(config));
  auto& actor =
      builder.emplace<blocks::Actor>("actor", rbf.num_features(), actor_params(config), period);
  result.sensors = &sensors;
  result.actor = &actor;
  builder.connect(robot.output_port("state"), sensors.input_port("plant_state"));
  const OutputPort& measured = sensors.output_port("measured");
  builder.connect(measured, failure.input_port("measured"));
  builder.connect(measured, normaliser.input_port("measured"));
  builder.connect(normaliser.output_port("x"), rbf.input_port("x"));
  builder.connect(rbf.output_port("features"), actor.input_port("features"));
  // Frozen: a zero TD error with omega = 1 leaves both actor rules without a term.
  const OutputPort& zero = constant(builder, "frozen", 0.0);
  builder.connect(zero, actor.input_port("td_error"));
  builder.connect(zero, actor.input_port("exploration_action"));
  builder.connect(constant(builder, "no_supervisor", 0.0), actor.input_port("supervisor_action"));
  builder.connect(constant(builder, "no_omega", 1.0), actor.input_port("omega"));

  auto& hold = builder.emplace<ZeroOrderHold>("hold", 1, period);
  builder.connect(actor.output_port("action"), hold.input_port("u"));
  const OutputPort* wheel_torque = &hold.output_port("y");
  if (push) {
    auto& pusher = builder.emplace<TorquePush>("push", *push, period);
    builder.connect(*wheel_torque, pusher.input_port("action"));
    wheel_torque = &pusher.output_port("torque");
  }
  auto& wheel_torques = builder.emplace<Multiplexer>(
      "wheel_torques", std::vector<Multiplexer::Input>{{"left", 1}, {"right", 1}});
  builder.connect(*wheel_torque, wheel_torques.input_port("left"));
  builder.connect(*wheel_torque, wheel_torques.input_port("right"));
  builder.connect(wheel_torques.output_port("y"), robot.input_port("torque"));
  result.diagram = builder.build();
  return result;
}

}  // namespace

void EvaluationSettings::validate() const {
  if (angles.empty()) throw std::invalid_argument("evaluation angles: at least one is needed");
  for (std::size_t i = 0; i < angles.size(); ++i) {
    if (!std::isfinite(angles[i])) {
      throw std::invalid_argument("evaluation angle [" + std::to_string(i) +
                                  "] must be finite; got " + std::to_string(angles[i]));
    }
  }
  if (repeats < 1) {
    throw std::invalid_argument("evaluation repeats must be >= 1; got " + std::to_string(repeats));
  }
  if (push) push->validate();
}

int AngleEvaluation::balanced() const {
  int count = 0;
  for (const auto& run : runs) count += run.status == TrialStatus::kSuccess ? 1 : 0;
  return count;
}

PolicyEvaluation evaluate_policy(const config::Config& config, const LearntWeights& weights,
                                 const EvaluationSettings& settings) {
  settings.validate();
  const EvaluationDiagram policy = build_evaluation_diagram(config, settings.push);
  if (weights.actor.size() != policy.actor->num_features()) {
    throw std::invalid_argument("the weights have " + std::to_string(weights.actor.size()) +
                                " actor weights; the config's RBF grid has " +
                                std::to_string(policy.actor->num_features()) + " features");
  }
  const double period = config.number("trial.period");
  const double duration = config.number("trial.duration");
  const double nan = std::numeric_limits<double>::quiet_NaN();
  PolicyEvaluation result;
  result.first_seed = config.integer("seed");

  Simulator simulator(*policy.diagram,
                      SimulatorOptions{.accuracy = config.number("plant.accuracy")},
                      static_cast<std::uint64_t>(result.first_seed));
  // Counts the ticks of a run as TrialRunner does (one per logged tick), keeping nothing.
  long long ticks = 0;
  SignalLog& tick_counter = simulator.add_log(policy.plant->output_port("state"), period);
  tick_counter.keep_in_memory(false);
  tick_counter.set_sink([&ticks](double, const double*) { ++ticks; });

  Context& context = simulator.context();
  for (const double theta0 : settings.angles) {
    AngleEvaluation angle;
    angle.theta0 = theta0;
    for (int repeat = 0; repeat < settings.repeats; ++repeat) {
      // A clean context: time 0, every block's initial state, this run's seed.
      context.reset_all_state();
      context.reseed(static_cast<std::uint64_t>(result.first_seed + repeat));
      policy.actor->mutable_weights(context) = weights.actor;
      policy.reset_plant(context, theta0);
      // As ControllerDiagram::start_trial: the first run matches a learnt_actor trial.
      policy.sensors->start_trial(context);
      ticks = 0;
      TrialOutcome outcome;
      outcome.mean_temperature = nan;
      outcome.mean_entropy = nan;
      try {
        simulator.initialize();
        const SimulationStatus status = simulator.advance_to(duration);
        outcome.status = status.terminated ? TrialStatus::kFailed : TrialStatus::kSuccess;
        outcome.final_theta = policy.diagram->eval_output(
            context, policy.plant->output_port("state"))[plant::kThetaB];
      } catch (const SimulationError& error) {
        outcome.status = TrialStatus::kDiverged;
        outcome.message = error.what();
        outcome.final_theta = nan;
      }
      outcome.steps = ticks;
      angle.runs.push_back(std::move(outcome));
    }
    result.angles.push_back(std::move(angle));
  }
  return result;
}

}  // namespace cbbg::diagrams
