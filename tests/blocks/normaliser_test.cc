#include "cbbg/blocks/normaliser.h"

#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>
#include <vector>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "cbbg/blocks/measured_signals.h"
#include "cbbg/framework/block_harness.h"

namespace cbbg::blocks {
namespace {

using ::testing::StrEq;
using ::testing::ThrowsMessage;
using Harness = testing::BlockHarness<Normaliser>;

Vector measured(double theta, double theta_dot) {
  Vector y = Vector::Zero(kMeasuredSize);
  y[kMeasuredThetaB] = theta;
  y[kMeasuredThetaBDot] = theta_dot;
  y[kMeasuredPhiLeft] = 7.0;  // the wheels must not matter
  return y;
}

TEST(Normaliser, DividesPitchAndRateByTheirScales) {
  Harness harness("normaliser", NormaliserParams{});
  const double scale = 0.05817764;
  harness.set_input("measured", measured(1.5 * scale, -0.5 * scale));
  Vector x = harness.output("x");
  EXPECT_NEAR(x[0], 1.5, 1e-15);
  EXPECT_NEAR(x[1], -0.5, 1e-15);

  // pi/54 rad is one grid unit (docs/model.md §2.2): 0.1744 rad is about 3 units.
  harness.set_input("measured", measured(std::numbers::pi / 54.0, 0.0));
  x = harness.output("x");
  EXPECT_NEAR(x[0], 1.0, 1e-7);
  EXPECT_EQ(x[1], 0.0);
}

TEST(Normaliser, SaturatesAtTheGridBounds) {
  Harness harness("normaliser", NormaliserParams{});
  harness.set_input("measured", measured(0.5, -10.0));  // 8.6 and -171.9 units
  Vector x = harness.output("x");
  EXPECT_EQ(x[0], 3.0);
  EXPECT_EQ(x[1], -3.0);

  // Just inside the bound stays as it is.
  harness.set_input("measured", measured(2.999 * 0.05817764, -2.999 * 0.05817764));
  x = harness.output("x");
  EXPECT_NEAR(x[0], 2.999, 1e-12);
  EXPECT_NEAR(x[1], -2.999, 1e-12);
}

TEST(Normaliser, UsesConfiguredScalesAndSaturation) {
  NormaliserParams params;
  params.scale_theta = 0.1;
  params.scale_dtheta = 2.0;
  params.saturation = 1.5;
  Harness harness("normaliser", params);
  harness.set_input("measured", measured(0.12, 2.0));
  Vector x = harness.output("x");
  EXPECT_NEAR(x[0], 1.2, 1e-15);
  EXPECT_EQ(x[1], 1.0);
  harness.set_input("measured", measured(-0.2, 4.0));
  x = harness.output("x");
  EXPECT_EQ(x[0], -1.5);
  EXPECT_EQ(x[1], 1.5);
}

TEST(Normaliser, SeesTheWheelsMeanAngleAndRateWhenAsked) {
  Vector y = measured(0.5 * 0.05817764, 0.0);
  y[kMeasuredPhiLeft] = 1.0;
  y[kMeasuredPhiRight] = 3.0;  // mean 2 rad: 1 unit of 2 rad
  y[kMeasuredPhiLeftDot] = -2.0;
  y[kMeasuredPhiRightDot] = -20.0;  // mean -11 rad/s: -5.5 units of 2 rad/s, saturated to -3
  NormaliserParams params;
  params.inputs = NormalisedInputs::kPitchWheelRate;
  Harness rate("normaliser", params);
  rate.set_input("measured", y);
  Vector x = rate.output("x");
  ASSERT_EQ(x.size(), 3);
  EXPECT_NEAR(x[0], 0.5, 1e-15);
  EXPECT_EQ(x[2], -3.0);
  params.inputs = NormalisedInputs::kPitchWheels;
  params.scale_dphi = 5.0;
  Harness wheels("normaliser", params);
  wheels.set_input("measured", y);
  x = wheels.output("x");
  ASSERT_EQ(x.size(), 4);
  EXPECT_EQ(x[2], 1.0);
  EXPECT_NEAR(x[3], -2.2, 1e-15);
}

// The paper's inputs keep the paper's layout (weights files made before the option load);
// each wider view lists the scales of what it sees.
TEST(Normaliser, ItsLayoutNamesTheScalesOfWhatItSees) {
  auto keys = [](NormalisedInputs inputs) {
    NormaliserParams params;
    params.inputs = inputs;
    std::vector<std::string> names;
    for (const LayoutEntry& entry : Normaliser("normaliser", params).layout()) {
      names.push_back(entry.key);
    }
    return names;
  };
  EXPECT_EQ(keys(NormalisedInputs::kPitch),
            (std::vector<std::string>{"normaliser.scale_theta", "normaliser.scale_dtheta",
                                      "normaliser.saturation"}));
  EXPECT_EQ(keys(NormalisedInputs::kPitchWheelRate),
            (std::vector<std::string>{"normaliser.scale_theta", "normaliser.scale_dtheta",
                                      "normaliser.saturation", "normaliser.scale_dphi"}));
  EXPECT_EQ(keys(NormalisedInputs::kPitchWheels),
            (std::vector<std::string>{"normaliser.scale_theta", "normaliser.scale_dtheta",
                                      "normaliser.saturation", "normaliser.scale_phi",
                                      "normaliser.scale_dphi"}));
}

TEST(Normaliser, RejectsNonPositiveOrNonFiniteParameters) {
  NormaliserParams zero_scale;
  zero_scale.scale_theta = 0.0;
  EXPECT_THAT([&] { Normaliser("normaliser", zero_scale); },
              ThrowsMessage<std::invalid_argument>(
                  StrEq("normaliser.scale_theta must be finite and > 0; got 0")));
  NormaliserParams negative_scale;
  negative_scale.scale_dtheta = -1.0;
  EXPECT_THAT([&] { Normaliser("normaliser", negative_scale); },
              ThrowsMessage<std::invalid_argument>(
                  StrEq("normaliser.scale_dtheta must be finite and > 0; got -1")));
  NormaliserParams nan_saturation;
  nan_saturation.saturation = NAN;
  EXPECT_THAT([&] { Normaliser("normaliser", nan_saturation); },
              ThrowsMessage<std::invalid_argument>(
                  StrEq("normaliser.saturation must be finite and > 0; got nan")));
  NormaliserParams zero_wheel_rate;
  zero_wheel_rate.scale_dphi = 0.0;
  EXPECT_THAT([&] { Normaliser("normaliser", zero_wheel_rate); },
              ThrowsMessage<std::invalid_argument>(
                  StrEq("normaliser.scale_dphi must be finite and > 0; got 0")));
}

}  // namespace
}  // namespace cbbg::blocks
