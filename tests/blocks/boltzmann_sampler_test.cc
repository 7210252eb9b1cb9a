#include "cbbg/blocks/boltzmann_sampler.h"

#include <cmath>
#include <stdexcept>
#include <vector>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "cbbg/framework/block_harness.h"
#include "cbbg/framework/diagram_builder.h"
#include "cbbg/framework/simulator.h"

namespace cbbg::blocks {
namespace {

using ::testing::StrEq;
using ::testing::ThrowsMessage;
using Harness = testing::BlockHarness<BoltzmannSampler>;

constexpr double kPeriod = Harness::kPeriod;

// a_E at each of `ticks` ticks for a_A = 0.7, T = 3, simulated with `root_seed`.
std::vector<double> draws(std::uint64_t root_seed, int ticks) {
  Harness harness("sampler", SamplerParams{}, kPeriod);
  harness.reseed(root_seed);
  harness.set_input("actor_action", 0.7);
  harness.set_input("temperature", 3.0);
  std::vector<double> values;
  for (int t = 0; t < ticks; ++t) {
    values.push_back(harness.scalar_output("exploration_action"));
    harness.tick();
  }
  return values;
}

TEST(BoltzmannSampler, MeanAndVarianceMatchOver100000Draws) {
  const int n = 100000;
  const std::vector<double> values = draws(1, n);
  double sum = 0.0;
  double sum_squares = 0.0;
  for (const double value : values) {
    sum += value;
    sum_squares += value * value;
  }
  const double mean = sum / n;
  const double variance = sum_squares / n - mean * mean;
  const double expected_variance = 1.0 * 3.0 / 2.0;  // K_B T / 2
  // Five standard errors: of the mean, sigma / sqrt(n); of the variance, sigma^2 sqrt(2 / n).
  EXPECT_NEAR(mean, 0.7, 5.0 * std::sqrt(expected_variance / n));
  EXPECT_NEAR(variance, expected_variance, 5.0 * expected_variance * std::sqrt(2.0 / n));
}

TEST(BoltzmannSampler, SameSeedGivesSameDraws) {
  EXPECT_EQ(draws(42, 1000), draws(42, 1000));
  EXPECT_NE(draws(42, 1000), draws(43, 1000));
}

TEST(BoltzmannSampler, TwoSamplersInOneDiagramAreNotCorrelated) {
  DiagramBuilder builder("cbbg");
  const auto& first = builder.emplace<BoltzmannSampler>("sampler_a", SamplerParams{}, kPeriod);
  const auto& second = builder.emplace<BoltzmannSampler>("sampler_b", SamplerParams{}, kPeriod);
  for (const auto* sampler : {&first, &second}) {
    builder.fix_input(sampler->input_port("actor_action"), Vector::Zero(1));
    builder.fix_input(sampler->input_port("temperature"), Vector::Constant(1, 2.0));  // var 1
  }
  const auto diagram = builder.build();
  Simulator simulator(*diagram, SimulatorOptions{}, 7);
  const int n = 100000;
  double sum_a = 0.0, sum_b = 0.0, sum_aa = 0.0, sum_bb = 0.0, sum_ab = 0.0;
  for (int t = 0; t < n; ++t) {
    simulator.advance_to((t + 0.5) * kPeriod);
    const double a =
        diagram->eval_output(simulator.context(), first.output_port("exploration_action"))[0];
    const double b =
        diagram->eval_output(simulator.context(), second.output_port("exploration_action"))[0];
    sum_a += a;
    sum_b += b;
    sum_aa += a * a;
    sum_bb += b * b;
    sum_ab += a * b;
  }
  const double cov = sum_ab / n - (sum_a / n) * (sum_b / n);
  const double var_a = sum_aa / n - (sum_a / n) * (sum_a / n);
  const double var_b = sum_bb / n - (sum_b / n) * (sum_b / n);
  const double correlation = cov / std::sqrt(var_a * var_b);
  // Independent draws: the sample correlation has standard error 1 / sqrt(n).
  EXPECT_LT(std::abs(correlation), 5.0 / std::sqrt(n));
  EXPECT_GT(var_a, 0.9);
  EXPECT_GT(var_b, 0.9);
}

TEST(BoltzmannSampler, ZeroTemperatureGivesTheActorAction) {
  Harness harness("sampler", SamplerParams{}, kPeriod);
  harness.set_input("actor_action", -1.25);
  harness.set_input("temperature", 0.0);
  for (int t = 0; t < 5; ++t) {
    harness.tick();
    EXPECT_EQ(harness.scalar_output("exploration_action"), -1.25);
  }
}

TEST(BoltzmannSampler, DeviationIsSqrtOfKbTOverTwoTimesTheHeldDraw) {
  SamplerParams literal;
  literal.k_b = 1.38e-23;  // the paper's Boltzmann constant: no exploration to speak of
  Harness harness("sampler", literal, kPeriod);
  harness.set_input("actor_action", 2.0);
  harness.set_input("temperature", 10.0);
  harness.tick();
  const double eps = harness.state_part("noise")[0];
  ASSERT_NE(eps, 0.0);
  EXPECT_EQ(harness.scalar_output("exploration_action"),
            2.0 + std::sqrt(1.38e-23 * 10.0 / 2.0) * eps);
  EXPECT_LT(std::abs(harness.scalar_output("exploration_action") - 2.0), 1e-10);
}

TEST(BoltzmannSampler, RejectsNonPositiveOrNonFiniteKb) {
  SamplerParams zero;
  zero.k_b = 0.0;
  EXPECT_THAT(
      [&] { BoltzmannSampler("sampler", zero, kPeriod); },
      ThrowsMessage<std::invalid_argument>(StrEq("sampler.k_b must be finite and > 0; got 0")));
  SamplerParams infinite;
  infinite.k_b = INFINITY;
  EXPECT_THAT(
      [&] { BoltzmannSampler("sampler", infinite, kPeriod); },
      ThrowsMessage<std::invalid_argument>(StrEq("sampler.k_b must be finite and > 0; got inf")));
}

}  // namespace
}  // namespace cbbg::blocks
