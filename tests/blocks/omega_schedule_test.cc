#include "cbbg/blocks/omega_schedule.h"

#include <cmath>
#include <stdexcept>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "cbbg/framework/block_harness.h"

namespace cbbg::blocks {
namespace {

using ::testing::StrEq;
using ::testing::ThrowsMessage;
using Harness = testing::BlockHarness<OmegaSchedule>;

constexpr double kPeriod = Harness::kPeriod;

OmegaParams mode(OmegaMode m) {
  OmegaParams params;
  params.mode = m;
  return params;
}

TEST(OmegaSchedule, IsZeroUntilN2ThenRisesAsWorkedOutByHand) {
  const OmegaSchedule schedule("omega", OmegaParams{}, kPeriod);  // n2 = 500, n3 = 200
  EXPECT_EQ(schedule.omega_at(0.0), 0.0);
  EXPECT_EQ(schedule.omega_at(499.0), 0.0);
  EXPECT_EQ(schedule.omega_at(500.0), 0.0);
  EXPECT_NEAR(schedule.omega_at(501.0), 1.0 - std::exp(-1.0 / 200.0), 1e-15);
  EXPECT_NEAR(schedule.omega_at(700.0), 1.0 - std::exp(-1.0), 1e-15);  // 0.632...
  EXPECT_NEAR(schedule.omega_at(1e5), 1.0, 1e-15);
}

TEST(OmegaSchedule, CountsTicksSinceLearningBeganAcrossTrials) {
  Harness harness("omega", OmegaParams{}, kPeriod);
  for (int t = 0; t < 500; ++t) {
    ASSERT_EQ(harness.scalar_output("omega"), 0.0) << "tick " << t;
    harness.tick();
  }
  // A new trial restarts the time, not the schedule.
  harness.restart_time();
  EXPECT_EQ(harness.block().ticks(harness.context()), 500.0);
  EXPECT_EQ(harness.scalar_output("omega"), 0.0);  // t = n2 exactly
  harness.tick();
  EXPECT_NEAR(harness.scalar_output("omega"), 1.0 - std::exp(-1.0 / 200.0), 1e-15);
  for (int t = 501; t < 700; ++t) harness.tick();
  EXPECT_NEAR(harness.scalar_output("omega"), 1.0 - std::exp(-1.0), 1e-15);
}

TEST(OmegaSchedule, FixedModesHoldTheirValue) {
  Harness zero("omega", mode(OmegaMode::kZero), kPeriod);
  Harness one("omega", mode(OmegaMode::kOne), kPeriod);
  for (int t = 0; t < 1000; ++t) {
    ASSERT_EQ(zero.scalar_output("omega"), 0.0);
    ASSERT_EQ(one.scalar_output("omega"), 1.0);
    zero.tick();
    one.tick();
  }
}

TEST(OmegaSchedule, ModeConstantHoldsItsConstantForever) {
  OmegaParams params;
  params.mode = OmegaMode::kConstant;
  params.constant = 0.5;
  Harness half("omega", params, kPeriod);
  for (int t = 0; t < 1000; ++t) {
    ASSERT_EQ(half.scalar_output("omega"), 0.5);
    half.tick();
  }
}

TEST(OmegaSchedule, ParsesItsModeAndRejectsInvalidParameters) {
  EXPECT_EQ(parse_omega_mode("schedule"), OmegaMode::kSchedule);
  EXPECT_EQ(parse_omega_mode("zero"), OmegaMode::kZero);
  EXPECT_EQ(parse_omega_mode("one"), OmegaMode::kOne);
  EXPECT_EQ(parse_omega_mode("constant"), OmegaMode::kConstant);
  EXPECT_EQ(to_string(OmegaMode::kOne), "one");
  EXPECT_EQ(to_string(OmegaMode::kConstant), "constant");
  EXPECT_THAT([] { parse_omega_mode("half"); },
              ThrowsMessage<std::invalid_argument>(
                  StrEq("omega.mode must be schedule, zero, one or constant; got 'half'")));
  OmegaParams too_much;
  too_much.mode = OmegaMode::kConstant;
  too_much.constant = 1.5;
  EXPECT_THAT(
      [&] { OmegaSchedule("omega", too_much, kPeriod); },
      ThrowsMessage<std::invalid_argument>(StrEq("omega constant must be in [0, 1]; got 1.5")));
  OmegaParams zero_n3;
  zero_n3.n3 = 0.0;
  EXPECT_THAT(
      [&] { OmegaSchedule("omega", zero_n3, kPeriod); },
      ThrowsMessage<std::invalid_argument>(StrEq("omega.n3 must be finite and > 0; got 0")));
  OmegaParams negative_n2;
  negative_n2.n2 = -1.0;
  EXPECT_THAT(
      [&] { OmegaSchedule("omega", negative_n2, kPeriod); },
      ThrowsMessage<std::invalid_argument>(StrEq("omega.n2 must be finite and >= 0; got -1")));
}

}  // namespace
}  // namespace cbbg::blocks
