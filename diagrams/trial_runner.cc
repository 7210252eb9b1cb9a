#include "diagrams/trial_runner.h"

#include <cmath>

#include "plant/plant_ports.h"

namespace cbbg::diagrams {

const char* to_string(TrialStatus status) {
  switch (status) {
    case TrialStatus::kSuccess:
      return "success";
    case TrialStatus::kFailed:
      return "failed";
    case TrialStatus::kDiverged:
      return "diverged";
  }
  return "unknown";
}

TrialRunner::TrialRunner(const ControllerDiagram& controller, std::uint64_t seed, double period)
    : controller_(&controller),
      simulator_(*controller.diagram, SimulatorOptions{.accuracy = controller.accuracy}, seed),
      telemetry_(&simulator_.add_log(*controller.telemetry, period)),
      period_(period) {}

TrialOutcome TrialRunner::run_trial(double theta0, double duration) {
  Context& context = simulator_.context();
  controller_->start_trial(context, theta0);
  telemetry_->clear();
  // Room for every tick before the trial starts: logging never allocates while ticking.
  telemetry_->reserve(static_cast<int>(std::ceil(duration / period_)) + 1);
  TrialOutcome outcome;
  try {
    simulator_.initialize();
    const SimulationStatus status = simulator_.advance_to(duration);
    outcome.status = status.terminated ? TrialStatus::kFailed : TrialStatus::kSuccess;
    outcome.final_theta = controller_->diagram->eval_output(
        context, controller_->plant->output_port("state"))[plant::kThetaB];
  } catch (const SimulationError& error) {
    outcome.status = TrialStatus::kDiverged;
    outcome.message = error.what();
    outcome.final_theta = std::numeric_limits<double>::quiet_NaN();
  }
  outcome.steps = telemetry_->num_samples();
  double temperature = 0.0;
  double entropy = 0.0;
  for (int k = 0; k < telemetry_->num_samples(); ++k) {
    temperature += telemetry_->sample(k)[kTelemetryTemperature];
    entropy += telemetry_->sample(k)[kTelemetryEntropy];
  }
  const double ticks = static_cast<double>(std::max<long long>(outcome.steps, 1));
  outcome.mean_temperature = temperature / ticks;
  outcome.mean_entropy = entropy / ticks;
  return outcome;
}

}  // namespace cbbg::diagrams
