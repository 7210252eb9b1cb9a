#include "cbbg/environment/vec_balance_environment.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <thread>

#include "cbbg/blocks/measured_signals.h"
#include "cbbg/framework/number_text.h"

namespace cbbg::environment {
namespace {

int thread_count(int requested, int num_envs) {
  if (requested < 0) {
    throw std::invalid_argument("threads must be 0 (the machine's) or more; got " +
                                std::to_string(requested));
  }
  const int machine = std::max(1, static_cast<int>(std::thread::hardware_concurrency()));
  return std::min(requested == 0 ? machine : requested, num_envs);
}

}  // namespace

VecBalanceEnvironment::VecBalanceEnvironment(const parameters::Parameters& parameters, int num_envs,
                                             VecOptions options) {
  if (num_envs < 1) {
    throw std::invalid_argument("num_envs must be at least 1; got " + std::to_string(num_envs));
  }
  pool_ = std::make_unique<WorkerPool>(thread_count(options.threads, num_envs));
  for (int i = 0; i < num_envs; ++i) {
    environments_.push_back(std::make_unique<BalanceEnvironment>(parameters, options.environment));
  }
  const auto n = static_cast<std::size_t>(num_envs);
  ended_.assign(n, 0);
  observations_.assign(n * blocks::kMeasuredSize, 0.0);
  rewards_.assign(n, 0.0);
  times_.assign(n, 0.0);
  supervisor_actions_.assign(n, 0.0);
  terminated_.assign(n, 0);
  truncated_.assign(n, 0);
  autoreset_.assign(n, 0);
}

void VecBalanceEnvironment::reset(std::optional<std::uint64_t> seed,
                                  const std::vector<double>* initial_pitches) {
  if (initial_pitches != nullptr && initial_pitches->size() != environments_.size()) {
    throw std::invalid_argument("reset: " + std::to_string(environments_.size()) +
                                " initial pitches expected, one per environment; got " +
                                std::to_string(initial_pitches->size()));
  }
  pool_->run(num_envs(), [&](int begin, int end) {
    for (int i = begin; i < end; ++i) {
      const auto at = static_cast<std::size_t>(i);
      reset_one(i, seed ? std::optional<std::uint64_t>(*seed + at) : std::nullopt,
                initial_pitches != nullptr ? std::optional<double>((*initial_pitches)[at])
                                           : std::nullopt);
      autoreset_[at] = 0;
    }
  });
  started_ = true;
}

void VecBalanceEnvironment::step(const double* actions) {
  if (!started_) throw std::logic_error("step: no episode has started; call reset() first");
  for (int i = 0; i < num_envs(); ++i) {
    if (!std::isfinite(actions[i])) {
      throw std::invalid_argument("step: action " + std::to_string(i) +
                                  " must be a finite torque in N m; got " +
                                  format_number(actions[i]));
    }
  }
  pool_->run(num_envs(), [&](int begin, int end) {
    for (int i = begin; i < end; ++i) step_one(i, actions[i]);
  });
}

void VecBalanceEnvironment::reset_one(int index, std::optional<std::uint64_t> seed,
                                      std::optional<double> pitch) {
  const auto at = static_cast<std::size_t>(index);
  BalanceEnvironment& env = *environments_[at];
  env.reset_into(seed, pitch, observations_.data() + at * blocks::kMeasuredSize);
  rewards_[at] = 0.0;
  terminated_[at] = truncated_[at] = 0;
  ended_[at] = 0;
  times_[at] = env.time();
  supervisor_actions_[at] = env.supervisor_action();
}

void VecBalanceEnvironment::step_one(int index, double action) {
  const auto at = static_cast<std::size_t>(index);
  if (ended_[at] != 0) {
    reset_one(index, std::nullopt, std::nullopt);
    autoreset_[at] = 1;
    return;
  }
  BalanceEnvironment& env = *environments_[at];
  ended_[at] = 1;  // until the step completes: an error ends the episode, the next step resets
  const StepFlags flags = env.step_into(action, observations_.data() + at * blocks::kMeasuredSize);
  rewards_[at] = flags.reward;
  terminated_[at] = flags.terminated ? 1 : 0;
  truncated_[at] = flags.truncated ? 1 : 0;
  autoreset_[at] = 0;
  ended_[at] = flags.terminated || flags.truncated ? 1 : 0;
  times_[at] = env.time();
  supervisor_actions_[at] = env.supervisor_action();
}

}  // namespace cbbg::environment
