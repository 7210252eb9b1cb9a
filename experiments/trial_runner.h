#pragma once
// Runs trials of a closed loop (diagrams/closed_loop.h) in one context: the weights learnt in one
// trial carry into the next. Each tick's telemetry feeds the trial's statistics, and optionally the
// rows of steps.csv and an in-memory log, so memory stays flat however long a trial runs.

#include <cstdint>
#include <functional>
#include <limits>
#include <memory>
#include <ostream>
#include <string>
#include <vector>

#include "cbbg/diagrams/closed_loop.h"
#include "cbbg/framework/simulator.h"
#include "cbbg/plant/plant_signals.h"
#include "cbbg/records/trial_outcome.h"

namespace cbbg::experiments {

using records::to_string;
using records::TrialOutcome;
using records::TrialStatus;

struct TelemetryOptions {
  // Keep every tick in telemetry() (tests, analysis); memory then grows with the trial.
  bool keep_in_memory = true;
  // steps.csv rows are written here as the trial runs: every `decimation`-th tick, each row
  // starting with `row_prefix` ("arm,seed,") and the trial number.
  std::ostream* steps = nullptr;
  long long decimation = 1;
  std::string row_prefix;
  // Where a trial's oscillation statistics start (trial.settle_time), s.
  double settle_time = 5.0;
  // When set and true, the runner first writes its rows' header line to `steps` (and sets it
  // false, so the runners of one task that share the stream write one header).
  bool* steps_header_pending = nullptr;
};

// The header line of steps.csv rows from a plant with `signals`: arm, seed, trial, t, the
// signals every loop has, then x, y and yaw where the plant has them.
std::string steps_csv_header(const plant::SignalIndex& signals = plant::two_wheeler_index());

class TrialRunner {
 public:
  TrialRunner(const diagrams::ClosedLoop& loop, std::uint64_t seed, double period,
              TelemetryOptions telemetry = {});

  // Runs trial number `trial` from `theta0` until failure or `duration`. A non-finite state
  // or an integrator failure ends the trial as diverged; the next trial starts clean. A
  // SimulationStopped (a robot's link) ends it as stopped.
  TrialOutcome run_trial(double theta0, double duration, int trial = 1);

  // What runs before each trial, in the trial's context: it may change the context's
  // parameters (a trial's noise, its push) and returns the initial pitch to start from, given
  // the one asked for (training_disturbances.h).
  using BeforeTrial = std::function<double(Context& context, int trial, double theta0)>;
  void set_before_trial(BeforeTrial before_trial) { before_trial_ = std::move(before_trial); }

  Context& context() { return simulator_.context(); }
  const Context& context() const { return simulator_.context(); }
  const diagrams::ClosedLoop& loop() const { return *loop_; }
  // The telemetry of the last trial, one sample per tick (diagrams::TelemetryIndex), when
  // kept in memory.
  const SignalLog& telemetry() const { return *telemetry_; }

 private:
  void record(double time, const double* values);
  // A learner whose value or temperature stops being finite has diverged, even while the
  // robot's state stays finite (the plant saturates any finite torque): throws
  // SimulationError, which ends the trial as diverged.
  void check_learning_signals(double time, const double* values) const;

  const diagrams::ClosedLoop* loop_;
  BeforeTrial before_trial_;
  Simulator simulator_;
  SignalLog* telemetry_;
  double period_;
  TelemetryOptions options_;
  std::vector<int> steps_columns_;  // the telemetry's columns in steps.csv, after t
  // Whether the controller outputs a learner's value and temperature to check (a user's
  // controller may keep them inside).
  bool checks_value_;
  bool checks_temperature_;
  // The current trial's running sums and its row prefix.
  long long ticks_ = 0;
  double temperature_sum_ = 0.0;
  double entropy_sum_ = 0.0;
  std::string trial_prefix_;
  // The oscillation's running figures, from the settle time on.
  struct Oscillation {
    long long ticks = 0;
    double pitch_sum = 0.0;
    double pitch_square_sum = 0.0;
    double pitch_min = 0.0;
    double pitch_max = 0.0;
    double first_time = 0.0;
    double first_wheels = 0.0;  // (phi_l + phi_r) / 2 there
    double last_time = 0.0;
    double last_wheels = 0.0;
  };
  void record_oscillation(double time, const double* values);
  void finish_oscillation(TrialOutcome& outcome) const;
  Oscillation oscillation_;
};

}  // namespace cbbg::experiments
