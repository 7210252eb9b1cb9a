#include "cbbg/blocks/actor.h"

#include <cmath>
#include <random>
#include <stdexcept>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "cbbg/blocks/mixer.h"
#include "cbbg/framework/block_harness.h"
#include "cbbg/framework/diagram_builder.h"
#include "cbbg/framework/simulator.h"

namespace cbbg::blocks {
namespace {

using ::testing::HasSubstr;
using ::testing::StrEq;
using ::testing::ThrowsMessage;
using Harness = testing::BlockHarness<Actor>;

constexpr double kPeriod = Harness::kPeriod;

Vector vector2(double a, double b) {
  Vector v(2);
  v << a, b;
  return v;
}

ActorParams params_with(ActorRule rule, double alpha = 0.1) {
  ActorParams params;
  params.rule = rule;
  params.alpha = alpha;
  return params;
}

// The actor's inputs at one tick.
struct Tick {
  Vector features;
  double td_error;
  double supervisor;
  double exploration;
  double omega;
};

void set_tick(Harness& harness, const Tick& tick) {
  harness.set_input("features", tick.features);
  harness.set_input("td_error", tick.td_error);
  harness.set_input("supervisor_action", tick.supervisor);
  harness.set_input("exploration_action", tick.exploration);
  harness.set_input("omega", tick.omega);
}

TEST(Actor, ActionIsTheWeightsDotTheFeatures) {
  Harness harness("actor", 2, ActorParams{}, kPeriod);
  harness.block().mutable_weights(harness.context()) = vector2(0.2, -0.4);
  set_tick(harness, {vector2(1.0, 0.5), 0.0, 0.0, 0.0, 0.0});
  EXPECT_EQ(harness.scalar_output("actor_action"), 0.0);  // 0.2 - 0.2
  set_tick(harness, {vector2(-2.0, 1.0), 0.0, 0.0, 0.0, 0.0});
  EXPECT_NEAR(harness.scalar_output("actor_action"), -0.8, 1e-15);
}

// theta = (0.2, -0.4); at t = 0: phi = (1, 0.5) so a_A = 0, a_S = 2, a_E = 1, omega = 0.25.
// At t = 1, delta_0 = -0.5.
Vector weights_after_one_transition(ActorRule rule) {
  Harness harness("actor", 2, params_with(rule), kPeriod);
  harness.block().mutable_weights(harness.context()) = vector2(0.2, -0.4);
  set_tick(harness, {vector2(1.0, 0.5), 7.0, 2.0, 1.0, 0.25});
  harness.tick();  // nothing to learn from yet, whatever td_error says
  EXPECT_EQ(harness.block().weights(harness.context()), vector2(0.2, -0.4));
  set_tick(harness, {vector2(0.0, 1.0), -0.5, 9.0, 9.0, 0.9});  // this tick's actions: unused
  harness.tick();
  return harness.block().weights(harness.context());
}

TEST(Actor, ImprovedRuleAsWorkedOutByHand) {
  // step = 0.1 (-0.5) [0.25 (1 - 2) + (2 - 0)] = -0.0875; theta += step (1, 0.5).
  const Vector theta = weights_after_one_transition(ActorRule::kImproved);
  EXPECT_NEAR(theta[0], 0.1125, 1e-15);
  EXPECT_NEAR(theta[1], -0.44375, 1e-15);
}

TEST(Actor, WeightedRuleAsWorkedOutByHand) {
  // step = 0.25 (0.1) (-0.5) (1 - 0) + 0.75 (0.1) (2 - 0) = -0.0125 + 0.15 = 0.1375.
  const Vector theta = weights_after_one_transition(ActorRule::kWeighted);
  EXPECT_NEAR(theta[0], 0.3375, 1e-15);
  EXPECT_NEAR(theta[1], -0.33125, 1e-15);
}

TEST(Actor, ImprovedRuleEqualsAlphaDeltaTimesMixedActionError) {
  // The actor wired to a real Mixer fed the same a_E, a_S and omega: the improved rule's
  // change must be alpha delta (a - a_A) phi(s_{t-1}), a the mixer's output at t-1.
  const int n = 6;
  const double alpha = 0.3;
  DiagramBuilder builder("cbbg");
  const auto& actor =
      builder.emplace<Actor>("actor", n, params_with(ActorRule::kImproved, alpha), kPeriod);
  const auto& mixer = builder.emplace<Mixer>("mixer");
  builder.export_input(actor.input_port("features"));
  builder.export_input(actor.input_port("td_error"));
  for (const char* port : {"supervisor_action", "exploration_action", "omega"}) {
    builder.export_input(actor.input_port(port));
    builder.export_input(mixer.input_port(port));  // same name: fans the input out to both
  }
  const auto diagram = builder.build();
  Simulator simulator(*diagram);
  Context& context = simulator.context();

  std::mt19937_64 generator(17);
  std::normal_distribution<double> normal;
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  auto random_vector = [&] {
    Vector v(n);
    for (int i = 0; i < n; ++i) v[i] = normal(generator);
    return v;
  };
  auto set = [&](const char* port, const Vector& value) {
    context.fix_input(diagram->input_port(port), value);
  };
  auto set_scalar = [&](const char* port, double value) { set(port, Vector::Constant(1, value)); };
  actor.mutable_weights(context) = random_vector();

  Vector previous_features;
  double previous_mixed = 0.0;
  double previous_actor = 0.0;
  for (int t = 0; t < 50; ++t) {
    const Vector features = random_vector();
    const double delta = normal(generator);
    set("features", features);
    set_scalar("td_error", delta);
    set_scalar("supervisor_action", 3.0 * normal(generator));
    set_scalar("exploration_action", 3.0 * normal(generator));
    set_scalar("omega", unit(generator));
    const Vector before = actor.weights(context);
    const double actor_action = diagram->eval_output(context, actor.output_port("actor_action"))[0];
    const double mixed = diagram->eval_output(context, mixer.output_port("action"))[0];
    simulator.advance_to((t + 0.5) * kPeriod);
    const Vector change = actor.weights(context) - before;
    if (t == 0) {
      EXPECT_EQ(change, Vector::Zero(n));
    } else {
      const Vector expected = alpha * delta * (previous_mixed - previous_actor) * previous_features;
      for (int i = 0; i < n; ++i) {
        ASSERT_NEAR(change[i], expected[i], 1e-12 * (1.0 + std::abs(expected[i])))
            << "tick " << t << ", weight " << i;
      }
    }
    previous_features = features;
    previous_mixed = mixed;
    previous_actor = actor_action;
  }
}

TEST(Actor, ZeroTdErrorLeavesTheImprovedRuleStill) {
  Harness harness("actor", 2, params_with(ActorRule::kImproved), kPeriod);
  harness.block().mutable_weights(harness.context()) = vector2(0.2, -0.4);
  for (int t = 0; t < 5; ++t) {
    set_tick(harness, {vector2(1.0, 0.5 * t), 0.0, 2.0 + t, -1.0, 0.1 * t});
    harness.tick();
  }
  EXPECT_EQ(harness.block().weights(harness.context()), vector2(0.2, -0.4));
}

TEST(Actor, ZeroTdErrorLeavesTheWeightedRuleOnlyItsSupervisedTerm) {
  // docs/model.md §2.11's weighted rule does not scale the supervised term by delta: with delta = 0
  // it is still (1 - omega) alpha (a_S - a_A) phi, and nothing at all when omega = 1.
  for (const double omega : {1.0, 0.25}) {
    Harness harness("actor", 2, params_with(ActorRule::kWeighted), kPeriod);
    harness.block().mutable_weights(harness.context()) = vector2(0.2, -0.4);
    set_tick(harness, {vector2(1.0, 0.5), 0.0, 2.0, -1.0, omega});  // a_A = 0
    harness.tick();
    set_tick(harness, {vector2(0.0, 1.0), 0.0, 0.0, 0.0, 0.0});
    harness.tick();
    const double step = (1.0 - omega) * 0.1 * (2.0 - 0.0);
    const Vector theta = harness.block().weights(harness.context());
    EXPECT_NEAR(theta[0], 0.2 + step, 1e-15) << "omega " << omega;
    EXPECT_NEAR(theta[1], -0.4 + 0.5 * step, 1e-15) << "omega " << omega;
  }
}

TEST(Actor, WeightedRuleWithOmegaZeroMovesTheActionTowardTheSupervisor) {
  Harness harness("actor", 3, params_with(ActorRule::kWeighted), kPeriod);
  Vector phi(3);
  phi << 0.2, 1.0, 0.6;
  std::mt19937_64 generator(23);
  std::normal_distribution<double> normal;
  const double supervisor = 1.5;
  double gap = std::abs(supervisor - 0.0);
  // Each tick shrinks the gap by 1 - alpha |phi|^2 = 0.86.
  for (int t = 0; t < 100; ++t) {
    // Exploration and TD error are noise; with omega = 0 they must not matter.
    set_tick(harness, {phi, normal(generator), supervisor, 5.0 * normal(generator), 0.0});
    harness.tick();
    const double new_gap = std::abs(supervisor - harness.scalar_output("actor_action"));
    if (t > 0) {
      ASSERT_LT(new_gap, gap) << "tick " << t;
    }
    gap = new_gap;
  }
  EXPECT_LT(gap, 1e-3);
}

TEST(Actor, StartTrialForgetsThePreviousTickAndKeepsTheWeights) {
  Harness harness("actor", 2, params_with(ActorRule::kImproved), kPeriod);
  set_tick(harness, {vector2(1.0, 0.5), 0.0, 2.0, 1.0, 0.25});
  harness.tick();
  set_tick(harness, {vector2(0.0, 1.0), -0.5, 2.0, 1.0, 0.25});
  harness.tick();
  const Vector learnt = harness.block().weights(harness.context());
  ASSERT_NE(learnt, vector2(0.0, 0.0));
  harness.context().reset_trial_state();
  harness.restart_time();
  set_tick(harness, {vector2(1.0, 1.0), -3.0, 2.0, 1.0, 0.25});
  harness.tick();
  EXPECT_EQ(harness.block().weights(harness.context()), learnt);
}

TEST(Actor, ParsesItsRuleAndRejectsInvalidParameters) {
  EXPECT_EQ(parse_actor_rule("improved"), ActorRule::kImproved);
  EXPECT_EQ(parse_actor_rule("weighted"), ActorRule::kWeighted);
  EXPECT_EQ(to_string(ActorRule::kWeighted), "weighted");
  EXPECT_THAT([] { parse_actor_rule("greedy"); },
              ThrowsMessage<std::invalid_argument>(
                  StrEq("actor.rule must be improved or weighted; got 'greedy'")));
  EXPECT_THAT(
      [] { Actor("actor", 2, params_with(ActorRule::kImproved, 0.0), kPeriod); },
      ThrowsMessage<std::invalid_argument>(StrEq("actor.alpha must be finite and > 0; got 0")));
  EXPECT_THAT(
      [] { Actor("actor", 2, params_with(ActorRule::kImproved, NAN), kPeriod); },
      ThrowsMessage<std::invalid_argument>(StrEq("actor.alpha must be finite and > 0; got nan")));
  EXPECT_THAT(
      [] { Actor("actor", 0, ActorParams{}, kPeriod); },
      ThrowsMessage<std::invalid_argument>(HasSubstr("the actor needs at least 1 feature; got 0")));
}

}  // namespace
}  // namespace cbbg::blocks
