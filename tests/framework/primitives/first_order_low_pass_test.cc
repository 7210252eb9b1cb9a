#include "cbbg/framework/primitives/first_order_low_pass.h"

#include <cmath>
#include <limits>
#include <stdexcept>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "cbbg/framework/diagram_builder.h"
#include "cbbg/framework/primitives/gain.h"
#include "cbbg/framework/primitives/step_source.h"
#include "cbbg/framework/simulator.h"

namespace cbbg {
namespace {

using ::testing::ThrowsMessage;

// Simulator accuracy 1e-6 per step; the global error of a decaying exponential stays below.
constexpr double kTolerance = 1e-5;

TEST(FirstOrderLowPass, PortsAndNoFeedthrough) {
  const FirstOrderLowPass filter("filter", 0.2, 3);
  ASSERT_EQ(filter.num_input_ports(), 1);
  ASSERT_EQ(filter.num_output_ports(), 1);
  EXPECT_EQ(filter.input_port("u").size(), 3);
  EXPECT_EQ(filter.output_port("y").size(), 3);
  EXPECT_TRUE(filter.output_reads(0).empty());  // y = x: it can close a loop
  EXPECT_EQ(filter.initial_continuous_state(), Vector::Zero(3));
  EXPECT_EQ(filter.time_constant(), 0.2);
  EXPECT_TRUE(filter.periodic_updates().empty());
}

TEST(FirstOrderLowPass, StepResponseMatchesTheExponential) {
  // u steps to (1, -2) at t = 0; from x0 = (0.5, 0): y = u + (x0 - u) e^{-t / tau}.
  const double tau = 0.2;
  DiagramBuilder builder("top");
  auto& step =
      builder.emplace<StepSource>("step", Vector::Zero(2), Eigen::Vector2d(1.0, -2.0), 0.0);
  auto& filter = builder.emplace<FirstOrderLowPass>("filter", tau, Eigen::Vector2d(0.5, 0.0));
  builder.connect(step, "y", filter, "u");
  auto diagram = builder.build();
  Simulator simulator(*diagram);
  for (const double t : {0.05, 0.2, 0.5, 1.0, 2.0}) {
    simulator.advance_to(t);
    const auto y = diagram->eval_output(simulator.context(), filter.output_port("y"));
    EXPECT_NEAR(y[0], 1.0 + (0.5 - 1.0) * std::exp(-t / tau), kTolerance) << "t = " << t;
    EXPECT_NEAR(y[1], -2.0 + (0.0 + 2.0) * std::exp(-t / tau), kTolerance) << "t = " << t;
  }
}

TEST(FirstOrderLowPass, ClosesAFeedbackLoop) {
  // x' = (u - x) / tau with u = -x: x' = -2 x / tau, x = x0 e^{-2t/tau}.
  DiagramBuilder builder("top");
  auto& filter = builder.emplace<FirstOrderLowPass>("filter", 0.5, Vector::Constant(1, 3.0));
  auto& negate = builder.emplace<Gain>("negate", -1.0, 1);
  builder.connect(filter, "y", negate, "u");
  builder.connect(negate, "y", filter, "u");
  auto diagram = builder.build();
  Simulator simulator(*diagram);
  simulator.advance_to(1.0);
  EXPECT_NEAR(simulator.context().continuous_state(filter)[0], 3.0 * std::exp(-4.0), kTolerance);
}

TEST(FirstOrderLowPass, RefusesBadArguments) {
  EXPECT_THAT([] { FirstOrderLowPass("lp", 0.0, 1); },
              ThrowsMessage<std::invalid_argument>(
                  "FirstOrderLowPass 'lp': time constant 0 must be positive and finite"));
  EXPECT_THAT([] { FirstOrderLowPass("lp", -0.5, 1); },
              ThrowsMessage<std::invalid_argument>(
                  "FirstOrderLowPass 'lp': time constant -0.5 must be positive and finite"));
  EXPECT_THAT([] { FirstOrderLowPass("lp", std::numeric_limits<double>::infinity(), 1); },
              ThrowsMessage<std::invalid_argument>(
                  "FirstOrderLowPass 'lp': time constant inf must be positive and finite"));
  EXPECT_THAT(
      [] { FirstOrderLowPass("lp", 0.1, 0); },
      ThrowsMessage<std::invalid_argument>("FirstOrderLowPass 'lp': size 0 must be at least 1"));
  EXPECT_THAT(
      [] {
        FirstOrderLowPass("lp", 0.1,
                          Eigen::Vector2d(1.0, std::numeric_limits<double>::quiet_NaN()));
      },
      ThrowsMessage<std::invalid_argument>(
          "FirstOrderLowPass 'lp': initial value nan at element 1 must be finite"));
}

}  // namespace
}  // namespace cbbg
