#include "cbbg/framework/primitives/ramp_source.h"

#include <limits>
#include <stdexcept>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "cbbg/framework/diagram_builder.h"

namespace cbbg {
namespace {

using ::testing::ThrowsMessage;

TEST(RampSource, PortsAndNoInputs) {
  const RampSource ramp("ramp", Eigen::Vector3d(1.0, 0.0, -1.0), 0.0, Eigen::Vector3d::Zero());
  EXPECT_EQ(ramp.num_input_ports(), 0);
  ASSERT_EQ(ramp.num_output_ports(), 1);
  EXPECT_EQ(ramp.output_port("y").size(), 3);
  EXPECT_TRUE(ramp.output_reads(0).empty());
}

TEST(RampSource, HoldsTheInitialValueUntilTheStartThenRises) {
  // y = y0 + s max(0, t - t_start)
  DiagramBuilder builder("top");
  auto& ramp = builder.emplace<RampSource>("ramp", Eigen::Vector2d(2.0, -0.5), 1.0,
                                           Eigen::Vector2d(1.0, 3.0));
  auto& scalar = builder.emplace<RampSource>("scalar", 4.0, 0.0);  // y0 = 0
  auto diagram = builder.build();
  auto context = diagram->create_context();
  const auto y_at = [&](const RampSource& source, double t) {
    context->set_time(t);
    return Vector(diagram->eval_output(*context, source.output_port("y")));
  };
  EXPECT_EQ(y_at(ramp, 0.0), Eigen::Vector2d(1.0, 3.0));
  EXPECT_EQ(y_at(ramp, 1.0), Eigen::Vector2d(1.0, 3.0));
  EXPECT_EQ(y_at(ramp, 1.5), Eigen::Vector2d(2.0, 2.75));
  EXPECT_EQ(y_at(ramp, 5.0), Eigen::Vector2d(9.0, 1.0));
  EXPECT_EQ(y_at(scalar, 0.25), Vector::Constant(1, 1.0));
}

TEST(RampSource, RefusesBadArguments) {
  EXPECT_THAT([] { RampSource("ramp", Vector::Ones(2), 0.0, Vector::Zero(3)); },
              ThrowsMessage<std::invalid_argument>(
                  "RampSource 'ramp': the initial value has size 3; it must have the slope's "
                  "size, 2"));
  EXPECT_THAT([] { RampSource("ramp", std::numeric_limits<double>::quiet_NaN(), 0.0); },
              ThrowsMessage<std::invalid_argument>("RampSource 'ramp': slope nan must be finite"));
  EXPECT_THAT(
      [] { RampSource("ramp", 1.0, -std::numeric_limits<double>::infinity()); },
      ThrowsMessage<std::invalid_argument>("RampSource 'ramp': start time -inf must be finite"));
}

}  // namespace
}  // namespace cbbg
