#include "cbbg/blocks/torque_push.h"

#include <limits>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "cbbg/framework/diagram_builder.h"
#include "cbbg/framework/primitives/constant_source.h"
#include "cbbg/framework/simulator.h"

namespace cbbg::blocks {
namespace {

TEST(TorquePush, AddsThePushOverTheTicksOfItsInterval) {
  // The push applied over [t_k, t_k+1) is the one the update at t_k set: sample half-way.
  for (const double start : {0.03, 0.025}) {  // on a tick, and between ticks (0.03 is next)
    DiagramBuilder builder("pushed");
    auto& action = builder.emplace<ConstantSource>("action", Vector::Constant(1, 1.5));
    auto& push = builder.emplace<TorquePush>("push", PushParams{start, 2.0, 0.02}, 0.01);
    builder.connect(action.output_port("y"), push.input_port("action"));
    const auto diagram = builder.build();
    Simulator simulator(*diagram);
    const SignalLog& log = simulator.add_log(push.output_port("torque"), 0.01, 0.005);
    simulator.advance_to(0.06);
    ASSERT_EQ(log.num_samples(), 6);
    const double expected[] = {1.5, 1.5, 1.5, 3.5, 3.5, 1.5};  // ticks 0.03 and 0.04 pushed
    for (int k = 0; k < 6; ++k) {
      EXPECT_EQ(log.sample(k)[0], expected[k]) << "start " << start << ", t " << log.times()[k];
    }
  }
}

TEST(TorquePush, RefusesPushesOutOfRange) {
  EXPECT_THAT(([] {
                PushParams{-0.5, 1.0, 0.1}.validate();
              }),
              ::testing::ThrowsMessage<std::invalid_argument>(
                  "push.start must be finite and >= 0; got -0.5"));
  EXPECT_THAT(
      ([] {
        PushParams{0.0, std::numeric_limits<double>::infinity(), 0.1}.validate();
      }),
      ::testing::ThrowsMessage<std::invalid_argument>("push.torque must be finite; got inf"));
  EXPECT_THAT(([] {
                PushParams{0.0, 1.0, 0.0}.validate();
              }),
              ::testing::ThrowsMessage<std::invalid_argument>(
                  "push.duration must be finite and > 0; got 0"));
}

}  // namespace
}  // namespace cbbg::blocks
