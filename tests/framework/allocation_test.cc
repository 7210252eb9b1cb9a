// One simulator tick allocates nothing on the heap after initialisation. This executable
// replaces the global allocation functions to count calls.

#include <atomic>
#include <cstdlib>
#include <new>

#include <gtest/gtest.h>

#include "framework/diagram_builder.h"
#include "framework/primitives/constant_source.h"
#include "framework/primitives/gain.h"
#include "framework/primitives/zero_order_hold.h"
#include "framework/simulator.h"
#include "tests/framework/test_blocks.h"

namespace {
std::atomic<long> allocations{0};
}  // namespace

void* operator new(std::size_t size) {
  ++allocations;
  if (void* memory = std::malloc(size == 0 ? 1 : size)) return memory;
  throw std::bad_alloc();
}
void* operator new[](std::size_t size) { return operator new(size); }
void operator delete(void* memory) noexcept { std::free(memory); }
void operator delete[](void* memory) noexcept { std::free(memory); }
void operator delete(void* memory, std::size_t) noexcept { std::free(memory); }
void operator delete[](void* memory, std::size_t) noexcept { std::free(memory); }

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

  const long before = allocations.load();
  simulator.advance_to(5.0);
  const long during = allocations.load() - before;
  EXPECT_EQ(during, 0) << "heap allocations in 495 ticks";
  EXPECT_EQ(simulator.num_event_instants(), 500);
  EXPECT_NEAR(simulator.context().continuous_state(integral)[0], 0.5 * 5.0, 1e-9);
  EXPECT_NEAR(simulator.context().continuous_state(self)[0], 0.5 * 5.0, 1e-9);
}

TEST(Allocation, TheCounterSeesAllocations) {
  // The test above could not fail if counting were broken.
  const long before = allocations.load();
  int* volatile observed = new int(3);  // volatile: the compiler may not elide the pair
  delete observed;
  EXPECT_EQ(allocations.load() - before, 1);
}

}  // namespace
}  // namespace cbbg
