#include "cbbg/framework/simulator.h"

#include <cmath>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "cbbg/framework/diagram_builder.h"
#include "cbbg/framework/primitives/constant_source.h"
#include "cbbg/framework/primitives/gain.h"
#include "cbbg/framework/primitives/zero_order_hold.h"
#include "tests/framework/test_blocks.h"

namespace cbbg {
namespace {

using ::testing::HasSubstr;

struct CounterDiagram {
  std::unique_ptr<Diagram> diagram;
  const testing::Counter* counter;
};

CounterDiagram make_counter(double period, double offset = 0.0, int stop_at = 0) {
  DiagramBuilder builder("top");
  auto& counter = builder.emplace<testing::Counter>("counter", period, offset, stop_at);
  return {builder.build(), &counter};
}

TEST(Simulator, FiresAPeriodicEventAtTimeZeroAndNotAtTheEndTime) {
  auto [diagram, counter] = make_counter(0.1);
  Simulator simulator(*diagram);
  simulator.advance_to(0.05);  // the instant t = 0 only
  EXPECT_EQ(simulator.context().discrete_state(*counter)[0], 1.0);
  simulator.advance_to(0.1);  // the event at 0.1 is left for the next call
  EXPECT_EQ(simulator.context().discrete_state(*counter)[0], 1.0);
  simulator.advance_to(0.1 + 1e-6);
  EXPECT_EQ(simulator.context().discrete_state(*counter)[0], 2.0);
  simulator.advance_to(1.0);  // instants 0, 0.1, ..., 0.9
  EXPECT_EQ(simulator.context().discrete_state(*counter)[0], 10.0);
  EXPECT_EQ(simulator.context().time(), 1.0);
}

TEST(Simulator, HonoursTheOffsetOfAPeriodicEvent) {
  auto [diagram, counter] = make_counter(0.1, 0.25);
  Simulator simulator(*diagram);
  simulator.advance_to(0.25);
  EXPECT_EQ(simulator.context().discrete_state(*counter)[0], 0.0);
  simulator.advance_to(0.3);  // 0.25
  EXPECT_EQ(simulator.context().discrete_state(*counter)[0], 1.0);
  simulator.advance_to(0.36);  // 0.35
  EXPECT_EQ(simulator.context().discrete_state(*counter)[0], 2.0);
}

TEST(Simulator, ThousandsOfPeriodsDoNotDrift) {
  auto [diagram, counter] = make_counter(0.01);
  Simulator simulator(*diagram);
  simulator.advance_to(20.0);
  EXPECT_EQ(simulator.context().discrete_state(*counter)[0], 2000.0);
  EXPECT_EQ(simulator.num_event_instants(), 2000);
}

TEST(Simulator, SimultaneousUpdatesReadTheValuesFromBeforeTheInstant) {
  DiagramBuilder builder("top");
  auto& a = builder.emplace<testing::IncrementInput>("a", 0.1);
  auto& b = builder.emplace<testing::IncrementInput>("b", 0.1);
  builder.connect(a, "y", b, "u");
  builder.connect(b, "y", a, "u");
  auto diagram = builder.build();
  Simulator simulator(*diagram);
  simulator.advance_to(0.05);
  // Sequential updates would give a = 1, b = 2.
  EXPECT_EQ(simulator.context().discrete_state(a)[0], 1.0);
  EXPECT_EQ(simulator.context().discrete_state(b)[0], 1.0);
  simulator.advance_to(0.15);
  EXPECT_EQ(simulator.context().discrete_state(a)[0], 2.0);
  EXPECT_EQ(simulator.context().discrete_state(b)[0], 2.0);
}

TEST(Simulator, EventsOfDifferentPeriodsCoincideInOneInstant) {
  DiagramBuilder builder("top");
  auto& fast = builder.emplace<testing::Counter>("fast", 0.01);
  auto& slow = builder.emplace<testing::Counter>("slow", 0.03);
  auto diagram = builder.build();
  Simulator simulator(*diagram);
  simulator.advance_to(0.3);
  EXPECT_EQ(simulator.context().discrete_state(fast)[0], 30.0);
  EXPECT_EQ(simulator.context().discrete_state(slow)[0], 10.0);
  // 0.03 k and 0.01 (3k) round differently, yet they are one instant.
  EXPECT_EQ(simulator.num_event_instants(), 30);
}

// A ramp x = t sampled by a hold every 0.1 s; a log every 0.05 s records what the updates
// read at each instant, so the new sample shows from the instant after it was taken.
TEST(Simulator, ZeroOrderHoldChangesAtItsSampleInstantsOnly) {
  DiagramBuilder builder("top");
  auto& rate = builder.emplace<ConstantSource>("rate", Vector::Ones(1));
  auto& ramp = builder.emplace<testing::Integrator>("ramp");
  auto& hold = builder.emplace<ZeroOrderHold>("hold", 1, 0.1);
  builder.connect(rate, "y", ramp, "u");
  builder.connect(ramp, "y", hold, "u");
  auto diagram = builder.build();
  Simulator simulator(*diagram, SimulatorOptions{.accuracy = 1e-10});
  SignalLog& log = simulator.add_log(hold.output_port("y"), 0.05);
  SignalLog& ramp_log = simulator.add_log(ramp.output_port("y"), 0.05);
  simulator.advance_to(0.3);
  ASSERT_EQ(log.num_samples(), 6);
  const double expected_hold[] = {0.0, 0.0, 0.0, 0.1, 0.1, 0.2};
  for (int k = 0; k < 6; ++k) {
    EXPECT_NEAR(log.times()[static_cast<size_t>(k)], 0.05 * k, 1e-15);
    EXPECT_NEAR(log.sample(k)[0], expected_hold[k], 1e-9) << "sample " << k;
    EXPECT_NEAR(ramp_log.sample(k)[0], 0.05 * k, 1e-9) << "sample " << k;
  }
}

TEST(Simulator, IntegratesContinuousStateToTheRequestedAccuracy) {
  DiagramBuilder builder("top");
  auto& decay = builder.emplace<testing::Exponential>("decay", -2.0, 1.0);
  auto diagram = builder.build();
  for (const double accuracy : {1e-4, 1e-8}) {
    Simulator simulator(*diagram, SimulatorOptions{.accuracy = accuracy});
    simulator.advance_to(1.0);
    EXPECT_NEAR(simulator.context().continuous_state(decay)[0], std::exp(-2.0), 10 * accuracy);
  }
}

TEST(Simulator, ContinuousBlocksSeeTheHeldInputBetweenInstants) {
  // x' = u with u = a counter held by its own state: u = 1 on [0, 0.1), 2 on [0.1, 0.2), ...
  DiagramBuilder builder("top");
  auto& counter = builder.emplace<testing::Counter>("counter", 0.1);
  auto& integral = builder.emplace<testing::Integrator>("integral");
  builder.connect(counter, "y", integral, "u");
  auto diagram = builder.build();
  Simulator simulator(*diagram, SimulatorOptions{.accuracy = 1e-10});
  simulator.advance_to(0.35);
  EXPECT_NEAR(simulator.context().continuous_state(integral)[0], 0.1 * (1 + 2 + 3) + 0.05 * 4,
              1e-9);
}

TEST(Simulator, SelfIntegratingBlocksAdvanceOverEachInterval) {
  DiagramBuilder builder("top");
  auto& counter = builder.emplace<testing::Counter>("counter", 0.1);
  auto& self = builder.emplace<testing::SelfIntegrator>("self");
  builder.connect(counter, "y", self, "u");
  auto diagram = builder.build();
  Simulator simulator(*diagram);
  simulator.advance_to(0.35);
  EXPECT_NEAR(simulator.context().continuous_state(self)[0], 0.1 * (1 + 2 + 3) + 0.05 * 4, 1e-12);
}

TEST(Simulator, TerminatesAfterTheUpdatesOfTheInstantThatAskedForIt) {
  auto [diagram, counter] = make_counter(0.01, 0.0, 3);
  Simulator simulator(*diagram);
  const SimulationStatus status = simulator.advance_to(1.0);
  EXPECT_TRUE(status.terminated);
  EXPECT_DOUBLE_EQ(status.time, 0.02);  // instants 0, 0.01, 0.02
  EXPECT_EQ(status.terminated_by, counter);
  EXPECT_STREQ(status.reason, "count reached");
  EXPECT_EQ(simulator.context().discrete_state(*counter)[0], 3.0);  // committed
  // A terminated simulation stays put until it is initialised again.
  EXPECT_TRUE(simulator.advance_to(2.0).terminated);
  EXPECT_DOUBLE_EQ(simulator.context().time(), 0.02);
}

TEST(Simulator, RestartsFromAStoredInitialContext) {
  auto [diagram, counter] = make_counter(0.01, 0.0, 3);
  Simulator simulator(*diagram);
  const auto initial = simulator.context().clone();
  simulator.advance_to(1.0);
  simulator.context().assign_from(*initial);
  simulator.initialize();
  const SimulationStatus status = simulator.advance_to(1.0);
  EXPECT_TRUE(status.terminated);
  EXPECT_DOUBLE_EQ(status.time, 0.02);
}

TEST(Simulator, ARestartFromAStoredContextRepeatsBitForBit) {
  DiagramBuilder builder("top");
  auto& counter = builder.emplace<testing::Counter>("counter", 0.01);
  auto& decay = builder.emplace<testing::Exponential>("decay", -3.0, 1.0);
  auto& integral = builder.emplace<testing::Integrator>("integral");
  builder.connect(counter, "y", integral, "u");
  auto diagram = builder.build();
  Simulator simulator(*diagram);
  const auto initial = simulator.context().clone();
  simulator.advance_to(1.0);
  const Vector first = simulator.context().continuous_states();
  simulator.context().assign_from(*initial);
  simulator.initialize();
  simulator.advance_to(1.0);
  EXPECT_EQ(simulator.context().continuous_states(), first);
  EXPECT_GT(simulator.context().continuous_state(decay)[0], 0.0);
  EXPECT_GT(simulator.context().continuous_state(integral)[0], 0.0);
}

TEST(Simulator, InitializationUpdatesRunOnceBeforeTheFirstInstant) {
  class InitialisedCounter final : public Block {
   public:
    InitialisedCounter() : Block("counter") {
      declare_discrete_state("state", Vector::Zero(2), StateLifetime::kPersistent);
      declare_initialization_update([](BlockContext&, VectorRef next) {
        next[0] = 100.0;  // runs first: the periodic update at t = 0 then sees 100
        return EventStatus::succeeded();
      });
      declare_periodic_update(0.1, 0.0, [](BlockContext& context, VectorRef next) {
        next[1] = context.discrete_state()[0] + next[1] + 1.0;
        return EventStatus::succeeded();
      });
    }
  };
  DiagramBuilder builder("top");
  auto& block = builder.add(std::make_unique<InitialisedCounter>());
  auto diagram = builder.build();
  Simulator simulator(*diagram);
  simulator.advance_to(0.15);
  EXPECT_EQ(simulator.context().discrete_state(block), Eigen::Vector2d(100.0, 202.0));
}

TEST(Simulator, AdvancingInPiecesEqualsAdvancingAtOnce) {
  DiagramBuilder builder("top");
  auto& counter = builder.emplace<testing::Counter>("counter", 0.01);
  auto& decay = builder.emplace<testing::Exponential>("decay", -1.0, 1.0);
  auto& integral = builder.emplace<testing::Integrator>("integral");
  builder.connect(counter, "y", integral, "u");
  auto diagram = builder.build();
  Simulator whole(*diagram);
  whole.advance_to(1.0);
  // End times on the event grid (k x 10 x 0.01, as the simulator computes instants): the same
  // intervals, the same steps, the same bits.
  Simulator pieces(*diagram);
  for (int k = 1; k <= 10; ++k) pieces.advance_to(static_cast<double>(10 * k) * 0.01);
  EXPECT_EQ(pieces.context().discrete_states(), whole.context().discrete_states());
  EXPECT_EQ(pieces.context().continuous_states(), whole.context().continuous_states());
  // End times off the grid by rounding (0.1 x 3 = 0.30000000000000004): equal to rounding.
  Simulator rounded(*diagram);
  for (int k = 1; k <= 10; ++k) rounded.advance_to(0.1 * k);
  EXPECT_EQ(rounded.context().discrete_states(), whole.context().discrete_states());
  EXPECT_NEAR(rounded.context().continuous_state(decay)[0],
              whole.context().continuous_state(decay)[0], 1e-12);
  EXPECT_NEAR(rounded.context().continuous_state(integral)[0],
              whole.context().continuous_state(integral)[0], 1e-12);
}

TEST(Simulator, RejectsAnUnsetRootInput) {
  DiagramBuilder builder("top");
  auto& gain = builder.emplace<Gain>("gain", 2.0, 1);
  auto& hold = builder.emplace<ZeroOrderHold>("hold", 1, 0.1);
  builder.connect(gain, "y", hold, "u");
  builder.export_input(gain.input_port("u"), "command");
  auto diagram = builder.build();
  Simulator simulator(*diagram);
  try {
    simulator.advance_to(1.0);
    ADD_FAILURE() << "no exception";
  } catch (const std::invalid_argument& error) {
    EXPECT_STREQ(error.what(),
                 "simulate: input 'top.command' of the root diagram has no value; set it with "
                 "Context::fix_input");
  }
  simulator.context().fix_input(diagram->input_port("command"), Vector::Constant(1, 4.0));
  simulator.advance_to(0.15);
  EXPECT_EQ(simulator.context().discrete_state(hold)[0], 8.0);
}

TEST(Simulator, ReportsANonFiniteDiscreteStateNamingTheBlock) {
  DiagramBuilder builder("top");
  auto& source = builder.emplace<ConstantSource>(
      "source", Vector::Constant(1, std::numeric_limits<double>::quiet_NaN()));
  auto& hold = builder.emplace<ZeroOrderHold>("hold", 1, 0.1);
  builder.connect(source, "y", hold, "u");
  auto diagram = builder.build();
  Simulator simulator(*diagram);
  try {
    simulator.advance_to(1.0);
    ADD_FAILURE() << "no exception";
  } catch (const SimulationError& error) {
    EXPECT_STREQ(error.what(),
                 "block 'top/hold': discrete state became non-finite at t = 0.000000");
  }
}

TEST(Simulator, ReportsANonFiniteContinuousStateNamingTheBlock) {
  DiagramBuilder builder("top");
  auto& source = builder.emplace<ConstantSource>(
      "source", Vector::Constant(1, std::numeric_limits<double>::infinity()));
  auto& integral = builder.emplace<testing::Integrator>("integral");
  builder.connect(source, "y", integral, "u");
  builder.emplace<testing::Counter>("counter", 0.1);
  auto diagram = builder.build();
  Simulator simulator(*diagram);
  try {
    simulator.advance_to(1.0);
    ADD_FAILURE() << "no exception";
  } catch (const SimulationError& error) {
    EXPECT_STREQ(error.what(),
                 "block 'top/integral': continuous state became non-finite at t = 0.100000");
  }
}

TEST(Simulator, ReportsAnIntegratorThatCannotMeetItsAccuracy) {
  DiagramBuilder builder("top");
  builder.emplace<testing::BlowUp>("blow_up");  // x' = x^2, x(0) = 1: infinite at t = 1
  auto diagram = builder.build();
  Simulator simulator(*diagram);
  try {
    simulator.advance_to(2.0);
    ADD_FAILURE() << "no exception";
  } catch (const SimulationError& error) {
    EXPECT_THAT(error.what(), HasSubstr("'top/blow_up'"));
  }
}

TEST(Simulator, RejectsNonFiniteTimesAndAccuracies) {
  auto [diagram, counter] = make_counter(0.1);
  EXPECT_THROW(Simulator(*diagram, SimulatorOptions{.accuracy = 0.0}), std::invalid_argument);
  Simulator simulator(*diagram);
  EXPECT_THROW(simulator.advance_to(std::numeric_limits<double>::infinity()),
               std::invalid_argument);
}

}  // namespace
}  // namespace cbbg
