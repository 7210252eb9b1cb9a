#include <cmath>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "cbbg/blocks/critic.h"
#include "cbbg/framework/block_harness.h"
#include "key_order.h"

namespace cbbg::blocks {
namespace {

using ::testing::ElementsAre;
using ::testing::HasSubstr;
using ::testing::StrEq;
using ::testing::ThrowsMessage;
using Harness = testing::BlockHarness<Critic>;

constexpr double kPeriod = Harness::kPeriod;

Vector vector2(double a, double b) {
  Vector v(2);
  v << a, b;
  return v;
}

// Sets the critic's inputs for one tick: phi(s_t), r_{t-1}, failed.
template <typename H>
void set_tick(H& harness, const Vector& features, double reward, bool failed) {
  harness.set_input("features", features);
  harness.set_input("reward", reward);
  harness.set_input("failed", failed ? 1.0 : 0.0);
}

// gamma = 0.8, beta = 0.1, epsilon = 0.5 over four ticks, every number worked out by hand.
TEST(CriticTd0, LearnsByNormalisedTd0AsWorkedOutByHand) {
  CriticParams params;
  params.kind = CriticKind::kTd0;
  params.gamma = 0.8;
  params.beta = 0.1;
  params.epsilon = 0.5;
  params.lambda = 0.5;  // not read: no trace
  Harness harness("critic", 2, params, kPeriod);

  // t = 0: no previous tick, so no TD error and nothing learnt; phi(s_0) is remembered.
  set_tick(harness, vector2(1.0, 0.0), -1.0, false);
  EXPECT_EQ(harness.scalar_output("td_error"), 0.0);
  harness.tick();
  EXPECT_EQ(harness.block().weights(harness.context()), vector2(0.0, 0.0));

  // t = 1: delta = -1; phi(s_0) . phi(s_0) = 1; w = 0.1 (-1) (1, 0) / 1.5 = (-1/15, 0).
  set_tick(harness, vector2(0.0, 1.0), -1.0, false);
  EXPECT_EQ(harness.scalar_output("td_error"), -1.0);
  harness.tick();
  Vector w = harness.block().weights(harness.context());
  EXPECT_NEAR(w[0], -1.0 / 15.0, 1e-15);
  EXPECT_EQ(w[1], 0.0);

  // t = 2: V(s_2) = -1/15; delta = 0.8 (-1/15) - w . (0, 1) = -0.8/15; phi(s_1) = (0, 1):
  // w[1] = 0.1 (-0.8/15) / 1.5 = -0.08/22.5, w[0] unchanged (no trace carries phi(s_0)).
  set_tick(harness, vector2(1.0, 1.0), 0.0, false);
  EXPECT_NEAR(harness.scalar_output("value"), -1.0 / 15.0, 1e-15);
  EXPECT_NEAR(harness.scalar_output("td_error"), -0.8 / 15.0, 1e-15);
  harness.tick();
  w = harness.block().weights(harness.context());
  EXPECT_NEAR(w[0], -1.0 / 15.0, 1e-15);
  EXPECT_NEAR(w[1], -0.08 / 22.5, 1e-15);

  // t = 3, a failure: V(s_3) counts as 0; delta = -1 - w . (1, 1); phi(s_2) . phi(s_2) = 2:
  // w += 0.1 delta (1, 1) / 2.5.
  set_tick(harness, vector2(0.5, 0.5), -1.0, true);
  const double delta = -1.0 + 1.0 / 15.0 + 0.08 / 22.5;
  EXPECT_NEAR(harness.scalar_output("td_error"), delta, 1e-15);
  harness.tick();
  w = harness.block().weights(harness.context());
  EXPECT_NEAR(w[0], -1.0 / 15.0 + 0.04 * delta, 1e-15);
  EXPECT_NEAR(w[1], -0.08 / 22.5 + 0.04 * delta, 1e-15);
}

// The TD error is the Critic's: from the same weights, the same value and delta.
TEST(CriticTd0, TdErrorAndValueAreTheCriticsForTheSameWeights) {
  const int n = 5;
  CriticParams params;
  params.kind = CriticKind::kTd0;
  Harness td0("critic", n, params, kPeriod);
  testing::BlockHarness<Critic> critic("critic", n, CriticParams{}, kPeriod);
  std::mt19937_64 generator(31);
  std::normal_distribution<double> normal;
  auto random_vector = [&] {
    Vector v(n);
    for (int i = 0; i < n; ++i) v[i] = normal(generator);
    return v;
  };
  for (int t = 0; t < 40; ++t) {
    const Vector w = random_vector();
    td0.block().mutable_weights(td0.context()) = w;
    critic.block().mutable_weights(critic.context()) = w;
    const Vector phi = random_vector();
    const double reward = normal(generator);
    const bool failed = t % 7 == 6;
    set_tick(td0, phi, reward, failed);
    set_tick(critic, phi, reward, failed);
    EXPECT_EQ(td0.scalar_output("value"), critic.scalar_output("value")) << "tick " << t;
    EXPECT_EQ(td0.scalar_output("td_error"), critic.scalar_output("td_error")) << "tick " << t;
    td0.tick();
    critic.tick();
  }
}

TEST(CriticTd0, FrozenKeepsTheWeights) {
  CriticParams params;
  params.kind = CriticKind::kTd0;
  params.frozen = true;
  Harness harness("critic", 2, params, kPeriod);
  harness.block().mutable_weights(harness.context()) = vector2(0.3, -0.2);
  for (int t = 0; t < 5; ++t) {
    set_tick(harness, vector2(1.0, 0.5 * t), -1.0, t == 4);
    if (t > 0) {
      EXPECT_NE(harness.scalar_output("td_error"), 0.0);
    }
    harness.tick();
    EXPECT_EQ(harness.block().weights(harness.context()), vector2(0.3, -0.2)) << "tick " << t;
  }
}

TEST(CriticTd0, StartTrialForgetsThePreviousTickButKeepsTheWeights) {
  CriticParams params;
  params.kind = CriticKind::kTd0;
  Harness harness("critic", 2, params, kPeriod);
  set_tick(harness, vector2(1.0, 0.0), 0.0, false);
  harness.tick();
  set_tick(harness, vector2(0.0, 1.0), -1.0, true);
  harness.tick();
  const Vector learnt = harness.block().weights(harness.context());
  ASSERT_NE(learnt, vector2(0.0, 0.0));

  harness.context().reset_trial_state();
  harness.restart_time();
  EXPECT_EQ(harness.state_part("has_previous")[0], 0.0);
  set_tick(harness, vector2(1.0, 1.0), -1.0, false);
  EXPECT_EQ(harness.scalar_output("td_error"), 0.0);
  harness.tick();
  EXPECT_EQ(harness.block().weights(harness.context()), learnt);
}

TEST(CriticTd0, IsACriticLearnerOfItsWeightsAndKeepsNoTrace) {
  CriticParams params;
  params.kind = CriticKind::kTd0;
  Harness harness("critic", 3, params, kPeriod);
  std::vector<std::string> names;
  for (const StatePart& part : harness.block().discrete_state_parts()) names.push_back(part.name);
  EXPECT_THAT(names, ElementsAre("weights", "previous_features", "has_previous"));
  const Learner& learner = harness.block();
  EXPECT_EQ(learner.learner_role(), Learner::Role::kCritic);
  EXPECT_EQ(&learner.learner_block(), &harness.block());
  EXPECT_EQ(learner.num_features(), 3);
  const auto parts = learner.learnt_parts();
  ASSERT_EQ(parts.size(), 1u);
  EXPECT_EQ(parts[0].name, "weights");
  EXPECT_EQ(parts[0].size, 3);
  Vector w(3);
  w << 1.0, 2.0, 3.0;
  learner.mutable_learnt(harness.context(), parts[0]) = w;
  EXPECT_EQ(harness.block().weights(harness.context()), w);
}

TEST(CriticParams, KindIsFirstEpsilonLastAndTheDefaultIsThePapers) {
  EXPECT_THAT(testing::declared_keys<CriticParams>(),
              ElementsAre("kind", "beta", "gamma", "lambda", "epsilon"));
  EXPECT_EQ(CriticParams{}.kind, CriticKind::kTdLambda);
  EXPECT_EQ(CriticParams{}.epsilon, 1e-3);
  for (const CriticKind kind : {CriticKind::kTdLambda, CriticKind::kTd0}) {
    EXPECT_EQ(parse_critic_kind(to_string(kind)), kind);
  }
}

TEST(CriticTd0, RejectsBadParametersNamingTheKey) {
  CriticParams zero_epsilon;
  zero_epsilon.epsilon = 0.0;
  EXPECT_THAT(
      [&] { Critic("critic", 4, zero_epsilon, kPeriod); },
      ThrowsMessage<std::invalid_argument>(StrEq("critic.epsilon must be finite and > 0; got 0")));
  CriticParams bad_gamma;
  bad_gamma.gamma = 1.5;
  EXPECT_THAT(
      [&] { Critic("critic", 4, bad_gamma, kPeriod); },
      ThrowsMessage<std::invalid_argument>(StrEq("critic.gamma must be in (0, 1]; got 1.5")));
  CriticParams unknown;
  unknown.kind = static_cast<CriticKind>(5);
  EXPECT_THAT(
      [&] { Critic("critic", 4, unknown, kPeriod); },
      ThrowsMessage<std::invalid_argument>(StrEq("critic.kind must be one of td_lambda, td0")));
  EXPECT_THAT([] { parse_critic_kind("td1"); },
              ThrowsMessage<std::invalid_argument>(
                  StrEq("critic.kind must be td_lambda or td0; got 'td1'")));
  EXPECT_THAT([] { Critic("critic", 0, CriticParams{}, kPeriod); },
              ThrowsMessage<std::invalid_argument>(
                  HasSubstr("the critic needs at least 1 feature; got 0")));
  EXPECT_THAT(
      [] { Critic("critic", 4, CriticParams{}, 0.0); },
      ThrowsMessage<std::invalid_argument>(StrEq("trial.period must be finite and > 0; got 0")));
}

}  // namespace
}  // namespace cbbg::blocks
