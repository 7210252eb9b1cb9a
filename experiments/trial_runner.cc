#include "cbbg/experiments/trial_runner.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <iterator>
#include <limits>

#include "cbbg/framework/number_text.h"

namespace cbbg::experiments {

using namespace diagrams;  // the telemetry indices
namespace {

struct StepsColumn {
  int telemetry;
  std::string name;
};

// steps.csv's signal columns from a plant with `signals`, after arm, seed, trial and t: the
// telemetry's recorded signals, the pose's where it exists, then the plant's logged ones.
std::vector<StepsColumn> steps_columns(const plant::SignalIndex& signals) {
  std::vector<StepsColumn> columns;
  for (const RecordedSignal& recorded : kRecordedSignals) {
    columns.push_back({recorded.telemetry, recorded.name});
  }
  if (signals.x >= 0) columns.push_back({kTelemetryX, "x"});
  if (signals.y >= 0) columns.push_back({kTelemetryY, "y"});
  if (signals.yaw >= 0) columns.push_back({kTelemetryYaw, "yaw"});
  for (std::size_t i = 0; i < signals.logged.size(); ++i) {
    columns.push_back({kTelemetrySize + static_cast<int>(i), signals.logged[i].name});
  }
  return columns;
}

// Writes `value` in its shortest round-trip form, without allocating.
void write_number(std::ostream& out, double value) {
  char buffer[32];
  const char* end = std::to_chars(buffer, buffer + sizeof buffer, value).ptr;
  out.write(buffer, end - buffer);
}

}  // namespace

std::string steps_csv_header(const plant::SignalIndex& signals) {
  std::string header = "arm,seed,trial,t";
  for (const StepsColumn& column : steps_columns(signals)) {
    header += ',';
    header += column.name;
  }
  return header + "\n";
}

TrialRunner::TrialRunner(const diagrams::ClosedLoop& loop, std::uint64_t seed, double period,
                         TelemetryOptions telemetry)
    : loop_(&loop),
      simulator_(*loop.diagram,
                 SimulatorOptions{.accuracy = loop.accuracy, .schedule = loop.schedule}, seed),
      telemetry_(&simulator_.add_log(*loop.telemetry, period)),
      period_(period),
      options_(std::move(telemetry)),
      checks_value_(loop.learner.critic != nullptr && loop.outputs("value")),
      checks_temperature_(loop.learner.tropism != nullptr && loop.outputs("temperature")) {
  for (const StepsColumn& column : steps_columns(loop.signals)) {
    steps_columns_.push_back(column.telemetry);
  }
  if (options_.steps != nullptr && options_.steps_header_pending != nullptr &&
      *options_.steps_header_pending) {
    *options_.steps << steps_csv_header(loop.signals);
    *options_.steps_header_pending = false;
  }
  telemetry_->keep_in_memory(options_.keep_in_memory);
  telemetry_->set_sink([this](double time, const double* values) { record(time, values); });
}

void TrialRunner::record(double time, const double* values) {
  temperature_sum_ += values[kTelemetryTemperature];
  entropy_sum_ += values[kTelemetryEntropy];
  if (options_.steps != nullptr && options_.decimation > 0 && ticks_ % options_.decimation == 0) {
    std::ostream& out = *options_.steps;
    out.write(trial_prefix_.data(), static_cast<std::streamsize>(trial_prefix_.size()));
    write_number(out, time);
    for (const int column : steps_columns_) {
      out.put(',');
      write_number(out, values[column]);
    }
    out.put('\n');
  }
  ++ticks_;
  record_oscillation(time, values);
  check_learning_signals(time, values);
}

void TrialRunner::record_oscillation(double time, const double* values) {
  if (time < options_.settle_time) return;
  Oscillation& o = oscillation_;
  const double pitch = values[kTelemetryThetaB];
  const double wheels = 0.5 * (values[kTelemetryPhiLeft] + values[kTelemetryPhiRight]);
  if (o.ticks == 0) {
    o.pitch_min = o.pitch_max = pitch;
    o.first_time = time;
    o.first_wheels = wheels;
  }
  ++o.ticks;
  o.pitch_sum += pitch;
  o.pitch_square_sum += pitch * pitch;
  o.pitch_min = std::min(o.pitch_min, pitch);
  o.pitch_max = std::max(o.pitch_max, pitch);
  o.last_time = time;
  o.last_wheels = wheels;
}

void TrialRunner::finish_oscillation(TrialOutcome& outcome) const {
  const Oscillation& o = oscillation_;
  if (o.ticks < 2) return;  // ended before the transient had passed: NaN
  // About its mean: the oscillation, not the steady lean that holds a speed.
  const auto n = static_cast<double>(o.ticks);
  const double mean = o.pitch_sum / n;
  outcome.pitch_rms = std::sqrt(std::max(0.0, o.pitch_square_sum / n - mean * mean));
  outcome.pitch_peak_to_peak = o.pitch_max - o.pitch_min;
  outcome.mean_forward_speed = loop_->plant->wheel_radius() * (o.last_wheels - o.first_wheels) /
                               (o.last_time - o.first_time);
}

void TrialRunner::check_learning_signals(double time, const double* values) const {
  const diagrams::LearnerBlocks& learner = loop_->learner;
  const bool value_ok = !checks_value_ || std::isfinite(values[kTelemetryValue]);
  const bool temperature_ok = !checks_temperature_ || std::isfinite(values[kTelemetryTemperature]);
  if (value_ok && temperature_ok) return;
  const Block& block =
      value_ok ? static_cast<const Block&>(*learner.tropism) : learner.critic->learner_block();
  throw SimulationError("block '" + block.path() +
                        "': " + (value_ok ? "the temperature T" : "the value V") +
                        " stopped being finite at t = " + format_number(time) + " s");
}

TrialOutcome TrialRunner::run_trial(double theta0, double duration, int trial) {
  Context& context = simulator_.context();
  telemetry_->clear();
  if (options_.keep_in_memory) {
    // Room for every tick before the trial starts: logging never allocates while ticking.
    telemetry_->reserve(static_cast<int>(std::ceil(duration / period_)) + 1);
  }
  ticks_ = 0;
  temperature_sum_ = 0.0;
  entropy_sum_ = 0.0;
  oscillation_ = Oscillation{};
  trial_prefix_ = options_.row_prefix + std::to_string(trial) + ",";

  TrialOutcome outcome;
  try {
    if (before_trial_) theta0 = before_trial_(context, trial, theta0);
    loop_->start_trial(context, theta0);  // a robot's link may be stopped already here
    simulator_.initialize();
    const SimulationStatus status = simulator_.advance_to(duration);
    outcome.status = status.terminated ? TrialStatus::kFailed : TrialStatus::kSuccess;
    outcome.final_theta =
        loop_->diagram->eval_output(context, loop_->plant->state_output())[loop_->signals.pitch];
  } catch (const SimulationError& error) {
    outcome.status = TrialStatus::kDiverged;
    outcome.message = error.what();
    outcome.final_theta = std::numeric_limits<double>::quiet_NaN();
  } catch (const SimulationStopped& error) {
    outcome.status = TrialStatus::kStopped;
    outcome.message = error.what();
    outcome.final_theta = ticks_ == 0
                              ? std::numeric_limits<double>::quiet_NaN()
                              : loop_->diagram->eval_output(
                                    context, loop_->plant->state_output())[loop_->signals.pitch];
  }
  outcome.steps = ticks_;
  finish_oscillation(outcome);
  const double ticks = static_cast<double>(std::max<long long>(ticks_, 1));
  outcome.mean_temperature = temperature_sum_ / ticks;
  outcome.mean_entropy = entropy_sum_ / ticks;
  if (outcome.status != TrialStatus::kDiverged && loop_->learner.tropism != nullptr &&
      !(std::isfinite(outcome.mean_temperature) && std::isfinite(outcome.mean_entropy))) {
    // Finite at every tick, but too large to sum: as unusable as a NaN.
    outcome.status = TrialStatus::kDiverged;
    outcome.message = "the trial's mean temperature or entropy is not finite";
  }
  return outcome;
}

}  // namespace cbbg::experiments
