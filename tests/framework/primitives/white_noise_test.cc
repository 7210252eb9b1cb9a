#include "cbbg/framework/primitives/white_noise.h"

#include <cmath>
#include <stdexcept>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "cbbg/framework/diagram_builder.h"
#include "cbbg/framework/simulator.h"

namespace cbbg {
namespace {

using ::testing::ThrowsMessage;

// A simulator of a diagram holding one WhiteNoise "noise", logged every `log_period`.
struct NoiseRun {
  std::unique_ptr<Diagram> diagram;
  std::unique_ptr<Simulator> simulator;
  SignalLog* log;

  NoiseRun(const Vector& mean, const Vector& deviation, double period, double log_period,
           std::uint64_t seed) {
    DiagramBuilder builder("top");
    builder.emplace<WhiteNoise>("noise", mean, deviation, period);
    diagram = builder.build();
    simulator = std::make_unique<Simulator>(*diagram, SimulatorOptions{}, seed);
    log = &simulator->add_log(diagram->block("noise").output_port("y"), log_period);
  }
};

TEST(WhiteNoise, PortsAndPerTrialState) {
  const WhiteNoise noise("noise", 0.0, 1.0, 3, 0.01);
  EXPECT_EQ(noise.num_input_ports(), 0);
  ASSERT_EQ(noise.num_output_ports(), 1);
  EXPECT_EQ(noise.output_port("y").size(), 3);
  EXPECT_TRUE(noise.output_reads(0).empty());
  EXPECT_EQ(noise.discrete_state_part("value").lifetime, StateLifetime::kPerTrial);
  EXPECT_EQ(noise.initialization_updates().size(), 1U);  // the first draw
  ASSERT_EQ(noise.periodic_updates().size(), 1U);
  EXPECT_EQ(noise.periodic_updates()[0].period, 0.01);
}

TEST(WhiteNoise, SampleMeanDeviationAndWhitenessMatch) {
  const int n = 20000;
  NoiseRun run(Eigen::Vector2d(1.0, -2.0), Eigen::Vector2d(0.5, 2.0), 0.01, 0.01, 42);
  run.log->reserve(n);
  run.simulator->advance_to(0.01 * n - 0.005);
  ASSERT_EQ(run.log->num_samples(), n);
  const Eigen::MatrixXd samples = run.log->values();  // 2 x n
  const Eigen::Vector2d expected_mean(1.0, -2.0);
  const Eigen::Vector2d expected_std(0.5, 2.0);
  for (int i = 0; i < 2; ++i) {
    const Eigen::ArrayXd x = samples.row(i).transpose().array();
    const double mean = x.mean();
    const double deviation = std::sqrt((x - mean).square().sum() / (n - 1));
    // 5 standard errors: sigma / sqrt(n) for the mean, about sigma / sqrt(2 n) for the std.
    EXPECT_NEAR(mean, expected_mean[i], 5.0 * expected_std[i] / std::sqrt(n)) << i;
    EXPECT_NEAR(deviation, expected_std[i], 5.0 * expected_std[i] / std::sqrt(2.0 * n)) << i;
    // Successive draws uncorrelated: the lag-1 autocorrelation within 5 / sqrt(n) of 0.
    const Eigen::ArrayXd centred = x - mean;
    const double lag1 = (centred.head(n - 1) * centred.tail(n - 1)).sum() / centred.square().sum();
    EXPECT_LT(std::abs(lag1), 5.0 / std::sqrt(n)) << i;
  }
  // The two elements are independent too.
  const Eigen::ArrayXd a = samples.row(0).transpose().array() - samples.row(0).mean();
  const Eigen::ArrayXd b = samples.row(1).transpose().array() - samples.row(1).mean();
  EXPECT_LT(std::abs((a * b).sum() / std::sqrt(a.square().sum() * b.square().sum())),
            5.0 / std::sqrt(n));
}

TEST(WhiteNoise, SameRootSeedSameSequenceOtherSeedAnother) {
  const Vector mean = Vector::Zero(1);
  const Vector deviation = Vector::Ones(1);
  NoiseRun first(mean, deviation, 0.1, 0.1, 7);
  NoiseRun again(mean, deviation, 0.1, 0.1, 7);
  NoiseRun other(mean, deviation, 0.1, 0.1, 8);
  for (NoiseRun* run : {&first, &again, &other}) run->simulator->advance_to(10.0);
  ASSERT_EQ(first.log->num_samples(), 100);
  EXPECT_EQ(Eigen::MatrixXd(first.log->values()), Eigen::MatrixXd(again.log->values()));
  EXPECT_NE(Eigen::MatrixXd(first.log->values()), Eigen::MatrixXd(other.log->values()));

  // A clone of a context holds its generators: it draws what the original would.
  auto context = first.diagram->create_context(9);
  auto clone = context->clone();
  Simulator original(*first.diagram, std::move(context));
  Simulator copy(*first.diagram, std::move(clone));
  const OutputPort& y = first.diagram->block("noise").output_port("y");
  SignalLog& original_log = original.add_log(y, 0.1);
  SignalLog& copy_log = copy.add_log(y, 0.1);
  original.advance_to(2.0);
  copy.advance_to(2.0);
  ASSERT_EQ(copy_log.num_samples(), 20);
  EXPECT_EQ(Eigen::MatrixXd(copy_log.values()), Eigen::MatrixXd(original_log.values()));
}

TEST(WhiteNoise, HoldsEachDrawForItsPeriod) {
  // Logged four times a period: the first draw (at initialisation) is seen at t = 0 only;
  // each later one from the instant after its sample time until its next sample time.
  NoiseRun run(Vector::Zero(1), Vector::Ones(1), 0.01, 0.0025, 3);
  run.simulator->advance_to(0.0299);
  ASSERT_EQ(run.log->num_samples(), 12);
  const auto y = [&](int k) { return run.log->sample(k)[0]; };
  EXPECT_NE(y(0), y(1));
  for (int k = 2; k <= 4; ++k) EXPECT_EQ(y(k), y(1)) << k;
  EXPECT_NE(y(5), y(4));
  for (int k = 6; k <= 8; ++k) EXPECT_EQ(y(k), y(5)) << k;
  EXPECT_NE(y(9), y(8));

  // A new trial draws afresh at initialisation: the generator is not reset.
  const double before = y(0);
  run.simulator->context().reset_trial_state();
  run.simulator->initialize();
  EXPECT_NE(run.simulator->context().discrete_state(run.diagram->block("noise"))[0], before);
}

TEST(WhiteNoise, ZeroDeviationGivesTheMean) {
  NoiseRun run(Eigen::Vector2d(3.0, -1.0), Eigen::Vector2d::Zero(), 0.1, 0.1, 1);
  run.simulator->advance_to(1.0);
  for (int k = 0; k < run.log->num_samples(); ++k) {
    EXPECT_EQ(Vector(run.log->sample(k)), Eigen::Vector2d(3.0, -1.0));
  }
}

TEST(WhiteNoise, RefusesBadArguments) {
  EXPECT_THAT([] { WhiteNoise("noise", 0.0, -1.0, 1, 0.1); },
              ThrowsMessage<std::invalid_argument>(
                  "WhiteNoise 'noise': standard deviation -1 must be finite and >= 0"));
  EXPECT_THAT([] { WhiteNoise("noise", Vector::Zero(2), Eigen::Vector2d(1.0, std::nan("")), 0.1); },
              ThrowsMessage<std::invalid_argument>(
                  "WhiteNoise 'noise': standard deviation nan at element 1 must be finite and "
                  ">= 0"));
  EXPECT_THAT([] { WhiteNoise("noise", Vector::Zero(2), Vector::Ones(3), 0.1); },
              ThrowsMessage<std::invalid_argument>(
                  "WhiteNoise 'noise': the standard deviation has size 3; it must have the "
                  "mean's size, 2"));
  EXPECT_THAT(
      [] { WhiteNoise("noise", 0.0, 1.0, 0, 0.1); },
      ThrowsMessage<std::invalid_argument>("WhiteNoise 'noise': size 0 must be at least 1"));
  EXPECT_THAT([] { WhiteNoise("noise", 0.0, 1.0, 1, -0.1); },
              ThrowsMessage<std::invalid_argument>(
                  "WhiteNoise 'noise': period -0.1 must be positive and finite"));
}

}  // namespace
}  // namespace cbbg
