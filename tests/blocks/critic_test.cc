#include "cbbg/blocks/critic.h"

#include <cmath>
#include <stdexcept>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "cbbg/framework/block_context.h"
#include "cbbg/framework/block_harness.h"
#include "cbbg/framework/diagram_builder.h"
#include "cbbg/framework/random.h"
#include "cbbg/framework/simulator.h"

namespace cbbg::blocks {
namespace {

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
void set_tick(Harness& harness, const Vector& features, double reward, bool failed) {
  harness.set_input("features", features);
  harness.set_input("reward", reward);
  harness.set_input("failed", failed ? 1.0 : 0.0);
}

TEST(Critic, ValueIsTheWeightsDotTheFeatures) {
  Harness harness("critic", 3, CriticParams{}, kPeriod);
  Vector w(3);
  w << 1.0, 2.0, 3.0;
  harness.block().mutable_weights(harness.context()) = w;
  Vector phi(3);
  phi << 0.5, 0.25, 1.0;
  set_tick(harness, phi, 0.0, false);
  EXPECT_EQ(harness.scalar_output("value"), 4.0);  // 0.5 + 0.5 + 3
  phi << -1.0, 0.0, 2.0;
  set_tick(harness, phi, 0.0, false);
  EXPECT_EQ(harness.scalar_output("value"), 5.0);
}

// gamma = 0.8, lambda = 0.5, beta = 0.1 over four ticks, every number worked out by hand.
TEST(Critic, LearnsByTdLambdaAsWorkedOutByHand) {
  CriticParams params;
  params.gamma = 0.8;
  params.lambda = 0.5;
  params.beta = 0.1;
  Harness harness("critic", 2, params, kPeriod);

  // t = 0: no previous tick, so no TD error and nothing learnt; phi(s_0) is remembered.
  set_tick(harness, vector2(1.0, 0.0), -1.0, false);
  EXPECT_EQ(harness.scalar_output("td_error"), 0.0);
  harness.tick();
  EXPECT_EQ(harness.block().weights(harness.context()), vector2(0.0, 0.0));

  // t = 1: delta = -1 + 0.8 * 0 - 0 = -1; z = (1, 0); w = (-0.1, 0).
  set_tick(harness, vector2(0.0, 1.0), -1.0, false);
  EXPECT_EQ(harness.scalar_output("td_error"), -1.0);
  harness.tick();
  Vector w = harness.block().weights(harness.context());
  EXPECT_NEAR(w[0], -0.1, 1e-15);
  EXPECT_EQ(w[1], 0.0);

  // t = 2: V(s_2) = -0.1; delta = 0 + 0.8 (-0.1) - 0 = -0.08; z = 0.4 (1, 0) + (0, 1);
  // w = (-0.1, 0) - 0.008 (0.4, 1) = (-0.1032, -0.008).
  set_tick(harness, vector2(1.0, 1.0), 0.0, false);
  EXPECT_NEAR(harness.scalar_output("value"), -0.1, 1e-15);
  EXPECT_NEAR(harness.scalar_output("td_error"), -0.08, 1e-15);
  harness.tick();
  w = harness.block().weights(harness.context());
  EXPECT_NEAR(w[0], -0.1032, 1e-15);
  EXPECT_NEAR(w[1], -0.008, 1e-15);

  // t = 3, a failure: V(s_3) counts as 0; delta = -1 - (-0.1032 - 0.008) = -0.8888;
  // z = 0.4 (0.4, 1) + (1, 1) = (1.16, 1.4); w += 0.1 (-0.8888) z.
  set_tick(harness, vector2(0.5, 0.5), -1.0, true);
  EXPECT_NEAR(harness.scalar_output("value"), -0.0556, 1e-15);  // the output still shows V
  EXPECT_NEAR(harness.scalar_output("td_error"), -0.8888, 1e-15);
  harness.tick();
  w = harness.block().weights(harness.context());
  EXPECT_NEAR(w[0], -0.1032 - 0.08888 * 1.16, 1e-15);
  EXPECT_NEAR(w[1], -0.008 - 0.08888 * 1.4, 1e-15);
}

TEST(Critic, StartTrialClearsTheTraceAndPreviousTickButKeepsTheWeights) {
  Harness harness("critic", 2, CriticParams{}, kPeriod);
  set_tick(harness, vector2(1.0, 0.0), 0.0, false);
  harness.tick();
  set_tick(harness, vector2(0.0, 1.0), -1.0, true);
  harness.tick();
  const Vector learnt = harness.block().weights(harness.context());
  ASSERT_NE(learnt, vector2(0.0, 0.0));

  harness.context().reset_trial_state();
  harness.restart_time();
  // The first tick of the new trial must not learn from the last tick of the previous one.
  set_tick(harness, vector2(1.0, 1.0), -1.0, false);
  EXPECT_EQ(harness.scalar_output("td_error"), 0.0);
  harness.tick();
  EXPECT_EQ(harness.block().weights(harness.context()), learnt);
  // The trace restarted from zero: the next update uses z = phi(s_0) only.
  set_tick(harness, vector2(0.0, 0.0), -1.0, false);
  const double delta = harness.scalar_output("td_error");
  EXPECT_NEAR(delta, -1.0 - learnt.sum(), 1e-15);
  harness.tick();
  const Vector w = harness.block().weights(harness.context());
  EXPECT_NEAR(w[0], learnt[0] + 0.1 * delta, 1e-15);
  EXPECT_NEAR(w[1], learnt[1] + 0.1 * delta, 1e-15);
}

// Sutton's random walk: states 1..5 between terminals 0 and 6, start at 3, a fair step each
// tick, reward 1 on entering 6. Its outputs are those of the controller's feature, reward
// and failure blocks: one-hot features of s_t, r_{t-1}, and "failed" on reaching a terminal
// (which then ends the episode after the critic's update, like the FailureDetector).
class RandomWalk final : public Block {
 public:
  static constexpr int kStart = 3;
  static constexpr int kRightEnd = 6;

  explicit RandomWalk(std::string name) : Block(std::move(name)) {
    declare_discrete_state("position", Vector::Constant(1, kStart), StateLifetime::kPerTrial);
    declare_output_port("features", kRightEnd - 1,
                        [](const BlockContext& context, VectorRef features) {
                          features.setZero();
                          const int s = position(context);
                          if (s > 0 && s < kRightEnd) features[s - 1] = 1.0;
                        },
                        {});
    declare_output_port("reward", 1,
                        [](const BlockContext& context, VectorRef reward) {
                          reward[0] = position(context) == kRightEnd ? 1.0 : 0.0;
                        },
                        {});
    declare_output_port("failed", 1,
                        [](const BlockContext& context, VectorRef failed) {
                          failed[0] = terminal(position(context)) ? 1.0 : 0.0;
                        },
                        {});
    declare_periodic_update(kPeriod, 0.0, [](BlockContext& context, VectorRef next) {
      const int s = position(context);
      if (terminal(s)) return EventStatus::terminate("the walk reached an end");
      next[0] = s + (draw_uniform(context.random_generator()) < 0.5 ? -1 : 1);
      return EventStatus::succeeded();
    });
  }

 private:
  static int position(const BlockContext& context) {
    return static_cast<int>(context.discrete_state()[0]);
  }
  static bool terminal(int s) { return s == 0 || s == kRightEnd; }
};

TEST(Critic, ConvergesToTrueValuesOnRandomWalk) {
  // With gamma = 1 the true values are the probabilities of ending right: s / 6. With a
  // constant beta, w keeps fluctuating around them by about sqrt(beta); beta = 2e-5 and
  // 1e6 episodes gave a largest error of 0.0008 to 0.0035 over root seeds 1 to 8.
  CriticParams params;
  params.gamma = 1.0;
  params.lambda = 0.8;
  params.beta = 2e-5;
  DiagramBuilder builder("random_walk");
  const auto& walk = builder.emplace<RandomWalk>("walk");
  const auto& critic = builder.emplace<Critic>("critic", 5, params, kPeriod);
  for (const char* port : {"features", "reward", "failed"}) {
    builder.connect(walk, port, critic, port);
  }
  const auto diagram = builder.build();
  Simulator simulator(*diagram, SimulatorOptions{}, 11);
  Context& context = simulator.context();

  const int episodes = 1000000;
  for (int episode = 0; episode < episodes; ++episode) {
    const SimulationStatus status = simulator.advance_to(1e6);
    ASSERT_TRUE(status.terminated);
    context.reset_trial_state();  // the walk back at its start, the critic's trace cleared
    simulator.initialize();
  }
  const Vector w = critic.weights(context);
  for (int s = 1; s <= 5; ++s) {
    EXPECT_NEAR(w[s - 1], s / 6.0, 1e-2) << "state " << s;
  }
}

TEST(Critic, RejectsParametersOutsideTheirRanges) {
  auto make = [](double beta, double gamma, double lambda) {
    CriticParams params;
    params.beta = beta;
    params.gamma = gamma;
    params.lambda = lambda;
    return [params] { Critic("critic", 4, params, kPeriod); };
  };
  EXPECT_THAT(make(0.1, 0.0, 0.8),
              ThrowsMessage<std::invalid_argument>(StrEq("critic.gamma must be in (0, 1]; got 0")));
  EXPECT_THAT(make(0.1, 1.5, 0.8), ThrowsMessage<std::invalid_argument>(
                                       StrEq("critic.gamma must be in (0, 1]; got 1.5")));
  EXPECT_THAT(make(0.1, 0.8, 1.0), ThrowsMessage<std::invalid_argument>(
                                       StrEq("critic.lambda must be in [0, 1); got 1")));
  EXPECT_THAT(make(0.1, 0.8, -0.1), ThrowsMessage<std::invalid_argument>(
                                        StrEq("critic.lambda must be in [0, 1); got -0.1")));
  EXPECT_THAT(make(NAN, 0.8, 0.8), ThrowsMessage<std::invalid_argument>(
                                       StrEq("critic.beta must be finite and > 0; got nan")));
  EXPECT_THAT(make(0.1, INFINITY, 0.8), ThrowsMessage<std::invalid_argument>(
                                            StrEq("critic.gamma must be in (0, 1]; got inf")));
  EXPECT_THAT([] { Critic("critic", 0, CriticParams{}, kPeriod); },
              ThrowsMessage<std::invalid_argument>(
                  HasSubstr("the critic needs at least 1 feature; got 0")));
  EXPECT_THAT([] { Critic("critic", 4, CriticParams{}, -0.01); },
              ThrowsMessage<std::invalid_argument>(
                  StrEq("trial.period must be finite and > 0; got -0.01")));
}

}  // namespace
}  // namespace cbbg::blocks
