#include "tests/diagrams/plain_loop.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <string>
#include <vector>

#include <Eigen/Core>
#include <boost/numeric/odeint.hpp>

#include "cbbg/diagrams/validated_parameters.h"
#include "cbbg/framework/random.h"
#include "cbbg/plant/robot_dynamics.h"
#include "cbbg/plant/robot_params.h"

namespace cbbg::tests {
namespace {

namespace odeint = boost::numeric::odeint;

// The plant's continuous state, as the analytic plant orders it:
// theta_b, phi_l, phi_r, their three rates, then x, y, yaw.
using OdeState = std::vector<double>;
using Stepper = odeint::controlled_runge_kutta<odeint::runge_kutta_dopri5<OdeState>>;
constexpr int kOdeSize = 9;

// The Simulator's rule for two event times being one instant, its first trial step (again
// at each initialize(), so at each trial) and its smallest step.
constexpr double kSimultaneous = 1e-9;
constexpr double kFirstStep = 1e-3;
constexpr double kMinStep = 1e-12;

bool same_instant(double a, double b) {
  return std::abs(a - b) <= kSimultaneous * std::max(1.0, std::abs(b));
}

enum class OmegaMode { kSchedule, kZero, kOne };

struct ArmShape {
  bool has_supervisor;
  OmegaMode omega;
  bool weighted_rule_forced;
  bool basal_ganglia = true;
  bool learning = true;
  bool exploration = true;
};

ArmShape parse_arm(std::string_view arm) {
  if (arm == "cbbg") return {true, OmegaMode::kSchedule, false};
  if (arm == "cbbg_weighted") return {true, OmegaMode::kSchedule, true};
  if (arm == "bg_only") return {false, OmegaMode::kOne, false};
  if (arm == "cb_only") return {true, OmegaMode::kZero, false};
  if (arm == "pd_only") return {true, OmegaMode::kZero, false, false};
  if (arm == "learnt_actor") return {false, OmegaMode::kOne, false, true, false, false};
  throw std::invalid_argument(
      "PlainLoop: the arm must be cbbg, cbbg_weighted, bg_only, cb_only, pd_only or "
      "learnt_actor; got '" +
      std::string(arm) + "'");
}

void require_all_zero(const config::Config& config, const char* key) {
  for (const double value : config.numbers(key)) {
    if (value != 0.0) {
      throw std::invalid_argument(std::string("PlainLoop writes the sensors out without noise: ") +
                                  key + " must be all 0");
    }
  }
}

}  // namespace

struct PlainLoop::State {
  // Parameters.
  plant::RobotParams robot;
  double period;
  double failure_angle;
  double reward_a1, reward_a2;
  double k_theta, k_dtheta, k_phi, k_dphi;
  bool has_supervisor;
  bool basal_ganglia;
  bool learning;
  bool exploration;
  double scale_theta, scale_dtheta, saturation;
  std::vector<double> centres;
  double inverse_two_width_squared;
  double beta, gamma, lambda;
  double alpha;
  bool weighted_rule;
  double k1, k2;
  double k_b;
  OmegaMode omega_mode;
  double n2, n3;

  // Memory that lasts across trials: the learnt weights, the omega counter and the
  // sampler's generator.
  Eigen::VectorXd critic_weights;
  Eigen::VectorXd actor_weights;
  double omega_ticks = 0.0;
  RandomGenerator generator;
  Stepper stepper;
  double held_torque = 0.0;

  // Memory of one trial.
  double integrator_step = kFirstStep;  // the step the stepper proposed last
  OdeState x = OdeState(kOdeSize, 0.0);
  Eigen::VectorXd trace;              // z
  Eigen::VectorXd previous_features;  // phi(s_{t-1})
  bool has_previous = false;          // a tick of this trial has run
  double previous_surface = 0.0;      // s(t-1)
  double previous_supervisor_action = 0.0;
  double previous_exploration_action = 0.0;
  double previous_actor_action = 0.0;
  double previous_omega = 0.0;
  double noise = 0.0;  // the standard normal the sampler uses at the next tick

  Eigen::VectorXd features;  // phi(s_t), working memory
  std::vector<PlainLoopTick> ticks;

  State(const config::Config& config, std::uint64_t root_seed)
      : generator(derive_seed(root_seed, "controller/basal_ganglia/sampler")),
        stepper(Stepper::error_checker_type(config.number("plant.accuracy"),
                                            config.number("plant.accuracy"))) {}

  bool tick();
  bool supervisor_alone(bool failed, double reward, double surface, double supervisor_action);
  void derivatives(const OdeState& state, OdeState& rate) const;
  bool integrate(double start_time, double end_time);
};

PlainLoop::PlainLoop(const config::Config& config, std::uint64_t root_seed, std::string_view arm) {
  const ArmShape shape = parse_arm(arm);
  if (config.text("supervisor.kind") != "pd") {
    throw std::invalid_argument(
        "PlainLoop writes out the pd supervisor only: supervisor.kind must be pd; got '" +
        config.text("supervisor.kind") + "'");
  }
  require_all_zero(config, "sensors.noise_std");
  require_all_zero(config, "sensors.quantisation");
  for (const char* push : {"push.torque", "push.force", "push.pitch_torque"}) {
    if (config.number(push) != 0.0) {
      throw std::invalid_argument(std::string("PlainLoop has no push: ") + push + " must be 0");
    }
  }
  diagrams::validated_parameters(config);

  state_ = std::make_unique<State>(config, root_seed);
  State& s = *state_;
  s.robot = parameters::read_parameters(config).plant.robot;
  s.period = config.number("trial.period");
  s.failure_angle = config.number("trial.failure_angle");
  s.reward_a1 = config.number("reward.a1");
  s.reward_a2 = config.number("reward.a2");
  s.k_theta = config.number("supervisor.k_theta");
  s.k_dtheta = config.number("supervisor.k_dtheta");
  s.k_phi = config.number("supervisor.k_phi");
  s.k_dphi = config.number("supervisor.k_dphi");
  s.has_supervisor = shape.has_supervisor;
  s.basal_ganglia = shape.basal_ganglia;
  s.learning = shape.learning;
  s.exploration = shape.exploration;
  s.scale_theta = config.number("normaliser.scale_theta");
  s.scale_dtheta = config.number("normaliser.scale_dtheta");
  s.saturation = config.number("normaliser.saturation");
  s.centres = config.numbers("rbf.centres");
  const double width = config.number("rbf.width");
  s.inverse_two_width_squared = 1.0 / (2.0 * width * width);
  s.beta = config.number("critic.beta");
  s.gamma = config.number("critic.gamma");
  s.lambda = config.number("critic.lambda");
  s.alpha = config.number("actor.alpha");
  s.weighted_rule = shape.weighted_rule_forced || config.text("actor.rule") == "weighted";
  s.k1 = config.number("tropism.k1");
  s.k2 = config.number("tropism.k2");
  s.k_b = config.number("sampler.k_b");
  s.omega_mode = shape.omega;
  s.n2 = config.number("omega.n2");
  s.n3 = config.number("omega.n3");

  const auto m = static_cast<Eigen::Index>(s.centres.size());
  const Eigen::Index n = m * m;
  s.critic_weights = Eigen::VectorXd::Zero(n);
  s.actor_weights = Eigen::VectorXd::Zero(n);
  s.trace = Eigen::VectorXd::Zero(n);
  s.previous_features = Eigen::VectorXd::Zero(n);
  s.features = Eigen::VectorXd::Zero(n);
}

PlainLoop::~PlainLoop() = default;

const std::vector<PlainLoopTick>& PlainLoop::ticks() const { return state_->ticks; }
const Eigen::VectorXd& PlainLoop::critic_weights() const { return state_->critic_weights; }
const Eigen::VectorXd& PlainLoop::actor_weights() const { return state_->actor_weights; }

void PlainLoop::set_weights(const Eigen::VectorXd& critic, const Eigen::VectorXd& actor) {
  state_->critic_weights = critic;
  state_->actor_weights = actor;
}

PlainLoopOutcome PlainLoop::run_trial(double theta0, double duration) {
  State& s = *state_;
  // A new trial: the robot at theta0, at rest; the trace, the previous tick and the
  // integrator's step size forgotten.
  s.integrator_step = kFirstStep;
  std::fill(s.x.begin(), s.x.end(), 0.0);
  s.x[0] = theta0;
  s.trace.setZero();
  s.previous_features.setZero();
  s.has_previous = false;
  s.previous_surface = 0.0;
  s.previous_supervisor_action = 0.0;
  s.previous_exploration_action = 0.0;
  s.previous_actor_action = 0.0;
  s.previous_omega = 0.0;
  if (s.basal_ganglia && s.exploration) {
    s.noise = draw_standard_normal(s.generator);  // the sampler's draw for the first tick
  }
  s.ticks.clear();
  s.ticks.reserve(static_cast<size_t>(std::ceil(duration / s.period)) + 1);

  PlainLoopOutcome outcome;
  double time = 0.0;
  long long next_tick = 0;
  while (time < duration) {
    const double tick_time = static_cast<double>(next_tick) * s.period;
    if (same_instant(tick_time, time)) {
      time = tick_time;
      ++next_tick;
      if (s.tick()) {
        outcome.status = PlainLoopStatus::kFailed;
        break;
      }
      continue;
    }
    if (!s.integrate(time, std::min(tick_time, duration))) {
      outcome.status = PlainLoopStatus::kDiverged;
      outcome.steps = static_cast<long long>(s.ticks.size());
      outcome.final_theta = std::numeric_limits<double>::quiet_NaN();
      return outcome;
    }
    time = std::min(tick_time, duration);
  }
  outcome.steps = static_cast<long long>(s.ticks.size());
  outcome.final_theta = s.x[0];
  return outcome;
}

// One tick: every signal from the state at t, then every update from those values and the
// memories from before the tick. Returns true when the trial fails at this tick.
bool PlainLoop::State::tick() {
  // Sensors (no noise, no quantisation): the plant state in the measured order.
  const double theta = x[0];
  const double theta_dot = x[3];
  const double phi_left = x[1];
  const double phi_right = x[2];
  const double phi_left_dot = x[4];
  const double phi_right_dot = x[5];
  const bool finite = std::isfinite(theta) && std::isfinite(theta_dot) && std::isfinite(phi_left) &&
                      std::isfinite(phi_right) && std::isfinite(phi_left_dot) &&
                      std::isfinite(phi_right_dot);

  const bool failed = std::abs(theta) > failure_angle || !finite;

  // Reward r_{t-1} from the sliding surface.
  const double surface = reward_a1 * theta + reward_a2 * theta_dot;
  double reward = 0.0;
  if (failed) {
    reward = -1.0;
  } else if (has_previous) {
    reward = surface * surface <= previous_surface * previous_surface ? 0.0 : -1.0;
  }

  const double supervisor_action = has_supervisor
                                       ? k_theta * theta + k_dtheta * theta_dot +
                                             k_phi * (phi_left + phi_right) / 2.0 +
                                             k_dphi * (phi_left_dot + phi_right_dot) / 2.0
                                       : 0.0;
  if (!basal_ganglia) return supervisor_alone(failed, reward, surface, supervisor_action);

  // Normalised, saturated state and its Gaussian features on the grid.
  const double x0 = std::clamp(theta / scale_theta, -saturation, saturation);
  const double x1 = std::clamp(theta_dot / scale_dtheta, -saturation, saturation);
  const int m = static_cast<int>(centres.size());
  for (int i = 0; i < m; ++i) {
    const double d0 = x0 - centres[static_cast<size_t>(i)];
    for (int j = 0; j < m; ++j) {
      const double d1 = x1 - centres[static_cast<size_t>(j)];
      features[i * m + j] = std::exp(-(d0 * d0 + d1 * d1) * inverse_two_width_squared);
    }
  }

  // Critic: V(s_t) and delta_{t-1}, with the weights before this tick's update. Dot
  // products go through Eigen, as in the blocks: its vectorised sum has its own order.
  const double value = critic_weights.dot(features);
  const double td_error =
      has_previous ? reward + gamma * (failed ? 0.0 : value) - critic_weights.dot(previous_features)
                   : 0.0;

  const double actor_action = actor_weights.dot(features);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double temperature = exploration ? k1 / (1.0 + std::exp(k2 * value)) : nan;
  const double exploration_action =
      exploration ? actor_action + std::sqrt(k_b * temperature / 2.0) * noise : actor_action;
  const double entropy =
      exploration ? 0.5 * std::log2(std::numbers::pi * std::numbers::e * k_b * temperature) : nan;
  double omega = 0.0;
  switch (omega_mode) {
    case OmegaMode::kZero:
      omega = 0.0;
      break;
    case OmegaMode::kOne:
      omega = 1.0;
      break;
    case OmegaMode::kSchedule:
      omega = std::max(0.0, 1.0 - std::exp(-(omega_ticks - n2) / n3));
      break;
  }
  const double action = omega * exploration_action + (1.0 - omega) * supervisor_action;

  ticks.push_back({theta, theta_dot, phi_left, phi_right, phi_left_dot, phi_right_dot,
                   supervisor_action, actor_action, exploration_action, action, omega, value,
                   td_error, temperature, reward, entropy, x[6], x[7], x[8]});

  // Updates, all from the values above and the memories before this tick.
  omega_ticks += 1.0;
  if (exploration) noise = draw_standard_normal(generator);
  previous_surface = surface;
  if (has_previous && learning) {
    trace = gamma * lambda * trace + previous_features;
    critic_weights = critic_weights + beta * td_error * trace;
    const double a_s = previous_supervisor_action;
    const double a_e = previous_exploration_action;
    const double a_a = previous_actor_action;
    const double w = previous_omega;
    const double step = weighted_rule
                            ? w * alpha * td_error * (a_e - a_a) + (1.0 - w) * alpha * (a_s - a_a)
                            : alpha * td_error * (w * (a_e - a_s) + (a_s - a_a));
    actor_weights = actor_weights + step * previous_features;
  }
  previous_features = features;
  previous_supervisor_action = supervisor_action;
  previous_exploration_action = exploration_action;
  previous_actor_action = actor_action;
  previous_omega = omega;
  has_previous = true;
  held_torque = action;  // the zero-order hold samples a at t
  return failed;
}

// A tick of the supervisor alone: a = a_S, and the signals of the learning blocks NaN.
bool PlainLoop::State::supervisor_alone(bool failed, double reward, double surface,
                                        double supervisor_action) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  ticks.push_back({x[0], x[3], x[1], x[2], x[4], x[5], supervisor_action, nan, nan,
                   supervisor_action, 0.0, nan, nan, nan, reward, nan, x[6], x[7], x[8]});
  previous_surface = surface;
  has_previous = true;
  held_torque = supervisor_action;
  return failed;
}

// The analytic plant's right-hand side with both wheels driven by the held torque.
void PlainLoop::State::derivatives(const OdeState& state, OdeState& rate) const {
  const plant::Coordinates q(state[0], state[1], state[2]);
  const plant::Coordinates q_dot(state[3], state[4], state[5]);
  const plant::Torques applied =
      plant::saturate_torque(plant::Torques(held_torque, held_torque), robot.torque_limit);
  const double v = plant::forward_speed(robot, q_dot[1], q_dot[2]);
  const double yaw = state[8];
  const plant::Coordinates q_ddot = plant::accelerations(robot, q, q_dot, applied);
  for (int i = 0; i < 3; ++i) {
    rate[static_cast<size_t>(i)] = q_dot[i];
    rate[static_cast<size_t>(3 + i)] = q_ddot[i];
  }
  rate[6] = v * std::cos(yaw);
  rate[7] = v * std::sin(yaw);
  rate[8] = plant::yaw_rate(robot, q_dot[1], q_dot[2]);
}

// Integrates the plant from start_time to end_time with the held torque, as the Simulator
// does: the stepper's first-same-as-last derivative is dropped (the torque may have just
// changed), the first step is the last proposal capped by the interval, and a step cut short
// to land on the interval's end does not shrink the next proposal. Returns false when the
// step falls below the smallest allowed or the state stops being finite.
bool PlainLoop::State::integrate(double start_time, double end_time) {
  stepper.reset();
  auto rhs = [this](const OdeState& state, OdeState& rate, double) { derivatives(state, rate); };
  double t = start_time;
  double step = std::min(integrator_step, end_time - start_time);
  while (t < end_time) {
    const bool last = t + step >= end_time;
    if (last) step = end_time - t;
    const double proposed_before = integrator_step;
    const auto result = stepper.try_step(rhs, x, t, step);
    if (result == odeint::success) {
      if (last) {
        t = end_time;
        integrator_step = std::max(step, proposed_before);
      } else {
        integrator_step = step;
      }
    } else if (step < kMinStep) {
      return false;
    }
  }
  return std::all_of(x.begin(), x.end(), [](double value) { return std::isfinite(value); });
}

}  // namespace cbbg::tests
