// A tick of the analytic plant under the PD law allocates nothing on the heap after
// initialisation. This executable replaces the global allocation functions to count calls.
// (The Simbody plant cannot promise this: Simbody's integrator allocates inside each step.)

#include <atomic>
#include <cstdlib>
#include <new>

#include <gtest/gtest.h>

#include "tests/plant/plant_rigs.h"

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

namespace cbbg::plant::testing {
namespace {

TEST(AnalyticPlantAllocation, ATickAllocatesNothingAfterInitialisation) {
  const RobotParams p;
  const Rig rig = make_rig(PlantKind::kAnalytic, p, kDefaultInitialPitch, Control::kPd);
  auto simulator = make_simulator(rig, p);
  simulator->advance_to(0.05);

  const long before = allocations.load();
  simulator->advance_to(5.0);
  EXPECT_EQ(allocations.load() - before, 0) << "heap allocations in 495 ticks";
  // A reset between trials allocates nothing either.
  const long before_reset = allocations.load();
  rig.reset(simulator->context(), kDefaultInitialPitch);
  EXPECT_EQ(allocations.load() - before_reset, 0);
}

TEST(AnalyticPlantAllocation, TheCounterSeesAllocations) {
  const long before = allocations.load();
  int* volatile observed = new int(3);
  delete observed;
  EXPECT_EQ(allocations.load() - before, 1);
}

}  // namespace
}  // namespace cbbg::plant::testing
