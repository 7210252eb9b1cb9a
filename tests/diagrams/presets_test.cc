// The table of named presets: each is the set of options its name says, the config's arm
// names are its rows, and arms compared under one seed share their random streams.

#include <cmath>
#include <string>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "cbbg/diagrams/presets.h"
#include "cbbg/framework/diagram.h"

namespace cbbg::diagrams {
namespace {

using ::testing::ThrowsMessage;

config::Config analytic_config() {
  config::Config config;
  config.set("plant.kind=analytic");
  return config;
}

// Whether a block of that name is anywhere inside `diagram`.
bool has_block(const Diagram& diagram, const std::string& name) {
  for (const auto& block : diagram.blocks()) {
    if (block->name() == name) return true;
    if (block->is_diagram() && has_block(static_cast<const Diagram&>(*block), name)) return true;
  }
  return false;
}

TEST(Presets, TheArmsAreEveryPresetButTheLearntActor) {
  std::vector<std::string> names;
  for (const auto& preset : presets()) names.push_back(preset.name);
  EXPECT_EQ(names, (std::vector<std::string>{"cbbg", "cbbg_weighted", "bg_only", "cb_only",
                                             "pd_only", kLearntActor}));
  std::vector<std::string> arms = names;
  arms.pop_back();
  EXPECT_EQ(arm_names(), arms);
}

TEST(Presets, EachHasTheBlocksItsNameSays) {
  const config::Config config = analytic_config();
  const ClosedLoop cbbg = build_preset("cbbg", parameters::read_parameters(config));
  EXPECT_TRUE(has_block(*cbbg.diagram, "cerebellum"));
  EXPECT_TRUE(has_block(*cbbg.diagram, "critic"));
  EXPECT_TRUE(has_block(*cbbg.diagram, "sampler"));
  const ClosedLoop bg_only = build_preset("bg_only", parameters::read_parameters(config));
  EXPECT_FALSE(has_block(*bg_only.diagram, "cerebellum"));
  EXPECT_TRUE(has_block(*bg_only.diagram, "actor"));
  const ClosedLoop pd_only = build_preset("pd_only", parameters::read_parameters(config));
  EXPECT_TRUE(has_block(*pd_only.diagram, "supervisor"));
  EXPECT_FALSE(has_block(*pd_only.diagram, "actor"));
  EXPECT_FALSE(pd_only.learner.learns());
  const ClosedLoop policy = build_preset(kLearntActor, parameters::read_parameters(config));
  EXPECT_TRUE(has_block(*policy.diagram, "actor"));
  EXPECT_FALSE(has_block(*policy.diagram, "sampler"));
  EXPECT_FALSE(has_block(*policy.diagram, "supervisor"));
  EXPECT_EQ(policy.learner.tropism, nullptr);
  EXPECT_EQ(cbbg.telemetry->size(), kTelemetrySize);
  EXPECT_EQ(preset("cbbg_weighted").options.actor_rule, blocks::ActorRule::kWeighted);
}

TEST(Presets, OmegaFollowsThePreset) {
  const config::Config config = analytic_config();
  for (const auto& [name, omega] : {std::pair<const char*, double>{"bg_only", 1.0},
                                    {"cb_only", 0.0},
                                    {"cbbg", 0.0},  // the schedule starts at 0 (n2 = 500)
                                    {"pd_only", 0.0},
                                    {kLearntActor, 1.0}}) {
    const ClosedLoop loop = build_preset(name, parameters::read_parameters(config));
    auto context = loop.diagram->create_context(1);
    EXPECT_EQ(loop.diagram->eval_output(*context, *loop.telemetry)[kTelemetryOmega], omega) << name;
  }
}

TEST(Presets, ThePlantKindAndSupervisorKindSwapBlocks) {
  config::Config config = analytic_config();
  config.set("supervisor.kind=lqr");
  const ClosedLoop lqr = build_preset("cbbg", parameters::read_parameters(config));
  auto context = lqr.diagram->create_context(1);
  // Leaning forward, both supervisors push the wheels forward (a_S > 0).
  EXPECT_GT(lqr.diagram->eval_output(*context, *lqr.telemetry)[kTelemetrySupervisorAction], 0.0);
  config.set("plant.kind=simbody");
  const ClosedLoop simbody = build_preset("cbbg", parameters::read_parameters(config));
  auto simbody_context = simbody.diagram->create_context(1);
  EXPECT_EQ(simbody.diagram->eval_output(*simbody_context, *simbody.telemetry)[kTelemetryThetaB],
            config.number("trial.theta0"));
}

TEST(Presets, UnknownNamesListThePresets) {
  EXPECT_THAT([] { preset("cbbg_fast"); },
              ThrowsMessage<std::invalid_argument>(
                  "unknown diagram 'cbbg_fast'; the presets are cbbg, cbbg_weighted, bg_only, "
                  "cb_only, pd_only, learnt_actor"));
  EXPECT_THAT([] { preset_arm(kLearntActor); },
              ThrowsMessage<std::invalid_argument>(
                  "learnt_actor evaluates an arm's learnt actor; it is not an arm"));
}

TEST(Presets, TheLearntActorOfAnArmKeepsItsSlots) {
  ControllerOptions options = preset("cb_only").options;
  options.slots.features = [](const std::string&, const parameters::Parameters&) {
    return std::unique_ptr<Block>();
  };
  options.slots.omega = [](const std::string&, const parameters::Parameters&) {
    return std::unique_ptr<Block>();
  };
  const ControllerOptions alone = learnt_actor(options);
  EXPECT_FALSE(alone.supervisor);
  EXPECT_FALSE(alone.critic_learns);
  EXPECT_FALSE(alone.actor_learns);
  EXPECT_FALSE(alone.exploration);
  EXPECT_EQ(alone.omega, blocks::OmegaMode::kOne);
  EXPECT_TRUE(static_cast<bool>(alone.slots.features));
  EXPECT_FALSE(static_cast<bool>(alone.slots.omega));  // the actor alone: omega is 1
  EXPECT_TRUE(static_cast<bool>(make_arm("mine", options).policy));
  EXPECT_FALSE(static_cast<bool>(preset_arm("pd_only").policy));
}

// The sampler's generator in a fresh context of preset `name` under `seed`.
RandomGenerator sampler_stream(const std::string& name, std::uint64_t seed) {
  const ClosedLoop loop = build_preset(name, parameters::read_parameters(analytic_config()));
  auto context = loop.diagram->create_context(seed);
  const auto& controller = static_cast<const Diagram&>(loop.diagram->block("controller"));
  const auto& basal_ganglia = static_cast<const Diagram&>(controller.block("basal_ganglia"));
  return context->random_generator(basal_ganglia.block("sampler"));
}

TEST(CommonRandomNumbers, SeedKGivesEveryArmTheSameExplorationStream) {
  for (const std::uint64_t seed : {1u, 7u}) {
    const RandomGenerator cbbg = sampler_stream("cbbg", seed);
    EXPECT_EQ(sampler_stream("bg_only", seed), cbbg) << "seed " << seed;
    EXPECT_EQ(sampler_stream("cb_only", seed), cbbg) << "seed " << seed;
    EXPECT_EQ(sampler_stream("cbbg_weighted", seed), cbbg) << "seed " << seed;
  }
  EXPECT_NE(sampler_stream("cbbg", 1), sampler_stream("cbbg", 2));
}

}  // namespace
}  // namespace cbbg::diagrams
