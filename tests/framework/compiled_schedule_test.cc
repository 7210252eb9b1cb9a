// The compiled schedule computes what the interpreted one does, bit for bit, with fewer calls:
// outputs that hold still between events once per interval, in-place updates without a copy.

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "cbbg/framework/block_context.h"
#include "cbbg/framework/diagram_builder.h"
#include "cbbg/framework/primitives/gain.h"
#include "cbbg/framework/primitives/zero_order_hold.h"
#include "cbbg/framework/simulator.h"
#include "tests/framework/test_blocks.h"

namespace cbbg {
namespace {

// y = x + t: an output that reads time, so it may change within an interval; counts its calls.
class TimeShift final : public Block {
 public:
  explicit TimeShift(std::string name, int* calls) : Block(std::move(name)) {
    const InputPort& u = declare_input_port("u", 1);
    declare_output_port("y", 1,
                        [&u, calls](const BlockContext& context, VectorRef y) {
                          ++*calls;
                          y[0] = context.input(u)[0] + context.time();
                        },
                        {&u});
  }
};

// y = 2 u, declared to read nothing but its input; counts its calls.
class CountingDouble final : public Block {
 public:
  CountingDouble(std::string name, int* calls) : Block(std::move(name)) {
    const InputPort& u = declare_input_port("u", 1);
    declare_output_port(
        "y", 1,
        [&u, calls](const BlockContext& context, VectorRef y) {
          ++*calls;
          y[0] = 2.0 * context.input(u)[0];
        },
        {&u}, "2 u", OutputSources::kDiscreteState);
  }
};

// x+ = x / 2 + u, written in place; y = x.
class InPlaceFilter final : public Block {
 public:
  InPlaceFilter(std::string name, double period) : Block(std::move(name)) {
    const InputPort& u = declare_input_port("u", 1);
    declare_discrete_state("x", Vector::Zero(1), StateLifetime::kPerTrial);
    declare_output_port(
        "y", 1, [](const BlockContext& context, VectorRef y) { y = context.discrete_state(); }, {},
        "x", OutputSources::kDiscreteState);
    declare_periodic_update(
        period, 0.0,
        [&u](BlockContext& context, VectorRef next) {
          next[0] = 0.5 * context.discrete_state()[0] + context.input(u)[0];
          return EventStatus::succeeded();
        },
        UpdateWrites::kInPlace);
  }
};

// A diagram with every kind of work: a hold and an in-place filter (discrete), a gain and a
// time-reading output between them and two integrators (one the simulator's, one its own),
// counters of two periods that coincide, and a crosswise pair that must read the values from
// before the instant.
struct Mixed {
  std::unique_ptr<Diagram> diagram;
  const OutputPort* probe = nullptr;  // every signal of interest, multiplexed by the log
  std::vector<const OutputPort*> logged;
};

Mixed build_mixed(int* shift_calls, int* double_calls) {
  DiagramBuilder builder("mixed");
  auto& decay = builder.emplace<testing::Exponential>("decay", -1.5, 2.0);
  auto& hold = builder.emplace<ZeroOrderHold>("hold", 1, 0.01);
  auto& filter = builder.emplace<InPlaceFilter>("filter", 0.01);
  auto& twice = builder.emplace<CountingDouble>("twice", double_calls);
  auto& gain = builder.emplace<Gain>("gain", -0.3, 1);
  auto& shift = builder.emplace<TimeShift>("shift", shift_calls);
  auto& integral = builder.emplace<testing::Integrator>("integral");
  auto& own = builder.emplace<testing::SelfIntegrator>("own");
  auto& a = builder.emplace<testing::IncrementInput>("a", 0.02);
  auto& b = builder.emplace<testing::IncrementInput>("b", 0.03);
  builder.connect(decay.output_port("y"), hold.input_port("u"));
  builder.connect(hold.output_port("y"), filter.input_port("u"));
  builder.connect(filter.output_port("y"), twice.input_port("u"));
  builder.connect(twice.output_port("y"), gain.input_port("u"));
  builder.connect(gain.output_port("y"), shift.input_port("u"));
  builder.connect(shift.output_port("y"), integral.input_port("u"));
  builder.connect(gain.output_port("y"), own.input_port("u"));
  builder.connect(a.output_port("y"), b.input_port("u"));
  builder.connect(b.output_port("y"), a.input_port("u"));
  Mixed mixed;
  mixed.logged = {&decay.output_port("y"), &filter.output_port("y"), &integral.output_port("y"),
                  &own.output_port("y"),   &a.output_port("y"),      &b.output_port("y")};
  mixed.diagram = builder.build();
  return mixed;
}

struct Outcome {
  std::vector<std::vector<double>> logs;
  Vector discrete;
  Vector continuous;
  int shift_calls = 0;
  int double_calls = 0;
};

Outcome simulate(Schedule schedule) {
  Outcome run;
  const Mixed mixed = build_mixed(&run.shift_calls, &run.double_calls);
  Simulator simulator(*mixed.diagram, SimulatorOptions{.accuracy = 1e-9, .schedule = schedule});
  std::vector<SignalLog*> logs;
  for (const OutputPort* port : mixed.logged) logs.push_back(&simulator.add_log(*port, 0.005));
  simulator.advance_to(0.37);
  simulator.advance_to(1.0);
  for (const SignalLog* log : logs) {
    std::vector<double> values;
    for (int i = 0; i < log->num_samples(); ++i) values.push_back(log->sample(i)[0]);
    run.logs.push_back(values);
  }
  run.discrete = simulator.context().discrete_states();
  run.continuous = simulator.context().continuous_states();
  return run;
}

TEST(CompiledSchedule, ComputesWhatTheInterpretedScheduleComputesBitForBit) {
  const Outcome compiled = simulate(Schedule::kCompiled);
  const Outcome interpreted = simulate(Schedule::kInterpreted);
  ASSERT_EQ(compiled.logs.size(), interpreted.logs.size());
  for (size_t i = 0; i < compiled.logs.size(); ++i) {
    EXPECT_EQ(compiled.logs[i], interpreted.logs[i]) << "log " << i;  // exact, not near
    EXPECT_EQ(compiled.logs[i].size(), 200u);
  }
  EXPECT_EQ(compiled.discrete, interpreted.discrete);
  EXPECT_EQ(compiled.continuous, interpreted.continuous);
  // The crosswise pair still reads the values from before each instant: a and b count their
  // own instants (b at 0.03 s: 34 of them up to 1 s).
  EXPECT_GT(compiled.continuous.norm(), 0.0);
}

TEST(CompiledSchedule, ComputesWhatHoldsStillOncePerIntervalAndTheRestAtEveryStage) {
  const Outcome compiled = simulate(Schedule::kCompiled);
  const Outcome interpreted = simulate(Schedule::kInterpreted);
  // The time-reading output changes within an interval: both compute it at every stage.
  EXPECT_EQ(compiled.shift_calls, interpreted.shift_calls);
  // The doubling holds still between events: once per interval (and once at each event)
  // instead of at every stage, for the same values (the test above).
  EXPECT_LT(compiled.double_calls * 3, interpreted.double_calls);
}

TEST(CompiledSchedule, TheDiagramSplitsTheContinuousInputsByWhetherTheyHoldStill) {
  int shift_calls = 0;
  int double_calls = 0;
  const Mixed mixed = build_mixed(&shift_calls, &double_calls);
  const Diagram& diagram = *mixed.diagram;
  auto names = [&diagram](const std::vector<OutputSlot>& order) {
    std::vector<std::string> result;
    for (const OutputSlot& slot : order) {
      result.push_back(diagram.leaves()[static_cast<size_t>(slot.leaf)].block->name());
    }
    return result;
  };
  // The filter reads only its state and the gain only its input: still between events. The
  // shift reads time.
  EXPECT_THAT(names(diagram.interval_input_order()),
              ::testing::ElementsAre("filter", "twice", "gain"));
  EXPECT_THAT(names(diagram.stage_input_order()), ::testing::ElementsAre("shift"));
  EXPECT_EQ(diagram.continuous_input_order().size(), 4u);
}

TEST(CompiledSchedule, AnInPlaceUpdateMustBeItsBlocksOnlyPeriodicUpdate) {
  class TwoUpdates final : public Block {
   public:
    explicit TwoUpdates(bool in_place_first) : Block("two") {
      declare_discrete_state("x", Vector::Zero(1), StateLifetime::kPerTrial);
      const auto update = [](BlockContext&, VectorRef) { return EventStatus::succeeded(); };
      declare_periodic_update(0.1, 0.0, update,
                              in_place_first ? UpdateWrites::kInPlace : UpdateWrites::kCopy);
      declare_periodic_update(0.2, 0.0, update,
                              in_place_first ? UpdateWrites::kCopy : UpdateWrites::kInPlace);
    }
  };
  EXPECT_THAT([] { TwoUpdates(true); },
              ::testing::ThrowsMessage<std::invalid_argument>(::testing::HasSubstr(
                  "block 'two': its update writes in place, so it can have no other periodic "
                  "update")));
  EXPECT_THAT([] { TwoUpdates(false); },
              ::testing::ThrowsMessage<std::invalid_argument>(::testing::HasSubstr(
                  "block 'two': an update that writes in place must be the block's only "
                  "periodic update")));
}

// y = 1 until `until`, NaN after: a source that spoils what samples it.
class SpoilsAfter final : public Block {
 public:
  SpoilsAfter(std::string name, double until) : Block(std::move(name)) {
    declare_output_port("y", 1,
                        [until](const BlockContext& context, VectorRef y) {
                          y[0] = context.time() < until ? 1.0
                                                        : std::numeric_limits<double>::quiet_NaN();
                        },
                        {});
  }
};

// The message a simulation of holds of `periods` sampling a source spoilt after `until` ends
// with on `schedule`.
std::string spoilt_error(Schedule schedule, std::vector<double> periods, double until) {
  DiagramBuilder builder("top");
  auto& source = builder.emplace<SpoilsAfter>("source", until);
  for (size_t i = 0; i < periods.size(); ++i) {
    auto& hold = builder.emplace<ZeroOrderHold>("hold" + std::to_string(i), 1, periods[i]);
    builder.connect(source.output_port("y"), hold.input_port("u"));
  }
  const auto diagram = builder.build();
  Simulator simulator(*diagram, SimulatorOptions{.schedule = schedule});
  try {
    simulator.advance_to(1.0);
  } catch (const SimulationError& error) {
    return error.what();
  }
  return "no error";
}

TEST(CompiledSchedule, NamesTheBlockWhoseStateTurnedNonFiniteAsTheInterpretedScheduleDoes) {
  for (const Schedule schedule : {Schedule::kCompiled, Schedule::kInterpreted}) {
    // Only the slow hold samples at 0.04: it alone is checked, and named.
    EXPECT_EQ(spoilt_error(schedule, {0.03, 0.04}, 0.035),
              "block 'top/hold1': discrete state became non-finite at t = 0.040000");
    // Both sample at 0.06 (their groups coincide): the first in leaf order is named.
    EXPECT_EQ(spoilt_error(schedule, {0.02, 0.03}, 0.05),
              "block 'top/hold0': discrete state became non-finite at t = 0.060000");
  }
}

}  // namespace
}  // namespace cbbg
