#include "diagrams/controller_diagram.h"

#include <limits>
#include <stdexcept>

#include "blocks/boltzmann_sampler.h"
#include "blocks/entropy.h"
#include "blocks/failure_detector.h"
#include "blocks/lqr_supervisor.h"
#include "blocks/mixer.h"
#include "blocks/normaliser.h"
#include "blocks/omega_schedule.h"
#include "blocks/pd_supervisor.h"
#include "blocks/rbf_features.h"
#include "diagrams/params_from_config.h"
#include "framework/diagram_builder.h"
#include "framework/primitives/constant_source.h"
#include "framework/primitives/multiplexer.h"
#include "framework/primitives/zero_order_hold.h"
#include "plant/analytic_plant.h"
#include "plant/plant_ports.h"
#include "plant/simbody_plant.h"

namespace cbbg::diagrams {
namespace {

// kLearntActor is not an arm: the policy a learning arm has learnt, evaluated alone.
enum class Arm { kCbbg, kCbbgWeighted, kBgOnly, kCbOnly, kPdOnly, kLearntActor };

Arm parse_arm(std::string_view name) {
  if (name == "cbbg") return Arm::kCbbg;
  if (name == "cbbg_weighted") return Arm::kCbbgWeighted;
  if (name == "bg_only") return Arm::kBgOnly;
  if (name == "cb_only") return Arm::kCbOnly;
  if (name == "pd_only") return Arm::kPdOnly;
  if (name == kLearntActorDiagram) return Arm::kLearntActor;
  throw std::invalid_argument("unknown diagram '" + std::string(name) +
                              "'; the diagrams are cbbg, cbbg_weighted, bg_only, cb_only, pd_only");
}

// Adds the plant of plant.kind and returns it with its reset.
const Block& add_plant(DiagramBuilder& builder, const config::Config& config,
                       ControllerDiagram& result) {
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

}  // namespace

void ControllerDiagram::start_trial(Context& context, double theta0) const {
  context.set_time(0.0);
  reset_plant(context, theta0);
  sensors->start_trial(context);
  reward->start_trial(context);
  if (critic != nullptr) critic->start_trial(context);
  if (actor != nullptr) actor->start_trial(context);
}

ControllerDiagram build_controller_diagram(std::string_view name, const config::Config& config,
                                           const DiagramOptions& options) {
  const Arm arm = parse_arm(name);
  const double period = config.number("trial.period");
  ControllerDiagram result;
  result.name = std::string(name);
  result.accuracy = config.number("plant.accuracy");

  DiagramBuilder builder(result.name);
  const Block& robot = add_plant(builder, config, result);
  result.plant = &robot;
  auto& sensors = builder.emplace<blocks::Sensors>("sensors", sensors_params(config), period);
  auto& failure =
      builder.emplace<blocks::FailureDetector>("failure", failure_params(config), period);
  auto& reward = builder.emplace<blocks::Reward>("reward", reward_params(config), period);
  result.sensors = &sensors;
  result.reward = &reward;
  builder.connect(robot.output_port("state"), sensors.input_port("plant_state"));
  const OutputPort& measured = sensors.output_port("measured");
  builder.connect(measured, failure.input_port("measured"));
  builder.connect(measured, reward.input_port("measured"));
  builder.connect(failure.output_port("failed"), reward.input_port("failed"));

  // The cerebellum: the supervisor's target action (a constant 0 where there is none).
  const OutputPort* supervisor_action = nullptr;
  if (arm == Arm::kBgOnly || arm == Arm::kLearntActor) {
    supervisor_action = &constant(builder, "no_supervisor", 0.0);
  } else {
    const Block& supervisor =
        config.text("supervisor.kind") == "lqr"
            ? static_cast<const Block&>(builder.emplace<blocks::LqrSupervisor>(
                  "supervisor", robot_params(config), lqr_supervisor_params(config)))
            : builder.emplace<blocks::PdSupervisor>("supervisor", pd_supervisor_params(config));
    builder.connect(measured, supervisor.input_port("measured"));
    supervisor_action = &supervisor.output_port("action");
  }

  const double nan = std::numeric_limits<double>::quiet_NaN();
  const OutputPort* action = supervisor_action;
  const OutputPort* omega = nullptr;
  const OutputPort* actor_action = nullptr;
  const OutputPort* exploration_action = nullptr;
  const OutputPort* value = nullptr;
  const OutputPort* td_error = nullptr;
  const OutputPort* temperature = nullptr;
  const OutputPort* entropy = nullptr;
  if (arm == Arm::kPdOnly) {
    omega = &constant(builder, "no_omega", 0.0);
    actor_action = exploration_action = value = td_error = temperature = entropy =
        &constant(builder, "not_learning", nan);
  } else if (arm == Arm::kLearntActor) {
    // a = a_A = theta . phi and nothing else. A zero TD error with omega = 1 leaves both
    // actor rules without a term: the weights stay as loaded.
    auto& normaliser = builder.emplace<blocks::Normaliser>("normaliser", normaliser_params(config));
    auto& rbf = builder.emplace<blocks::RbfFeatures>("rbf", rbf_params(config));
    const int num_features = rbf.output_port("features").size();
    auto& actor =
        builder.emplace<blocks::Actor>("actor", num_features, actor_params(config), period);
    result.actor = &actor;
    builder.connect(measured, normaliser.input_port("measured"));
    builder.connect(normaliser.output_port("x"), rbf.input_port("x"));
    builder.connect(rbf.output_port("features"), actor.input_port("features"));
    const OutputPort& zero = constant(builder, "frozen", 0.0);
    builder.connect(zero, actor.input_port("td_error"));
    builder.connect(zero, actor.input_port("exploration_action"));
    builder.connect(*supervisor_action, actor.input_port("supervisor_action"));
    omega = &constant(builder, "no_omega", 1.0);
    builder.connect(*omega, actor.input_port("omega"));
    action = actor_action = &actor.output_port("action");
    exploration_action = value = td_error = temperature = entropy =
        &constant(builder, "not_learning", nan);
  } else {
    // The basal ganglia: features, critic, actor, tropism and Boltzmann exploration.
    auto& normaliser = builder.emplace<blocks::Normaliser>("normaliser", normaliser_params(config));
    auto& rbf = builder.emplace<blocks::RbfFeatures>("rbf", rbf_params(config));
    const int num_features = rbf.output_port("features").size();
    auto& critic =
        builder.emplace<blocks::Critic>("critic", num_features, critic_params(config), period);
    blocks::ActorParams actor_config = actor_params(config);
    if (arm == Arm::kCbbgWeighted) actor_config.rule = blocks::ActorRule::kWeighted;
    auto& actor = builder.emplace<blocks::Actor>("actor", num_features, actor_config, period);
    auto& tropism = builder.emplace<blocks::Tropism>("tropism", tropism_params(config));
    auto& sampler =
        builder.emplace<blocks::BoltzmannSampler>("sampler", sampler_params(config), period);
    auto& entropy_block = builder.emplace<blocks::Entropy>("entropy", entropy_params(config));
    const blocks::OmegaMode mode = arm == Arm::kBgOnly   ? blocks::OmegaMode::kOne
                                   : arm == Arm::kCbOnly ? blocks::OmegaMode::kZero
                                                         : blocks::OmegaMode::kSchedule;
    auto& schedule =
        builder.emplace<blocks::OmegaSchedule>("omega", omega_params(config, mode), period);
    auto& mixer = builder.emplace<blocks::Mixer>("mixer");
    result.critic = &critic;
    result.actor = &actor;
    result.tropism = &tropism;

    builder.connect(measured, normaliser.input_port("measured"));
    builder.connect(normaliser.output_port("x"), rbf.input_port("x"));
    const OutputPort& features = rbf.output_port("features");
    builder.connect(features, critic.input_port("features"));
    builder.connect(features, actor.input_port("features"));
    builder.connect(reward.output_port("reward"), critic.input_port("reward"));
    builder.connect(failure.output_port("failed"), critic.input_port("failed"));
    builder.connect(critic.output_port("value"), tropism.input_port("value"));
    builder.connect(critic.output_port("td_error"), actor.input_port("td_error"));
    builder.connect(actor.output_port("action"), sampler.input_port("actor_action"));
    builder.connect(tropism.output_port("temperature"), sampler.input_port("temperature"));
    builder.connect(tropism.output_port("temperature"), entropy_block.input_port("temperature"));
    builder.connect(*supervisor_action, actor.input_port("supervisor_action"));
    builder.connect(*supervisor_action, mixer.input_port("supervisor_action"));
    builder.connect(sampler.output_port("action"), actor.input_port("exploration_action"));
    builder.connect(sampler.output_port("action"), mixer.input_port("exploration_action"));
    builder.connect(schedule.output_port("omega"), actor.input_port("omega"));
    builder.connect(schedule.output_port("omega"), mixer.input_port("omega"));
    action = &mixer.output_port("action");
    omega = &schedule.output_port("omega");
    actor_action = &actor.output_port("action");
    exploration_action = &sampler.output_port("action");
    value = &critic.output_port("value");
    td_error = &critic.output_port("td_error");
    temperature = &tropism.output_port("temperature");
    entropy = &entropy_block.output_port("entropy");
  }

  // The action is sampled every tick and held (zero-order hold); both wheels get it.
  auto& hold = builder.emplace<ZeroOrderHold>("hold", 1, period);
  auto& wheel_torques = builder.emplace<Multiplexer>(
      "wheel_torques", std::vector<Multiplexer::Input>{{"left", 1}, {"right", 1}});
  builder.connect(*action, hold.input_port("u"));
  const OutputPort* wheel_torque = &hold.output_port("y");
  if (options.push) {
    auto& push = builder.emplace<TorquePush>("push", *options.push, period);
    builder.connect(*wheel_torque, push.input_port("action"));
    wheel_torque = &push.output_port("torque");
  }
  builder.connect(*wheel_torque, wheel_torques.input_port("left"));
  builder.connect(*wheel_torque, wheel_torques.input_port("right"));
  builder.connect(wheel_torques.output_port("y"), robot.input_port("torque"));

  auto& telemetry = builder.emplace<Multiplexer>(
      "telemetry", std::vector<Multiplexer::Input>{{"measured", measured.size()},
                                                   {"supervisor_action", 1},
                                                   {"actor_action", 1},
                                                   {"exploration_action", 1},
                                                   {"action", 1},
                                                   {"omega", 1},
                                                   {"value", 1},
                                                   {"td_error", 1},
                                                   {"temperature", 1},
                                                   {"reward", 1},
                                                   {"entropy", 1}});
  builder.connect(measured, telemetry.input_port("measured"));
  builder.connect(*supervisor_action, telemetry.input_port("supervisor_action"));
  builder.connect(*actor_action, telemetry.input_port("actor_action"));
  builder.connect(*exploration_action, telemetry.input_port("exploration_action"));
  builder.connect(*action, telemetry.input_port("action"));
  builder.connect(*omega, telemetry.input_port("omega"));
  builder.connect(*value, telemetry.input_port("value"));
  builder.connect(*td_error, telemetry.input_port("td_error"));
  builder.connect(*temperature, telemetry.input_port("temperature"));
  builder.connect(reward.output_port("reward"), telemetry.input_port("reward"));
  builder.connect(*entropy, telemetry.input_port("entropy"));
  result.telemetry = &telemetry.output_port("y");

  result.diagram = builder.build();
  return result;
}

}  // namespace cbbg::diagrams
