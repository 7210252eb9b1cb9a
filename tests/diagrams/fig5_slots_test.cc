// Every block of the paper's Fig. 5 as a slot: a user's block fills each (the controller's
// critic, actor, exploration, tropism, entropy and mixer; the task's sensors, failure
// detector and reward), a block that does not fit is refused in one line naming the slot,
// the port and what is expected, and the drawing shows the user's type in its place. Then
// what the slots promise: the recorded reward is the one the critic receives, a learner
// with two learnt parts is kept bit for bit, and exploration keeps common random numbers.

#include <cmath>
#include <functional>
#include <memory>
#include <ostream>
#include <string>
#include <utility>
#include <vector>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "cbbg/blocks/learner.h"
#include "cbbg/blocks/measured_signals.h"
#include "cbbg/diagrams/presets.h"
#include "cbbg/experiments/learnt_weights.h"
#include "cbbg/experiments/trial_runner.h"
#include "cbbg/framework/block_context.h"
#include "cbbg/framework/diagram_builder.h"
#include "cbbg/framework/graphviz.h"
#include "cbbg/store/weights_file.h"
#include "tests/diagrams/slot_fixtures.h"
#include "tests/support/scratch_directory.h"

namespace cbbg::diagrams {
namespace {

using ::testing::HasSubstr;
using testing::quick_parameters;
using ::testing::ThrowsMessage;

using Ports = std::vector<std::pair<std::string, int>>;

// A block of the given ports whose outputs are constant: the shape of a user's block, and
// of a wrong one.
class PortsBlock : public Block {
 public:
  PortsBlock(std::string name, const Ports& inputs, const Ports& outputs, double value = 0.0)
      : Block(std::move(name)) {
    std::vector<const InputPort*> reads;
    for (const auto& [port, size] : inputs) reads.push_back(&declare_input_port(port, size));
    for (const auto& [port, size] : outputs) {
      declare_output_port(
          port, size, [value](const BlockContext&, VectorRef y) { y.setConstant(value); }, reads);
    }
  }
};

// The user's types, one per slot, so the drawing can show which is where.
#define CBBG_USER_BLOCK(Type)            \
  class Type final : public PortsBlock { \
   public:                               \
    using PortsBlock::PortsBlock;        \
  };
CBBG_USER_BLOCK(UserCritic)
CBBG_USER_BLOCK(UserActor)
CBBG_USER_BLOCK(UserExploration)
CBBG_USER_BLOCK(UserTropism)
CBBG_USER_BLOCK(UserEntropy)
CBBG_USER_BLOCK(UserMixer)
CBBG_USER_BLOCK(UserFailure)
CBBG_USER_BLOCK(UserReward)
#undef CBBG_USER_BLOCK

// Sensors of the user's: the plant's pitch and wheel signals, noiseless.
class UserSensors final : public Block {
 public:
  UserSensors(std::string name, const plant::SignalIndex& signals, int state_size)
      : Block(std::move(name)) {
    const InputPort& state = declare_input_port("plant_state", state_size);
    const std::vector<int> picks{signals.pitch,           signals.pitch_rate,
                                 signals.wheel_left,      signals.wheel_right,
                                 signals.wheel_left_rate, signals.wheel_right_rate};
    declare_output_port("measured", blocks::kMeasuredSize,
                        [&state, picks](const BlockContext& context, VectorRef y) {
                          for (int i = 0; i < blocks::kMeasuredSize; ++i)
                            y[i] = context.input(state)[picks[i]];
                        },
                        {&state});
  }
};

// One slot: how a test fills it with a factory, and the path of its block in the loop.
struct Slot {
  std::string name;
  std::string path;  // under the loop's root
  std::function<void(ControllerOptions&, ClosedLoopOptions&, BlockFactory)> fill;
};

std::vector<Slot> slots() {
  auto controller = [](BlockFactory ControllerSlots::*slot) {
    return [slot](ControllerOptions& options, ClosedLoopOptions&, BlockFactory factory) {
      options.slots.*slot = std::move(factory);
    };
  };
  auto task = [](BlockFactory TaskSlots::*slot) {
    return [slot](ControllerOptions&, ClosedLoopOptions& loop, BlockFactory factory) {
      loop.slots.*slot = std::move(factory);
    };
  };
  const std::string bg = "controller/basal_ganglia/";
  return {{"critic", bg + "critic", controller(&ControllerSlots::critic)},
          {"actor", bg + "actor", controller(&ControllerSlots::actor)},
          {"exploration", bg + "sampler", controller(&ControllerSlots::exploration)},
          {"tropism", bg + "tropism", controller(&ControllerSlots::tropism)},
          {"entropy", bg + "entropy", controller(&ControllerSlots::entropy)},
          {"mixer", "controller/mixer", controller(&ControllerSlots::mixer)},
          {"sensors", "sensors", task(&TaskSlots::sensors)},
          {"failure", "failure", task(&TaskSlots::failure)},
          {"reward", "reward", task(&TaskSlots::reward)}};
}

template <class Type>
BlockFactory ports_block(Ports inputs, Ports outputs, double value = 0.0) {
  return [=](const SlotRequest& request) {
    return std::make_shared<Type>(request.name, inputs, outputs, value);
  };
}

// The user's block that fits each slot (the features are the paper's 49).
BlockFactory user_block(const std::string& slot) {
  if (slot == "critic") {
    return ports_block<UserCritic>({{"features", 49}}, {{"value", 1}, {"td_error", 1}});
  }
  if (slot == "actor")
    return ports_block<UserActor>({{"features", 49}}, {{"actor_action", 1}}, 0.5);
  if (slot == "exploration") {
    return ports_block<UserExploration>({{"actor_action", 1}}, {{"exploration_action", 1}});
  }
  if (slot == "tropism") return ports_block<UserTropism>({{"value", 1}}, {{"temperature", 1}}, 1.0);
  if (slot == "entropy") return ports_block<UserEntropy>({{"temperature", 1}}, {{"entropy", 1}});
  if (slot == "mixer") return ports_block<UserMixer>({{"supervisor_action", 1}}, {{"action", 1}});
  if (slot == "failure") return ports_block<UserFailure>({{"measured", 6}}, {{"failed", 1}});
  if (slot == "reward") return ports_block<UserReward>({{"failed", 1}}, {{"reward", 1}}, -0.25);
  return [](const SlotRequest& request) {
    return std::make_shared<UserSensors>(request.name, *request.signals, request.plant_state_size);
  };
}

// The cbbg preset's loop with `factory` in `slot`.
ClosedLoop loop_with(const Slot& slot, BlockFactory factory) {
  ControllerOptions options = preset("cbbg").options;
  ClosedLoopOptions loop;
  slot.fill(options, loop, std::move(factory));
  return closed_loop_factory("cbbg_mine", options, loop)(quick_parameters());
}

const Block& block_at(const Diagram& root, const std::string& path) {
  const Block* block = &root;
  std::size_t start = 0;
  while (start <= path.size()) {
    const std::size_t end = std::min(path.find('/', start), path.size());
    block = &static_cast<const Diagram&>(*block).block(path.substr(start, end - start));
    start = end + 1;
  }
  return *block;
}

// gtest names a case by these (not by the object's bytes).
void PrintTo(const Slot& slot, std::ostream* out) { *out << slot.name; }

class EverySlot : public ::testing::TestWithParam<Slot> {};

TEST_P(EverySlot, TakesAUsersBlockDrawnWithItsType) {
  const Slot& slot = GetParam();
  const ClosedLoop loop = loop_with(slot, user_block(slot.name));
  const Block& block = block_at(*loop.diagram, slot.path);
  EXPECT_THAT(block.type_name(), HasSubstr("User"));
  // The drawing shows the user's type in the slot's place.
  const std::string leaf = slot.path.substr(slot.path.rfind('/') + 1);
  EXPECT_THAT(to_dot(*loop.diagram),
              HasSubstr("<b>" + leaf + "</b><br/><font point-size=\"10\">" + block.type_name()));
  experiments::TrialRunner runner(loop, 1, 0.01);
  EXPECT_GT(runner.run_trial(0.1744, 0.5).steps, 0);
}

INSTANTIATE_TEST_SUITE_P(Fig5, EverySlot, ::testing::ValuesIn(slots()),
                         [](const auto& test) { return test.param.name; });

// A block that does not fit each slot, and the line that refuses it.
struct Misfit {
  std::string slot;
  BlockFactory block;
  std::string message;
};

std::vector<Misfit> misfits() {
  return {
      {"critic", ports_block<UserCritic>({{"features", 49}}, {{"values", 1}, {"td_error", 1}}),
       "critic slot: the block 'critic' has no output \"value\"; it must have outputs \"value\" "
       "(1), \"td_error\" (1)"},
      {"actor", ports_block<UserActor>({{"features", 3}}, {{"actor_action", 1}}),
       "actor slot: the block 'actor' has an input \"features\" of size 3; the slot feeds it 49"},
      {"exploration", ports_block<UserExploration>({{"actor_action", 1}}, {{"action", 1}}),
       "exploration slot: the block 'sampler' has no output \"exploration_action\"; it must have "
       "outputs \"exploration_action\" (1)"},
      {"tropism", ports_block<UserTropism>({{"values", 1}}, {{"temperature", 1}}),
       "tropism slot: the block 'tropism' has an input \"values\" the slot does not feed; it "
       "feeds \"value\" (1)"},
      {"entropy", ports_block<UserEntropy>({{"temperature", 1}}, {{"entropy", 2}}),
       "entropy slot: the block 'entropy' has an output \"entropy\" of size 2; the slot reads 1"},
      {"mixer", ports_block<UserMixer>({{"measured", 6}}, {{"action", 1}}),
       "mixer slot: the block 'mixer' has an input \"measured\" the slot does not feed; it feeds "
       "\"exploration_action\" (1), \"supervisor_action\" (1), \"omega\" (1)"},
      {"sensors", ports_block<UserFailure>({{"plant_state", 3}}, {{"measured", 6}}),
       "sensors slot: the block 'sensors' has an input \"plant_state\" of size 3; the slot feeds "
       "it 10"},
      {"failure", ports_block<UserFailure>({{"measured", 6}}, {{"fail", 1}}),
       "failure slot: the block 'failure' has no output \"failed\"; it must have outputs "
       "\"failed\" (1)"},
      {"reward", ports_block<UserReward>({{"measured", 5}}, {{"reward", 1}}),
       "reward slot: the block 'reward' has an input \"measured\" of size 5; the slot feeds it 6"},
  };
}

void PrintTo(const Misfit& misfit, std::ostream* out) { *out << misfit.slot; }

class EverySlotRefuses : public ::testing::TestWithParam<Misfit> {};

TEST_P(EverySlotRefuses, ABlockThatDoesNotFitNamingTheSlotAndThePort) {
  const Misfit& misfit = GetParam();
  for (const Slot& slot : slots()) {
    if (slot.name != misfit.slot) continue;
    EXPECT_THAT([&] { loop_with(slot, misfit.block); },
                ThrowsMessage<std::invalid_argument>(misfit.message));
    EXPECT_THAT([&] { loop_with(slot, [](const SlotRequest&) { return nullptr; }); },
                ThrowsMessage<std::invalid_argument>("the factory of the " + slot.name +
                                                     " slot returned null"));
  }
}

INSTANTIATE_TEST_SUITE_P(Fig5, EverySlotRefuses, ::testing::ValuesIn(misfits()),
                         [](const auto& test) { return test.param.slot; });

// A critic of the user's whose TD error is the reward it received, tick by tick.
class RewardEchoCritic final : public Block {
 public:
  RewardEchoCritic(std::string name, int num_features) : Block(std::move(name)) {
    declare_input_port("features", num_features);
    const InputPort& reward = declare_input_port("reward", 1);
    declare_output_port("value", 1, [](const BlockContext&, VectorRef v) { v[0] = 0.0; }, {});
    declare_output_port(
        "td_error", 1,
        [&reward](const BlockContext& context, VectorRef d) { d[0] = context.input(reward)[0]; },
        {&reward});
  }
};

// A reward of the user's: -theta_b^2, -1 on failure.
class PitchSquareReward final : public Block {
 public:
  explicit PitchSquareReward(std::string name) : Block(std::move(name)) {
    const InputPort& measured = declare_input_port("measured", blocks::kMeasuredSize);
    const InputPort& failed = declare_input_port("failed", 1);
    declare_output_port("reward", 1,
                        [&measured, &failed](const BlockContext& context, VectorRef r) {
                          const double pitch = context.input(measured)[blocks::kMeasuredThetaB];
                          r[0] = context.input(failed)[0] > 0.5 ? -1.0 : -pitch * pitch;
                        },
                        {&measured, &failed});
  }
};

TEST(Fig5Slots, TheRecordedRewardIsTheOneTheCriticReceives) {
  ControllerOptions options = preset("cbbg").options;
  options.slots.critic = [](const SlotRequest& request) {
    return std::make_shared<RewardEchoCritic>(request.name, request.num_features);
  };
  ClosedLoopOptions task;
  task.slots.reward = [](const std::string& name, const parameters::Parameters&) {
    return std::make_shared<PitchSquareReward>(name);
  };
  const ClosedLoop loop = closed_loop_factory("echo", options, task)(quick_parameters());
  experiments::TrialRunner runner(loop, 1, 0.01);
  runner.run_trial(0.1744, 2.0);
  const SignalLog& log = runner.telemetry();
  ASSERT_GT(log.num_samples(), 100);
  int distinct = 0;
  for (int k = 0; k < log.num_samples(); ++k) {
    const auto tick = log.sample(k);
    EXPECT_EQ(tick[kTelemetryReward], tick[kTelemetryTdError]) << "tick " << k;
    distinct += tick[kTelemetryReward] != 0.0 && tick[kTelemetryReward] != -1.0;
  }
  EXPECT_GT(distinct, 100);  // the user's reward, not the sliding surface's 0 and -1
}

// A controller that makes its own reward: the loop records it and builds none of its own.
TEST(Fig5Slots, AControllersOwnRewardIsRecordedAndTheLoopBuildsNone) {
  DiagramBuilder builder("rewarding");
  const auto& measured = builder.emplace<PortsBlock>("gain", Ports{{"measured", 6}},
                                                     Ports{{"action", 1}, {"reward", 1}}, -0.5);
  builder.export_input(measured.input_port("measured"), "measured");
  builder.export_output(measured.output_port("action"), "action");
  builder.export_output(measured.output_port("reward"), "reward");
  const ClosedLoop loop = build_closed_loop("own_reward", quick_parameters(), builder.build());
  for (const auto& block : loop.diagram->blocks()) EXPECT_NE(block->name(), "reward");
  auto context = loop.diagram->create_context(1);
  EXPECT_EQ(loop.diagram->eval_output(*context, *loop.telemetry)[kTelemetryReward], -0.5);
}

TEST(Fig5Slots, AControllerThatBothReadsAndMakesARewardIsRefused) {
  DiagramBuilder builder("both");
  const auto& block = builder.emplace<PortsBlock>("gain", Ports{{"measured", 6}, {"reward", 1}},
                                                  Ports{{"action", 1}, {"reward", 1}});
  builder.export_input(block.input_port("measured"), "measured");
  builder.export_input(block.input_port("reward"), "reward");
  builder.export_output(block.output_port("action"), "action");
  builder.export_output(block.output_port("reward"), "reward");
  EXPECT_THAT([&] { build_closed_loop("both_loop", quick_parameters(), builder.build()); },
              ThrowsMessage<std::invalid_argument>(
                  "controller 'both' has both an input \"reward\" and an output \"reward\": it "
                  "learns from the loop's reward or makes its own, not both"));
}

// A critic of the user's that learns two parts across trials: TD(0) weights and the feature
// mass each weight has seen.
class TwoPartCritic final : public Block, public blocks::Learner {
 public:
  TwoPartCritic(std::string name, int num_features, bool learns)
      : Block(std::move(name)), num_features_(num_features) {
    const InputPort& features = declare_input_port("features", num_features);
    const InputPort& reward = declare_input_port("reward", 1);
    const Vector zeros = Vector::Zero(num_features);
    const StatePart weights = declare_discrete_state("weights", zeros, StateLifetime::kPersistent);
    const StatePart visits = declare_discrete_state("visits", zeros, StateLifetime::kPersistent);
    const StatePart previous = declare_discrete_state("previous", zeros, StateLifetime::kPerTrial);
    declare_output_port("value", 1,
                        [&features, weights](const BlockContext& c, VectorRef v) {
                          v[0] = weights.of(c.discrete_state()).dot(c.input(features));
                        },
                        {&features});
    declare_output_port(
        "td_error", 1, [&reward](const BlockContext& c, VectorRef d) { d[0] = c.input(reward)[0]; },
        {&reward});
    declare_periodic_update(0.01, 0.0, [=, &features, &reward](BlockContext& c, VectorRef next) {
      const auto x = c.discrete_state();
      if (learns) {
        visits.of(next) = visits.of(x) + previous.of(x);
        weights.of(next) = weights.of(x) + 0.1 * c.input(reward)[0] * previous.of(x);
      }
      previous.of(next) = c.input(features);
      return EventStatus::succeeded();
    });
  }
  Role learner_role() const override { return Role::kCritic; }
  const Block& learner_block() const override { return *this; }
  int num_features() const override { return num_features_; }

 private:
  int num_features_;
};

ControllerOptions two_part_options(ControllerOptions options) {
  options.slots.critic = [](const SlotRequest& request) {
    return std::make_shared<TwoPartCritic>(request.name, request.num_features, request.learns);
  };
  return options;
}

TEST(Fig5Slots, ALearnerWithTwoPartsIsSavedLoadedAndCarriedOverBitForBit) {
  const parameters::Parameters p = quick_parameters();
  const ClosedLoop loop =
      closed_loop_factory("cbbg_two", two_part_options(preset("cbbg").options))(p);
  experiments::TrialRunner runner(loop, 1, 0.01);
  runner.run_trial(0.1744, 2.0);
  const experiments::LearntWeights learnt =
      experiments::learnt_weights(loop, runner.context(), {"cbbg_two", 1, 1, "analytic"});
  ASSERT_EQ(learnt.critic.parts.size(), 2u);
  EXPECT_EQ(learnt.critic.parts[1].name, "visits");
  EXPECT_GT(learnt.critic.parts[1].values.sum(), 0.0);

  // Saved (version 2) and loaded: the same parts, bit for bit.
  const cbbg::testing::ScratchDirectory scratch;
  const auto file = scratch.path() / "two.txt";
  store::save_weights(file, learnt);
  EXPECT_EQ(store::load_weights(file), learnt);

  // Loaded into another loop of the same shape, and carried on as exp2 carries a seed's
  // context from its first loop into the next.
  const ClosedLoop later =
      closed_loop_factory("bg_two", two_part_options(preset("bg_only").options))(p);
  experiments::TrialRunner next(later, 1, 0.01);
  next.context().continue_from(runner.context());
  EXPECT_EQ(experiments::learnt_weights(later, next.context(), learnt.provenance), learnt);
  auto fresh = later.diagram->create_context(2);
  experiments::load_learnt_weights(later, *fresh, store::load_weights(file));
  EXPECT_EQ(experiments::learnt_weights(later, *fresh, learnt.provenance), learnt);

  // The paper's critic learns one part: the file refuses to load onto it.
  const ClosedLoop paper = preset_arm("cbbg").learner(p);
  EXPECT_THAT([&] { experiments::check_weights(learnt, "analytic", paper, file); },
              ThrowsMessage<config::ConfigError>(
                  "weights file '" + file.string() +
                  "' holds critic parts weights (49), visits (49); the critic "
                  "'cbbg/controller/basal_ganglia/critic' learns weights (49)"));
}

// What the telemetry records of the exploration at each tick: its standard normal (a_E =
// a_A + sqrt(K_B T / 2) eps) and the temperature T.
struct Exploration {
  std::vector<double> noise;
  std::vector<double> temperature;
};

Exploration exploration_of(const ClosedLoop& loop) {
  experiments::TrialRunner runner(loop, 7, 0.01);
  runner.run_trial(0.1744, 3.0);
  Exploration seen;
  const SignalLog& log = runner.telemetry();
  for (int k = 0; k < log.num_samples(); ++k) {
    const auto tick = log.sample(k);
    seen.temperature.push_back(tick[kTelemetryTemperature]);
    seen.noise.push_back((tick[kTelemetryExplorationAction] - tick[kTelemetryActorAction]) /
                         std::sqrt(tick[kTelemetryTemperature] / 2.0));
  }
  return seen;
}

TEST(Fig5Slots, ArmsThatDifferOnlyInTheCriticSeeTheSameExplorationNoise) {
  parameters::Parameters td0 = quick_parameters();
  td0.critic.kind = blocks::CriticKind::kTd0;
  const ControllerOptions options = preset("cbbg").options;
  const Exploration paper = exploration_of(closed_loop_factory("a", options)(quick_parameters()));
  const Exploration other = exploration_of(closed_loop_factory("b", options)(td0));
  const std::size_t ticks = std::min(paper.noise.size(), other.noise.size());
  ASSERT_GT(ticks, 50u);
  int other_temperatures = 0;  // the critics differ: so do their values and temperatures
  for (std::size_t k = 0; k < ticks; ++k) {
    EXPECT_NEAR(paper.noise[k], other.noise[k], 1e-9 * (1.0 + std::abs(paper.noise[k])))
        << "tick " << k;
    other_temperatures += paper.temperature[k] != other.temperature[k];
  }
  EXPECT_GT(other_temperatures, 10);
}

}  // namespace
}  // namespace cbbg::diagrams
