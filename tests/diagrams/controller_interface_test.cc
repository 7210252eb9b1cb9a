// The controller as an interface, from user code only: omega held constant or made by a
// user's block, one learner frozen while the other learns, and controllers built by hand
// (with and without the library's basal ganglia) in the closed loop and through exp1.

#include <cmath>
#include <memory>
#include <string>
#include <utility>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "cbbg/blocks/measured_signals.h"
#include "cbbg/blocks/mixer.h"
#include "cbbg/blocks/normaliser.h"
#include "cbbg/blocks/rbf_features.h"
#include "cbbg/diagrams/basal_ganglia.h"
#include "cbbg/diagrams/presets.h"
#include "cbbg/diagrams/telemetry.h"
#include "cbbg/experiments/experiments.h"
#include "cbbg/experiments/trial_runner.h"
#include "cbbg/framework/block_context.h"
#include "cbbg/framework/diagram_builder.h"
#include "cbbg/framework/primitives/constant_source.h"
#include "cbbg/framework/primitives/selector.h"
#include "tests/diagrams/slot_fixtures.h"

namespace cbbg::diagrams {
namespace {

using testing::PitchSupervisor;
using testing::quick_parameters;
using ::testing::ThrowsMessage;

// The telemetry's omega over one trial of `loop` from 0.1744 rad, `seconds` long.
std::vector<double> omega_over_a_trial(const ClosedLoop& loop, double seconds) {
  experiments::TelemetryOptions telemetry;
  experiments::TrialRunner runner(loop, 1, 0.01, telemetry);
  runner.run_trial(0.1744, seconds);
  const auto values = runner.telemetry().values();
  std::vector<double> omega;
  for (Eigen::Index t = 0; t < values.cols(); ++t) omega.push_back(values(kTelemetryOmega, t));
  return omega;
}

TEST(ControllerInterface, OmegaHeldAtAConstant) {
  ControllerOptions options = preset("cbbg").options;
  options.omega = blocks::OmegaMode::kConstant;
  options.omega_constant = 0.5;
  const ClosedLoop loop = make_arm("cbbg_half", options).learner(quick_parameters());
  for (const double omega : omega_over_a_trial(loop, 3.0)) ASSERT_EQ(omega, 0.5);
  options.omega_constant = 1.5;
  EXPECT_THAT([&] { make_arm("cbbg_too_much", options); },
              ThrowsMessage<std::invalid_argument>(
                  "controller options: omega_constant must be in [0, 1]; got 1.5"));
}

// A user's omega: a quarter, then a half once a hundred ticks have passed.
class StepOmega final : public Block {
 public:
  explicit StepOmega(std::string name) : Block(std::move(name)) {
    declare_discrete_state("ticks", Vector::Zero(1), StateLifetime::kPersistent);
    declare_output_port("omega", 1,
                        [](const BlockContext& context, VectorRef omega) {
                          omega[0] = context.discrete_state()[0] < 100.0 ? 0.25 : 0.5;
                        },
                        {});
    declare_periodic_update(0.01, 0.0, [](BlockContext& context, VectorRef next) {
      next[0] = context.discrete_state()[0] + 1.0;
      return EventStatus::succeeded();
    });
  }
};

TEST(ControllerInterface, AUsersBlockFillsTheOmegaSlot) {
  ControllerOptions options = preset("cbbg").options;
  options.slots.omega = [](const std::string& name, const parameters::Parameters&) {
    return std::make_unique<StepOmega>(name);
  };
  const Arm arm = make_arm("cbbg_step", options);
  const std::vector<double> omega = omega_over_a_trial(arm.learner(quick_parameters()), 2.0);
  EXPECT_EQ(omega.front(), 0.25);
  EXPECT_EQ(omega.back(), 0.5);
  // Through a protocol, its learnt actor evaluated alone as any arm's.
  const experiments::ExperimentResults results = experiments::run_exp1(quick_parameters(), {arm});
  EXPECT_TRUE(results.run(0, 0).weights.has_value());

  options.slots.omega = [](const std::string& name, const parameters::Parameters&) {
    return std::make_unique<blocks::Mixer>(name);
  };
  EXPECT_THAT([&] { make_arm("cbbg_mixer", options).learner(quick_parameters()); },
              ThrowsMessage<std::invalid_argument>(
                  "omega slot: the block 'omega' must have no input and one output \"omega\" "
                  "of size 1"));
}

// The weights of `loop`'s critic and actor after one trial of a few seconds.
std::pair<Vector, Vector> weights_after_a_trial(const ClosedLoop& loop) {
  experiments::TrialRunner runner(loop, 1, 0.01);
  runner.run_trial(0.1744, 3.0);
  return {loop.learner.critic->learnt(runner.context(), "weights"),
          loop.learner.actor->learnt(runner.context(), "weights")};
}

TEST(ControllerInterface, EachLearnerFreezesAlone) {
  ControllerOptions critic_frozen = preset("cbbg").options;
  critic_frozen.critic_learns = false;
  const auto [frozen_critic, learning_actor] =
      weights_after_a_trial(make_arm("critic_frozen", critic_frozen).learner(quick_parameters()));
  EXPECT_EQ(frozen_critic.norm(), 0.0);
  EXPECT_GT(learning_actor.norm(), 0.0);

  ControllerOptions actor_frozen = preset("cbbg").options;
  actor_frozen.actor_learns = false;
  const auto [learning_critic, frozen_actor] =
      weights_after_a_trial(make_arm("actor_frozen", actor_frozen).learner(quick_parameters()));
  EXPECT_GT(learning_critic.norm(), 0.0);
  EXPECT_EQ(frozen_actor.norm(), 0.0);
}

// A controller built by hand: the user's law alone, with no diagnostics at all.
std::unique_ptr<Diagram> law_alone(const parameters::Parameters&) {
  DiagramBuilder builder("controller");
  const Block& law = builder.emplace<PitchSupervisor>("law");
  builder.export_input(law.input_port("measured"), "measured");
  builder.export_output(law.output_port("action"), "action");
  return builder.build();
}

TEST(ControllerInterface, AHandBuiltControllerNeedsOnlyItsPorts) {
  const ClosedLoop loop = build_closed_loop("mine", quick_parameters(), law_alone({}));
  EXPECT_FALSE(loop.learner.learns());
  experiments::TelemetryOptions telemetry;
  experiments::TrialRunner runner(loop, 1, 0.01, telemetry);
  EXPECT_EQ(runner.run_trial(0.1744, 5.0).status, experiments::TrialStatus::kSuccess);
  const auto values = runner.telemetry().values();
  EXPECT_TRUE(std::isnan(values(kTelemetryValue, 0)));  // diagnostics it lacks are NaN
  EXPECT_EQ(values(kTelemetryAction, 0), 40.0 * 0.1744);
  // An arm of it runs exp1, evaluated as it is (it learns nothing).
  const experiments::ExperimentResults results =
      experiments::run_exp1(quick_parameters(), {make_arm("law", law_alone)});
  EXPECT_TRUE(results.run(0, 0).succeeded);
  EXPECT_FALSE(results.run(0, 0).weights.has_value());
  EXPECT_FALSE(results.run(0, 0).evaluation.empty());
}

// The ablation of a fixed omega of 1/2 built by hand from the library's subsystems: the
// user's supervisor, the paper's normaliser and basal ganglia, the user's own mixing. No
// name of a block inside the library is needed.
std::unique_ptr<Diagram> half_and_half(const parameters::Parameters& p) {
  DiagramBuilder builder("controller");
  const Block& law = builder.emplace<PitchSupervisor>("supervisor");
  const Block& normaliser = builder.emplace<blocks::Normaliser>("normaliser", p.normaliser);
  BasalGangliaParams params;
  params.critic = p.critic;
  params.actor = p.actor;
  params.tropism = p.tropism;
  params.sampler = p.sampler;
  params.entropy = blocks::EntropyParams{p.sampler.k_b};
  params.period = p.trial.period;
  auto& bg = builder.emplace<BasalGanglia>(
      "basal_ganglia", std::make_unique<blocks::RbfFeatures>("features", p.rbf), params);
  const OutputPort& half =
      builder.emplace<ConstantSource>("half", Vector::Constant(1, 0.5)).output_port("y");
  const Block& mixer = builder.emplace<blocks::Mixer>("mixer");
  builder.export_input(law.input_port("measured"), "measured");
  builder.export_input(normaliser.input_port("measured"), "measured");
  builder.export_input(*bg.reward(), "reward");
  builder.export_input(*bg.failed(), "failed");
  builder.connect(normaliser.output_port("x"), bg.state());
  builder.connect(law.output_port("action"), *bg.supervisor_action());
  builder.connect(half, *bg.omega());
  builder.connect(law.output_port("action"), mixer.input_port("supervisor_action"));
  builder.connect(half, mixer.input_port("omega"));
  builder.connect(bg.exploration_action(), mixer.input_port("exploration_action"));
  builder.export_output(mixer.output_port("action"), "action");
  builder.export_output(half, "omega");
  builder.export_output(bg.value(), "value");
  return builder.build();
}

TEST(ControllerInterface, AHandBuiltLearningControllerHasItsLearnersFound) {
  const ClosedLoop loop =
      build_closed_loop("half", quick_parameters(), half_and_half(quick_parameters()));
  ASSERT_TRUE(loop.learner.learns());
  ASSERT_NE(loop.learner.critic, nullptr);
  ASSERT_NE(loop.learner.tropism, nullptr);
  const std::vector<double> omega = omega_over_a_trial(loop, 1.0);
  EXPECT_EQ(omega.front(), 0.5);
  const experiments::ExperimentResults results =
      experiments::run_exp1(quick_parameters(), {make_arm("half", half_and_half)});
  ASSERT_TRUE(results.run(0, 0).weights.has_value());
  EXPECT_GT(results.run(0, 0).weights->actor.weights("actor").norm(), 0.0);
}

// A user's own learner: a weight per feature of its input, its output their dot product.
// It learns nothing itself (a policy found by another method, say), but it answers to the
// protocols as the library's critic and actor do.
class DotProduct final : public Block, public blocks::Learner {
 public:
  DotProduct(std::string name, Role role) : Block(std::move(name)), role_(role) {
    const InputPort& features = declare_input_port("features", kFeatures);
    weights_ =
        declare_discrete_state("weights", Vector::Zero(kFeatures), StateLifetime::kPersistent);
    declare_output_port("y", 1,
                        [this, &features](const BlockContext& context, VectorRef y) {
                          y[0] = weights_.of(context.discrete_state()).dot(context.input(features));
                        },
                        {&features});
  }
  Role learner_role() const override { return role_; }
  const Block& learner_block() const override { return *this; }
  int num_features() const override { return kFeatures; }

 private:
  static constexpr int kFeatures = 2;  // theta_b, theta_b'
  Role role_;
  StatePart weights_;
};

using Role = blocks::Learner::Role;

// Two DotProducts of the given names and roles in `builder`'s controller, both fed the
// measured pitch and pitch rate (the controller's input "measured").
std::pair<const Block*, const Block*> two_learners(DiagramBuilder& builder, const char* first,
                                                   Role first_role, const char* second,
                                                   Role second_role) {
  auto& pitch = builder.emplace<Selector>(
      "pitch", blocks::kMeasuredSize,
      std::vector<int>{blocks::kMeasuredThetaB, blocks::kMeasuredThetaBDot});
  const Block& one = builder.emplace<DotProduct>(first, first_role);
  const Block& other = builder.emplace<DotProduct>(second, second_role);
  builder.export_input(pitch.input_port("u"), "measured");
  builder.connect(pitch.output_port("y"), one.input_port("features"));
  builder.connect(pitch.output_port("y"), other.input_port("features"));
  return {&one, &other};
}

// A user's actor and critic on the measured pitch and pitch rate.
std::unique_ptr<Diagram> dot_product_controller(const parameters::Parameters&) {
  DiagramBuilder builder("controller");
  const auto [actor, critic] =
      two_learners(builder, "policy", Role::kActor, "value", Role::kCritic);
  builder.export_output(actor->output_port("y"), "action");
  builder.export_output(critic->output_port("y"), "value");
  return builder.build();
}

TEST(ControllerInterface, TwoLearnersOfAKindAreRefused) {
  auto two_actors = [](const parameters::Parameters&) {
    DiagramBuilder builder("controller");
    const auto [first, second] =
        two_learners(builder, "first", Role::kActor, "second", Role::kActor);
    auto& mixer = builder.emplace<blocks::Mixer>("mixer");
    builder.connect(first->output_port("y"), mixer.input_port("supervisor_action"));
    builder.connect(second->output_port("y"), mixer.input_port("exploration_action"));
    builder.fix_input(mixer.input_port("omega"), Vector::Constant(1, 0.5));
    builder.export_output(mixer.output_port("action"), "action");
    return builder.build();
  };
  EXPECT_THAT([&] { build_closed_loop("two", quick_parameters(), two_actors({})); },
              ThrowsMessage<std::invalid_argument>(
                  "controller 'controller' has two actors ('two/controller/first' and "
                  "'two/controller/second'); a closed loop keeps the weights of one"));
}

TEST(ControllerInterface, AUsersLearnersAreFoundAndTheirWeightsKept) {
  const ClosedLoop loop = build_closed_loop("dot", quick_parameters(), dot_product_controller({}));
  ASSERT_TRUE(loop.learner.learns());
  EXPECT_EQ(loop.learner.actor->learner_block().name(), "policy");
  EXPECT_EQ(loop.learner.critic->learner_block().name(), "value");
  experiments::LearntWeights pd;
  pd.features = 2;
  pd.actor = experiments::LearntState::of_weights(Vector{{40.0, 8.0}});  // a PD law's weights
  pd.critic = experiments::LearntState::of_weights(Vector{{-1.0, 0.0}});
  experiments::TrialRunner runner(loop, 1, 0.01);
  experiments::load_learnt_weights(loop, runner.context(), pd);
  EXPECT_EQ(runner.run_trial(0.1744, 5.0).status, experiments::TrialStatus::kSuccess);
  const experiments::LearntWeights kept = experiments::learnt_weights(loop, runner.context(), {});
  EXPECT_EQ(kept.actor, pd.actor);
  EXPECT_EQ(kept.critic, pd.critic);
}

// A controller the closed loop cannot feed, or whose learners are ambiguous, is refused.
TEST(ControllerInterface, AControllerWithoutTheClosedLoopsPortsIsRefused) {
  auto no_action = [](const parameters::Parameters&) {
    DiagramBuilder builder("controller");
    const Block& law = builder.emplace<PitchSupervisor>("law");
    builder.export_input(law.input_port("measured"), "measured");
    builder.export_output(law.output_port("action"), "torque");
    return builder.build();
  };
  EXPECT_THAT([&] { build_closed_loop("bad", quick_parameters(), no_action({})); },
              ThrowsMessage<std::invalid_argument>(
                  "controller 'controller' must have an output \"action\" of size 1; its "
                  "outputs are: torque"));
  auto extra_input = [](const parameters::Parameters&) {
    DiagramBuilder builder("controller");
    const Block& law = builder.emplace<PitchSupervisor>("law");
    const Block& mixer = builder.emplace<blocks::Mixer>("mixer");
    builder.export_input(law.input_port("measured"), "measured");
    builder.export_input(mixer.input_port("omega"), "gain");
    builder.connect(law.output_port("action"), mixer.input_port("supervisor_action"));
    builder.connect(law.output_port("action"), mixer.input_port("exploration_action"));
    builder.export_output(mixer.output_port("action"), "action");
    return builder.build();
  };
  EXPECT_THAT([&] { build_closed_loop("bad", quick_parameters(), extra_input({})); },
              ThrowsMessage<std::invalid_argument>(
                  "controller 'controller' has an input \"gain\" the closed loop does not "
                  "feed; it feeds \"measured\" (6), \"reward\" (1) and \"failed\" (1)"));
}

}  // namespace
}  // namespace cbbg::diagrams
