#include "cbbg/framework/primitives/step_source.h"

#include <limits>
#include <stdexcept>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "cbbg/framework/diagram_builder.h"

namespace cbbg {
namespace {

using ::testing::ThrowsMessage;

TEST(StepSource, PortsAndNoInputs) {
  const StepSource step("step", Eigen::Vector3d(1.0, 2.0, 3.0), Eigen::Vector3d::Zero(), 1.0);
  EXPECT_EQ(step.num_input_ports(), 0);
  ASSERT_EQ(step.num_output_ports(), 1);
  EXPECT_EQ(step.output_port("y").size(), 3);
  EXPECT_TRUE(step.output_reads(0).empty());
  EXPECT_TRUE(step.initial_discrete_state().size() == 0 && !step.has_continuous_state());
}

TEST(StepSource, InitialValueBeforeTheStepTimeFinalFromIt) {
  DiagramBuilder builder("top");
  auto& step = builder.emplace<StepSource>("step", Eigen::Vector2d(1.0, -1.0),
                                           Eigen::Vector2d(3.0, 0.5), 0.75);
  auto& scalar = builder.emplace<StepSource>("scalar", 2.0, -2.0, 0.0);
  auto diagram = builder.build();
  auto context = diagram->create_context();
  const auto y_at = [&](const StepSource& source, double t) {
    context->set_time(t);
    return Vector(diagram->eval_output(*context, source.output_port("y")));
  };
  EXPECT_EQ(y_at(step, 0.0), Eigen::Vector2d(1.0, -1.0));
  EXPECT_EQ(y_at(step, 0.7499), Eigen::Vector2d(1.0, -1.0));
  EXPECT_EQ(y_at(step, 0.75), Eigen::Vector2d(3.0, 0.5));  // the final value from t_step on
  EXPECT_EQ(y_at(step, 10.0), Eigen::Vector2d(3.0, 0.5));
  EXPECT_EQ(y_at(scalar, 0.0), Vector::Constant(1, -2.0));  // a step at 0 is on from the start
}

TEST(StepSource, RefusesBadArguments) {
  EXPECT_THAT([] { StepSource("step", Vector::Zero(2), Vector::Zero(3), 1.0); },
              ThrowsMessage<std::invalid_argument>(
                  "StepSource 'step': the final value has size 3; it must have the initial "
                  "value's size, 2"));
  EXPECT_THAT([] { StepSource("step", Vector(), Vector(), 1.0); },
              ThrowsMessage<std::invalid_argument>("StepSource 'step': size 0 must be at least 1"));
  EXPECT_THAT(
      [] { StepSource("step", 0.0, std::numeric_limits<double>::infinity(), 1.0); },
      ThrowsMessage<std::invalid_argument>("StepSource 'step': final value inf must be finite"));
  EXPECT_THAT(
      [] { StepSource("step", 0.0, 1.0, std::numeric_limits<double>::quiet_NaN()); },
      ThrowsMessage<std::invalid_argument>("StepSource 'step': step time nan must be finite"));
}

}  // namespace
}  // namespace cbbg
