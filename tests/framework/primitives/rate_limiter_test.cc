#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <limits>
#include <stdexcept>

#include "cbbg/framework/block_harness.h"
#include "cbbg/framework/diagram_builder.h"
#include "cbbg/framework/primitives/constant_source.h"
#include "cbbg/framework/primitives/rate_limiter.h"
#include "cbbg/framework/simulator.h"

namespace cbbg {
namespace {

using ::testing::ThrowsMessage;

constexpr double kInf = std::numeric_limits<double>::infinity();

TEST(RateLimiter, HoldsItsOutputAsPerTrialStateThatItsOutputReads) {
  const RateLimiter limiter("lim", 2, 1.0, 1.0, 0.1);
  ASSERT_EQ(limiter.num_input_ports(), 1);
  EXPECT_EQ(limiter.input_port("u").size(), 2);
  ASSERT_EQ(limiter.num_output_ports(), 1);
  EXPECT_EQ(limiter.output_port("y").size(), 2);
  EXPECT_TRUE(limiter.output_reads(0).empty());  // no feedthrough: it breaks loops
  EXPECT_EQ(limiter.discrete_state_part("output").size, 2);
  EXPECT_EQ(limiter.discrete_state_part("output").lifetime, StateLifetime::kPerTrial);
  EXPECT_EQ(limiter.initial_discrete_state(), Vector::Zero(2));
}

TEST(RateLimiter, RampsAStepAtItsRisingRateOnePeriodLate) {
  // A step to 1, rising at most 2 per second, every 0.1 s: y_k = min(0.2 (k + 1), 1) after
  // the update at t_k; read at t_k (the log) it is still y_{k-1} = min(0.2 k, 1).
  DiagramBuilder builder("top");
  auto& step = builder.emplace<ConstantSource>("step", Vector::Ones(1));
  auto& limiter = builder.emplace<RateLimiter>("lim", 1, 2.0, 5.0, 0.1);
  builder.connect(step, "y", limiter, "u");
  auto diagram = builder.build();
  Simulator simulator(*diagram);
  const SignalLog& log = simulator.add_log(limiter.output_port("y"), 0.1);
  simulator.advance_to(0.75);
  ASSERT_EQ(log.num_samples(), 8);
  for (int k = 0; k < 8; ++k) EXPECT_NEAR(log.sample(k)[0], std::min(0.2 * k, 1.0), 1e-12) << k;
  EXPECT_EQ(log.sample(7)[0], 1.0);  // reached within the limit: exactly the input
  simulator.context().reset_trial_state();
  EXPECT_EQ(simulator.context().discrete_state(limiter)[0], 0.0);
}

TEST(RateLimiter, FallsAtItsFallingRateAndFollowsAStepWithinItsLimitsExactly) {
  testing::BlockHarness<RateLimiter> harness("lim", Vector::Constant(1, 1.0), 10.0, 50.0,
                                             testing::BlockHarness<RateLimiter>::kPeriod);
  harness.set_input("u", -1.0);  // falls at most 50 * 0.01 = 0.5 a tick
  for (const double expected : {0.5, 0.0, -0.5, -1.0, -1.0}) {
    harness.tick();
    EXPECT_NEAR(harness.scalar_output("y"), expected, 1e-12);
  }
  harness.set_input("u", -0.95);  // within the rising limit of 0.1 a tick
  harness.tick();
  EXPECT_EQ(harness.scalar_output("y"), -0.95);
}

TEST(RateLimiter, WithInfiniteRatesIsAUnitDelay) {
  testing::BlockHarness<RateLimiter> harness("lim", 1, kInf, kInf,
                                             testing::BlockHarness<RateLimiter>::kPeriod);
  harness.set_input("u", 123.25);
  EXPECT_EQ(harness.scalar_output("y"), 0.0);
  harness.tick();
  EXPECT_EQ(harness.scalar_output("y"), 123.25);
}

TEST(RateLimiter, RefusesNegativeOrNanRatesABadPeriodOrSizeOrInitialValue) {
  EXPECT_THAT([] { RateLimiter("lim", 1, -1.0, 1.0, 0.1); },
              ThrowsMessage<std::invalid_argument>(
                  "RateLimiter 'lim': rising rate -1 must be >= 0 (inf for no limit)"));
  EXPECT_THAT([] { RateLimiter("lim", 1, 1.0, std::numeric_limits<double>::quiet_NaN(), 0.1); },
              ThrowsMessage<std::invalid_argument>(
                  "RateLimiter 'lim': falling rate nan must be >= 0 (inf for no limit)"));
  EXPECT_THAT([] { RateLimiter("lim", 1, 1.0, 1.0, 0.0); },
              ThrowsMessage<std::invalid_argument>(
                  "RateLimiter 'lim': period 0 must be positive and finite"));
  EXPECT_THAT([] { RateLimiter("lim", 0, 1.0, 1.0, 0.1); },
              ThrowsMessage<std::invalid_argument>("RateLimiter 'lim': size 0 must be at least 1"));
  EXPECT_THAT(
      [] { RateLimiter("lim", Vector::Constant(1, kInf), 1.0, 1.0, 0.1); },
      ThrowsMessage<std::invalid_argument>("RateLimiter 'lim': initial value inf must be finite"));
}

}  // namespace
}  // namespace cbbg
