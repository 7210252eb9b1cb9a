#include "cbbg/blocks/normaliser.h"

#include <cmath>
#include <numbers>
#include <stdexcept>

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
}

}  // namespace
}  // namespace cbbg::blocks
