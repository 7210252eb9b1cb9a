#include "cbbg/blocks/ou_exploration.h"

#include <cmath>
#include <stdexcept>
#include <vector>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "cbbg/blocks/exploration_params.h"
#include "cbbg/blocks/gaussian_exploration.h"
#include "cbbg/framework/block_harness.h"

namespace cbbg::blocks {
namespace {

using ::testing::StrEq;
using ::testing::ThrowsMessage;
using Harness = testing::BlockHarness<OuExploration>;

constexpr double kPeriod = Harness::kPeriod;

ExplorationParams ou(double sigma, double theta) {
  ExplorationParams params;
  params.kind = ExplorationKind::kOu;
  params.sigma = sigma;
  params.ou_theta = theta;
  return params;
}

// With e^(-theta Ts) = 0 nothing is remembered: the Gaussian's values with a fixed sigma, the
// same bits, tick by tick and across a new trial.
TEST(OuExploration, AHugeThetaGivesTheGaussiansValuesBitForBit) {
  Harness ou_harness("sampler", ou(1.3, 1e6), kPeriod);
  ExplorationParams fixed = ou(1.3, 1e6);
  fixed.kind = ExplorationKind::kGaussian;
  testing::BlockHarness<GaussianExploration> gaussian("sampler", fixed, kPeriod);
  ou_harness.reseed(9);
  gaussian.reseed(9);
  for (int trial = 0; trial < 2; ++trial) {
    for (int t = 0; t < 300; ++t) {
      const double a_a = std::cos(0.05 * t);
      ou_harness.set_input("actor_action", a_a);
      gaussian.set_input("actor_action", a_a);
      ou_harness.tick();
      gaussian.tick();
      ASSERT_EQ(ou_harness.scalar_output("exploration_action"),
                gaussian.scalar_output("exploration_action"))
          << "trial " << trial << ", tick " << t;
    }
    ou_harness.context().reset_trial_state();
    gaussian.context().reset_trial_state();
    ou_harness.restart_time();
    gaussian.restart_time();
  }
}

// x_0 = sigma eps_0, x_k = e^(-theta Ts) x_{k-1} + sigma sqrt(1 - e^(-2 theta Ts)) eps_k, with
// the eps of a GaussianExploration of sigma 1 at the same path and seed (the same draws).
TEST(OuExploration, FollowsTheExactDiscretisationTickByTick) {
  const double sigma = 2.0;
  const double theta = 5.0;
  Harness harness("sampler", ou(sigma, theta), kPeriod);
  testing::BlockHarness<GaussianExploration> draws("sampler", ou(1.0, theta), kPeriod);
  harness.reseed(5);
  draws.reseed(5);
  harness.set_input("actor_action", 0.5);
  draws.set_input("actor_action", 0.0);
  const double decay = std::exp(-theta * kPeriod);
  const double innovation = sigma * std::sqrt(1.0 - std::exp(-2.0 * theta * kPeriod));
  harness.simulator().initialize();
  draws.simulator().initialize();
  double x = sigma * draws.state_part("noise")[0];
  EXPECT_EQ(harness.state_part("noise")[0], x);  // the stationary law: x_0 = sigma eps_0
  for (int t = 0; t < 100; ++t) {
    harness.tick();
    draws.tick();
    x = decay * x + innovation * draws.state_part("noise")[0];
    EXPECT_NEAR(harness.state_part("noise")[0], x, 1e-12) << "tick " << t;
    EXPECT_NEAR(harness.scalar_output("exploration_action"), 0.5 + x, 1e-12) << "tick " << t;
  }
}

// Over many ticks: variance sigma^2 and lag-one autocorrelation e^(-theta Ts). For an AR(1)
// of coefficient rho over n ticks, the standard error of the variance is about
// sigma^2 sqrt(2 (1 + rho^2) / ((1 - rho^2) n)) and of rho sqrt((1 - rho^2) / n); five of
// each would still catch e^(-2 theta Ts) for rho, or an Euler step's sqrt(2 theta Ts) for
// the innovation.
TEST(OuExploration, StationaryVarianceAndLagOneAutocorrelation) {
  const double sigma = 1.58;
  const double theta = 5.0;
  Harness harness("sampler", ou(sigma, theta), kPeriod);
  harness.reseed(13);
  harness.set_input("actor_action", 0.0);
  const int n = 400000;
  std::vector<double> x(n);
  for (int t = 0; t < n; ++t) {
    harness.tick();
    x[t] = harness.scalar_output("exploration_action");
  }
  double mean = 0.0;
  for (const double value : x) mean += value;
  mean /= n;
  double variance = 0.0;
  double lagged = 0.0;
  for (int t = 0; t < n; ++t) {
    variance += (x[t] - mean) * (x[t] - mean);
    if (t > 0) lagged += (x[t] - mean) * (x[t - 1] - mean);
  }
  variance /= n;
  const double rho = std::exp(-theta * kPeriod);
  const double correlation = lagged / n / variance;
  const double sigma2 = sigma * sigma;
  const double ratio = (1.0 + rho * rho) / (1.0 - rho * rho);
  EXPECT_NEAR(mean, 0.0, 5.0 * sigma * std::sqrt((1.0 + rho) / (1.0 - rho) / n));
  EXPECT_NEAR(variance, sigma2, 5.0 * sigma2 * std::sqrt(2.0 * ratio / n));
  EXPECT_NEAR(correlation, rho, 5.0 * std::sqrt((1.0 - rho * rho) / n));
}

TEST(OuExploration, ANewTrialDrawsTheNoiseAfreshFromTheStationaryLaw) {
  Harness harness("sampler", ou(1.0, 5.0), kPeriod);
  harness.set_input("actor_action", 0.0);
  for (int t = 0; t < 10; ++t) harness.tick();
  const double last = harness.state_part("noise")[0];
  harness.context().reset_trial_state();
  EXPECT_EQ(harness.state_part("noise")[0], 0.0);
  harness.restart_time();
  const double first = harness.state_part("noise")[0];
  EXPECT_NE(first, 0.0);
  EXPECT_NE(first, last);
}

TEST(OuExploration, RejectsBadParametersNamingTheKey) {
  EXPECT_THAT([] { OuExploration("sampler", ou(1.0, 0.0), kPeriod); },
              ThrowsMessage<std::invalid_argument>(
                  StrEq("exploration.ou_theta must be finite and > 0; got 0")));
  EXPECT_THAT([] { OuExploration("sampler", ou(1.0, -2.0), kPeriod); },
              ThrowsMessage<std::invalid_argument>(
                  StrEq("exploration.ou_theta must be finite and > 0; got -2")));
  EXPECT_THAT([] { OuExploration("sampler", ou(-1.0, 5.0), kPeriod); },
              ThrowsMessage<std::invalid_argument>(
                  StrEq("exploration.sigma must be finite and > 0; got -1")));
  EXPECT_THAT(
      [] { OuExploration("sampler", ou(1.0, 5.0), NAN); },
      ThrowsMessage<std::invalid_argument>(StrEq("trial.period must be finite and > 0; got nan")));
}

}  // namespace
}  // namespace cbbg::blocks
