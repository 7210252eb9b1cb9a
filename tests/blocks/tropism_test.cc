#include "cbbg/blocks/tropism.h"

#include <cmath>
#include <numbers>
#include <stdexcept>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "cbbg/framework/block_harness.h"
#include "key_order.h"

namespace cbbg::blocks {
namespace {

using ::testing::ElementsAre;
using ::testing::StrEq;
using ::testing::ThrowsMessage;
using Harness = testing::BlockHarness<Tropism>;

double temperature_at(Harness& harness, double value) {
  harness.set_input("value", value);
  return harness.scalar_output("temperature");
}

TEST(Tropism, TemperatureAsWorkedOutByHand) {
  Harness harness("tropism", TropismParams{});
  EXPECT_EQ(temperature_at(harness, 0.0), 5.0);  // k1 / 2
  EXPECT_NEAR(temperature_at(harness, 10.0), 10.0 / (1.0 + std::numbers::e), 1e-14);
  EXPECT_NEAR(temperature_at(harness, -10.0), 10.0 / (1.0 + 1.0 / std::numbers::e), 1e-14);
}

TEST(Tropism, TemperatureTendsToItsBoundsForExtremeValues) {
  Harness harness("tropism", TropismParams{});
  EXPECT_EQ(temperature_at(harness, -1e5), 10.0);  // exp(-1e4) underflows to 0: T = k1
  EXPECT_EQ(temperature_at(harness, 1e5), 0.0);    // exp(1e4) overflows: T = 0, not NaN
}

TEST(Tropism, AnnealingChangesK1InTheContext) {
  Harness harness("tropism", TropismParams{});
  EXPECT_EQ(harness.block().k1(harness.context()), 10.0);
  harness.block().set_k1(harness.context(), 0.5);
  EXPECT_EQ(harness.block().k1(harness.context()), 0.5);
  EXPECT_EQ(temperature_at(harness, 0.0), 0.25);
  // The same block in a fresh context keeps the configured k1.
  EXPECT_EQ(harness.simulator().diagram().create_context()->parameter(harness.block(), "k1")[0],
            10.0);
}

TEST(Tropism, FixedKindHoldsHalfK1WhateverTheValueAndFollowsTheAnnealing) {
  TropismParams fixed;
  fixed.kind = TropismKind::kFixed;
  Harness harness("tropism", fixed);
  for (const double value : {0.0, 10.0, -10.0, 1e5, -1e5}) {
    EXPECT_EQ(temperature_at(harness, value), 5.0) << "V = " << value;  // k1 / 2
  }
  harness.block().set_k1(harness.context(), 0.5);  // exp2's annealing still reaches it
  EXPECT_EQ(temperature_at(harness, 10.0), 0.25);
}

TEST(TropismParams, KindIsLastAndTheDefaultIsThePapers) {
  EXPECT_THAT(testing::declared_keys<TropismParams>(), ElementsAre("k1", "k2", "kind"));
  EXPECT_EQ(TropismParams{}.kind, TropismKind::kValue);
  for (const TropismKind kind : {TropismKind::kValue, TropismKind::kFixed}) {
    EXPECT_EQ(parse_tropism_kind(to_string(kind)), kind);
  }
  EXPECT_THAT([] { parse_tropism_kind("constant"); },
              ThrowsMessage<std::invalid_argument>(
                  StrEq("tropism.kind must be value or fixed; got 'constant'")));
  TropismParams unknown;
  unknown.kind = static_cast<TropismKind>(4);
  EXPECT_THAT(
      [&] { Tropism("tropism", unknown); },
      ThrowsMessage<std::invalid_argument>(StrEq("tropism.kind must be one of value, fixed")));
}

TEST(Tropism, RejectsInvalidParameters) {
  TropismParams zero_k1;
  zero_k1.k1 = 0.0;
  EXPECT_THAT(
      [&] { Tropism("tropism", zero_k1); },
      ThrowsMessage<std::invalid_argument>(StrEq("tropism.k1 must be finite and > 0; got 0")));
  TropismParams nan_k2;
  nan_k2.k2 = NAN;
  EXPECT_THAT([&] { Tropism("tropism", nan_k2); },
              ThrowsMessage<std::invalid_argument>(StrEq("tropism.k2 must be finite; got nan")));
  Harness harness("tropism", TropismParams{});
  EXPECT_THAT(
      [&] { harness.block().set_k1(harness.context(), -1.0); },
      ThrowsMessage<std::invalid_argument>(StrEq("tropism.k1 must be finite and > 0; got -1")));
  EXPECT_EQ(harness.block().k1(harness.context()), 10.0);
}

}  // namespace
}  // namespace cbbg::blocks
