// After initialisation, a tick of a diagram of every learning block allocates nothing.

#include <initializer_list>

#include <gtest/gtest.h>

#include "cbbg/blocks/actor.h"
#include "cbbg/blocks/boltzmann_sampler.h"
#include "cbbg/blocks/critic.h"
#include "cbbg/blocks/entropy.h"
#include "cbbg/blocks/failure_detector.h"
#include "cbbg/blocks/lqr_supervisor.h"
#include "cbbg/blocks/mixer.h"
#include "cbbg/blocks/normaliser.h"
#include "cbbg/blocks/omega_schedule.h"
#include "cbbg/blocks/pd_supervisor.h"
#include "cbbg/blocks/rbf_features.h"
#include "cbbg/blocks/reward.h"
#include "cbbg/blocks/sensors.h"
#include "cbbg/blocks/tropism.h"
#include "cbbg/framework/diagram_builder.h"
#include "cbbg/framework/primitives/constant_source.h"
#include "cbbg/framework/simulator.h"
#include "cbbg/plant/plant_ports.h"
#include "tests/support/allocation_counter.h"

namespace cbbg::blocks {
namespace {

constexpr double kPeriod = 0.01;

TEST(BlocksAllocation, ATickOfEveryLearningBlockAllocatesNothing) {
  DiagramBuilder builder("cbbg");
  Vector plant_state = Vector::Zero(plant::kStateSize);
  plant_state[plant::kThetaB] = 0.1744;
  plant_state[plant::kThetaBDot] = -0.3;
  const auto& robot = builder.emplace<ConstantSource>("plant", plant_state);
  SensorsParams noisy;
  noisy.noise_std.fill(0.01);
  noisy.quantisation.fill(1e-4);
  const auto& sensors = builder.emplace<Sensors>("sensors", noisy, kPeriod);
  const auto& normaliser = builder.emplace<Normaliser>("normaliser", NormaliserParams{});
  const auto& rbf = builder.emplace<RbfFeatures>("rbf", RbfParams{});
  const auto& failure =
      builder.emplace<FailureDetector>("failure", FailureDetectorParams{}, kPeriod);
  const auto& reward = builder.emplace<Reward>("reward", RewardParams{}, kPeriod);
  const auto& critic =
      builder.emplace<Critic>("critic", rbf.num_features(), CriticParams{}, kPeriod);
  const auto& actor = builder.emplace<Actor>("actor", rbf.num_features(), ActorParams{}, kPeriod);
  const auto& supervisor = builder.emplace<PdSupervisor>("supervisor", PdSupervisorParams{});
  const auto& lqr =
      builder.emplace<LqrSupervisor>("lqr", plant::RobotParams{}, LqrSupervisorParams{});
  const auto& tropism = builder.emplace<Tropism>("tropism", TropismParams{});
  const auto& sampler = builder.emplace<BoltzmannSampler>("sampler", SamplerParams{}, kPeriod);
  const auto& omega = builder.emplace<OmegaSchedule>("omega", OmegaParams{}, kPeriod);
  const auto& mixer = builder.emplace<Mixer>("mixer");
  const auto& entropy = builder.emplace<Entropy>("entropy", EntropyParams{});

  builder.connect(robot, "y", sensors, "plant_state");
  for (const Block* reader :
       std::initializer_list<const Block*>{&normaliser, &failure, &reward, &supervisor, &lqr}) {
    builder.connect(sensors, "measured", *reader, "measured");
  }
  builder.connect(normaliser, "x", rbf, "x");
  builder.connect(rbf, "features", critic, "features");
  builder.connect(rbf, "features", actor, "features");
  builder.connect(failure, "failed", critic, "failed");
  builder.connect(failure, "failed", reward, "failed");
  builder.connect(reward, "reward", critic, "reward");
  builder.connect(critic, "value", tropism, "value");
  builder.connect(critic, "td_error", actor, "td_error");
  builder.connect(tropism, "temperature", sampler, "temperature");
  builder.connect(tropism, "temperature", entropy, "temperature");
  builder.connect(actor, "actor_action", sampler, "actor_action");
  builder.connect(sampler, "exploration_action", actor, "exploration_action");
  builder.connect(sampler, "exploration_action", mixer, "exploration_action");
  builder.connect(supervisor, "action", actor, "supervisor_action");
  builder.connect(supervisor, "action", mixer, "supervisor_action");
  builder.connect(omega, "omega", actor, "omega");
  builder.connect(omega, "omega", mixer, "omega");
  const auto diagram = builder.build();
  Simulator simulator(*diagram, SimulatorOptions{}, 1);
  simulator.advance_to(0.105);  // initialisation and the first ticks
  ASSERT_FALSE(simulator.advance_to(0.105).terminated);

  const long long before = cbbg::testing::allocation_count();
  const auto status = simulator.advance_to(10.005);  // 990 more ticks
  const long long during_ticks = cbbg::testing::allocation_count() - before;
  ASSERT_FALSE(status.terminated);
  EXPECT_EQ(during_ticks, 0);

  // The learning did happen, and a new trial's reset allocates nothing either.
  EXPECT_NE(critic.weights(simulator.context()).norm(), 0.0);
  EXPECT_NE(actor.weights(simulator.context()).norm(), 0.0);
  const long long before_reset = cbbg::testing::allocation_count();
  simulator.context().reset_trial_state();
  EXPECT_EQ(cbbg::testing::allocation_count() - before_reset, 0);
}

}  // namespace
}  // namespace cbbg::blocks
