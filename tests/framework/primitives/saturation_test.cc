#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <limits>
#include <stdexcept>
#include <vector>

#include "cbbg/framework/block_harness.h"
#include "cbbg/framework/primitives/saturation.h"

namespace cbbg {
namespace {

using ::testing::ThrowsMessage;

constexpr double kInf = std::numeric_limits<double>::infinity();

TEST(Saturation, HasOneInputOfItsSizeThatItsOutputReads) {
  const Saturation saturation("sat", -1.0, 2.0, 3);
  ASSERT_EQ(saturation.num_input_ports(), 1);
  EXPECT_EQ(saturation.input_port("u").size(), 3);
  ASSERT_EQ(saturation.num_output_ports(), 1);
  EXPECT_EQ(saturation.output_port("y").size(), 3);
  EXPECT_EQ(saturation.output_reads(0), std::vector<int>{0});  // direct feedthrough

  const Saturation per_element("sat", Eigen::Vector2d(0.0, -1.0), Eigen::Vector2d(1.0, 0.0));
  EXPECT_EQ(per_element.input_port("u").size(), 2);
  EXPECT_EQ(per_element.output_port("y").size(), 2);
}

TEST(Saturation, ClampsEachElementToItsLimits) {
  testing::BlockHarness<Saturation> harness("sat", -1.0, 2.0, 3);
  harness.set_input("u", Eigen::Vector3d(-5.0, 0.5, 7.0));
  EXPECT_EQ(harness.output("y"), Eigen::Vector3d(-1.0, 0.5, 2.0));
  harness.set_input("u", Eigen::Vector3d(-1.0, 2.0, 1.999));
  EXPECT_EQ(harness.output("y"), Eigen::Vector3d(-1.0, 2.0, 1.999));
}

TEST(Saturation, TakesLimitsPerElementAndAnInfiniteLimitLeavesItsSideOpen) {
  testing::BlockHarness<Saturation> harness("sat", Vector(Eigen::Vector2d(0.0, -kInf)),
                                            Vector(Eigen::Vector2d(1.0, 0.0)));
  harness.set_input("u", Eigen::Vector2d(2.0, -100.0));
  EXPECT_EQ(harness.output("y"), Eigen::Vector2d(1.0, -100.0));
  harness.set_input("u", Eigen::Vector2d(-2.0, 100.0));
  EXPECT_EQ(harness.output("y"), Eigen::Vector2d(0.0, 0.0));
}

TEST(Saturation, RefusesCrossedNanOrInvertedInfiniteLimitsAndAnEmptySize) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THAT([] { Saturation("sat", 2.0, 1.0, 1); },
              ThrowsMessage<std::invalid_argument>(
                  "Saturation 'sat': lower limit 2 is above upper limit 1"));
  EXPECT_THAT([] { Saturation("sat", Eigen::Vector2d(0.0, 2.0), Eigen::Vector2d(1.0, 1.0)); },
              ThrowsMessage<std::invalid_argument>(
                  "Saturation 'sat': lower limit 2 is above upper limit 1 at element 1"));
  EXPECT_THAT([nan] { Saturation("sat", nan, 1.0, 1); },
              ThrowsMessage<std::invalid_argument>(
                  "Saturation 'sat': lower limit nan must be a number below inf (-inf for none)"));
  EXPECT_THAT([] { Saturation("sat", kInf, kInf, 1); },
              ThrowsMessage<std::invalid_argument>(
                  "Saturation 'sat': lower limit inf must be a number below inf (-inf for none)"));
  EXPECT_THAT([] { Saturation("sat", -1.0, -kInf, 1); },
              ThrowsMessage<std::invalid_argument>(
                  "Saturation 'sat': upper limit -inf must be a number above -inf (inf for none)"));
  EXPECT_THAT([] { Saturation("sat", Eigen::Vector2d(0.0, 0.0), Eigen::Vector3d(1.0, 1.0, 1.0)); },
              ThrowsMessage<std::invalid_argument>(
                  "Saturation 'sat': 2 lower limits and 3 upper limits; give as many of each"));
  EXPECT_THAT([] { Saturation("sat", Vector(), Vector()); },
              ThrowsMessage<std::invalid_argument>(
                  "Saturation 'sat': no limits; give at least one element"));
  EXPECT_THAT([] { Saturation("sat", -1.0, 1.0, 0); },
              ThrowsMessage<std::invalid_argument>("Saturation 'sat': size 0 must be at least 1"));
}

}  // namespace
}  // namespace cbbg
