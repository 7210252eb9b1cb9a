#pragma once
// The signals a closed loop records every tick (its "telemetry" multiplexer), in this order.
// Each is an output port of the controller with the same name, except the six measured
// signals, which come from the sensors, and the pose, which comes from the plant. A signal a
// controller does not have (the value of a supervisor alone, say) is NaN. After them come
// the plant's logged signals (RobotPlant::logged_signals), at kTelemetrySize + i.

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

// What steps.csv calls the telemetry's signals it records, after arm, seed, trial and t
// (then x, y and yaw where the plant has them, and the plant's logged signals).
struct RecordedSignal {
  int telemetry;
  const char* name;
};
inline constexpr RecordedSignal kRecordedSignals[] = {
    {kTelemetryThetaB, "theta_b"},        {kTelemetryThetaBDot, "dtheta_b"},
    {kTelemetryPhiLeft, "phi_l"},         {kTelemetryPhiRight, "phi_r"},
    {kTelemetrySupervisorAction, "a_S"},  {kTelemetryActorAction, "a_A"},
    {kTelemetryExplorationAction, "a_E"}, {kTelemetryAction, "a"},
    {kTelemetryOmega, "omega"},           {kTelemetryValue, "V"},
    {kTelemetryTdError, "delta"},         {kTelemetryTemperature, "T"},
    {kTelemetryReward, "reward"}};
inline constexpr const char* kStepsKeyColumns[] = {"arm", "seed", "trial", "t"};

}  // namespace cbbg::diagrams
