#include "cbbg/blocks/mixer.h"

#include <gtest/gtest.h>

#include "cbbg/framework/block_harness.h"

namespace cbbg::blocks {
namespace {

using Harness = testing::BlockHarness<Mixer>;

double mix(Harness& harness, double exploration, double supervisor, double omega) {
  harness.set_input("exploration_action", exploration);
  harness.set_input("supervisor_action", supervisor);
  harness.set_input("omega", omega);
  return harness.scalar_output("action");
}

TEST(Mixer, BlendsExplorationAndSupervisionByOmega) {
  Harness harness("mixer");
  EXPECT_EQ(mix(harness, 4.0, -2.0, 0.25), -0.5);  // 0.25 (4) + 0.75 (-2) = 1 - 1.5
  EXPECT_EQ(mix(harness, 4.0, -2.0, 0.5), 1.0);
}

TEST(Mixer, OmegaZeroGivesTheSupervisorAndOmegaOneTheExploration) {
  Harness harness("mixer");
  EXPECT_EQ(mix(harness, 4.0, -2.0, 0.0), -2.0);
  EXPECT_EQ(mix(harness, 4.0, -2.0, 1.0), 4.0);
  EXPECT_EQ(mix(harness, 12.0, 7.0, 1.0), 12.0);  // no saturation here: the plant saturates
}

}  // namespace
}  // namespace cbbg::blocks
