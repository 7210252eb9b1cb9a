#pragma once
// N balancing environments (balance_environment.h) stepped together in C++ threads: what a
// learner that collects from many robots at once steps, with Gymnasium 1.x's vector-env
// semantics (gymnasium.vector, autoreset mode NEXT_STEP):
//
//   reset(seed)    every environment reset; environment i seeded with seed + i (Gymnasium's
//                  SyncVectorEnv does the same), or, without a seed, continuing its streams.
//   step(actions)  environment i steps with actions[i] unless its episode ended at the
//                  previous step: then it is reset instead (its action ignored) and returns
//                  the reset's observation, reward 0, terminated and truncated false, and
//                  autoreset[i] true. The final observation of an episode is the one returned
//                  with its terminated or truncated flag, as in Gymnasium 1.x; nothing is kept
//                  in an info.
//
// Outputs are arrays the class owns, rewritten by each call: observations (N x 6, row by
// row), rewards, terminated, truncated, autoreset, and the info's time and supervisor_action
// (saturated). Environment i's numbers depend only on its seed and actions, never on the
// thread count: the same bytes with 1 thread or many.

#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

#include "cbbg/environment/balance_environment.h"
#include "cbbg/environment/worker_pool.h"

namespace cbbg::environment {

struct VecOptions {
  EnvironmentOptions environment{};  // each environment's (plant, reset distribution)
  int threads = 0;                   // 0: as many as the machine has, at most N
};

class VecBalanceEnvironment {
 public:
  // Throws what BalanceEnvironment's constructor throws, and std::invalid_argument for
  // num_envs < 1 or threads < 0.
  VecBalanceEnvironment(const parameters::Parameters& parameters, int num_envs,
                        VecOptions options = {});

  int num_envs() const { return static_cast<int>(environments_.size()); }
  int threads() const { return pool_->threads(); }
  const BalanceEnvironment& environment(int index) const { return *environments_.at(index); }

  // Resets every environment (the header's reset); `initial_pitches`, when given, N pitches,
  // else each draws from its reset distribution.
  void reset(std::optional<std::uint64_t> seed = std::nullopt,
             const std::vector<double>* initial_pitches = nullptr);
  // Steps every environment with actions[0 .. N) (the header's step). Throws
  // std::invalid_argument naming the first non-finite action before any environment steps,
  // std::logic_error before reset, and the first (lowest index) environment's error.
  void step(const double* actions);

  const std::vector<double>& observations() const { return observations_; }  // N x 6
  const std::vector<double>& rewards() const { return rewards_; }
  const std::vector<std::uint8_t>& terminated() const { return terminated_; }
  const std::vector<std::uint8_t>& truncated() const { return truncated_; }
  const std::vector<std::uint8_t>& autoreset() const { return autoreset_; }
  const std::vector<double>& times() const { return times_; }
  const std::vector<double>& supervisor_actions() const { return supervisor_actions_; }

 private:
  void reset_one(int index, std::optional<std::uint64_t> seed, std::optional<double> pitch);
  void step_one(int index, double action);

  std::vector<std::unique_ptr<BalanceEnvironment>> environments_;
  std::unique_ptr<WorkerPool> pool_;
  bool started_ = false;
  std::vector<std::uint8_t> ended_;  // environment i's episode ended at the last step
  std::vector<double> observations_, rewards_, times_, supervisor_actions_;
  std::vector<std::uint8_t> terminated_, truncated_, autoreset_;
};

}  // namespace cbbg::environment
