#include "cbbg/diagrams/closed_loop.h"

#include <algorithm>
#include <iterator>
#include <limits>
#include <stdexcept>

#include "cbbg/blocks/external_push.h"
#include "cbbg/blocks/measured_signals.h"
#include "cbbg/blocks/torque_push.h"
#include "cbbg/config/config.h"
#include "cbbg/diagrams/configured_blocks.h"
#include "cbbg/diagrams/slot_check.h"
#include "cbbg/framework/diagram_builder.h"
#include "cbbg/framework/primitives/constant_source.h"
#include "cbbg/framework/primitives/multiplexer.h"
#include "cbbg/framework/primitives/selector.h"
#include "cbbg/framework/primitives/zero_order_hold.h"
#include "cbbg/parameters/parameters.h"
#include "cbbg/plant/plant_ports.h"

namespace cbbg::diagrams {
namespace {

// A plant's logged signal may not take the name of a column steps.csv has already.
void check_logged_names(const std::string& plant, const std::vector<plant::LoggedSignal>& logged) {
  for (const plant::LoggedSignal& signal : logged) {
    bool taken = std::any_of(std::begin(kStepsKeyColumns), std::end(kStepsKeyColumns),
                             [&](const char* name) { return signal.name == name; });
    for (const RecordedSignal& recorded : kRecordedSignals) taken |= signal.name == recorded.name;
    if (taken) {
      throw std::invalid_argument("plant '" + plant + "' logs '" + signal.name +
                                  "', a name steps.csv gives one of its own columns; rename "
                                  "the signal");
    }
  }
}

// The plant's ports checked, and where its signals sit in its state output.
plant::SignalIndex check_plant(const plant::RobotPlant& robot) {
  const InputPort* torque = robot.find_input_port("torque");
  const OutputPort* state = robot.find_output_port("state");
  const std::vector<std::string> signals = robot.signals();
  if (torque == nullptr || torque->size() != plant::kTorqueSize || state == nullptr) {
    throw std::invalid_argument("plant '" + robot.name() +
                                "' must have an input \"torque\" of size 2 and an output "
                                "\"state\" (plant/robot_plant.h)");
  }
  if (state->size() != static_cast<int>(signals.size())) {
    throw std::invalid_argument("plant '" + robot.name() + "' names " +
                                std::to_string(signals.size()) + " signals, but its output " +
                                "\"state\" has size " + std::to_string(state->size()));
  }
  plant::SignalIndex index = plant::index_signals(robot.name(), signals, robot.logged_signals());
  check_logged_names(robot.name(), index.logged);
  return index;
}

// The push of push.*, when it pushes at all.
std::optional<blocks::PushParams> configured_push(const parameters::Parameters& parameters) {
  if (!parameters.push.any()) return std::nullopt;
  return parameters.push;
}

// The plant of the arm's own factory or of plant.kind's, built for the loop's push (a kind's
// plant declares its input "disturbance" when push.* pushes from outside).
std::shared_ptr<plant::RobotPlant> make_plant(const parameters::Parameters& p,
                                              const ClosedLoopOptions& options) {
  const auto make = [&options](const parameters::Parameters& q) {
    return options.plant ? options.plant("plant", q) : plant_kind(q.plant.kind).make("plant", q);
  };
  if (!options.push) return make(p);
  parameters::Parameters pushed = p;  // a copy only for a loop of its own push
  pushed.push = *options.push;
  return make(pushed);
}

// A push from outside into the plant's input "disturbance"; a plant that declares the input
// gets zero without one.
void wire_disturbance(DiagramBuilder& builder, double period, const plant::RobotPlant& robot,
                      const std::optional<blocks::PushParams>& push) {
  const InputPort* disturbance = robot.disturbance_input();
  if (!push || !push->from_outside()) {
    if (disturbance != nullptr) builder.fix_input(*disturbance, Vector::Zero(disturbance->size()));
    return;
  }
  if (disturbance == nullptr || disturbance->size() != plant::kDisturbanceSize) {
    throw config::ConfigError(
        "push.force and push.pitch_torque push the robot from outside, but plant '" + robot.name() +
        "' has no input \"disturbance\" of size 2 (force, pitch torque); keep "
        "them 0 for this plant, or push through the motors (push.torque)");
  }
  auto& pusher = builder.emplace<blocks::ExternalPush>("external_push", *push, period);
  builder.connect(pusher.output_port("disturbance"), *disturbance);
}

// The action sampled every tick and held (zero-order hold), optionally pushed through the
// motors, to both wheels.
void wire_actuation(DiagramBuilder& builder, double period, const OutputPort& action,
                    const plant::RobotPlant& robot, const std::optional<blocks::PushParams>& push) {
  auto& hold = builder.emplace<ZeroOrderHold>("hold", 1, period);
  auto& wheel_torques = builder.emplace<Multiplexer>(
      "wheel_torques", std::vector<Multiplexer::Input>{{"left", 1}, {"right", 1}});
  builder.connect(action, hold.input_port("u"));
  const OutputPort* wheel_torque = &hold.output_port("y");
  if (push && push->through_motors()) {
    auto& pusher = builder.emplace<blocks::TorquePush>("push", *push, period);
    builder.connect(*wheel_torque, pusher.input_port("action"));
    wheel_torque = &pusher.output_port("torque");
  }
  builder.connect(*wheel_torque, wheel_torques.input_port("left"));
  builder.connect(*wheel_torque, wheel_torques.input_port("right"));
  builder.connect(wheel_torques.output_port("y"), robot.torque_input());
}

// The controller's diagnostic outputs, and one NaN source for all those it does not have (and
// for a pose signal the plant does not have).
class Diagnostics {
 public:
  Diagnostics(DiagramBuilder& builder, const Diagram& controller)
      : builder_(builder), controller_(controller) {}

  const OutputPort& operator()(const std::string& name) {
    if (const OutputPort* output = controller_.find_output_port(name)) return *output;
    return none();
  }

  // The NaN source.
  const OutputPort& none() {
    if (missing_ == nullptr) {
      missing_ =
          &builder_
               .emplace<ConstantSource>(
                   "no_diagnostics", Vector::Constant(1, std::numeric_limits<double>::quiet_NaN()))
               .output_port("y");
    }
    return *missing_;
  }

 private:
  DiagramBuilder& builder_;
  const Diagram& controller_;
  const OutputPort* missing_ = nullptr;
};

// The robot's pose (x, y, yaw) from its state; NaN where the plant has no such signal.
const OutputPort& wire_pose(DiagramBuilder& builder, const plant::RobotPlant& robot,
                            const plant::SignalIndex& signals, Diagnostics& missing) {
  const int size = robot.state_output().size();
  if (signals.has_pose()) {
    auto& pose = builder.emplace<Selector>("pose", size,
                                           std::vector<int>{signals.x, signals.y, signals.yaw});
    builder.connect(robot.state_output(), pose.input_port("u"));
    return pose.output_port("y");
  }
  auto& pose = builder.emplace<Multiplexer>(
      "pose", std::vector<Multiplexer::Input>{{"x", 1}, {"y", 1}, {"yaw", 1}});
  for (const auto& [name, index] :
       {std::pair{"x", signals.x}, std::pair{"y", signals.y}, std::pair{"yaw", signals.yaw}}) {
    if (index < 0) {
      builder.connect(missing.none(), pose.input_port(name));
      continue;
    }
    auto& one =
        builder.emplace<Selector>(std::string("pose_") + name, size, std::vector<int>{index});
    builder.connect(robot.state_output(), one.input_port("u"));
    builder.connect(one.output_port("y"), pose.input_port(name));
  }
  return pose.output_port("y");
}

// The multiplexer of telemetry.h's signals, then the plant's logged ones.
const OutputPort& wire_telemetry(DiagramBuilder& builder, const OutputPort& measured,
                                 const Diagram& controller, const OutputPort& reward,
                                 const plant::RobotPlant& robot,
                                 const plant::SignalIndex& signals) {
  const std::vector<std::string> from_controller{
      "supervisor_action", "actor_action", "exploration_action", "action", "omega", "value",
      "td_error",          "temperature"};
  std::vector<Multiplexer::Input> inputs{{"measured", measured.size()}};
  for (const auto& name : from_controller) inputs.push_back({name, 1});
  inputs.push_back({"reward", 1});
  inputs.push_back({"entropy", 1});
  inputs.push_back({"pose", 3});
  if (!signals.logged.empty()) {
    inputs.push_back({"logged", static_cast<int>(signals.logged.size())});
  }
  auto& telemetry = builder.emplace<Multiplexer>("telemetry", inputs);
  Diagnostics diagnostic(builder, controller);
  builder.connect(wire_pose(builder, robot, signals, diagnostic), telemetry.input_port("pose"));
  builder.connect(measured, telemetry.input_port("measured"));
  for (const auto& name : from_controller) {
    builder.connect(diagnostic(name), telemetry.input_port(name));
  }
  builder.connect(reward, telemetry.input_port("reward"));
  builder.connect(diagnostic("entropy"), telemetry.input_port("entropy"));
  if (!signals.logged.empty()) {
    std::vector<int> indices;
    for (const plant::LoggedSignal& signal : signals.logged) indices.push_back(signal.index);
    auto& logged = builder.emplace<Selector>("logged", robot.state_output().size(), indices);
    builder.connect(robot.state_output(), logged.input_port("u"));
    builder.connect(logged.output_port("y"), telemetry.input_port("logged"));
  }
  return telemetry.output_port("y");
}

// The task's blocks: sensors, failure detector, and the reward, unless the controller makes
// its own (null then).
struct Task {
  const Block& sensors;
  const Block& failure;
  const Block* reward;
};

Task add_task(DiagramBuilder& builder, const parameters::Parameters& p, const TaskSlots& slots,
              const plant::RobotPlant& robot, const plant::SignalIndex& signals,
              const Diagram& controller) {
  const int state_size = robot.state_output().size();
  const Block& sensors = builder.add(fill_slot("sensors", slots.sensors, configured_sensors,
                                               {"sensors", p, 0, true, state_size, &signals}));
  check_slot(&sensors, sensors_contract(state_size));
  const Block& failure =
      builder.add(fill_slot("failure", slots.failure, configured_failure, {"failure", p}));
  check_slot(&failure, failure_contract());
  if (controller.find_output_port("reward") != nullptr) {
    if (controller.find_input_port("reward") != nullptr) {
      throw std::invalid_argument("controller '" + controller.name() +
                                  "' has both an input \"reward\" and an output \"reward\": it "
                                  "learns from the loop's reward or makes its own, not both");
    }
    return {sensors, failure, nullptr};
  }
  const Block& reward =
      builder.add(fill_slot("reward", slots.reward, configured_reward, {"reward", p}));
  check_slot(&reward, reward_contract());
  return {sensors, failure, &reward};
}

}  // namespace

SlotContract sensors_contract(int plant_state_size) {
  return {
      "sensors slot", {{"plant_state", plant_state_size}}, {{"measured", blocks::kMeasuredSize}}};
}

SlotContract failure_contract() {
  return {"failure slot", {{"measured", blocks::kMeasuredSize}}, {{"failed", 1}}};
}

SlotContract reward_contract() {
  return {"reward slot", {{"measured", blocks::kMeasuredSize}, {"failed", 1}}, {{"reward", 1}}};
}

void ClosedLoop::start_trial(Context& context, double theta0) const {
  context.reset_trial_state();
  plant->reset(context, theta0);
}

ClosedLoop build_closed_loop(std::string name, const parameters::Parameters& p,
                             std::shared_ptr<Diagram> controller,
                             const ClosedLoopOptions& options) {
  if (!controller) throw std::invalid_argument("the controller factory returned null");
  check_controller_ports(*controller);
  ClosedLoop loop;
  loop.accuracy = p.plant.robot.accuracy;
  const double period = p.trial.period;
  DiagramBuilder builder(std::move(name));
  const std::optional<blocks::PushParams> push = options.push ? options.push : configured_push(p);
  std::shared_ptr<plant::RobotPlant> made = make_plant(p, options);
  loop.plant_of_kind = !options.plant;
  if (!made) throw std::invalid_argument("the plant factory returned null");
  loop.signals = check_plant(*made);
  const plant::RobotPlant& robot = builder.add(std::move(made));
  const Task task = add_task(builder, p, options.slots, robot, loop.signals, *controller);
  const Diagram& brain = builder.add(std::move(controller));
  loop.plant = &robot;
  loop.controller = &brain;
  ControllerSurvey survey = survey_controller(brain);
  loop.learner = survey.learner;
  loop.layout = std::move(survey.layout);
  loop.layout_notes = std::move(survey.layout_notes);

  connect_if_read(builder, robot.state_output(), task.sensors, "plant_state");
  const OutputPort& measured = task.sensors.output_port("measured");
  const OutputPort& failed = task.failure.output_port("failed");
  connect_if_read(builder, measured, task.failure, "measured");
  if (task.reward != nullptr) {
    connect_if_read(builder, measured, *task.reward, "measured");
    connect_if_read(builder, failed, *task.reward, "failed");
  }
  builder.connect(measured, brain.input_port("measured"));
  const OutputPort& reward =
      task.reward != nullptr ? task.reward->output_port("reward") : brain.output_port("reward");
  connect_if_read(builder, reward, brain, "reward");
  connect_if_read(builder, failed, brain, "failed");
  wire_actuation(builder, period, brain.output_port("action"), robot, push);
  wire_disturbance(builder, period, robot, push);
  loop.telemetry = &wire_telemetry(builder, measured, brain, reward, robot, loop.signals);
  loop.diagram = builder.build();
  return loop;
}

ClosedLoopFactory closed_loop_factory(std::string name, ControllerOptions controller,
                                      ClosedLoopOptions options) {
  controller.validate();
  return closed_loop_factory(
      std::move(name),
      [controller = std::move(controller)](const parameters::Parameters& parameters) {
        return std::make_unique<CbbgController>("controller", parameters, controller);
      },
      std::move(options));
}

ClosedLoopFactory closed_loop_factory(std::string name, ControllerFactory controller,
                                      ClosedLoopOptions options) {
  return [name = std::move(name), controller = std::move(controller),
          options = std::move(options)](const parameters::Parameters& parameters) {
    return build_closed_loop(name, parameters, controller(parameters), options);
  };
}

}  // namespace cbbg::diagrams
