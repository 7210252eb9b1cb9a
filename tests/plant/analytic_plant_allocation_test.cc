// A tick of the analytic plant under the PD law allocates nothing on the heap after
// initialisation. This executable counts calls of the C allocator
// (tests/support/allocation_counter.h). (The Simbody plant cannot promise this: Simbody's
// integrator allocates inside each step.)

#include <gtest/gtest.h>

#include "tests/plant/plant_rigs.h"
#include "tests/support/allocation_counter.h"

namespace cbbg::plant::testing {
namespace {

TEST(AnalyticPlantAllocation, ATickAllocatesNothingAfterInitialisation) {
  const RobotParams p;
  const Rig rig = make_rig(PlantKind::kAnalytic, p, kDefaultInitialPitch, Control::kPd);
  auto simulator = make_simulator(rig, p);
  simulator->advance_to(0.05);

  const long long before = cbbg::testing::allocation_count();
  simulator->advance_to(5.0);
  EXPECT_EQ(cbbg::testing::allocation_count() - before, 0) << "heap allocations in 495 ticks";
  // A reset between trials allocates nothing either.
  const long long before_reset = cbbg::testing::allocation_count();
  rig.reset(simulator->context(), kDefaultInitialPitch);
  EXPECT_EQ(cbbg::testing::allocation_count() - before_reset, 0);
}

}  // namespace
}  // namespace cbbg::plant::testing
