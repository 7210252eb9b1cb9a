#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <limits>
#include <stdexcept>

#include "cbbg/framework/diagram_builder.h"
#include "cbbg/framework/primitives/unit_delay.h"
#include "cbbg/framework/simulator.h"
#include "tests/framework/test_blocks.h"

namespace cbbg {
namespace {

using ::testing::ThrowsMessage;

TEST(UnitDelay, HoldsItsInputAsPerTrialStateThatItsOutputReads) {
  const UnitDelay delay("delay", Eigen::Vector2d(1.0, 2.0), 0.1);
  ASSERT_EQ(delay.num_input_ports(), 1);
  EXPECT_EQ(delay.input_port("u").size(), 2);
  ASSERT_EQ(delay.num_output_ports(), 1);
  EXPECT_EQ(delay.output_port("y").size(), 2);
  EXPECT_TRUE(delay.output_reads(0).empty());  // no feedthrough: it breaks loops
  EXPECT_EQ(delay.discrete_state_part("delayed").size, 2);
  EXPECT_EQ(delay.discrete_state_part("delayed").lifetime, StateLifetime::kPerTrial);
  EXPECT_EQ(delay.initial_discrete_state(), Eigen::Vector2d(1.0, 2.0));
  ASSERT_EQ(delay.periodic_updates().size(), 1U);
  EXPECT_EQ(delay.periodic_updates()[0].period, 0.1);
  EXPECT_EQ(UnitDelay("zero", 3, 0.1).initial_discrete_state(), Vector::Zero(3));
}

TEST(UnitDelay, AtEachInstantGivesTheSampleOfTheInstantBefore) {
  // The counter reads k at t_k = 0.1 k; the delay, read at t_k, gives u_{k-1} = k - 1, and
  // its initial value at t_0.
  DiagramBuilder builder("top");
  auto& counter = builder.emplace<testing::Counter>("counter", 0.1);
  auto& delay = builder.emplace<UnitDelay>("delay", Vector::Constant(1, -1.0), 0.1);
  builder.connect(counter, "y", delay, "u");
  auto diagram = builder.build();
  Simulator simulator(*diagram);
  const SignalLog& log = simulator.add_log(delay.output_port("y"), 0.1);
  simulator.advance_to(0.55);
  ASSERT_EQ(log.num_samples(), 6);
  for (int k = 0; k < 6; ++k) EXPECT_EQ(log.sample(k)[0], k == 0 ? -1.0 : k - 1.0) << k;
  // Between instants (after t_5's update) it holds u_5.
  EXPECT_EQ(diagram->eval_output(simulator.context(), delay.output_port("y"))[0], 5.0);
  simulator.context().reset_trial_state();
  EXPECT_EQ(simulator.context().discrete_state(delay)[0], -1.0);
}

TEST(UnitDelay, RefusesABadSizePeriodOffsetOrInitialValue) {
  EXPECT_THAT([] { UnitDelay("delay", 0, 0.1); },
              ThrowsMessage<std::invalid_argument>("UnitDelay 'delay': size 0 must be at least 1"));
  EXPECT_THAT([] { UnitDelay("delay", 1, -0.01); },
              ThrowsMessage<std::invalid_argument>(
                  "UnitDelay 'delay': period -0.01 must be positive and finite"));
  EXPECT_THAT([] { UnitDelay("delay", 1, std::numeric_limits<double>::infinity()); },
              ThrowsMessage<std::invalid_argument>(
                  "UnitDelay 'delay': period inf must be positive and finite"));
  EXPECT_THAT(
      [] { UnitDelay("delay", 1, 0.1, -1.0); },
      ThrowsMessage<std::invalid_argument>("UnitDelay 'delay': offset -1 must be finite and >= 0"));
  EXPECT_THAT(
      [] {
        UnitDelay("delay", Vector::Constant(1, std::numeric_limits<double>::quiet_NaN()), 0.1);
      },
      ThrowsMessage<std::invalid_argument>("UnitDelay 'delay': initial value nan must be finite"));
}

}  // namespace
}  // namespace cbbg
