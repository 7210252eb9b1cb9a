// The vectorised environment: its worker pool shares out the work and reports errors in
// order; each environment is a BalanceEnvironment seeded seed + i, reset at the step after its
// episode ends (its action ignored); the same bytes with any thread count; what it refuses.

#include "cbbg/environment/vec_balance_environment.h"

#include <atomic>
#include <stdexcept>
#include <string>
#include <vector>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "cbbg/blocks/measured_signals.h"
#include "cbbg/diagrams/validated_parameters.h"

namespace cbbg::environment {
namespace {

using ::testing::ThrowsMessage;

parameters::Parameters analytic(const std::vector<std::string>& settings = {}) {
  config::Config config;
  config.set("plant.kind=analytic");
  for (const std::string& setting : settings) config.set(setting);
  return diagrams::validated_parameters(config);
}

TEST(WorkerPool, EveryIndexRunsOnceInContiguousShares) {
  WorkerPool pool(3);
  std::vector<std::atomic<int>> runs(10);
  for (int round = 0; round < 50; ++round) {
    pool.run(10, [&](int begin, int end) {
      for (int i = begin; i < end; ++i) ++runs[static_cast<std::size_t>(i)];
    });
  }
  for (const auto& count : runs) EXPECT_EQ(count.load(), 50);
}

TEST(WorkerPool, TheLowestSharesErrorIsRethrownAfterAllFinish) {
  WorkerPool pool(2);
  std::atomic<int> finished = 0;
  EXPECT_THAT(
      [&] {
        pool.run(4, [&](int begin, int) {
          ++finished;
          throw std::runtime_error("share at " + std::to_string(begin));
        });
      },
      ThrowsMessage<std::runtime_error>("share at 0"));
  EXPECT_EQ(finished.load(), 2);
  pool.run(4, [](int, int) {});  // the errors were cleared
  EXPECT_THAT([] { WorkerPool(0); },
              ThrowsMessage<std::invalid_argument>("a worker pool needs at least 1 thread; got 0"));
}

std::vector<double> row(const VecBalanceEnvironment& envs, int i) {
  const auto begin = envs.observations().begin() + i * blocks::kMeasuredSize;
  return {begin, begin + blocks::kMeasuredSize};
}

TEST(VecBalanceEnvironment, EachEnvironmentIsASingleOneAndResetsAtTheStepAfterItsEnd) {
  const parameters::Parameters p =
      analytic({"trial.duration=0.1", "sensors.noise_std=[0.01,0.01,0.01,0.01,0.01,0.01]"});
  VecBalanceEnvironment envs(p, 3, {.threads = 2});
  std::vector<BalanceEnvironment> singles;
  for (int i = 0; i < 3; ++i) singles.emplace_back(p);
  envs.reset(20);
  for (int i = 0; i < 3; ++i) {
    const ResetResult start = singles[static_cast<std::size_t>(i)].reset(20 + i);
    EXPECT_EQ(row(envs, i),
              std::vector<double>(start.observation.begin(), start.observation.end()));
  }
  const double actions[3] = {0.5, -0.5, 1.0};
  for (int k = 0; k < 10; ++k) envs.step(actions);  // the 10th step truncates each
  for (int i = 0; i < 3; ++i) {
    BalanceEnvironment& single = singles[static_cast<std::size_t>(i)];
    StepResult step;
    for (int k = 0; k < 10; ++k) step = single.step(actions[i]);
    EXPECT_EQ(row(envs, i), std::vector<double>(step.observation.begin(), step.observation.end()));
    EXPECT_TRUE(envs.truncated()[static_cast<std::size_t>(i)]);
    EXPECT_EQ(envs.rewards()[static_cast<std::size_t>(i)], step.reward);
  }
  envs.step(actions);
  for (int i = 0; i < 3; ++i) {
    const ResetResult again = singles[static_cast<std::size_t>(i)].reset();
    EXPECT_TRUE(envs.autoreset()[static_cast<std::size_t>(i)]);
    EXPECT_EQ(row(envs, i),
              std::vector<double>(again.observation.begin(), again.observation.end()));
    EXPECT_EQ(envs.times()[static_cast<std::size_t>(i)], 0.0);
  }
}

TEST(VecBalanceEnvironment, TheSameBytesWithAnyThreadCount) {
  const parameters::Parameters p =
      analytic({"trial.duration=0.3", "sensors.noise_std=[0.02,0.02,0.02,0.02,0.02,0.02]"});
  const auto run = [&p](int threads) {
    VecBalanceEnvironment envs(
        p, 7, {.environment = {.initial_pitch = InitialPitch{-0.3, 0.3}}, .threads = threads});
    envs.reset(9);
    std::vector<double> trace = envs.observations();
    std::vector<double> actions(7);
    for (int k = 0; k < 80; ++k) {
      for (int i = 0; i < 7; ++i)
        actions[static_cast<std::size_t>(i)] = 4.0 * std::sin(i + k / 5.0);
      envs.step(actions.data());
      trace.insert(trace.end(), envs.observations().begin(), envs.observations().end());
    }
    return trace;
  };
  const std::vector<double> one = run(1);
  EXPECT_EQ(run(2), one);
  EXPECT_EQ(run(3), one);
}

TEST(VecBalanceEnvironment, RefusesBadCountsActionsAndCallsInOneLine) {
  EXPECT_THAT([] { VecBalanceEnvironment(analytic(), 0); },
              ThrowsMessage<std::invalid_argument>("num_envs must be at least 1; got 0"));
  EXPECT_THAT(
      [] { VecBalanceEnvironment(analytic(), 2, {.threads = -1}); },
      ThrowsMessage<std::invalid_argument>("threads must be 0 (the machine's) or more; got -1"));
  VecBalanceEnvironment envs(analytic(), 2);
  const double actions[2] = {0.0, std::nan("")};
  EXPECT_THAT([&] { envs.step(actions); },
              ThrowsMessage<std::logic_error>("step: no episode has started; call reset() first"));
  envs.reset(1);
  EXPECT_THAT([&] { envs.step(actions); },
              ThrowsMessage<std::invalid_argument>(
                  "step: action 1 must be a finite torque in N m; got nan"));
  const std::vector<double> one_pitch = {0.1};
  EXPECT_THAT([&] { envs.reset(1, &one_pitch); },
              ThrowsMessage<std::invalid_argument>(
                  "reset: 2 initial pitches expected, one per environment; got 1"));
}

}  // namespace
}  // namespace cbbg::environment
