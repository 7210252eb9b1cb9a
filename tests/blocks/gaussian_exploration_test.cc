#include "cbbg/blocks/gaussian_exploration.h"

#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "cbbg/blocks/boltzmann_sampler.h"
#include "cbbg/blocks/exploration_params.h"
#include "cbbg/framework/block_harness.h"
#include "key_order.h"

namespace cbbg::blocks {
namespace {

using ::testing::ElementsAre;
using ::testing::StrEq;
using ::testing::ThrowsMessage;
using Harness = testing::BlockHarness<GaussianExploration>;

constexpr double kPeriod = Harness::kPeriod;

ExplorationParams gaussian(double sigma, double half_life = 0.0) {
  ExplorationParams params;
  params.kind = ExplorationKind::kGaussian;
  params.sigma = sigma;
  params.half_life = half_life;
  return params;
}

TEST(GaussianExploration, OutputIsTheActorActionPlusSigmaTimesTheHeldDraw) {
  Harness harness("sampler", gaussian(0.75), kPeriod);
  harness.reseed(3);
  std::vector<double> draws;
  for (int t = 0; t < 50; ++t) {
    const double a_a = 0.1 * t - 2.0;
    harness.set_input("actor_action", a_a);
    harness.tick();
    const double eps = harness.state_part("noise")[0];
    EXPECT_EQ(harness.scalar_output("exploration_action"), a_a + 0.75 * eps) << "tick " << t;
    draws.push_back(eps);
  }
  // A fresh standard normal at every tick.
  for (std::size_t t = 1; t < draws.size(); ++t) {
    EXPECT_NE(draws[t], draws[t - 1]);
  }
}

TEST(GaussianExploration, MeanAndVarianceMatchOver100000Draws) {
  Harness harness("sampler", gaussian(2.0), kPeriod);
  harness.reseed(1);
  harness.set_input("actor_action", 0.7);
  const int n = 100000;
  double sum = 0.0;
  double sum_squares = 0.0;
  for (int t = 0; t < n; ++t) {
    harness.tick();
    const double value = harness.scalar_output("exploration_action");
    sum += value;
    sum_squares += value * value;
  }
  const double mean = sum / n;
  const double variance = sum_squares / n - mean * mean;
  // Five standard errors: of the mean, sigma / sqrt(n); of the variance, sigma^2 sqrt(2 / n).
  EXPECT_NEAR(mean, 0.7, 5.0 * 2.0 / std::sqrt(n));
  EXPECT_NEAR(variance, 4.0, 5.0 * 4.0 * std::sqrt(2.0 / n));
}

// Common random numbers: at the same path and seed, the Gaussian arm's eps is the Boltzmann
// sampler's, tick by tick and across a new trial. With sigma = sqrt(K_B T / 2) = 1 the two
// actions are the same bits.
TEST(GaussianExploration, DrawsTheSameEpsAsTheBoltzmannSamplerForTheSameSeedAndPath) {
  Harness mine("sampler", gaussian(1.0), kPeriod);
  testing::BlockHarness<BoltzmannSampler> boltzmann("sampler", SamplerParams{}, kPeriod);
  mine.reseed(42);
  boltzmann.reseed(42);
  boltzmann.set_input("temperature", 2.0);  // K_B T / 2 = 1
  for (int trial = 0; trial < 2; ++trial) {
    for (int t = 0; t < 200; ++t) {
      const double a_a = std::sin(0.1 * t);
      mine.set_input("actor_action", a_a);
      boltzmann.set_input("actor_action", a_a);
      mine.tick();
      boltzmann.tick();
      ASSERT_EQ(mine.state_part("noise")[0], boltzmann.state_part("noise")[0])
          << "trial " << trial << ", tick " << t;
      ASSERT_EQ(mine.scalar_output("exploration_action"),
                boltzmann.scalar_output("exploration_action"));
    }
    for (auto* context : {&mine.context(), &boltzmann.context()}) context->reset_trial_state();
    mine.restart_time();
    boltzmann.restart_time();
  }
}

TEST(GaussianExploration, AnotherPathDrawsAnotherStream) {
  Harness sampler("sampler", gaussian(1.0), kPeriod);
  Harness elsewhere("exploration", gaussian(1.0), kPeriod);
  for (Harness* harness : {&sampler, &elsewhere}) {
    harness->reseed(42);
    harness->set_input("actor_action", 0.0);
    harness->tick();
  }
  EXPECT_NE(sampler.state_part("noise")[0], elsewhere.state_part("noise")[0]);
}

TEST(GaussianExploration, AnnealingHalvesSigmaAfterHalfLifeOfLearningTimeAcrossTrials) {
  const double sigma = 1.5;
  Harness harness("sampler", gaussian(sigma, 0.5), kPeriod);
  EXPECT_EQ(harness.block().sigma_at(0.0), sigma);
  EXPECT_EQ(harness.block().sigma_at(0.5), sigma / 2.0);
  EXPECT_EQ(harness.block().sigma_at(1.0), sigma / 4.0);
  harness.set_input("actor_action", 0.25);
  // 30 ticks of a first trial, 20 of a second: half a second of learning.
  for (int t = 0; t < 30; ++t) harness.tick();
  EXPECT_NEAR(harness.block().elapsed(harness.context()), 0.3, 1e-12);
  harness.context().reset_trial_state();
  harness.restart_time();
  EXPECT_NEAR(harness.state_part("elapsed")[0], 0.3, 1e-12);  // persistent: not reset
  for (int t = 0; t < 20; ++t) {
    harness.tick();
    const double elapsed = 0.3 + (t + 1) * kPeriod;
    EXPECT_NEAR(harness.state_part("elapsed")[0], elapsed, 1e-12);
    const double eps = harness.state_part("noise")[0];
    EXPECT_NEAR(harness.scalar_output("exploration_action"),
                0.25 + sigma * std::exp2(-elapsed / 0.5) * eps, 1e-12);
  }
  const double eps = harness.state_part("noise")[0];
  ASSERT_GT(std::abs(eps), 0.01);
  EXPECT_NEAR((harness.scalar_output("exploration_action") - 0.25) / eps, sigma / 2.0, 1e-12);
}

TEST(GaussianExploration, AFixedSigmaIgnoresTheLearningTime) {
  Harness harness("sampler", gaussian(1.5), kPeriod);
  harness.set_input("actor_action", 0.0);
  for (int t = 0; t < 100; ++t) harness.tick();
  EXPECT_NEAR(harness.state_part("elapsed")[0], 1.0, 1e-12);  // counted all the same
  EXPECT_EQ(harness.block().sigma_at(1e6), 1.5);
  EXPECT_EQ(harness.scalar_output("exploration_action"), 1.5 * harness.state_part("noise")[0]);
}

TEST(ExplorationParams, KindsAreTheirWordsAndTheDefaultIsThePapers) {
  EXPECT_EQ(ExplorationParams{}.kind, ExplorationKind::kBoltzmann);
  for (const ExplorationKind kind :
       {ExplorationKind::kBoltzmann, ExplorationKind::kGaussian, ExplorationKind::kOu}) {
    EXPECT_EQ(parse_exploration_kind(to_string(kind)), kind);
  }
  EXPECT_EQ(to_string(ExplorationKind::kOu), "ou");
  EXPECT_THAT(testing::declared_keys<ExplorationParams>(),
              ElementsAre("kind", "sigma", "half_life", "ou_theta"));
  EXPECT_NEAR(ExplorationParams{}.sigma, std::sqrt(1.0 * 10.0 / 4.0), 0.005);  // sqrt(K_B k1 / 4)
}

TEST(ExplorationParams, RejectsBadParametersNamingTheKey) {
  EXPECT_THAT([] { parse_exploration_kind("normal"); },
              ThrowsMessage<std::invalid_argument>(
                  StrEq("exploration.kind must be boltzmann, gaussian or ou; got 'normal'")));
  ExplorationParams unknown;
  unknown.kind = static_cast<ExplorationKind>(7);
  EXPECT_THAT([&] { unknown.validate(); },
              ThrowsMessage<std::invalid_argument>(
                  StrEq("exploration.kind must be one of boltzmann, gaussian, ou")));
  EXPECT_THAT([] { GaussianExploration("sampler", gaussian(0.0), kPeriod); },
              ThrowsMessage<std::invalid_argument>(
                  StrEq("exploration.sigma must be finite and > 0; got 0")));
  EXPECT_THAT([] { GaussianExploration("sampler", gaussian(NAN), kPeriod); },
              ThrowsMessage<std::invalid_argument>(
                  StrEq("exploration.sigma must be finite and > 0; got nan")));
  EXPECT_THAT([] { GaussianExploration("sampler", gaussian(1.0, -1.0), kPeriod); },
              ThrowsMessage<std::invalid_argument>(
                  StrEq("exploration.half_life must be finite and >= 0; got -1")));
  EXPECT_THAT([] { GaussianExploration("sampler", gaussian(1.0, INFINITY), kPeriod); },
              ThrowsMessage<std::invalid_argument>(
                  StrEq("exploration.half_life must be finite and >= 0; got inf")));
  EXPECT_THAT(
      [] { GaussianExploration("sampler", gaussian(1.0), 0.0); },
      ThrowsMessage<std::invalid_argument>(StrEq("trial.period must be finite and > 0; got 0")));
}

}  // namespace
}  // namespace cbbg::blocks
