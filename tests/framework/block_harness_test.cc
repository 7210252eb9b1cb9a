// testing::BlockHarness: tick() fires exactly one event instant, the simulator's next, whatever
// the block's period, and stops halfway to the instant after it.

#include "cbbg/framework/block_harness.h"

#include <gtest/gtest.h>

#include "cbbg/framework/primitives/gain.h"
#include "cbbg/framework/primitives/pid_controller.h"

namespace cbbg {
namespace {

// An integrating PID of period `period`: I_{k+1} = I_k + period e_k, one sample per instant.
testing::BlockHarness<PidController> integrator(double period) {
  return testing::BlockHarness<PidController>("pid", PidController::Params{.ki = 1.0}, period);
}

TEST(BlockHarness, ATickOfAFiveMillisecondBlockFiresOneSample) {
  auto harness = integrator(0.005);
  harness.set_input("e", 1.0);
  for (int tick = 1; tick <= 3; ++tick) {
    harness.tick();
    EXPECT_DOUBLE_EQ(harness.state_part("integral")[0], 0.005 * tick) << "tick " << tick;
    EXPECT_EQ(harness.simulator().num_event_instants(), tick);
    // Halfway between the sample fired and the next.
    EXPECT_DOUBLE_EQ(harness.context().time(), 0.005 * (tick - 0.5)) << "tick " << tick;
  }
}

TEST(BlockHarness, ATickOfASlowBlockFiresItsNextSampleAlone) {
  auto harness = integrator(0.1);
  harness.set_input("e", 1.0);
  harness.tick();
  EXPECT_DOUBLE_EQ(harness.state_part("integral")[0], 0.1);
  harness.tick();
  EXPECT_DOUBLE_EQ(harness.state_part("integral")[0], 0.2);
  EXPECT_EQ(harness.simulator().num_event_instants(), 2);
  EXPECT_DOUBLE_EQ(harness.context().time(), 0.15);
}

TEST(BlockHarness, ATickOfAHundredthOfASecondBlockStopsWhereItDid) {
  auto harness = integrator(0.01);
  harness.set_input("e", 1.0);
  harness.tick();
  EXPECT_DOUBLE_EQ(harness.context().time(), 0.005);
  harness.tick();
  EXPECT_DOUBLE_EQ(harness.context().time(), 0.015);
  EXPECT_DOUBLE_EQ(harness.state_part("integral")[0], 0.02);
}

// A log of another period adds instants of its own: a tick fires the earliest of all.
TEST(BlockHarness, ALogsInstantsAreInstantsToo) {
  auto harness = integrator(0.005);
  harness.set_input("e", 1.0);
  const SignalLog& log = harness.simulator().add_log(harness.block().output_port("u"), 0.003);
  // The instants: 0 (both), 0.003 (the log), 0.005 (the PID), 0.006 (the log).
  harness.tick();
  EXPECT_DOUBLE_EQ(harness.state_part("integral")[0], 0.005);
  EXPECT_EQ(log.num_samples(), 1);
  harness.tick();
  EXPECT_DOUBLE_EQ(harness.state_part("integral")[0], 0.005);
  EXPECT_EQ(log.num_samples(), 2);
  harness.tick();
  EXPECT_DOUBLE_EQ(harness.state_part("integral")[0], 0.01);
  EXPECT_EQ(log.num_samples(), 2);
  EXPECT_EQ(harness.simulator().num_event_instants(), 3);
}

// A block with no periodic event has no instant to fire: a tick moves time by kPeriod.
TEST(BlockHarness, ATickOfABlockWithoutEventsMovesTimeOn) {
  testing::BlockHarness<Gain> harness("k", 2.0, 1);
  harness.set_input("u", 1.5);
  harness.tick();
  harness.tick();
  EXPECT_DOUBLE_EQ(harness.context().time(), 1.5 * testing::BlockHarness<Gain>::kPeriod);
  EXPECT_EQ(harness.scalar_output("y"), 3.0);
}

}  // namespace
}  // namespace cbbg
