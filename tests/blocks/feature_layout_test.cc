// blocks::first_difference and layout_text: where two feature layouts first differ, in the
// words a weights file's refusal shows (experiments::check_layout), whichever of the two is
// shorter.

#include "cbbg/blocks/feature_layout.h"

#include <gtest/gtest.h>

namespace cbbg::blocks {
namespace {

const FeatureLayout kGrid{
    {"normaliser.saturation", {3}}, {"rbf.centres", {-1, 0, 1}}, {"rbf.width", {0.5}}};

TEST(FeatureLayout, TheSameLayoutsDifferNowhere) {
  EXPECT_TRUE(first_difference(kGrid, kGrid).empty());
  EXPECT_TRUE(first_difference({}, {}).empty());
}

// A weights file (the first) made before its blocks described an entry the loop's have.
TEST(FeatureLayout, AFirstLayoutShorterThanTheSecondLacksItsNextEntry) {
  const FeatureLayout file(kGrid.begin(), kGrid.begin() + 1);
  const LayoutDifference difference = first_difference(file, kGrid);
  EXPECT_EQ(difference.first, "no rbf.centres");
  EXPECT_EQ(difference.second, "rbf.centres [-1, 0, 1]");
  const LayoutDifference from_nothing = first_difference({}, kGrid);
  EXPECT_EQ(from_nothing.first, "no normaliser.saturation");
  EXPECT_EQ(from_nothing.second, "normaliser.saturation 3");
}

TEST(FeatureLayout, ASecondLayoutShorterThanTheFirstLacksItsNextEntry) {
  const FeatureLayout loop(kGrid.begin(), kGrid.begin() + 2);
  const LayoutDifference difference = first_difference(kGrid, loop);
  EXPECT_EQ(difference.first, "rbf.width 0.5");
  EXPECT_EQ(difference.second, "no rbf.width");
}

TEST(FeatureLayout, EntriesAreShownOneNumberBareAndSeveralInBrackets) {
  EXPECT_EQ(layout_text(kGrid),
            "normaliser.saturation 3 and rbf.centres [-1, 0, 1] and rbf.width 0.5");
  EXPECT_EQ(layout_text({}), "no layout");
}

}  // namespace
}  // namespace cbbg::blocks
