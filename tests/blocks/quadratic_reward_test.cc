#include "cbbg/blocks/quadratic_reward.h"

#include <cmath>
#include <stdexcept>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "cbbg/blocks/measured_signals.h"
#include "cbbg/blocks/reward.h"
#include "cbbg/framework/block_harness.h"
#include "key_order.h"

namespace cbbg::blocks {
namespace {

using ::testing::ElementsAre;
using ::testing::StrEq;
using ::testing::ThrowsMessage;
using Harness = testing::BlockHarness<QuadraticReward>;

constexpr double kPeriod = Harness::kPeriod;

RewardParams quadratic(double q0, double q1, double q2) {
  RewardParams params;
  params.kind = RewardKind::kQuadratic;
  params.q = {q0, q1, q2};
  return params;
}

// The reward output at one tick, then the tick.
double reward_at(Harness& harness, double theta, double theta_dot, double phi_left_dot,
                 double phi_right_dot, bool failed = false) {
  Vector y = Vector::Zero(kMeasuredSize);
  y[kMeasuredThetaB] = theta;
  y[kMeasuredThetaBDot] = theta_dot;
  y[kMeasuredPhiLeft] = 100.0;  // the wheels' angles are not in the cost
  y[kMeasuredPhiRight] = -40.0;
  y[kMeasuredPhiLeftDot] = phi_left_dot;
  y[kMeasuredPhiRightDot] = phi_right_dot;
  harness.set_input("measured", y);
  harness.set_input("failed", failed ? 1.0 : 0.0);
  const double reward = harness.scalar_output("reward");
  harness.tick();
  return reward;
}

TEST(QuadraticReward, IsMinusTheQuadraticCostAsWorkedOutByHand) {
  Harness defaults("reward", quadratic(1.0, 0.1, 0.0), kPeriod);
  // -(0.2^2 + 0.1 (-1)^2) = -0.14, from the first tick: nothing is remembered.
  EXPECT_NEAR(reward_at(defaults, 0.2, -1.0, 5.0, 5.0), -0.14, 1e-15);
  EXPECT_EQ(reward_at(defaults, 0.0, 0.0, 3.0, -1.0), 0.0);  // upright: the best reward
  EXPECT_NEAR(reward_at(defaults, -0.3, 0.5, 0.0, 0.0), -(0.09 + 0.025), 1e-15);

  Harness weighted("reward", quadratic(2.0, 0.5, 0.25), kPeriod);
  // phi' = (1 + 3) / 2 = 2: -(2 0.01 + 0.5 0.04 + 0.25 4) = -1.04.
  EXPECT_NEAR(reward_at(weighted, 0.1, 0.2, 1.0, 3.0), -1.04, 1e-15);
  EXPECT_NEAR(reward_at(weighted, 0.0, 0.0, -1.0, -1.0), -0.25, 1e-15);
}

TEST(QuadraticReward, FailureIsMinusOne) {
  Harness harness("reward", quadratic(1.0, 0.1, 0.0), kPeriod);
  EXPECT_EQ(reward_at(harness, 0.6, 0.0, 0.0, 0.0, true), -1.0);  // -0.36 without the failure
  EXPECT_EQ(reward_at(harness, 0.0, 0.0, 0.0, 0.0, true), -1.0);
  EXPECT_EQ(reward_at(harness, 2.0, 10.0, 0.0, 0.0, true), -1.0);  // not -14
}

TEST(RewardParams, KindIsFirstQIsLastAndTheDefaultIsThePapers) {
  EXPECT_THAT(testing::declared_keys<RewardParams>(),
              ElementsAre("kind", "a1", "a2", "k_phi", "q"));
  const RewardParams defaults;
  EXPECT_EQ(defaults.kind, RewardKind::kSliding);
  EXPECT_THAT(defaults.q, ElementsAre(1.0, 0.1, 0.0));
  for (const RewardKind kind : {RewardKind::kSliding, RewardKind::kQuadratic}) {
    EXPECT_EQ(parse_reward_kind(to_string(kind)), kind);
  }
}

TEST(QuadraticReward, RejectsBadParametersNamingTheKey) {
  RewardParams two = quadratic(1.0, 0.1, 0.0);
  two.q = {1.0, 0.1};
  const char* size_message =
      "reward.q must be a list of 3 numbers (on theta_b^2, theta_b'^2, phi'^2); got a list of 2";
  EXPECT_THAT([&] { QuadraticReward("reward", two, kPeriod); },
              ThrowsMessage<std::invalid_argument>(StrEq(size_message)));
  EXPECT_THAT([&] { two.validate(); }, ThrowsMessage<std::invalid_argument>(StrEq(size_message)));
  EXPECT_THAT(
      [] { QuadraticReward("reward", quadratic(1.0, -1.0, 0.0), kPeriod); },
      ThrowsMessage<std::invalid_argument>(StrEq("reward.q[1] must be finite and >= 0; got -1")));
  EXPECT_THAT(
      [] { QuadraticReward("reward", quadratic(1.0, 0.0, NAN), kPeriod); },
      ThrowsMessage<std::invalid_argument>(StrEq("reward.q[2] must be finite and >= 0; got nan")));
  RewardParams unknown;
  unknown.kind = static_cast<RewardKind>(3);
  EXPECT_THAT(
      [&] { QuadraticReward("reward", unknown, kPeriod); },
      ThrowsMessage<std::invalid_argument>(StrEq("reward.kind must be one of sliding, quadratic")));
  EXPECT_THAT([] { parse_reward_kind("cost"); },
              ThrowsMessage<std::invalid_argument>(
                  StrEq("reward.kind must be sliding or quadratic; got 'cost'")));
  EXPECT_THAT(
      [] { QuadraticReward("reward", quadratic(1.0, 0.1, 0.0), -1.0); },
      ThrowsMessage<std::invalid_argument>(StrEq("trial.period must be finite and > 0; got -1")));
}

}  // namespace
}  // namespace cbbg::blocks
