#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <limits>
#include <memory>
#include <stdexcept>

#include "cbbg/framework/diagram_builder.h"
#include "cbbg/framework/primitives/constant_source.h"
#include "cbbg/framework/primitives/discrete_derivative.h"
#include "cbbg/framework/primitives/integrator.h"
#include "cbbg/framework/simulator.h"
#include "tests/framework/test_blocks.h"

namespace cbbg {
namespace {

using ::testing::ThrowsMessage;
using Transient = DiscreteDerivative::InitialTransient;

TEST(DiscreteDerivative, HoldsTheLastTwoSamplesAsPerTrialStateThatItsOutputReads) {
  const DiscreteDerivative derivative("d", 2, 0.1);
  ASSERT_EQ(derivative.num_input_ports(), 1);
  EXPECT_EQ(derivative.input_port("u").size(), 2);
  ASSERT_EQ(derivative.num_output_ports(), 1);
  EXPECT_EQ(derivative.output_port("y").size(), 2);
  EXPECT_TRUE(derivative.output_reads(0).empty());  // no feedthrough: it breaks loops
  for (const char* part : {"last", "before", "count"}) {
    EXPECT_EQ(derivative.discrete_state_part(part).lifetime, StateLifetime::kPerTrial) << part;
  }
  EXPECT_EQ(derivative.discrete_state_part("last").size, 2);
  EXPECT_EQ(derivative.discrete_state_part("before").size, 2);
  EXPECT_EQ(derivative.discrete_state_part("count").size, 1);
}

TEST(DiscreteDerivative, OfACounterIsOneOverThePeriodOnePeriodLate) {
  // The counter reads k at t_k = 0.1 k. Read at t_k (the log), the derivative is
  // (u_{k-1} - u_{k-2}) / h = 10, and zero until two samples are stored (after t_1).
  DiagramBuilder builder("top");
  auto& counter = builder.emplace<testing::Counter>("counter", 0.1);
  auto& derivative = builder.emplace<DiscreteDerivative>("d", 1, 0.1);
  builder.connect(counter, "y", derivative, "u");
  auto diagram = builder.build();
  Simulator simulator(*diagram);
  const SignalLog& log = simulator.add_log(derivative.output_port("y"), 0.1);
  simulator.advance_to(0.45);
  ASSERT_EQ(log.num_samples(), 5);
  for (int k = 0; k < 5; ++k) EXPECT_EQ(log.sample(k)[0], k < 2 ? 0.0 : 1.0 / 0.1) << k;
  simulator.context().reset_trial_state();  // a new trial forgets the samples
  EXPECT_EQ(diagram->eval_output(simulator.context(), derivative.output_port("y"))[0], 0.0);
}

// u = 1 + 3 t, sampled every 0.1 s; the derivative read between instants.
class RampDerivative {
 public:
  explicit RampDerivative(Transient transient) {
    DiagramBuilder builder("top");
    auto& slope = builder.emplace<ConstantSource>("slope", Vector::Constant(1, 3.0));
    auto& ramp = builder.emplace<Integrator>("ramp", Vector::Ones(1));
    derivative_ = &builder.emplace<DiscreteDerivative>("d", 1, 0.1, transient);
    builder.connect(slope, "y", ramp, "u");
    builder.connect(ramp, "y", *derivative_, "u");
    diagram_ = builder.build();
    simulator_ = std::make_unique<Simulator>(*diagram_);
  }
  double at(double time) {
    simulator_->advance_to(time);
    return diagram_->eval_output(simulator_->context(), derivative_->output_port("y"))[0];
  }

 private:
  const DiscreteDerivative* derivative_;
  std::unique_ptr<Diagram> diagram_;
  std::unique_ptr<Simulator> simulator_;
};

TEST(DiscreteDerivative, OfARampIsItsSlopeOnceTwoSamplesAreStored) {
  RampDerivative suppressed(Transient::kSuppress);
  EXPECT_EQ(suppressed.at(0.05), 0.0);  // one sample (u_0 = 1) stored
  EXPECT_NEAR(suppressed.at(0.15), 3.0, 1e-9);
  EXPECT_NEAR(suppressed.at(1.05), 3.0, 1e-9);

  RampDerivative kept(Transient::kKeep);  // the sample before u_0 is zero
  EXPECT_NEAR(kept.at(0.05), 1.0 / 0.1, 1e-12);
  EXPECT_NEAR(kept.at(0.15), 3.0, 1e-9);
}

TEST(DiscreteDerivative, RefusesABadSizePeriodOrOffset) {
  EXPECT_THAT(
      [] { DiscreteDerivative("d", 0, 0.1); },
      ThrowsMessage<std::invalid_argument>("DiscreteDerivative 'd': size 0 must be at least 1"));
  EXPECT_THAT([] { DiscreteDerivative("d", 1, std::numeric_limits<double>::quiet_NaN()); },
              ThrowsMessage<std::invalid_argument>(
                  "DiscreteDerivative 'd': period nan must be positive and finite"));
  EXPECT_THAT([] { DiscreteDerivative("d", 1, 0.1, Transient::kKeep, -0.5); },
              ThrowsMessage<std::invalid_argument>(
                  "DiscreteDerivative 'd': offset -0.5 must be finite and >= 0"));
}

}  // namespace
}  // namespace cbbg
