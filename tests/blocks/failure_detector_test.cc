#include "cbbg/blocks/failure_detector.h"

#include <cmath>
#include <stdexcept>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "cbbg/blocks/measured_signals.h"
#include "cbbg/blocks/parameter_checks.h"
#include "cbbg/framework/block_harness.h"

namespace cbbg::blocks {
namespace {

using ::testing::StrEq;
using ::testing::ThrowsMessage;
using Harness = testing::BlockHarness<FailureDetector>;

constexpr double kPeriod = Harness::kPeriod;

Vector measured_with_pitch(double theta) {
  Vector y = Vector::Zero(kMeasuredSize);
  y[kMeasuredThetaB] = theta;
  y[kMeasuredThetaBDot] = 3.0;  // a fast fall alone is no failure
  return y;
}

TEST(FailureDetector, StandsUpToAndIncludingTheFailureAngle) {
  Harness harness("failure", FailureDetectorParams{}, kPeriod);
  for (const double theta : {0.0, 0.1744, 0.5236, -0.5236}) {
    harness.set_input("measured", measured_with_pitch(theta));
    EXPECT_EQ(harness.scalar_output("failed"), 0.0) << "theta " << theta;
    EXPECT_FALSE(harness.tick().terminated) << "theta " << theta;
  }
}

TEST(FailureDetector, FailsJustBeyondTheAngleAndEndsTheTrial) {
  for (const double theta : {std::nextafter(0.5236, 1.0), -0.6}) {
    Harness harness("failure", FailureDetectorParams{}, kPeriod);
    harness.set_input("measured", measured_with_pitch(theta));
    EXPECT_EQ(harness.scalar_output("failed"), 1.0) << "theta " << theta;
    const SimulationStatus status = harness.tick();
    EXPECT_TRUE(status.terminated);
    EXPECT_STREQ(status.reason, "|theta_b| exceeded trial.failure_angle");
    EXPECT_EQ(status.terminated_by, &harness.block());
  }
}

TEST(FailureDetector, UsesTheConfiguredAngle) {
  FailureDetectorParams params;
  params.failure_angle = 0.2;
  Harness harness("failure", params, kPeriod);
  harness.set_input("measured", measured_with_pitch(0.2));
  EXPECT_EQ(harness.scalar_output("failed"), 0.0);
  harness.set_input("measured", measured_with_pitch(-0.21));
  EXPECT_EQ(harness.scalar_output("failed"), 1.0);
}

TEST(FailureDetector, FailsOnANonFiniteMeasurement) {
  Harness harness("failure", FailureDetectorParams{}, kPeriod);
  Vector y = measured_with_pitch(0.0);
  y[kMeasuredPhiRightDot] = NAN;
  harness.set_input("measured", y);
  EXPECT_EQ(harness.scalar_output("failed"), 1.0);
  // (The simulator reads a NaN root input as "never set", so the tick uses infinity.)
  y[kMeasuredPhiRightDot] = INFINITY;
  harness.set_input("measured", y);
  EXPECT_EQ(harness.scalar_output("failed"), 1.0);
  const SimulationStatus status = harness.tick();
  EXPECT_TRUE(status.terminated);
  EXPECT_STREQ(status.reason, "a measured signal is not finite");
}

TEST(FailureDetector, RejectsNonPositiveOrNonFiniteAngles) {
  for (const double angle : {0.0, -0.5}) {
    FailureDetectorParams params;
    params.failure_angle = angle;
    EXPECT_THAT([&] { FailureDetector("failure", params, kPeriod); },
                ThrowsMessage<std::invalid_argument>(StrEq(
                    "trial.failure_angle must be finite and > 0; got " + format_number(angle))));
  }
  FailureDetectorParams nan;
  nan.failure_angle = NAN;
  EXPECT_THAT([&] { FailureDetector("failure", nan, kPeriod); },
              ThrowsMessage<std::invalid_argument>(
                  StrEq("trial.failure_angle must be finite and > 0; got nan")));
}

}  // namespace
}  // namespace cbbg::blocks
