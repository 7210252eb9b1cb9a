#include "cbbg/blocks/sensors.h"

#include <cmath>
#include <stdexcept>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "cbbg/framework/block_harness.h"
#include "cbbg/plant/plant_ports.h"

namespace cbbg::blocks {
namespace {

using ::testing::StrEq;
using ::testing::ThrowsMessage;
using Harness = testing::BlockHarness<Sensors>;

constexpr double kPeriod = Harness::kPeriod;

Vector plant_state() {
  Vector state(10);
  state << 0.1744, -0.25, 1.5, 2.5, -3.0, 4.0, 0.3, 0.4, 0.05, 0.6;
  return state;
}

TEST(Sensors, MeasuresPitchAndWheelsWithoutNoiseByDefault) {
  Harness harness("sensors", SensorsParams{}, kPeriod);
  harness.set_input("plant_state", plant_state());
  harness.tick();
  Vector expected(6);
  expected << 0.1744, -0.25, 1.5, 2.5, -3.0, 4.0;
  EXPECT_EQ(harness.output("measured"), expected);
  harness.tick();
  EXPECT_EQ(harness.output("measured"), expected);
}

TEST(Sensors, QuantisationRoundsToTheNearestStep) {
  SensorsParams params;
  params.quantisation[kMeasuredThetaB] = 0.01;
  params.quantisation[kMeasuredPhiRight] = 0.5;
  Harness harness("sensors", params, kPeriod);
  harness.set_input("plant_state", plant_state());
  harness.tick();
  const Vector measured = harness.output("measured");
  EXPECT_NEAR(measured[kMeasuredThetaB], 0.17, 1e-15);  // 17.44 steps -> 17
  EXPECT_EQ(measured[kMeasuredPhiRight], 2.5);          // already on a step
  EXPECT_EQ(measured[kMeasuredThetaBDot], -0.25);       // not quantised

  Vector state = plant_state();
  state[plant::kThetaB] = -0.0267;  // -2.67 steps -> -3
  state[plant::kPhiRight] = 2.76;   // 5.52 steps -> 6
  harness.set_input("plant_state", state);
  const Vector next = harness.output("measured");
  EXPECT_NEAR(next[kMeasuredThetaB], -0.03, 1e-15);
  EXPECT_EQ(next[kMeasuredPhiRight], 3.0);
}

TEST(Sensors, NoiseHasTheConfiguredDeviationOnItsSignalOnly) {
  SensorsParams params;
  params.noise_std[kMeasuredThetaBDot] = 0.2;
  Harness harness("sensors", params, kPeriod);
  harness.set_input("plant_state", plant_state());
  const int n = 20000;
  double sum = 0.0;
  double sum_squares = 0.0;
  for (int i = 0; i < n; ++i) {
    harness.tick();  // draws the noise of the next tick
    const Vector measured = harness.output("measured");
    const double noise = measured[kMeasuredThetaBDot] - (-0.25);
    sum += noise;
    sum_squares += noise * noise;
    ASSERT_EQ(measured[kMeasuredThetaB], 0.1744);
    ASSERT_EQ(measured[kMeasuredPhiLeftDot], -3.0);
  }
  const double mean = sum / n;
  const double variance = sum_squares / n - mean * mean;
  // Five standard errors: of the mean, sigma / sqrt(n); of the variance, sigma^2 sqrt(2 / n).
  EXPECT_NEAR(mean, 0.0, 5.0 * 0.2 / std::sqrt(n));
  EXPECT_NEAR(variance, 0.04, 5.0 * 0.04 * std::sqrt(2.0 / n));
}

TEST(Sensors, ANewTrialDrawsFreshNoise) {
  SensorsParams params;
  params.noise_std.fill(1.0);
  Harness harness("sensors", params, kPeriod);
  harness.set_input("plant_state", plant_state());
  harness.tick();
  const Vector before = harness.state_part("noise");
  harness.context().reset_trial_state();
  EXPECT_EQ(harness.state_part("noise"), Vector::Zero(kMeasuredSize));  // the noise is per trial
  harness.restart_time();  // the trial's initialisation draws the first tick's noise
  const Vector after = harness.state_part("noise");
  for (int i = 0; i < kMeasuredSize; ++i) {
    EXPECT_NE(after[i], before[i]) << "signal " << i;
    EXPECT_NE(after[i], 0.0) << "signal " << i;
  }
}

TEST(Sensors, RejectsNegativeOrNonFiniteNoiseAndSteps) {
  SensorsParams negative_noise;
  negative_noise.noise_std[2] = -0.1;
  EXPECT_THAT([&] { Sensors("sensors", negative_noise, kPeriod); },
              ThrowsMessage<std::invalid_argument>(
                  StrEq("sensors.noise_std[2] must be finite and >= 0; got -0.1")));
  SensorsParams infinite_step;
  infinite_step.quantisation[0] = INFINITY;
  EXPECT_THAT([&] { Sensors("sensors", infinite_step, kPeriod); },
              ThrowsMessage<std::invalid_argument>(
                  StrEq("sensors.quantisation[0] must be finite and >= 0; got inf")));
  EXPECT_THAT(
      [] { Sensors("sensors", SensorsParams{}, 0.0); },
      ThrowsMessage<std::invalid_argument>(StrEq("trial.period must be finite and > 0; got 0")));
}

}  // namespace
}  // namespace cbbg::blocks
