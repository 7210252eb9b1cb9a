#include "cbbg/blocks/external_push.h"

#include <limits>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "cbbg/framework/diagram_builder.h"
#include "cbbg/framework/simulator.h"

namespace cbbg::blocks {
namespace {

PushParams push_from_outside(double start, double force, double pitch_torque) {
  PushParams push;
  push.start = start;
  push.duration = 0.02;
  push.force = force;
  push.pitch_torque = pitch_torque;
  return push;
}

TEST(ExternalPush, OutputsTheForceAndPitchTorqueOverTheTicksOfItsInterval) {
  // As TorquePush: the value over [t_k, t_k+1) is the one the update at t_k set.
  for (const double start : {0.03, 0.025}) {
    DiagramBuilder builder("pushed");
    auto& push = builder.emplace<ExternalPush>("push", push_from_outside(start, 40.0, -3.0), 0.01);
    const auto diagram = builder.build();
    Simulator simulator(*diagram);
    const SignalLog& log = simulator.add_log(push.output_port("disturbance"), 0.01, 0.005);
    simulator.advance_to(0.06);
    ASSERT_EQ(log.num_samples(), 6);
    for (int k = 0; k < 6; ++k) {
      const bool on = k == 3 || k == 4;  // the ticks 0.03 and 0.04
      EXPECT_EQ(log.sample(k)[0], on ? 40.0 : 0.0) << "start " << start << ", k " << k;
      EXPECT_EQ(log.sample(k)[1], on ? -3.0 : 0.0) << "start " << start << ", k " << k;
    }
  }
}

TEST(ExternalPush, IgnoresTheTorqueThatGoesThroughTheMotors) {
  PushParams push = push_from_outside(0.0, 0.0, 2.0);
  push.torque = 5.0;
  DiagramBuilder builder("pushed");
  auto& pusher = builder.emplace<ExternalPush>("push", push, 0.01);
  const auto diagram = builder.build();
  Simulator simulator(*diagram);
  const SignalLog& log = simulator.add_log(pusher.output_port("disturbance"), 0.01, 0.005);
  simulator.advance_to(0.01);
  ASSERT_EQ(log.num_samples(), 1);
  EXPECT_EQ(log.sample(0)[0], 0.0);
  EXPECT_EQ(log.sample(0)[1], 2.0);
}

TEST(ExternalPush, RefusesPushesOutOfRange) {
  EXPECT_THAT(
      ([] { ExternalPush("push", push_from_outside(0.0, std::nan(""), 0.0), 0.01); }),
      ::testing::ThrowsMessage<std::invalid_argument>("push.force must be finite; got nan"));
  EXPECT_THAT(([] {
                ExternalPush("push",
                             push_from_outside(0.0, 1.0, -std::numeric_limits<double>::infinity()),
                             0.01);
              }),
              ::testing::ThrowsMessage<std::invalid_argument>(
                  "push.pitch_torque must be finite; got -inf"));
  EXPECT_THAT(([] { ExternalPush("push", push_from_outside(0.0, 1.0, 0.0), 0.0); }),
              ::testing::ThrowsMessage<std::invalid_argument>(::testing::HasSubstr("period")));
}

}  // namespace
}  // namespace cbbg::blocks
