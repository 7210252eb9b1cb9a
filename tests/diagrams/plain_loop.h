#pragma once
// The learning controller of docs/model.md §2 written as one plain C++ loop, without the
// framework: no Block, Diagram, Context or Simulator. It drives the analytic plant
// (plant/robot_dynamics.h) through the same Boost.Odeint stepper the Simulator uses and
// repeats each block's floating-point operations in the blocks' order (dot products through
// Eigen, as the blocks do), so for the same root seed it must give bit-identical numbers to
// the closed loop of every preset (diagrams::build_preset). It is the reference of the
// diagram-wiring test and the baseline of the diagram overhead benchmark.
//
// One tick at t, as the Simulator's step semantics order it: every signal is computed from
// the state at t (sensors, failure, reward, supervisor, normaliser, features, critic, actor,
// tropism, sampler, entropy, omega, mixer); then every update runs on those values and the
// pre-update memories (omega counter, next sampler draw, reward surface, critic trace and
// weights, actor weights, the held torque); a failure ends the trial after them. Between
// ticks the plant integrates with the held torque.

#include <cstdint>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include <Eigen/Core>

#include "cbbg/config/config.h"

namespace cbbg::tests {

// The signals of one tick, in the order of diagrams::TelemetryIndex.
struct PlainLoopTick {
  double theta_b = 0.0;
  double theta_b_dot = 0.0;
  double phi_left = 0.0;
  double phi_right = 0.0;
  double phi_left_dot = 0.0;
  double phi_right_dot = 0.0;
  double supervisor_action = 0.0;   // a_S
  double actor_action = 0.0;        // a_A
  double exploration_action = 0.0;  // a_E
  double action = 0.0;              // a, before the plant's saturation
  double omega = 0.0;
  double value = 0.0;        // V(s_t)
  double td_error = 0.0;     // delta_{t-1}
  double temperature = 0.0;  // T
  double reward = 0.0;       // r_{t-1}
  double entropy = 0.0;      // E, bits
  double x = 0.0;            // the pose: m, m, rad
  double y = 0.0;
  double yaw = 0.0;
};

enum class PlainLoopStatus { kSuccess, kFailed, kDiverged };

struct PlainLoopOutcome {
  PlainLoopStatus status = PlainLoopStatus::kSuccess;
  long long steps = 0;       // ticks the trial ran
  double final_theta = 0.0;  // theta_b at the end, rad
};

class PlainLoop {
 public:
  // The closed loop of preset `arm` (cbbg, cbbg_weighted, bg_only, cb_only, pd_only or
  // learnt_actor) with the parameters of `config` and the sampler's generator seeded as the
  // preset's block "controller/basal_ganglia/sampler" is under `root_seed`. Throws
  // std::invalid_argument for another arm or for a config this loop does not write out (sensor
  // noise or quantisation, a supervisor other than pd); config::ConfigError for a value a block
  // would reject.
  PlainLoop(const config::Config& config, std::uint64_t root_seed, std::string_view arm = "cbbg");
  ~PlainLoop();
  PlainLoop(const PlainLoop&) = delete;
  PlainLoop& operator=(const PlainLoop&) = delete;

  // Runs one trial from `theta0` until failure or `duration`; learnt weights, the omega
  // counter and the sampler's generator carry into the next.
  PlainLoopOutcome run_trial(double theta0, double duration);

  // Every tick of the last trial.
  const std::vector<PlainLoopTick>& ticks() const;
  // The learnt weights: the critic's w and the actor's theta.
  const Eigen::VectorXd& critic_weights() const;
  const Eigen::VectorXd& actor_weights() const;
  // Where learning starts (the weights a learnt actor is evaluated with).
  void set_weights(const Eigen::VectorXd& critic, const Eigen::VectorXd& actor);

 private:
  struct State;
  std::unique_ptr<State> state_;
};

}  // namespace cbbg::tests
