#pragma once
// The closed loop a trial runs: any robot plant (plant/robot_plant.h, plant_kinds.h), the sensors,
// the task (failure detector and reward: slots, TaskSlots), any controller (a CbbgController, or
// a diagram of the user's with a controller's ports), the zero-order hold on its action, and a
// telemetry multiplexer of what each tick records (telemetry.h).
//
//   plant -> sensors -> failure, reward -> controller -> hold [-> push] -> both wheels -> plant
//
// The protocols (experiments/) take a ClosedLoopFactory: any callable that builds one from
// the run's typed parameters. The presets (presets.h) are such factories; a user writes another.

#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "cbbg/blocks/push_params.h"
#include "cbbg/diagrams/block_factory.h"
#include "cbbg/diagrams/cbbg_controller.h"
#include "cbbg/diagrams/controller_ports.h"
#include "cbbg/diagrams/plant_kinds.h"
#include "cbbg/diagrams/telemetry.h"
#include "cbbg/framework/diagram.h"
#include "cbbg/framework/simulator.h"
#include "cbbg/plant/robot_plant.h"

namespace cbbg::diagrams {

struct ClosedLoop {
  std::unique_ptr<Diagram> diagram;
  const plant::RobotPlant* plant = nullptr;
  plant::SignalIndex signals;  // where the loop found each signal it reads or logs in the plant's
                               // state
  bool plant_of_kind = true;   // built by plant.kind's kind, not ClosedLoopOptions::plant
  // kTelemetrySize signals in TelemetryIndex order, then signals.logged's
  const OutputPort* telemetry = nullptr;
  LearnerBlocks learner;
  // What the controller's blocks say gives its features their meaning (normaliser.*, rbf.*
  // for the presets), in the order they were built, and their notes for a weights file.
  blocks::FeatureLayout layout;
  std::vector<std::string> layout_notes;
  const Diagram* controller = nullptr;      // kControllerDiagnostics' comment: its ports
  double accuracy = 1e-6;                   // the simulator's (plant.accuracy)
  Schedule schedule = Schedule::kCompiled;  // the simulator's (bench/diagrams compares both)

  // Whether the controller has the diagnostic output `name` (the telemetry's is NaN if not).
  bool outputs(const char* name) const {
    return controller == nullptr || controller->find_output_port(name) != nullptr;
  }

  // Starts a trial in `context`: time 0, every block's per-trial state reset
  // (Context::reset_trial_state), the robot at `theta0` and at rest; learnt weights, the
  // omega counter and the random streams carry on.
  void start_trial(Context& context, double theta0) const;
};

// The task's slots around the controller, each filled by a user's block or the parameters'
// own (configured_blocks.h), with the port contract the loop checks when it builds
// (check_slot). The reward the loop records in steps.csv is the one the controller learns
// from, wherever it comes from.
struct TaskSlots {
  // Feeds "plant_state" (the plant's output "state", SlotRequest::plant_state_size; where
  // each signal sits: SlotRequest::signals); reads "measured" (6, blocks/measured_signals.h).
  // Default: blocks::Sensors (sensors.*).
  BlockFactory sensors;
  // Feeds "measured" (6); reads "failed" (1: 1 when the trial fails at this tick). Default:
  // blocks::FailureDetector (trial.failure_angle).
  BlockFactory failure;
  // Feeds "measured" (6) and "failed" (1); reads "reward" (1: r_{t-1}). Default:
  // reward.kind's (sliding: blocks::Reward; quadratic: blocks::QuadraticReward). A
  // controller with an output "reward" (1) makes its own reward instead: the loop builds
  // none, and records the controller's.
  BlockFactory reward;
};

// The contracts check_slot checks; `plant_state_size` the plant's output "state" size.
SlotContract sensors_contract(int plant_state_size);
SlotContract failure_contract();
SlotContract reward_contract();

struct ClosedLoopOptions {
  // Empty: plant.kind's (plant_kinds.h). A plant given here is the arm's own: an evaluation
  // that changes the robot refuses it (the change reaches a plant through its kind).
  PlantFactory plant{};
  // The push (cbbg eval --push-*): its torque between the hold and the wheels (TorquePush),
  // its force and pitch torque into the plant's input "disturbance" (ExternalPush). Empty:
  // push.*'s, if it pushes at all.
  std::optional<blocks::PushParams> push{};
  TaskSlots slots{};
};

// Wires `controller` (any diagram with the ports of controller_ports.h; CbbgController is
// one) into the closed loop named `name`. Its learners (blocks::Learner, blocks::Tropism)
// are found wherever they sit in it. Throws std::invalid_argument when the controller's or
// the plant's ports or signals do not fit, naming them, or the controller has two learners
// of a kind; config::ConfigError when the push comes from outside (push.force,
// push.pitch_torque) and the plant has no input "disturbance".
ClosedLoop build_closed_loop(std::string name, const parameters::Parameters& parameters,
                             std::shared_ptr<Diagram> controller,
                             const ClosedLoopOptions& options = {});

// Builds the closed loop of one arm from the run's typed parameters; called once per task
// (maybe in several threads at once, each with its own result). The seed reaches the loop
// through its blocks' random generators (BlockContext::random_generator) alone, never
// through parameters.run.seed: the arms of a seed then draw the same numbers, and a run
// that drew none is every seed's (transfer shares such an evaluation across the seeds).
using ClosedLoopFactory = std::function<ClosedLoop(const parameters::Parameters& parameters)>;

// Builds a controller (any diagram with a controller's ports) from the run's parameters (a
// std::unique_ptr converts).
using ControllerFactory = std::function<std::shared_ptr<Diagram>(const parameters::Parameters&)>;

// The factory of a CB-BG controller with `controller` options, in a closed loop named `name`.
ClosedLoopFactory closed_loop_factory(std::string name, ControllerOptions controller,
                                      ClosedLoopOptions options = {});
// The same for a controller of the user's own.
ClosedLoopFactory closed_loop_factory(std::string name, ControllerFactory controller,
                                      ClosedLoopOptions options = {});

}  // namespace cbbg::diagrams
