#include "cbbg/blocks/entropy.h"

#include <cmath>
#include <numbers>
#include <stdexcept>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "cbbg/framework/block_harness.h"

namespace cbbg::blocks {
namespace {

using ::testing::StrEq;
using ::testing::ThrowsMessage;
using Harness = testing::BlockHarness<Entropy>;

constexpr double kPiE = std::numbers::pi * std::numbers::e;

double entropy_at(Harness& harness, double temperature) {
  harness.set_input("temperature", temperature);
  return harness.scalar_output("entropy");
}

TEST(Entropy, BitsAsWorkedOutByHand) {
  Harness harness("entropy", EntropyParams{});
  EXPECT_NEAR(entropy_at(harness, 1.0 / kPiE), 0.0, 1e-15);            // log2(1) / 2
  EXPECT_NEAR(entropy_at(harness, 4.0 / kPiE), 1.0, 1e-15);            // log2(4) / 2
  EXPECT_NEAR(entropy_at(harness, 1.0 / (16.0 * kPiE)), -2.0, 1e-15);  // negative when small
  EXPECT_EQ(entropy_at(harness, 0.0), -INFINITY);
}

TEST(Entropy, ScalesWithKb) {
  EntropyParams literal;
  literal.k_b = 1.38e-23;
  Harness harness("entropy", literal);
  EXPECT_NEAR(entropy_at(harness, 4.0 / (kPiE * 1.38e-23)), 1.0, 1e-13);
  // 1.38e-23 is about 2^-75.94: at T = 1 the entropy is about -36.4 bits.
  EXPECT_NEAR(entropy_at(harness, 1.0), 0.5 * (std::log2(kPiE) - 75.9397), 1e-3);
}

TEST(Entropy, RejectsNonPositiveKb) {
  EntropyParams negative;
  negative.k_b = -1.0;
  EXPECT_THAT(
      [&] { Entropy("entropy", negative); },
      ThrowsMessage<std::invalid_argument>(StrEq("sampler.k_b must be finite and > 0; got -1")));
}

}  // namespace
}  // namespace cbbg::blocks
