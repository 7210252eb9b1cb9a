#pragma once
// The balancing task as a reinforcement-learning environment with the shape of Gymnasium's
// API, without depending on Gymnasium:
//
//   Gymnasium                                   here
//   env.reset(seed=, options=)                  reset(seed, initial_pitch) -> {observation, info}
//   env.step(action) -> (observation, reward,   step(action) -> {observation, reward,
//                        terminated, truncated,                  terminated, truncated, info}
//                        info)
//   observation_space = Box(low, high, (6,))    observation_low(), observation_high()
//   action_space = Box(low, high, (1,))         action_low(), action_high()
//
//   parameters::Parameters p = diagrams::validated_parameters(config);
//   environment::BalanceEnvironment env(p);      // plant.kind's plant, or options.plant
//   auto [observation, info] = env.reset(42);
//   for (;;) {
//     const auto step = env.step(my_policy(observation));  // N m on both wheels, one period
//     observation = step.observation;
//     if (step.terminated || step.truncated) break;
//   }
//
// Underneath is the library's closed loop (diagrams/closed_loop.h), the one every trial runs:
// plant, sensors, failure detector, sliding-surface reward, zero-order hold, push.* if set,
// with an AgentController (agent_controller.h) in the controller's place. The agent's action
// takes the place of the controller's; nothing else differs, so a rollout that plays the
// supervisor's action (info.supervisor_action) is the `pd_only` preset's trial, tick for tick.
//
// Timing. Ticks are t_k = k Ts, Ts = trial.period; the episode is the trial's ticks.
//  - reset: the robot at rest at the initial pitch, t_0 = 0; the observation is y_0, what the
//    sensors measure at t_0 (sensors.* noise and quantisation included).
//  - step k (the k-th call since reset, from 0) takes a_k: the loop's hold samples it at t_k
//    and the wheels get it over [t_k, t_{k+1}) (a controller's action at tick k is computed
//    from y_k and held the same way). It returns what the loop sees at t_{k+1}, before that
//    tick's updates run (they run at the start of the next step, as in a trial):
//    - observation: y_{k+1};
//    - reward: r_k, the transition's, which the Reward block outputs at t_{k+1} and a learner
//      receives there (as r_{t-1}, blocks/reward.h): -1 if the robot fell at t_{k+1}, else 0
//      if s(y_{k+1})^2 <= s(y_k)^2 and -1 if it grew, s = reward.a1 theta_b + reward.a2
//      theta_b' on the measured signals. reset has no reward (there is no transition yet);
//    - terminated: the failure detector's output at t_{k+1}: |measured theta_b| >
//      trial.failure_angle, or a measured signal not finite. A trial ends at that tick too,
//      after its updates (a learner learns from the failing transition); the environment
//      stops before them, and the failing observation is the one returned;
//    - truncated: t_{k+1} reached trial.duration without a fall: the N-th step, N =
//      trial.duration / Ts (when trial.duration is not a multiple of Ts, the last step is
//      shorter and ends at trial.duration). A trial runs the same ticks t_0 .. t_{N-1} and
//      has none at trial.duration, so it never looks at the state there: the last step's
//      reward is one no learner receives, and a fall within the last period is terminated
//      here where the trial would count a success.
//  - after terminated or truncated, step throws std::logic_error until reset.
//
// Randomness and determinism: every block draws from its own stream, derived from a root
// seed and its path (framework/context.h); the same parameters, seed, initial pitch and
// actions give the same bytes. reset(seed) re-seeds the streams: the episode is then a trial
// run with root seed `seed` (experiments::TrialRunner(loop, seed, ...)). reset() without a
// seed continues the streams where the last episode left them (Gymnasium's convention); the
// first episode's streams are then those of the run's root seed (the key `seed`).
//
// One environment is one simulation: not for two threads at once; environments in several
// threads are independent.

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "cbbg/diagrams/closed_loop.h"
#include "cbbg/diagrams/plant_kinds.h"
#include "cbbg/environment/agent_controller.h"
#include "cbbg/framework/simulator.h"
#include "cbbg/framework/types.h"
#include "cbbg/parameters/parameters.h"

namespace cbbg::environment {

// The reset distribution of the initial pitch: uniform on [low, high], rad (low == high: that
// pitch; the default, trial.theta0's, is the paper's fixed angle).
struct InitialPitch {
  double low = 0.0;
  double high = 0.0;
};

struct EnvironmentOptions {
  // The robot: empty, plant.kind's (diagrams/plant_kinds.h: simbody, analytic, a registered
  // kind); set, a plant::RobotPlant of the user's own, with its own signals.
  diagrams::PlantFactory plant{};
  // Empty: trial.theta0. Both bounds strictly inside +-trial.failure_angle.
  std::optional<InitialPitch> initial_pitch{};
};

// What a step returns besides the observation and the info (BalanceEnvironment::step_into).
struct StepFlags {
  double reward = 0.0;
  bool terminated = false;
  bool truncated = false;
};

// Gymnasium's info: what the agent may read besides the observation.
struct Info {
  double time = 0.0;  // the instant of the observation, s
  // supervisor.kind's action on the observation, N m, saturated at the action space's bounds
  // (+-plant.torque_limit), where the plant saturates it too.
  double supervisor_action = 0.0;
  // The same before saturation: the torque the pd_only controller hands a plant.
  double unsaturated_supervisor_action = 0.0;
  Vector state;                           // the plant's state output at `time`: true, without noise
  std::vector<std::string> signal_names;  // the name of each entry of `state`
  std::string failure_reason;             // why the episode terminated; empty otherwise
};

struct ResetResult {
  Vector observation;  // 6 measured signals (blocks/measured_signals.h)
  Info info;
};

struct StepResult {
  Vector observation;  // 6 measured signals (blocks/measured_signals.h)
  double reward = 0.0;
  bool terminated = false;
  bool truncated = false;
  Info info;
};

class BalanceEnvironment {
 public:
  // Builds the closed loop of `parameters` (checked as a run's are: throws
  // config::ConfigError) around the agent. Throws std::invalid_argument when the plant does
  // not fit the loop, or supervisor.kind is lqr and plant.kind's kind has no linearisation
  // (the LQR supervisor is designed on plant.kind's, even with options.plant).
  explicit BalanceEnvironment(const parameters::Parameters& parameters,
                              EnvironmentOptions options = {});

  // A new episode: the streams re-seeded when `seed` is given, every block's per-trial state
  // reset, the robot at rest at `initial_pitch` (default: a draw of the reset distribution,
  // EnvironmentOptions::initial_pitch, from the environment's own stream, which `seed`
  // re-seeds too), time 0. Throws std::invalid_argument for an initial pitch that is not
  // finite or not strictly inside +-trial.failure_angle.
  ResetResult reset(std::optional<std::uint64_t> seed = std::nullopt,
                    std::optional<double> initial_pitch = std::nullopt);
  // The same, writing only the observation (kMeasuredSize values): no allocation.
  void reset_into(std::optional<std::uint64_t> seed, std::optional<double> initial_pitch,
                  double* observation);

  // Holds `action` (N m, on each wheel, push.*'s pulse added when set; the plant saturates
  // the sum at +-plant.torque_limit) for one period and returns the new state's observation
  // (the header's Timing). Throws
  // std::invalid_argument for a non-finite action, std::logic_error before reset or after the
  // episode ended, and cbbg::SimulationError where the simulation cannot go on (a non-finite
  // state, an integrator that cannot meet plant.accuracy), which also ends the episode.
  StepResult step(double action);
  // The same, writing only the observation (kMeasuredSize values) and returning the flags:
  // no allocation unless the episode terminates (the vectorised environment's step).
  StepFlags step_into(double action, double* observation);
  // The info's scalars at the last observation.
  double time() const;
  double supervisor_action() const;
  // The observation space: every signal unbounded (+-inf), so that every observation lies in
  // it, a terminated episode's last one too (beyond +-trial.failure_angle: that is why it
  // terminated). A running episode's pitch stays within +-failure_angle().
  const Vector& observation_low() const { return observation_low_; }
  const Vector& observation_high() const { return observation_high_; }
  // The action space: +-the torque limit of plant.kind's kind (diagrams::kind_torque_limit:
  // plant.torque_limit, where the library's plants saturate each wheel's torque, or what a
  // registered kind declares).
  double action_low() const { return -torque_limit_; }
  double action_high() const { return torque_limit_; }
  // trial.failure_angle: the pitch beyond which an episode terminates, rad.
  double failure_angle() const { return parameters_.trial.failure_angle; }
  // The reset distribution of the initial pitch.
  const InitialPitch& initial_pitch() const { return initial_pitch_; }
  // trial.period: how long step holds the action, s.
  double period() const { return parameters_.trial.period; }
  // trial.duration: an episode that lasts this long is truncated, s.
  double duration() const { return parameters_.trial.duration; }
  // The names of Info::state's entries (plant::RobotPlant::signals()).
  const std::vector<std::string>& signal_names() const { return signal_names_; }
  const parameters::Parameters& parameters() const { return parameters_; }
  // The closed loop stepped (to draw it: framework/graphviz.h).
  const diagrams::ClosedLoop& closed_loop() const { return loop_; }

 private:
  enum class Episode { kNotStarted, kRunning, kEnded };

  void check_initial_pitch(double pitch) const;
  double draw_initial_pitch();
  void check_can_step(double action) const;
  // Computes every output of the loop at the context's instant, for the reads below.
  void evaluate();
  bool failed() const;
  double reward() const;
  Info info(std::string failure_reason = {}) const;
  // The step an update ended before its end (status.terminated).
  StepFlags stopped_early(const SimulationStatus& status, double* observation);
  // Keeps the observation just computed as the last one, and writes it to `observation`.
  void keep_observation(double* observation);

  parameters::Parameters parameters_;
  const AgentController* controller_ = nullptr;
  diagrams::ClosedLoop loop_;
  std::unique_ptr<Simulator> simulator_;
  // The loop's outputs the environment reads.
  const OutputPort* measured_ = nullptr;
  const OutputPort* failed_ = nullptr;
  const OutputPort* reward_ = nullptr;
  const OutputPort* supervisor_action_ = nullptr;
  std::vector<std::string> signal_names_;
  Vector observation_low_;
  Vector observation_high_;
  InitialPitch initial_pitch_;
  double torque_limit_ = 0.0;
  RandomGenerator pitch_generator_;  // the reset distribution's draws
  Episode episode_ = Episode::kNotStarted;
  long long ticks_ = 0;         // steps taken in this episode: the context is at t_{ticks_}
  Vector last_observation_;     // the observation returned last
  double last_time_ = 0.0;      // and its instant
  std::string failure_reason_;  // why the last step terminated
};

}  // namespace cbbg::environment
