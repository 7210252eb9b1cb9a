// Paired statistics against values worked by hand.

#include "cbbg/records/paired_statistics.h"

#include <cmath>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

namespace cbbg::records {
namespace {

TEST(PairedStatistics, TheSignTestIsTheExactBinomialTail) {
  // 9 of 10 positive: 2 (C(10,0) + C(10,1)) / 2^10 = 22 / 1024.
  EXPECT_DOUBLE_EQ(sign_test_p(9, 1), 22.0 / 1024.0);
  EXPECT_DOUBLE_EQ(sign_test_p(1, 9), 22.0 / 1024.0);
  // All 20 positive: 2 / 2^20.
  EXPECT_DOUBLE_EQ(sign_test_p(20, 0), 2.0 / 1048576.0);
  // 3 and 3: the tail holds more than half the mass, so p is capped at 1.
  EXPECT_DOUBLE_EQ(sign_test_p(3, 3), 1.0);
  // 2 of 6: 2 (1 + 6 + 15) / 64 = 44 / 64.
  EXPECT_DOUBLE_EQ(sign_test_p(2, 4), 44.0 / 64.0);
  EXPECT_DOUBLE_EQ(sign_test_p(0, 0), 1.0);
}

TEST(PairedStatistics, DifferencesMeanAndCountsArePerSeed) {
  const PairedComparison c = compare_paired({0, 0, 0, 1}, {3, 2, 0, 4});
  EXPECT_EQ(c.differences, (std::vector<double>{3, 2, 0, 3}));
  EXPECT_DOUBLE_EQ(c.mean, 2.0);
  EXPECT_EQ(c.positive, 3);
  EXPECT_EQ(c.negative, 0);
  EXPECT_EQ(c.ties, 1);
  EXPECT_DOUBLE_EQ(c.sign_test_p, 2.0 / 8.0);  // 3 of 3 positive
  // A resampled mean of {3, 2, 0, 3} lies in [0, 3]; the interval holds the mean.
  EXPECT_GE(c.ci_low, 0.0);
  EXPECT_LE(c.ci_high, 3.0);
  EXPECT_LE(c.ci_low, c.mean);
  EXPECT_GE(c.ci_high, c.mean);
}

TEST(PairedStatistics, TheBootstrapIsExactForEqualDifferencesAndRepeatable) {
  const PairedComparison same = compare_paired({1, 2, 3}, {3, 4, 5});
  EXPECT_DOUBLE_EQ(same.ci_low, 2.0);
  EXPECT_DOUBLE_EQ(same.ci_high, 2.0);
  const std::vector<double> a{2, 3, 3, 4, 2, 4, 3, 5, 4, 2};
  const std::vector<double> b{0, 0, 0, 0, 0, 0, 0, 0, 0, 1};
  const PairedComparison first = compare_paired(a, b);
  const PairedComparison again = compare_paired(a, b);
  EXPECT_EQ(first.ci_low, again.ci_low);
  EXPECT_EQ(first.ci_high, again.ci_high);
  EXPECT_DOUBLE_EQ(first.mean, -3.1);
  // The bootstrap mean of 10 draws from differences in [-5, -1]: well inside, around -3.1.
  EXPECT_GT(first.ci_low, -4.0);
  EXPECT_LT(first.ci_high, -2.3);
  // Two seeds with differences 0 and 2: a resampled mean is 0, 1 or 2 with chances 1/4,
  // 1/2 and 1/4, so the 2.5 % and 97.5 % points are 0 and 2.
  const PairedComparison two = compare_paired({0, 0}, {0, 2});
  EXPECT_DOUBLE_EQ(two.ci_low, 0.0);
  EXPECT_DOUBLE_EQ(two.ci_high, 2.0);
}

TEST(PairedStatistics, RefusesListsOfDifferentSeeds) {
  EXPECT_THAT(
      [] {
        compare_paired({1, 2}, {1});
      },
      ::testing::ThrowsMessage<std::invalid_argument>(
          "compare_paired: two lists of the same seeds are needed; got 2 and 1"));
  EXPECT_THROW(compare_paired({}, {}), std::invalid_argument);
}

}  // namespace
}  // namespace cbbg::records
