#pragma once
// How one trial ended, as the trial runner (experiments/trial_runner.h) measures it.

#include <limits>
#include <string>

namespace cbbg::records {

// kStopped: stopped from outside (framework/simulator.h's SimulationStopped), not a failure.
enum class TrialStatus { kSuccess, kFailed, kDiverged, kStopped };
const char* to_string(TrialStatus status);

struct TrialOutcome {
  TrialStatus status = TrialStatus::kSuccess;
  long long steps = 0;            // ticks the trial ran
  double mean_temperature = 0.0;  // over its ticks (NaN without learning blocks)
  double mean_entropy = 0.0;
  double final_theta = 0.0;  // theta_b at the end, rad
  std::string message;       // why it diverged or was stopped
  // The oscillation after the initial transient (ticks from the settle time on; NaN when
  // the trial ended before it): theta_b's RMS about its mean and its peak-to-peak, rad, and
  // the mean forward speed R (phi_l + phi_r)' / 2 over that span, m/s (the robot's drift).
  double pitch_rms = std::numeric_limits<double>::quiet_NaN();
  double pitch_peak_to_peak = std::numeric_limits<double>::quiet_NaN();
  double mean_forward_speed = std::numeric_limits<double>::quiet_NaN();
};

}  // namespace cbbg::records
