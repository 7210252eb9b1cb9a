// Named calculations: a block's outputs, updates and derivatives declared as its own const
// member functions, called through the trampoline calculation.h instantiates for each, on
// both schedules; callables (lambdas) beside them.

#include <gtest/gtest.h>

#include <memory>
#include <string>

#include "cbbg/framework/block_context.h"
#include "cbbg/framework/diagram_builder.h"
#include "cbbg/framework/simulator.h"

namespace cbbg {
namespace {

// Something a block may inherit before Block, so that its Block part does not start at the
// object's address: the trampoline must call the member on the right `this`.
struct Tagged {
  virtual ~Tagged() = default;
  double tag = 0.0;
};

// x+ = x + step (from 1 at initialisation); y = scale x; a continuous z' = y.
class NamedCounter final : public Tagged, public Block {
 public:
  NamedCounter(std::string name, double scale, double step, double period)
      : Block(std::move(name)), scale_(scale), step_(step) {
    count_ = declare_discrete_state("count", Vector::Zero(1), StateLifetime::kPerTrial);
    y_ = &declare_output_port<&NamedCounter::calc_y>("y", 1, {}, "scale x",
                                                     OutputSources::kDiscreteState);
    declare_output_port<&NamedCounter::calc_z>("z", 1, {}, "z");
    declare_initialization_update<&NamedCounter::start>();
    declare_periodic_update<&NamedCounter::count>(period, 0.0, UpdateWrites::kInPlace);
    declare_continuous_state<&NamedCounter::calc_derivatives>(Vector::Zero(1));
  }

 private:
  void calc_y(const BlockContext& context, VectorRef y) const {
    y[0] = scale_ * count_.of(context.discrete_state())[0];
  }
  void calc_z(const BlockContext& context, VectorRef z) const { z = context.continuous_state(); }
  EventStatus start(BlockContext&, VectorRef next) const {
    count_.of(next)[0] = 1.0;
    return EventStatus::succeeded();
  }
  EventStatus count(BlockContext& context, VectorRef next) const {
    count_.of(next)[0] = count_.of(context.discrete_state())[0] + step_;
    return EventStatus::succeeded();
  }
  void calc_derivatives(const BlockContext& context, VectorRef z_dot) const {
    z_dot[0] = context.output(*y_)[0];
  }

  double scale_;
  double step_;
  StatePart count_;
  const OutputPort* y_ = nullptr;
};

// The same block written with lambdas.
class LambdaCounter final : public Block {
 public:
  LambdaCounter(std::string name, double scale, double step, double period)
      : Block(std::move(name)) {
    const StatePart count =
        declare_discrete_state("count", Vector::Zero(1), StateLifetime::kPerTrial);
    const OutputPort& y = declare_output_port(
        "y", 1,
        [count, scale](const BlockContext& context, VectorRef value) {
          value[0] = scale * count.of(context.discrete_state())[0];
        },
        {}, "scale x", OutputSources::kDiscreteState);
    declare_output_port(
        "z", 1, [](const BlockContext& context, VectorRef z) { z = context.continuous_state(); },
        {}, "z");
    declare_initialization_update([count](BlockContext&, VectorRef next) {
      count.of(next)[0] = 1.0;
      return EventStatus::succeeded();
    });
    declare_periodic_update(
        period, 0.0,
        [count, step](BlockContext& context, VectorRef next) {
          count.of(next)[0] = count.of(context.discrete_state())[0] + step;
          return EventStatus::succeeded();
        },
        UpdateWrites::kInPlace);
    declare_continuous_state(Vector::Zero(1), [&y](const BlockContext& context, VectorRef z_dot) {
      z_dot[0] = context.output(y)[0];
    });
  }
};

template <typename Counter>
Vector run(Schedule schedule) {
  DiagramBuilder builder("top");
  builder.emplace<Counter>("counter", 0.5, 0.25, 0.1);
  const auto diagram = builder.build();
  Simulator simulator(*diagram, SimulatorOptions{.schedule = schedule});
  simulator.advance_to(1.05);
  Vector values(2);
  values << simulator.context().discrete_states()[0], simulator.context().continuous_states()[0];
  return values;
}

TEST(NamedCalculations, RunOnBothSchedulesAsTheSameBlockWrittenWithLambdas) {
  const Vector expected = run<LambdaCounter>(Schedule::kInterpreted);
  EXPECT_EQ(expected[0], 1.0 + 11 * 0.25);  // initialised to 1, counted at 0, 0.1, ..., 1.0
  EXPECT_GT(expected[1], 0.0);
  for (const Schedule schedule : {Schedule::kCompiled, Schedule::kInterpreted}) {
    const Vector named = run<NamedCounter>(schedule);
    EXPECT_EQ(named[0], expected[0]);  // bit for bit
    EXPECT_EQ(named[1], expected[1]);
  }
}

TEST(NamedCalculations, AreCalledOnTheBlockTheyWereDeclaredOn) {
  // Two blocks of one class with different members: each call reads its own block's.
  DiagramBuilder builder("top");
  const auto& slow = builder.emplace<NamedCounter>("slow", 1.0, 1.0, 0.1);
  const auto& fast = builder.emplace<NamedCounter>("fast", 10.0, 1.0, 0.1);
  const auto diagram = builder.build();
  Simulator simulator(*diagram);
  simulator.advance_to(0.05);
  const Context& context = simulator.context();
  // Evaluated at t = 0, from the count of 1 the initialisation set.
  EXPECT_EQ(context.signal(slow.output_port("y"))[0], 1.0);
  EXPECT_EQ(context.signal(fast.output_port("y"))[0], 10.0);  // scaled by its own 10
}

TEST(Calculation, IsEmptyUntilBoundAndCallsWhatItWasGiven) {
  const OutputCalculation none = OutputCalculation::callable(nullptr);
  EXPECT_FALSE(none);
  double seen = 0.0;
  const UpdateCalculation update =
      UpdateCalculation::callable([&seen](BlockContext&, VectorRef next) {
        seen = next[0];
        return EventStatus::terminate("done");
      });
  ASSERT_TRUE(update);
  Vector next = Vector::Constant(1, 7.0);
  DiagramBuilder builder("top");
  builder.emplace<NamedCounter>("counter", 1.0, 1.0, 0.1);
  const auto diagram = builder.build();
  const auto context = diagram->create_context(0);
  BlockContext view(*context, diagram->leaves()[0]);
  EXPECT_STREQ(update(view, next).reason(), "done");
  EXPECT_EQ(seen, 7.0);
  // A copy calls the same callable, which the copies keep alive.
  const UpdateCalculation copy = update;
  next[0] = 8.0;
  copy(view, next);
  EXPECT_EQ(seen, 8.0);
}

}  // namespace
}  // namespace cbbg
