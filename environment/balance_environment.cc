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

// The stream the reset distribution draws from, beside the blocks' (framework/random.h).
constexpr const char* kPitchStream = "environment/initial_pitch";

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
  observation_high_ =
      Vector::Constant(blocks::kMeasuredSize, std::numeric_limits<double>::infinity());
  observation_low_ = -observation_high_;
  last_observation_ = Vector::Zero(blocks::kMeasuredSize);
  torque_limit_ = diagrams::kind_torque_limit(parameters_);
  const double theta0 = parameters_.trial.theta0;
  initial_pitch_ = options.initial_pitch.value_or(InitialPitch{theta0, theta0});
  check_initial_pitch(initial_pitch_.low);
  check_initial_pitch(initial_pitch_.high);
  if (!(initial_pitch_.low <= initial_pitch_.high)) {
    throw std::invalid_argument("the initial pitch range must have low <= high; got [" +
                                format_number(initial_pitch_.low) + ", " +
                                format_number(initial_pitch_.high) + "]");
  }
  pitch_generator_.seed(
      derive_seed(static_cast<std::uint64_t>(parameters_.run.seed), kPitchStream));
}

ResetResult BalanceEnvironment::reset(std::optional<std::uint64_t> seed,
                                      std::optional<double> initial_pitch) {
  ResetResult result;
  result.observation.resize(blocks::kMeasuredSize);
  reset_into(seed, initial_pitch, result.observation.data());
  result.info = info();
  return result;
}

void BalanceEnvironment::reset_into(std::optional<std::uint64_t> seed,
                                    std::optional<double> initial_pitch, double* observation) {
  if (initial_pitch) check_initial_pitch(*initial_pitch);
  Context& context = simulator_->context();
  if (seed) {
    context.reseed(*seed);
    pitch_generator_.seed(derive_seed(*seed, kPitchStream));
  }
  loop_.start_trial(context, initial_pitch ? *initial_pitch : draw_initial_pitch());
  // The initialisation updates draw the sensors' noise for t = 0, from the streams as they
  // now are: after the re-seeding, so that the seed decides the whole episode.
  simulator_->initialize();
  ticks_ = 0;
  episode_ = Episode::kRunning;
  evaluate();
  keep_observation(observation);
}

StepResult BalanceEnvironment::step(double action) {
  StepResult result;
  result.observation.resize(blocks::kMeasuredSize);
  const StepFlags flags = step_into(action, result.observation.data());
  result.reward = flags.reward;
  result.terminated = flags.terminated;
  result.truncated = flags.truncated;
  result.info = info(flags.terminated ? failure_reason_ : std::string());
  return result;
}

StepFlags BalanceEnvironment::step_into(double action, double* observation) {
  check_can_step(action);
  controller_->held_action().set(simulator_->context(), action);
  // t_{k+1} as the simulator computes its event times, so the step ends on the tick itself.
  const double next_tick = static_cast<double>(ticks_ + 1) * period();
  const bool last_step = next_tick > duration() || same_instant(next_tick, duration());
  // Ended until the step completes, so that a SimulationError leaves it ended.
  episode_ = Episode::kEnded;
  const SimulationStatus status =
      simulator_->advance_to(last_step ? std::min(next_tick, duration()) : next_tick);
  if (status.terminated) return stopped_early(status, observation);
  ++ticks_;
  evaluate();
  keep_observation(observation);
  StepFlags flags;
  flags.reward = reward();
  flags.terminated = failed();
  flags.truncated = last_step && !flags.terminated;
  if (flags.terminated) {
    failure_reason_ = failure_reason(last_observation_, parameters_.trial.failure_angle);
  } else if (!flags.truncated) {
    episode_ = Episode::kRunning;
  }
  return flags;
}

void BalanceEnvironment::keep_observation(double* observation) {
  last_observation_ = simulator_->context().signal(*measured_);
  last_time_ = simulator_->context().time();
  std::copy(last_observation_.begin(), last_observation_.end(), observation);
}

StepFlags BalanceEnvironment::stopped_early(const SimulationStatus& status, double* observation) {
  // The steps before have each checked the failure detector at their end, so an update
  // stops the simulation at this step's first instant only where the observation reset gave
  // is already beyond the angle (sensor noise or quantisation), or a user's plant ends it
  // with an update of its own. The agent's action has not acted: the observation is the
  // one returned last, unless the plant's update came later in the period.
  if (simulator_->context().time() > last_time_) {
    evaluate();
    keep_observation(observation);
  } else {
    std::copy(last_observation_.begin(), last_observation_.end(), observation);
  }
  failure_reason_ = status.reason;
  return {-1.0, true, false};  // a failure's reward, as blocks/reward.h gives it
}

double BalanceEnvironment::draw_initial_pitch() {
  if (initial_pitch_.low == initial_pitch_.high) return initial_pitch_.low;  // draws nothing
  return initial_pitch_.low +
         (initial_pitch_.high - initial_pitch_.low) * draw_uniform(pitch_generator_);
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

bool BalanceEnvironment::failed() const { return simulator_->context().signal(*failed_)[0] > 0.5; }

double BalanceEnvironment::reward() const { return simulator_->context().signal(*reward_)[0]; }

double BalanceEnvironment::time() const { return simulator_->context().time(); }

double BalanceEnvironment::supervisor_action() const {
  return std::clamp(simulator_->context().signal(*supervisor_action_)[0], action_low(),
                    action_high());
}

Info BalanceEnvironment::info(std::string failure_reason) const {
  const Context& context = simulator_->context();
  return Info{.time = context.time(),
              .supervisor_action = supervisor_action(),
              .unsaturated_supervisor_action = context.signal(*supervisor_action_)[0],
              .state = context.signal(loop_.plant->state_output()),
              .signal_names = signal_names_,
              .failure_reason = std::move(failure_reason)};
}

}  // namespace cbbg::environment
