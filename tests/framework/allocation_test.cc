// One simulator tick allocates nothing on the heap after initialisation. This executable
// counts calls of the C allocator (tests/support/allocation_counter.h), which catches Eigen
// and operator new alike.

#include <gtest/gtest.h>

#include "cbbg/framework/diagram_builder.h"
#include "cbbg/framework/primitives/constant_source.h"
#include "cbbg/framework/primitives/gain.h"
#include "cbbg/framework/primitives/zero_order_hold.h"
#include "cbbg/framework/simulator.h"
#include "tests/framework/test_blocks.h"
#include "tests/support/allocation_counter.h"

namespace cbbg {
namespace {

TEST(Allocation, ASimulatorTickAllocatesNothingAfterInitialisation) {
  // Source -> gain chain -> hold -> integrator, with a nested diagram, a self-integrating
  // block, a terminating counter that never fires, and a log with memory reserved.
  DiagramBuilder inner_builder("inner");
  auto& inner_gain = inner_builder.emplace<Gain>("gain", 0.5, 1);
  inner_builder.export_input(inner_gain.input_port("u"));
  inner_builder.export_output(inner_gain.output_port("y"));

  DiagramBuilder builder("top");
  auto& source = builder.emplace<ConstantSource>("source", Vector::Ones(1));
  auto& inner = builder.add(inner_builder.build());
  auto& hold = builder.emplace<ZeroOrderHold>("hold", 1, 0.01);
  auto& integral = builder.emplace<testing::Integrator>("integral");
  auto& self = builder.emplace<testing::SelfIntegrator>("self");
  builder.emplace<testing::Counter>("counter", 0.01, 0.0, 1000000);
  builder.connect(source, "y", inner, "u");
  builder.connect(inner, "y", hold, "u");
  builder.connect(hold, "y", integral, "u");
  builder.connect(hold, "y", self, "u");
  auto diagram = builder.build();

  Simulator simulator(*diagram);
  SignalLog& log = simulator.add_log(integral.output_port("y"), 0.01);
  log.reserve(1000);
  simulator.advance_to(0.05);  // initialisation and the first instants

  const long long before = testing::allocation_count();
  simulator.advance_to(5.0);
  const long long during = testing::allocation_count() - before;
  EXPECT_EQ(during, 0) << "heap allocations in 495 ticks";
  EXPECT_EQ(simulator.num_event_instants(), 500);
  EXPECT_NEAR(simulator.context().continuous_state(integral)[0], 0.5 * 5.0, 1e-9);
  EXPECT_NEAR(simulator.context().continuous_state(self)[0], 0.5 * 5.0, 1e-9);
}

TEST(Allocation, TheCounterSeesOperatorNewAndEigen) {
  // The test above could not fail if counting were broken.
  const long long before = testing::allocation_count();
  int* volatile observed = new int(3);  // volatile: the compiler may not elide the pair
  delete observed;
  EXPECT_EQ(testing::allocation_count() - before, 1);
  const Vector grown = Vector::Ones(16) * 2.0;  // Eigen allocates with std::malloc
  EXPECT_EQ(testing::allocation_count() - before, 2);
  EXPECT_EQ(grown.sum(), 32.0);
}

}  // namespace
}  // namespace cbbg
