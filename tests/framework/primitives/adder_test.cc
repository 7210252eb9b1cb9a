#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <stdexcept>
#include <vector>

#include "cbbg/framework/block_harness.h"
#include "cbbg/framework/primitives/adder.h"

namespace cbbg {
namespace {

using ::testing::ThrowsMessage;

TEST(Adder, DeclaresANamedInputPerTermAndReadsThemAll) {
  const Adder adder("err", {{"r", +1}, {"y", -1}, {"d", +1}}, 2);
  ASSERT_EQ(adder.num_input_ports(), 3);
  EXPECT_EQ(adder.input_port_names(), "r, y, d");
  for (int i = 0; i < 3; ++i) EXPECT_EQ(adder.input_port(i).size(), 2);
  ASSERT_EQ(adder.num_output_ports(), 1);
  EXPECT_EQ(adder.output_port("y").size(), 2);
  EXPECT_EQ(adder.output_reads(0), (std::vector<int>{0, 1, 2}));  // direct feedthrough
  EXPECT_FALSE(adder.has_continuous_state());
  EXPECT_EQ(adder.initial_discrete_state().size(), 0);
}

TEST(Adder, SumsItsInputsWithTheirSigns) {
  testing::BlockHarness<Adder> harness(
      "err", std::vector<Adder::Input>{{"r", +1}, {"y", -1}, {"d", +1}}, 2);
  harness.set_input("r", Eigen::Vector2d(1.0, 2.0));
  harness.set_input("y", Eigen::Vector2d(0.5, 4.0));
  harness.set_input("d", Eigen::Vector2d(3.0, -1.0));
  EXPECT_EQ(harness.output("y"), Eigen::Vector2d(3.5, -3.0));  // r - y + d
}

TEST(Adder, AFirstNegativeInputIsNegatedAndADifferenceIsExact) {
  testing::BlockHarness<Adder> negated("neg", std::vector<Adder::Input>{{"a", -1}, {"b", +1}}, 1);
  negated.set_input("a", 2.5);
  negated.set_input("b", 1.0);
  EXPECT_EQ(negated.scalar_output("y"), -1.5);

  testing::BlockHarness<Adder> difference("err", std::vector<Adder::Input>{{"r", +1}, {"y", -1}},
                                          1);
  difference.set_input("r", 0.1);
  difference.set_input("y", 0.3);
  EXPECT_EQ(difference.scalar_output("y"), 0.1 - 0.3);  // bit for bit
}

TEST(Adder, RefusesNoInputsASignOtherThanPlusOrMinusOneAndAnEmptySize) {
  EXPECT_THAT([] { Adder("err", {}, 1); },
              ThrowsMessage<std::invalid_argument>("Adder 'err': no inputs; give at least one"));
  EXPECT_THAT(
      [] {
        Adder("err", {{"r", +1}, {"y", 2}}, 1);
      },
      ThrowsMessage<std::invalid_argument>(
          "Adder 'err': input 'y' has sign 2; a sign is +1 or -1"));
  EXPECT_THAT(
      [] {
        Adder("err", {{"r", 0}}, 1);
      },
      ThrowsMessage<std::invalid_argument>(
          "Adder 'err': input 'r' has sign 0; a sign is +1 or -1"));
  EXPECT_THAT(
      [] {
        Adder("err", {{"r", +1}}, 0);
      },
      ThrowsMessage<std::invalid_argument>("Adder 'err': size 0 must be at least 1"));
}

}  // namespace
}  // namespace cbbg
