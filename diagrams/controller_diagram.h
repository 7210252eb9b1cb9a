#pragma once
// The named diagrams of SPEC section 4: the robot plant (plant.kind), the supervisor
// (supervisor.kind) and the CB-BG learning blocks, wired as the diagram's name says.
//
//   cbbg           supervisor + basal ganglia, omega schedule, actor.rule (improved by default)
//   cbbg_weighted  the same with the weighted rule (paper eq. 7)
//   bg_only        basal ganglia alone: omega = 1, no supervisor (a_S = 0)
//   cb_only        omega = 0: the supervisor drives, the actor learns from it alone
//   pd_only        the supervisor alone, no learning blocks

#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <string_view>

#include "blocks/actor.h"
#include "blocks/critic.h"
#include "blocks/reward.h"
#include "blocks/sensors.h"
#include "blocks/tropism.h"
#include "config/config.h"
#include "diagrams/torque_push.h"
#include "framework/diagram.h"

namespace cbbg::diagrams {

// The signals of the "telemetry" multiplexer, recorded every tick.
enum TelemetryIndex : int {
  kTelemetryThetaB = 0,
  kTelemetryThetaBDot,
  kTelemetryPhiLeft,
  kTelemetryPhiRight,
  kTelemetryPhiLeftDot,
  kTelemetryPhiRightDot,
  kTelemetrySupervisorAction,   // a_S
  kTelemetryActorAction,        // a_A
  kTelemetryExplorationAction,  // a_E
  kTelemetryAction,             // a, the mixed action (before the plant's saturation)
  kTelemetryOmega,
  kTelemetryValue,        // V(s_t)
  kTelemetryTdError,      // delta_{t-1}
  kTelemetryTemperature,  // T
  kTelemetryReward,       // r_{t-1}
  kTelemetryEntropy,      // E, bits
  kTelemetrySize
};

struct ControllerDiagram {
  std::string name;
  std::unique_ptr<Diagram> diagram;
  const Block* plant = nullptr;
  std::function<void(Context&, double)> reset_plant;
  const blocks::Sensors* sensors = nullptr;
  const blocks::Reward* reward = nullptr;
  const blocks::Critic* critic = nullptr;    // null in pd_only
  const blocks::Actor* actor = nullptr;      // null in pd_only
  const blocks::Tropism* tropism = nullptr;  // null in pd_only
  const OutputPort* telemetry = nullptr;     // size kTelemetrySize
  double accuracy = 1e-6;                    // the simulator's, from plant.accuracy

  // Starts a trial in `context`: the robot at `theta0`, everything else at rest, time 0,
  // every block's per-trial memory forgotten; learnt weights and the omega counter kept.
  void start_trial(Context& context, double theta0) const;
  bool learns() const { return actor != nullptr; }
};

// The evaluation diagram of a learnt policy: the actor alone drives (a = a_A; omega = 1, no
// exploration, no supervisor) and its weights do not change. Load them with
// ControllerDiagram::actor->mutable_weights.
inline constexpr const char* kLearntActorDiagram = "learnt_actor";

// Variations of a named diagram that are not config keys.
struct DiagramOptions {
  // A TorquePush "push" between the hold and the wheels (cbbg eval --push-*).
  std::optional<PushParams> push;
};

// Builds the diagram `name` (one of config::diagram_names(), or kLearntActorDiagram). Throws
// config::ConfigError for a value a block rejects, std::invalid_argument for an unknown name.
ControllerDiagram build_controller_diagram(std::string_view name, const config::Config& config,
                                           const DiagramOptions& options = {});

}  // namespace cbbg::diagrams
