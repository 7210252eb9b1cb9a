#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <limits>
#include <stdexcept>
#include <vector>

#include "cbbg/framework/block_harness.h"
#include "cbbg/framework/primitives/gain.h"

namespace cbbg {
namespace {

using ::testing::ThrowsMessage;

Eigen::MatrixXd two_by_three() {
  Eigen::MatrixXd k(2, 3);
  k << 1.0, 2.0, 3.0, 4.0, 5.0, 6.0;
  return k;
}

TEST(Gain, AMatrixGainTakesItsColumnsInAndGivesItsRowsOut) {
  const Gain gain("K", two_by_three());
  ASSERT_EQ(gain.num_input_ports(), 1);
  EXPECT_EQ(gain.input_port("u").size(), 3);
  ASSERT_EQ(gain.num_output_ports(), 1);
  EXPECT_EQ(gain.output_port("y").size(), 2);
  EXPECT_EQ(gain.output_reads(0), std::vector<int>{0});  // direct feedthrough

  const Gain scalar("k", 2.0, 4);
  EXPECT_EQ(scalar.input_port("u").size(), 4);
  EXPECT_EQ(scalar.output_port("y").size(), 4);
  EXPECT_EQ(scalar.output_reads(0), std::vector<int>{0});
}

TEST(Gain, AMatrixGainMultipliesItsInput) {
  testing::BlockHarness<Gain> harness("K", two_by_three());
  harness.set_input("u", Eigen::Vector3d(1.0, -1.0, 2.0));
  EXPECT_EQ(harness.output("y"), Eigen::Vector2d(5.0, 11.0));  // (1 - 2 + 6, 4 - 5 + 12)
}

TEST(Gain, AScalarGainMultipliesEachElementBitForBit) {
  testing::BlockHarness<Gain> harness("k", 0.1, 3);
  const Eigen::Vector3d u(0.3, -7.0, 1e-3);
  harness.set_input("u", u);
  const Vector y = harness.output("y");
  for (int i = 0; i < 3; ++i) EXPECT_EQ(y[i], 0.1 * u[i]);
}

TEST(Gain, RefusesAnEmptyOrNonFiniteMatrix) {
  EXPECT_THAT([] { Gain("K", Eigen::MatrixXd(0, 3)); },
              ThrowsMessage<std::invalid_argument>(
                  "Gain 'K': matrix is 0x3; it needs at least one row and one column"));
  EXPECT_THAT(
      [] {
        Eigen::MatrixXd k = two_by_three();
        k(1, 0) = std::numeric_limits<double>::quiet_NaN();
        Gain("K", k);
      },
      ThrowsMessage<std::invalid_argument>(
          "Gain 'K': matrix element (1, 0) is nan; every element must be finite"));
}

}  // namespace
}  // namespace cbbg
