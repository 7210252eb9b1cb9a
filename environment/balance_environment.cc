#include "cbbg/environment/balance_environment.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <utility>

#include "cbbg/blocks/measured_signals.h"
#include "cbbg/diagrams/validated_parameters.h"
#include "cbbg/framework/number_text.h"

namespace cbbg::environment {
namespace {

// The simulator's test of simultaneous instants (framework/simulator.cc): a tick this close
// to trial.duration is the trial's end, not one more tick.
bool same_instant(double a, double b) {
  return std::abs(a - b) <= 1e-9 * std::max(1.0, std::abs(b));
}

// Why the failure detector fired on `measured`, in its own words, with the values.
std::string failure_reason(const Vector& measured, double failure_angle) {
  if (!measured.allFinite()) return "a measured signal is not finite";
  return "|theta_b| = " + format_number(std::abs(measured[blocks::kMeasuredThetaB])) +
         " rad exceeded trial.failure_angle = " + format_number(failure_angle) + " rad";
}

// The observation space's upper bound: the pitch up to the failure angle, the rest free.
Vector pitch_limited_bound(double failure_angle) {
  Vector high = Vector::Constant(blocks::kMeasuredSize, std::numeric_limits<double>::infinity());
  high[blocks::kMeasuredThetaB] = failure_angle;
  return high;
}

parameters::Parameters checked(const parameters::Parameters& parameters) {
  diagrams::validate_parameters(parameters);
  return parameters;
}

}  // namespace

BalanceEnvironment::BalanceEnvironment(const parameters::Parameters& parameters,
                                       EnvironmentOptions options)
    : parameters_(checked(parameters)) {
  auto controller = std::make_unique<AgentController>("controller", parameters_);
  controller_ = controller.get();
  loop_ =
      diagrams::build_closed_loop("environment", parameters_, std::move(controller),
                                  diagrams::ClosedLoopOptions{.plant = std::move(options.plant)});
  // The root seed a trial of this run would start from, until reset is given another.
  simulator_ = std::make_unique<Simulator>(
      *loop_.diagram, SimulatorOptions{.accuracy = loop_.accuracy, .schedule = loop_.schedule},
      static_cast<std::uint64_t>(parameters_.run.seed));
  // The task's blocks, by the names build_closed_loop gives them.
  measured_ = &loop_.diagram->block("sensors").output_port("measured");
  failed_ = &loop_.diagram->block("failure").output_port("failed");
  reward_ = &loop_.diagram->block("reward").output_port("reward");
  supervisor_action_ = &controller_->output_port("supervisor_action");
  signal_names_ = loop_.plant->signals();
  observation_high_ = pitch_limited_bound(parameters_.trial.failure_angle);
  observation_low_ = -observation_high_;
}

ResetResult BalanceEnvironment::reset(std::optional<std::uint64_t> seed,
                                      std::optional<double> initial_pitch) {
  const double pitch = initial_pitch.value_or(parameters_.trial.theta0);
  check_initial_pitch(pitch);
  Context& context = simulator_->context();
  if (seed) context.reseed(*seed);
  loop_.start_trial(context, pitch);
  // The initialisation updates draw the sensors' noise for t = 0, from the streams as they
  // now are: after the re-seeding, so that the seed decides the whole episode.
  simulator_->initialize();
  ticks_ = 0;
  episode_ = Episode::kRunning;
  evaluate();
  last_ = ResetResult{measured(), info()};
  return last_;
}

StepResult BalanceEnvironment::step(double action) {
  check_can_step(action);
  controller_->held_action().set(simulator_->context(), action);
  // t_{k+1} as the simulator computes its event times, so the step ends on the tick itself.
  const double next_tick = static_cast<double>(ticks_ + 1) * period();
  const bool last_step = next_tick > duration() || same_instant(next_tick, duration());
  // Ended until the step completes, so that a SimulationError leaves it ended.
  episode_ = Episode::kEnded;
  const SimulationStatus status =
      simulator_->advance_to(last_step ? std::min(next_tick, duration()) : next_tick);
  if (status.terminated) return stopped_early(status);
  ++ticks_;
  evaluate();

  StepResult result;
  result.observation = measured();
  result.reward = reward();
  result.terminated = failed();
  result.truncated = last_step && !result.terminated;
  result.info =
      info(result.terminated ? failure_reason(result.observation, parameters_.trial.failure_angle)
                             : std::string());
  if (!result.terminated && !result.truncated) episode_ = Episode::kRunning;
  last_ = ResetResult{result.observation, result.info};
  return result;
}

StepResult BalanceEnvironment::stopped_early(const SimulationStatus& status) {
  // The steps before have each checked the failure detector at their end, so an update
  // stops the simulation at this step's first instant only where the observation reset gave
  // is already beyond the angle (sensor noise or quantisation), or a user's plant ends it
  // with an update of its own. The agent's action has not acted: the observation is the
  // one returned last, unless the plant's update came later in the period.
  StepResult result;
  if (simulator_->context().time() > last_.info.time) {
    evaluate();
    last_ = ResetResult{measured(), info()};
  }
  result.observation = last_.observation;
  result.reward = -1.0;  // a failure's, as blocks/reward.h gives it
  result.terminated = true;
  result.info = last_.info;
  result.info.failure_reason = status.reason;
  return result;
}

void BalanceEnvironment::check_initial_pitch(double pitch) const {
  const double limit = parameters_.trial.failure_angle;
  if (std::isfinite(pitch) && std::abs(pitch) < limit) return;
  throw std::invalid_argument(
      "reset: the initial pitch must be finite and strictly inside "
      "+-trial.failure_angle (" +
      format_number(limit) + " rad); got " + format_number(pitch));
}

void BalanceEnvironment::check_can_step(double action) const {
  if (episode_ == Episode::kNotStarted) {
    throw std::logic_error("step: no episode has started; call reset() first");
  }
  if (episode_ == Episode::kEnded) {
    throw std::logic_error(
        "step: the episode has ended (terminated or truncated); call reset() to start another");
  }
  if (!std::isfinite(action)) {
    throw std::invalid_argument("step: the action must be a finite torque in N m; got " +
                                format_number(action));
  }
}

void BalanceEnvironment::evaluate() { loop_.diagram->evaluate_outputs(simulator_->context()); }

Vector BalanceEnvironment::measured() const { return simulator_->context().signal(*measured_); }

bool BalanceEnvironment::failed() const { return simulator_->context().signal(*failed_)[0] > 0.5; }

double BalanceEnvironment::reward() const { return simulator_->context().signal(*reward_)[0]; }

Info BalanceEnvironment::info(std::string failure_reason) const {
  const Context& context = simulator_->context();
  return Info{.time = context.time(),
              .supervisor_action = context.signal(*supervisor_action_)[0],
              .state = context.signal(loop_.plant->state_output()),
              .signal_names = signal_names_,
              .failure_reason = std::move(failure_reason)};
}

}  // namespace cbbg::environment
