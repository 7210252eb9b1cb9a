#pragma once
// The closed loop a trial runs: any robot plant (plant/robot_plant.h), the sensors, the task
// (failure detector and sliding-surface reward), a CB-BG controller, the zero-order hold on
// its action, and a telemetry multiplexer of what each tick records (telemetry.h).
//
//   plant -> sensors -> failure, reward -> controller -> hold [-> push] -> both wheels -> plant
//
// The protocols (experiments/) take a ClosedLoopFactory: any callable that builds one from
// the run's typed parameters. The presets (presets.h) are such factories; a user writes another.

#include <functional>
#include <memory>
#include <optional>
#include <string>

#include "blocks/critic.h"
#include "blocks/torque_push.h"
#include "blocks/tropism.h"
#include "diagrams/cbbg_controller.h"
#include "diagrams/telemetry.h"
#include "framework/diagram.h"
#include "plant/robot_plant.h"

namespace cbbg::diagrams {

// The learning blocks the protocols read and write (weights files, exp2's annealing of k1);
// null where a controller has none.
struct LearnerBlocks {
  const blocks::Critic* critic = nullptr;
  const blocks::Actor* actor = nullptr;
  const blocks::Tropism* tropism = nullptr;  // null without exploration
  bool learns() const { return actor != nullptr; }
};

struct ClosedLoop {
  std::unique_ptr<Diagram> diagram;
  const plant::RobotPlant* plant = nullptr;
  const OutputPort* telemetry = nullptr;  // kTelemetrySize signals, TelemetryIndex order
  LearnerBlocks learner;
  double accuracy = 1e-6;      // the simulator's (plant.accuracy)
  double wheel_radius = 0.15;  // plant.wheel_radius, m: wheel angles to distance

  // Starts a trial in `context`: time 0, every block's per-trial state reset
  // (Context::reset_trial_state), the robot at `theta0` and at rest; learnt weights, the
  // omega counter and the random streams carry on.
  void start_trial(Context& context, double theta0) const;
};

// Makes the plant block named `name` from the run's typed parameters.
using PlantFactory = std::function<std::unique_ptr<plant::RobotPlant>(
    const std::string& name, const config::Parameters& parameters)>;

struct ClosedLoopOptions {
  // Empty: plant.kind's (plant::SimbodyPlant or plant::AnalyticPlant).
  PlantFactory plant{};
  // A torque pulse between the hold and the wheels (cbbg eval --push-*); empty: push.*'s,
  // if push.torque is not zero.
  std::optional<blocks::PushParams> push{};
};

// Wires `controller` (named anything; its ports as CbbgController's) into the closed loop
// named `name`. Throws std::invalid_argument when the plant's ports are not the
// RobotPlant's, config::ConfigError for a value a block rejects.
ClosedLoop build_closed_loop(std::string name, const config::Parameters& parameters,
                             std::unique_ptr<CbbgController> controller,
                             const ClosedLoopOptions& options = {});

// Builds the closed loop of one arm from the run's typed parameters; called once per task
// (maybe in several threads at once, each with its own result).
using ClosedLoopFactory = std::function<ClosedLoop(const config::Parameters& parameters)>;

// The factory of a CB-BG controller with `controller` options, in a closed loop named `name`.
ClosedLoopFactory closed_loop_factory(std::string name, ControllerOptions controller,
                                      ClosedLoopOptions options = {});

}  // namespace cbbg::diagrams
