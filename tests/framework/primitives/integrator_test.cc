#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <stdexcept>

#include "cbbg/framework/diagram_builder.h"
#include "cbbg/framework/primitives/constant_source.h"
#include "cbbg/framework/primitives/gain.h"
#include "cbbg/framework/primitives/integrator.h"
#include "cbbg/framework/simulator.h"

namespace cbbg {
namespace {

using ::testing::ThrowsMessage;

TEST(Integrator, HasContinuousStateAndAnOutputThatReadsNoInput) {
  const Integrator integrator("int", Eigen::Vector2d(1.0, -2.0));
  ASSERT_EQ(integrator.num_input_ports(), 1);
  EXPECT_EQ(integrator.input_port("u").size(), 2);
  ASSERT_EQ(integrator.num_output_ports(), 1);
  EXPECT_EQ(integrator.output_port("y").size(), 2);
  EXPECT_TRUE(integrator.output_reads(0).empty());  // no feedthrough: it breaks loops
  EXPECT_EQ(integrator.initial_continuous_state(), Eigen::Vector2d(1.0, -2.0));
  EXPECT_FALSE(integrator.integrates_itself());
  EXPECT_EQ(integrator.initial_discrete_state().size(), 0);
  EXPECT_EQ(Integrator("zero", 3).initial_continuous_state(), Vector::Zero(3));
}

TEST(Integrator, OfAConstantIsTheInitialValuePlusTheConstantTimesTheTime) {
  DiagramBuilder builder("top");
  auto& source = builder.emplace<ConstantSource>("c", Eigen::Vector2d(0.5, -3.0));
  auto& integrator = builder.emplace<Integrator>("int", Eigen::Vector2d(1.0, -2.0));
  builder.connect(source, "y", integrator, "u");
  auto diagram = builder.build();
  Simulator simulator(*diagram);
  for (const double t : {0.7, 2.0}) {
    simulator.advance_to(t);
    const Vector y = diagram->eval_output(simulator.context(), integrator.output_port("y"));
    EXPECT_NEAR(y[0], 1.0 + 0.5 * t, 1e-12) << "t = " << t;
    EXPECT_NEAR(y[1], -2.0 - 3.0 * t, 1e-12) << "t = " << t;
  }
  // Continuous state outlives a trial; reset_state puts the initial value back.
  simulator.context().reset_trial_state();
  EXPECT_NEAR(simulator.context().continuous_state(integrator)[0], 2.0, 1e-12);
  simulator.context().reset_state(integrator);
  EXPECT_EQ(simulator.context().continuous_state(integrator)[0], 1.0);
}

TEST(Integrator, ClosesAFeedbackLoopOnItself) {
  // x' = -x from 1: x(t) = exp(-t). No algebraic loop, since y reads only the state.
  DiagramBuilder builder("top");
  auto& integrator = builder.emplace<Integrator>("int", Vector::Ones(1));
  auto& gain = builder.emplace<Gain>("minus", -1.0, 1);
  builder.connect(integrator, "y", gain, "u");
  builder.connect(gain, "y", integrator, "u");
  auto diagram = builder.build();
  Simulator simulator(*diagram);
  simulator.advance_to(1.0);
  EXPECT_NEAR(simulator.context().continuous_state(integrator)[0], std::exp(-1.0), 1e-5);
}

TEST(Integrator, RefusesAnEmptySizeAndANonFiniteInitialValue) {
  EXPECT_THAT([] { Integrator("int", 0); },
              ThrowsMessage<std::invalid_argument>("Integrator 'int': size 0 must be at least 1"));
  EXPECT_THAT([] { Integrator("int", Vector()); },
              ThrowsMessage<std::invalid_argument>("Integrator 'int': size 0 must be at least 1"));
  EXPECT_THAT(
      [] { Integrator("int", Eigen::Vector2d(0.0, std::numeric_limits<double>::quiet_NaN())); },
      ThrowsMessage<std::invalid_argument>(
          "Integrator 'int': initial value nan at element 1 must be finite"));
}

}  // namespace
}  // namespace cbbg
