#include "cbbg/blocks/rbf_features.h"

#include <cmath>
#include <random>
#include <stdexcept>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "cbbg/blocks/critic.h"
#include "cbbg/framework/block_harness.h"
#include "cbbg/framework/diagram_builder.h"

namespace cbbg::blocks {
namespace {

using ::testing::StrEq;
using ::testing::ThrowsMessage;
using Harness = testing::BlockHarness<RbfFeatures>;

Vector point(double x0, double x1) {
  Vector x(2);
  x << x0, x1;
  return x;
}

TEST(RbfFeatures, HasOneUnitPerGridPoint) {
  EXPECT_EQ(RbfFeatures("rbf", RbfParams{}).num_features(), 49);
  RbfParams small;
  small.centres = {-1.0, 0.0, 1.0};
  EXPECT_EQ(RbfFeatures("rbf", small).num_features(), 9);
}

TEST(RbfFeatures, MatchesHandValuesOnTheDefaultGrid) {
  Harness harness("rbf", RbfParams{});
  // At the grid's centre: unit (3, 3) sits on it; 1/(2 b^2) = 2 with b = 0.5.
  harness.set_input("x", point(0.0, 0.0));
  Vector phi = harness.output("features");
  EXPECT_EQ(phi[3 * 7 + 3], 1.0);
  EXPECT_NEAR(phi[3 * 7 + 4], std::exp(-2.0), 1e-16);  // centre (0, 1)
  EXPECT_NEAR(phi[4 * 7 + 4], std::exp(-4.0), 1e-16);  // centre (1, 1)
  EXPECT_NEAR(phi[0], std::exp(-36.0), 1e-25);         // centre (-3, -3)

  // Pitch picks the row, rate the column: x = (0.5, -1) is 0.5 from (0, -1) and (1, -1).
  harness.set_input("x", point(0.5, -1.0));
  phi = harness.output("features");
  EXPECT_NEAR(phi[3 * 7 + 2], std::exp(-0.5), 1e-16);
  EXPECT_NEAR(phi[4 * 7 + 2], std::exp(-0.5), 1e-16);
  // Unit (2, 3) at (-1, 0): distance^2 = 1.5^2 + 1^2 = 3.25.
  EXPECT_NEAR(phi[2 * 7 + 3], std::exp(-6.5), 1e-16);
}

TEST(RbfFeatures, MatchDirectEvaluationOnAnyGrid) {
  RbfParams params;
  params.centres = {-1.5, -0.5, 0.5, 1.5};
  params.width = 0.8;
  Harness harness("rbf", params);
  std::mt19937_64 generator(3);
  std::uniform_real_distribution<double> uniform(-2.0, 2.0);
  for (int trial = 0; trial < 20; ++trial) {
    const Vector x = point(uniform(generator), uniform(generator));
    harness.set_input("x", x);
    const Vector phi = harness.output("features");
    ASSERT_EQ(phi.size(), 16);
    for (int i = 0; i < 4; ++i) {
      for (int j = 0; j < 4; ++j) {
        const Vector centre =
            point(params.centres[static_cast<size_t>(i)], params.centres[static_cast<size_t>(j)]);
        const double expected =
            std::exp(-(x - centre).squaredNorm() / (2.0 * params.width * params.width));
        EXPECT_NEAR(phi[i * 4 + j], expected, 1e-15);
      }
    }
  }
}

// Three and four axes (the normaliser's wider views): unit k's digits in base m, the first
// axis the most significant, pick its centre on each axis.
TEST(RbfFeatures, MatchDirectEvaluationOnAGridOfThreeOrFourAxes) {
  RbfParams params;
  params.centres = {-1.0, 0.0, 0.5};
  params.width = 0.6;
  std::mt19937_64 generator(5);
  std::uniform_real_distribution<double> uniform(-1.5, 1.5);
  for (const int d : {3, 4}) {
    testing::BlockHarness<RbfFeatures> harness("rbf", params, d);
    const int units = d == 3 ? 27 : 81;
    EXPECT_EQ(harness.block().num_features(), units);
    for (int trial = 0; trial < 5; ++trial) {
      Vector x(d);
      for (int a = 0; a < d; ++a) x[a] = uniform(generator);
      harness.set_input("x", x);
      const Vector phi = harness.output("features");
      ASSERT_EQ(phi.size(), units);
      for (int k = 0; k < units; ++k) {
        double distance = 0.0;
        for (int a = 0, rest = k; a < d; ++a) {
          int place = 1;  // m^(d - 1 - a), m = 3
          for (int b = a + 1; b < d; ++b) place *= 3;
          const int digit = rest / place;
          rest %= place;
          distance += std::pow(x[a] - params.centres[static_cast<size_t>(digit)], 2);
        }
        EXPECT_NEAR(phi[k], std::exp(-distance / (2.0 * 0.36)), 1e-15) << "d " << d << ", k " << k;
      }
    }
  }
  EXPECT_THAT([] { RbfFeatures("rbf", RbfParams{}, 5); },
              ThrowsMessage<std::invalid_argument>(
                  StrEq("RbfFeatures 'rbf': dimensions must be from 1 to 4; got 5")));
}

TEST(RbfFeatures, PerAxisUnitsSitOnEachAxisAlone) {
  RbfParams params;
  params.centres = {-1.0, 0.0, 0.5};
  params.width = 0.6;
  params.units = RbfUnits::kPerAxis;
  std::mt19937_64 generator(9);
  std::uniform_real_distribution<double> uniform(-1.5, 1.5);
  for (const int d : {2, 3, 4}) {
    testing::BlockHarness<RbfFeatures> harness("rbf", params, d);
    ASSERT_EQ(harness.block().num_features(), 3 * d);
    Vector x(d);
    for (int a = 0; a < d; ++a) x[a] = uniform(generator);
    harness.set_input("x", x);
    const Vector phi = harness.output("features");
    for (int a = 0; a < d; ++a) {
      for (int i = 0; i < 3; ++i) {
        const double delta = x[a] - params.centres[static_cast<size_t>(i)];
        EXPECT_NEAR(phi[3 * a + i], std::exp(-delta * delta / (2.0 * 0.36)), 1e-15)
            << "d " << d << ", axis " << a << ", unit " << i;
      }
    }
  }
  // The grid's layout is as it was; per_axis says itself, so weights of one are refused by
  // the other.
  const FeatureLayout grid = RbfFeatures("rbf", RbfParams{}).layout();
  ASSERT_EQ(grid.size(), 2U);
  EXPECT_EQ(grid[1].key, "rbf.width");
  const FeatureLayout per_axis = RbfFeatures("rbf", params).layout();
  ASSERT_EQ(per_axis.size(), 3U);
  EXPECT_EQ(per_axis[2], (LayoutEntry{"rbf.per_axis", {1.0}}));
  EXPECT_EQ(
      RbfFeatures("rbf", params, 4).layout_note(),
      "Weight k belongs to the unit at rbf.centres[k % m] on axis k / m alone (of 4), m = 3.");
}

TEST(RbfFeatures, AreTheGradientOfTheValueWithRespectToTheWeights) {
  DiagramBuilder builder("value");
  const auto& rbf = builder.emplace<RbfFeatures>("rbf", RbfParams{});
  const auto& critic = builder.emplace<Critic>("critic", rbf.num_features(), CriticParams{}, 0.01);
  builder.export_input(rbf.input_port("x"));
  builder.connect(rbf, "features", critic, "features");
  builder.fix_input(critic.input_port("reward"), Vector::Zero(1));
  builder.fix_input(critic.input_port("failed"), Vector::Zero(1));
  const auto diagram = builder.build();
  auto context = diagram->create_context();
  context->fix_input(diagram->input_port("x"), point(0.7, -1.3));

  std::mt19937_64 generator(5);
  std::normal_distribution<double> normal;
  auto w = critic.mutable_weights(*context);
  for (int i = 0; i < w.size(); ++i) w[i] = normal(generator);
  const Vector phi = diagram->eval_output(*context, rbf.output_port("features"));
  const double h = 1e-6;
  for (int i = 0; i < w.size(); ++i) {
    const double original = w[i];
    w[i] = original + h;
    const double above = diagram->eval_output(*context, critic.output_port("value"))[0];
    w[i] = original - h;
    const double below = diagram->eval_output(*context, critic.output_port("value"))[0];
    w[i] = original;
    EXPECT_NEAR((above - below) / (2.0 * h), phi[i], 1e-8) << "weight " << i;
  }
}

TEST(RbfFeatures, RejectsInvalidGrids) {
  RbfParams negative_width;
  negative_width.width = -0.5;
  EXPECT_THAT(
      [&] { RbfFeatures("rbf", negative_width); },
      ThrowsMessage<std::invalid_argument>(StrEq("rbf.width must be finite and > 0; got -0.5")));
  RbfParams no_centres;
  no_centres.centres.clear();
  EXPECT_THAT([&] { RbfFeatures("rbf", no_centres); },
              ThrowsMessage<std::invalid_argument>(
                  StrEq("rbf.centres must list at least one centre; got none")));
  RbfParams nan_centre;
  nan_centre.centres = {-1.0, NAN, 1.0};
  EXPECT_THAT(
      [&] { RbfFeatures("rbf", nan_centre); },
      ThrowsMessage<std::invalid_argument>(StrEq("rbf.centres[1] must be finite; got nan")));
  RbfParams unordered;
  unordered.centres = {0.0, 1.0, 1.0};
  EXPECT_THAT([&] { RbfFeatures("rbf", unordered); },
              ThrowsMessage<std::invalid_argument>(
                  StrEq("rbf.centres[2] must be greater than the centre before it (1); got 1")));
}

}  // namespace
}  // namespace cbbg::blocks
