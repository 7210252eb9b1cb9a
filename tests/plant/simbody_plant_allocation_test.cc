// What the Simbody plant's own code allocates per tick: nothing. Setting the held torques
// and reading the state back, the plant's part of every tick, allocate nothing on the heap;
// the allocations left in a step are Simbody's own, inside its integrator (the plant
// benchmark counts them per configuration). This executable counts calls of the C allocator
// (tests/support/allocation_counter.h).

#include <memory>

#include <gtest/gtest.h>

#include "cbbg/plant/multibody_robot.h"
#include "cbbg/plant/plant_ports.h"
#include "tests/support/allocation_counter.h"

namespace cbbg::plant {
namespace {

TEST(SimbodyPlantAllocation, TheTorqueAndStateExchangeAllocateNothing) {
  for (const SimbodyModel model : {SimbodyModel::kRollingBase, SimbodyModel::kNoSlipConstraints}) {
    RobotParams params;
    params.simbody_model = model;
    MultibodyRobotRun run(std::make_shared<const MultibodyRobot>(params));
    Eigen::VectorXd state = Eigen::VectorXd::Zero(kStateSize);
    state[kThetaB] = kDefaultInitialPitch;
    run.set_state(0.0, state);
    run.set_torque(1.0, 1.0);
    run.advance_to(0.01);

    const long long before = cbbg::testing::allocation_count();
    for (int tick = 0; tick < 100; ++tick) {
      run.set_torque(0.01 * tick, -0.01 * tick);
      run.get_state(state);
    }
    EXPECT_EQ(cbbg::testing::allocation_count() - before, 0) << "model " << static_cast<int>(model);
    EXPECT_GT(run.time(), 0.0);
  }
}

}  // namespace
}  // namespace cbbg::plant
