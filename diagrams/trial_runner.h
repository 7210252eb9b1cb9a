#pragma once
// Runs trials of a controller diagram in one context: the weights learnt in one trial carry
// into the next. Records the telemetry of every tick of the current trial.

#include <cstdint>
#include <memory>
#include <string>

#include "diagrams/controller_diagram.h"
#include "framework/simulator.h"

namespace cbbg::diagrams {

enum class TrialStatus { kSuccess, kFailed, kDiverged };
const char* to_string(TrialStatus status);

struct TrialOutcome {
  TrialStatus status = TrialStatus::kSuccess;
  long long steps = 0;            // ticks the trial ran
  double mean_temperature = 0.0;  // over its ticks (NaN without learning blocks)
  double mean_entropy = 0.0;
  double final_theta = 0.0;  // theta_b at the end, rad
  std::string message;       // why it diverged
};

class TrialRunner {
 public:
  TrialRunner(const ControllerDiagram& controller, std::uint64_t seed, double period);

  // Runs one trial from `theta0` until failure or `duration`. A non-finite state or an
  // integrator failure ends the trial as diverged; the next trial starts clean.
  TrialOutcome run_trial(double theta0, double duration);

  Context& context() { return simulator_.context(); }
  const ControllerDiagram& controller() const { return *controller_; }
  // The telemetry of the last trial: one sample per tick (diagrams::TelemetryIndex).
  const SignalLog& telemetry() const { return *telemetry_; }

 private:
  const ControllerDiagram* controller_;
  Simulator simulator_;
  SignalLog* telemetry_;
  double period_;
};

}  // namespace cbbg::diagrams
