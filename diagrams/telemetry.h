#pragma once
// The signals a closed loop records every tick (its "telemetry" multiplexer), in this order.
// Each is an output port of the controller with the same name, except the six measured
// signals, which come from the sensors, and the pose, which comes from the plant. A signal a
// controller does not have (the value of a supervisor alone, say) is NaN.

namespace cbbg::diagrams {

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
  kTelemetryX,            // the robot's true pose (the plant's, not measured): x, m
  kTelemetryY,            // y, m
  kTelemetryYaw,          // heading, rad
  kTelemetrySize
};

}  // namespace cbbg::diagrams
