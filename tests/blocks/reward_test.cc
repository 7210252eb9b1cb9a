#include "cbbg/blocks/reward.h"

#include <cmath>
#include <stdexcept>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "cbbg/blocks/measured_signals.h"
#include "cbbg/framework/block_harness.h"

namespace cbbg::blocks {
namespace {

using ::testing::StrEq;
using ::testing::ThrowsMessage;
using Harness = testing::BlockHarness<Reward>;

constexpr double kPeriod = Harness::kPeriod;

// The reward output at one tick, then the tick's update.
double reward_at(Harness& harness, double theta, double theta_dot, bool failed = false) {
  Vector y = Vector::Zero(kMeasuredSize);
  y[kMeasuredThetaB] = theta;
  y[kMeasuredThetaBDot] = theta_dot;
  harness.set_input("measured", y);
  harness.set_input("failed", failed ? 1.0 : 0.0);
  const double reward = harness.scalar_output("reward");
  harness.tick();
  return reward;
}

TEST(Reward, PenalisesAGrowingSlidingSurfaceAsWorkedOutByHand) {
  Harness harness("reward", RewardParams{}, kPeriod);  // s = 10 theta + theta'
  EXPECT_EQ(reward_at(harness, 0.1, -0.5), 0.0);       // s = 0.5; no transition yet
  EXPECT_EQ(reward_at(harness, 0.05, 0.2), -1.0);      // s = 0.7: 0.49 > 0.25
  EXPECT_EQ(reward_at(harness, 0.05, -0.2), 0.0);      // s = 0.3: 0.09 <= 0.49
  EXPECT_EQ(reward_at(harness, -0.05, 0.2), 0.0);      // s = -0.3: equal squares count as no growth
  EXPECT_EQ(reward_at(harness, 0.0, 0.31), -1.0);      // s = 0.31
}

TEST(Reward, FailureIsPenalisedEvenWhenTheSurfaceShrinks) {
  Harness harness("reward", RewardParams{}, kPeriod);
  EXPECT_EQ(reward_at(harness, 0.1, 0.0), 0.0);         // s = 1
  EXPECT_EQ(reward_at(harness, 0.0, 0.0, true), -1.0);  // s = 0 would earn 0
  Harness first_tick("reward", RewardParams{}, kPeriod);
  EXPECT_EQ(reward_at(first_tick, 0.6, 0.0, true), -1.0);  // even on a trial's first tick
}

TEST(Reward, UsesConfiguredSurfaceWeights) {
  RewardParams params;
  params.a1 = 1.0;
  params.a2 = -2.0;
  Harness harness("reward", params, kPeriod);
  EXPECT_EQ(reward_at(harness, 1.0, 0.25), 0.0);  // s = 0.5
  EXPECT_EQ(reward_at(harness, 1.0, 0.0), -1.0);  // s = 1
  EXPECT_EQ(reward_at(harness, 1.0, 1.0), 0.0);   // s = -1
}

TEST(Reward, TheWheelRateWeightAddsTheWheelsMeanRateToTheSurface) {
  RewardParams params;
  params.k_phi = 0.5;  // s = 10 theta + theta' + 0.5 (phi_l' + phi_r') / 2
  Harness harness("reward", params, kPeriod);
  Vector y = Vector::Zero(kMeasuredSize);
  y[kMeasuredPhiLeftDot] = 1.0;
  y[kMeasuredPhiRightDot] = 3.0;
  harness.set_input("measured", y);  // s = 1
  harness.set_input("failed", 0.0);
  harness.tick();
  y[kMeasuredThetaB] = -0.09;  // s = -0.9 + 1 = 0.1: shrank
  harness.set_input("measured", y);
  EXPECT_EQ(harness.scalar_output("reward"), 0.0);
  harness.tick();
  y[kMeasuredThetaB] = 0.0;  // s = 1: grew, though the paper's surface (0) did not
  harness.set_input("measured", y);
  EXPECT_EQ(harness.scalar_output("reward"), -1.0);
}

TEST(Reward, StartTrialForgetsThePreviousSurface) {
  Harness harness("reward", RewardParams{}, kPeriod);
  EXPECT_EQ(reward_at(harness, 0.0, 0.0), 0.0);  // s = 0: anything after it is a growth
  harness.context().reset_trial_state();
  harness.restart_time();
  EXPECT_EQ(reward_at(harness, 0.1, 0.0), 0.0);  // a first tick again: no transition
  EXPECT_EQ(reward_at(harness, 0.2, 0.0), -1.0);
}

TEST(Reward, RejectsNonFiniteWeights) {
  RewardParams infinite;
  infinite.a1 = INFINITY;
  EXPECT_THAT([&] { Reward("reward", infinite, kPeriod); },
              ThrowsMessage<std::invalid_argument>(StrEq("reward.a1 must be finite; got inf")));
  RewardParams nan;
  nan.a2 = NAN;
  EXPECT_THAT([&] { Reward("reward", nan, kPeriod); },
              ThrowsMessage<std::invalid_argument>(StrEq("reward.a2 must be finite; got nan")));
}

}  // namespace
}  // namespace cbbg::blocks
