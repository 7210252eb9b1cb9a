#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <stdexcept>
#include <vector>

#include "cbbg/framework/block_harness.h"
#include "cbbg/framework/primitives/deadband.h"

namespace cbbg {
namespace {

using ::testing::ThrowsMessage;

constexpr double kInf = std::numeric_limits<double>::infinity();

TEST(Deadband, HasOneInputOfItsSizeThatItsOutputReads) {
  const Deadband deadband("dz", -1.0, 2.0, 5);
  ASSERT_EQ(deadband.num_input_ports(), 1);
  EXPECT_EQ(deadband.input_port("u").size(), 5);
  ASSERT_EQ(deadband.num_output_ports(), 1);
  EXPECT_EQ(deadband.output_port("y").size(), 5);
  EXPECT_EQ(deadband.output_reads(0), std::vector<int>{0});  // direct feedthrough
}

TEST(Deadband, IsZeroInsideTheZoneAndTheDistancePastTheNearerLimitOutside) {
  testing::BlockHarness<Deadband> harness("dz", -1.0, 2.0, 5);
  Vector u(5);
  u << -3.0, -1.0, 0.0, 2.0, 5.0;
  harness.set_input("u", u);
  Vector expected(5);
  expected << -2.0, 0.0, 0.0, 0.0, 3.0;  // u - lower, zero at both limits, u - upper
  EXPECT_EQ(harness.output("y"), expected);
}

TEST(Deadband, TakesLimitsPerElementWhereAnInfiniteLimitHasNoZoneOnItsSide) {
  testing::BlockHarness<Deadband> harness("dz", Vector(Eigen::Vector2d(-kInf, 0.0)),
                                          Vector(Eigen::Vector2d(1.0, 0.0)));
  harness.set_input("u", Eigen::Vector2d(-50.0, -2.0));
  EXPECT_EQ(harness.output("y"), Eigen::Vector2d(0.0, -2.0));
  harness.set_input("u", Eigen::Vector2d(3.0, 4.0));
  EXPECT_EQ(harness.output("y"), Eigen::Vector2d(2.0, 4.0));
}

TEST(Deadband, PassesANanInputOn) {
  testing::BlockHarness<Deadband> harness("dz", -1.0, 1.0, 1);
  harness.set_input("u", std::numeric_limits<double>::quiet_NaN());
  EXPECT_TRUE(std::isnan(harness.scalar_output("y")));
}

TEST(Deadband, RefusesCrossedOrNanLimitsAndAnEmptySize) {
  EXPECT_THAT(
      [] { Deadband("dz", 1.0, -1.0, 2); },
      ThrowsMessage<std::invalid_argument>("Deadband 'dz': lower limit 1 is above upper limit -1"));
  EXPECT_THAT([] { Deadband("dz", Eigen::Vector2d(0.0, 0.5), Eigen::Vector2d(0.0, 0.25)); },
              ThrowsMessage<std::invalid_argument>(
                  "Deadband 'dz': lower limit 0.5 is above upper limit 0.25 at element 1"));
  EXPECT_THAT([] { Deadband("dz", 0.0, std::numeric_limits<double>::quiet_NaN(), 1); },
              ThrowsMessage<std::invalid_argument>(
                  "Deadband 'dz': upper limit nan must be a number above -inf (inf for none)"));
  EXPECT_THAT([] { Deadband("dz", -1.0, 1.0, -2); },
              ThrowsMessage<std::invalid_argument>("Deadband 'dz': size -2 must be at least 1"));
}

}  // namespace
}  // namespace cbbg
