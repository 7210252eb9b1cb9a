// Every block's topology, as its port table documents it: port names and sizes, which inputs
// each output reads directly (direct feedthrough, what breaks or makes an algebraic loop),
// and the named parts of its discrete state with their lifetimes.

#include <functional>
#include <memory>
#include <ostream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "cbbg/blocks/actor.h"
#include "cbbg/blocks/boltzmann_sampler.h"
#include "cbbg/blocks/critic.h"
#include "cbbg/blocks/entropy.h"
#include "cbbg/blocks/external_push.h"
#include "cbbg/blocks/failure_detector.h"
#include "cbbg/blocks/gaussian_exploration.h"
#include "cbbg/blocks/lqr_supervisor.h"
#include "cbbg/blocks/mixer.h"
#include "cbbg/blocks/normaliser.h"
#include "cbbg/blocks/omega_schedule.h"
#include "cbbg/blocks/ou_exploration.h"
#include "cbbg/blocks/pd_supervisor.h"
#include "cbbg/blocks/quadratic_reward.h"
#include "cbbg/blocks/rbf_features.h"
#include "cbbg/blocks/reward.h"
#include "cbbg/blocks/sensors.h"
#include "cbbg/blocks/torque_push.h"
#include "cbbg/blocks/tropism.h"

namespace cbbg::blocks {
namespace {

constexpr double kPeriod = 0.01;
constexpr auto kTrial = StateLifetime::kPerTrial;
constexpr auto kKept = StateLifetime::kPersistent;

struct PortShape {
  std::string name;
  int size;
};
struct OutputShape {
  std::string name;
  int size;
  std::vector<std::string> reads;  // input names, in declaration order
};
struct PartShape {
  std::string name;
  int size;
  StateLifetime lifetime;
};
struct Topology {
  std::string block;
  std::function<std::unique_ptr<Block>()> make;
  std::vector<PortShape> inputs;
  std::vector<OutputShape> outputs;
  std::vector<PartShape> state;
};

std::vector<Topology> topologies() {
  const int n = 49;  // the 7 x 7 RBF grid
  return {
      {"Actor",
       [] { return std::make_unique<Actor>("actor", 49, ActorParams{}, kPeriod); },
       {{"features", n},
        {"td_error", 1},
        {"supervisor_action", 1},
        {"exploration_action", 1},
        {"omega", 1}},
       {{"actor_action", 1, {"features"}}},  // never the TD error: no loop through the critic
       {{"weights", n, kKept},
        {"previous_features", n, kTrial},
        {"previous_actions", 4, kTrial},
        {"has_previous", 1, kTrial}}},
      {"BoltzmannSampler",
       [] { return std::make_unique<BoltzmannSampler>("sampler", SamplerParams{}, kPeriod); },
       {{"actor_action", 1}, {"temperature", 1}},
       {{"exploration_action", 1, {"actor_action", "temperature"}}},
       {{"noise", 1, kTrial}}},
      {"Critic",
       [] { return std::make_unique<Critic>("critic", 49, CriticParams{}, kPeriod); },
       {{"features", n}, {"reward", 1}, {"failed", 1}},
       {{"value", 1, {"features"}}, {"td_error", 1, {"features", "reward", "failed"}}},
       {{"weights", n, kKept},
        {"trace", n, kTrial},
        {"previous_features", n, kTrial},
        {"has_previous", 1, kTrial}}},
      {"Entropy",
       [] { return std::make_unique<Entropy>("entropy", EntropyParams{}); },
       {{"temperature", 1}},
       {{"entropy", 1, {"temperature"}}},
       {}},
      {"FailureDetector",
       [] {
         return std::make_unique<FailureDetector>("failure", FailureDetectorParams{}, kPeriod);
       },
       {{"measured", 6}},
       {{"failed", 1, {"measured"}}},
       {}},
      {"GaussianExploration",
       [] {
         return std::make_unique<GaussianExploration>("sampler", ExplorationParams{}, kPeriod);
       },
       {{"actor_action", 1}},
       {{"exploration_action", 1, {"actor_action"}}},  // no temperature
       {{"noise", 1, kTrial}, {"elapsed", 1, kKept}}},
      {"LqrSupervisor",
       [] {
         return std::make_unique<LqrSupervisor>("supervisor", plant::RobotParams{},
                                                LqrSupervisorParams{});
       },
       {{"measured", 6}},
       {{"action", 1, {"measured"}}},
       {}},
      {"Mixer",
       [] { return std::make_unique<Mixer>("mixer"); },
       {{"exploration_action", 1}, {"supervisor_action", 1}, {"omega", 1}},
       {{"action", 1, {"exploration_action", "supervisor_action", "omega"}}},
       {}},
      {"Normaliser",
       [] { return std::make_unique<Normaliser>("normaliser", NormaliserParams{}); },
       {{"measured", 6}},
       {{"x", 2, {"measured"}}},
       {}},
      {"OmegaSchedule",
       [] { return std::make_unique<OmegaSchedule>("omega", OmegaParams{}, kPeriod); },
       {},
       {{"omega", 1, {}}},
       {{"ticks", 1, kKept}}},
      {"OuExploration",
       [] { return std::make_unique<OuExploration>("sampler", ExplorationParams{}, kPeriod); },
       {{"actor_action", 1}},
       {{"exploration_action", 1, {"actor_action"}}},
       {{"noise", 1, kTrial}}},
      {"PdSupervisor",
       [] { return std::make_unique<PdSupervisor>("supervisor", PdSupervisorParams{}); },
       {{"measured", 6}},
       {{"action", 1, {"measured"}}},
       {}},
      {"QuadraticReward",
       [] { return std::make_unique<QuadraticReward>("reward", RewardParams{}, kPeriod); },
       {{"measured", 6}, {"failed", 1}},
       {{"reward", 1, {"measured", "failed"}}},
       {}},
      {"RbfFeatures",
       [] { return std::make_unique<RbfFeatures>("features", RbfParams{}); },
       {{"x", 2}},
       {{"features", n, {"x"}}},
       {}},
      {"ExternalPush",
       [] {
         return std::make_unique<ExternalPush>("push", PushParams{0.0, 0.0, 0.1, 20.0, 1.0},
                                               kPeriod);
       },
       {},
       {{"disturbance", 2, {}}},
       {{"push", 2, kTrial}}},
      {"Reward",
       [] { return std::make_unique<Reward>("reward", RewardParams{}, kPeriod); },
       {{"measured", 6}, {"failed", 1}},
       {{"reward", 1, {"measured", "failed"}}},
       {{"previous_surface", 1, kTrial}, {"has_previous", 1, kTrial}}},
      {"Sensors",
       [] { return std::make_unique<Sensors>("sensors", SensorsParams{}, kPeriod); },
       {{"plant_state", 10}},
       {{"measured", 6, {"plant_state"}}},
       {{"noise", 6, kTrial}}},
      {"CriticTd0",
       [] {
         CriticParams td0;
         td0.kind = CriticKind::kTd0;
         return std::make_unique<Critic>("critic", 49, td0, kPeriod);
       },
       {{"features", n}, {"reward", 1}, {"failed", 1}},
       {{"value", 1, {"features"}}, {"td_error", 1, {"features", "reward", "failed"}}},
       {{"weights", n, kKept}, {"previous_features", n, kTrial}, {"has_previous", 1, kTrial}}},
      {"TorquePush",
       [] {
         return std::make_unique<TorquePush>("push", PushParams{0.0, 1.0, 0.1}, kPeriod);
       },
       {{"action", 1}},
       {{"torque", 1, {"action"}}},
       {{"push", 1, kTrial}}},
      {"Tropism",
       [] { return std::make_unique<Tropism>("tropism", TropismParams{}); },
       {{"value", 1}},
       {{"temperature", 1, {"value"}}},
       {}},
  };
}

// gtest prints a parameter by this: the block's name, not its bytes.
void PrintTo(const Topology& topology, std::ostream* out) { *out << topology.block; }

class BlockTopology : public ::testing::TestWithParam<Topology> {};

TEST_P(BlockTopology, PortsReadsAndStateAreAsDocumented) {
  const Topology& expected = GetParam();
  const std::unique_ptr<Block> block = expected.make();
  ASSERT_EQ(block->num_input_ports(), static_cast<int>(expected.inputs.size()));
  for (int i = 0; i < block->num_input_ports(); ++i) {
    const auto& want = expected.inputs[static_cast<size_t>(i)];
    EXPECT_EQ(block->input_port(i).name(), want.name) << "input " << i;
    EXPECT_EQ(block->input_port(i).size(), want.size) << want.name;
  }
  ASSERT_EQ(block->num_output_ports(), static_cast<int>(expected.outputs.size()));
  for (int o = 0; o < block->num_output_ports(); ++o) {
    const auto& want = expected.outputs[static_cast<size_t>(o)];
    EXPECT_EQ(block->output_port(o).name(), want.name) << "output " << o;
    EXPECT_EQ(block->output_port(o).size(), want.size) << want.name;
    std::vector<std::string> reads;
    for (const int input : block->output_reads(o)) {
      reads.push_back(block->input_port(input).name());
    }
    EXPECT_EQ(reads, want.reads) << want.name << " reads";
  }
  const auto& parts = block->discrete_state_parts();
  ASSERT_EQ(parts.size(), expected.state.size());
  int offset = 0;
  for (std::size_t p = 0; p < parts.size(); ++p) {
    EXPECT_EQ(parts[p].name, expected.state[p].name);
    EXPECT_EQ(parts[p].size, expected.state[p].size) << parts[p].name;
    EXPECT_EQ(parts[p].lifetime, expected.state[p].lifetime) << parts[p].name;
    EXPECT_EQ(parts[p].offset, offset) << parts[p].name;  // back to back, in order
    offset += parts[p].size;
  }
  EXPECT_EQ(block->initial_discrete_state().size(), offset);
}

INSTANTIATE_TEST_SUITE_P(EveryBlock, BlockTopology, ::testing::ValuesIn(topologies()),
                         [](const ::testing::TestParamInfo<Topology>& param) {
                           return param.param.block;
                         });

}  // namespace
}  // namespace cbbg::blocks
