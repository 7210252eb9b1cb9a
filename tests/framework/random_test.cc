#include "cbbg/framework/random.h"

#include <cmath>

#include <gtest/gtest.h>

namespace cbbg {
namespace {

TEST(Random, DerivedSeedsDependOnRootSeedAndPath) {
  EXPECT_EQ(derive_seed(1, "top/a"), derive_seed(1, "top/a"));
  EXPECT_NE(derive_seed(1, "top/a"), derive_seed(1, "top/b"));
  EXPECT_NE(derive_seed(1, "top/a"), derive_seed(2, "top/a"));
  EXPECT_NE(derive_seed(0, ""), 0u);
}

TEST(Random, StandardNormalHasUnitMomentsAndIsReproducible) {
  RandomGenerator generator(derive_seed(5, "test"));
  constexpr int kDraws = 200000;
  double sum = 0.0;
  double sum_squares = 0.0;
  double sum_fourth = 0.0;
  for (int i = 0; i < kDraws; ++i) {
    const double x = draw_standard_normal(generator);
    sum += x;
    sum_squares += x * x;
    sum_fourth += x * x * x * x;
  }
  const double mean = sum / kDraws;
  const double variance = sum_squares / kDraws - mean * mean;
  // Five standard errors: sd(mean) = 1/sqrt(n), sd(variance) = sqrt(2/n).
  EXPECT_NEAR(mean, 0.0, 5.0 / std::sqrt(kDraws));
  EXPECT_NEAR(variance, 1.0, 5.0 * std::sqrt(2.0 / kDraws));
  EXPECT_NEAR(sum_fourth / kDraws, 3.0, 5.0 * std::sqrt(96.0 / kDraws));  // Gaussian kurtosis

  RandomGenerator a(9);
  RandomGenerator b(9);
  for (int i = 0; i < 10; ++i) EXPECT_EQ(draw_standard_normal(a), draw_standard_normal(b));
}

TEST(Random, UniformStaysInTheUnitInterval) {
  RandomGenerator generator(3);
  double low = 1.0;
  double high = 0.0;
  for (int i = 0; i < 100000; ++i) {
    const double u = draw_uniform(generator);
    low = std::min(low, u);
    high = std::max(high, u);
  }
  EXPECT_GE(low, 0.0);
  EXPECT_LT(low, 1e-3);
  EXPECT_LT(high, 1.0);
  EXPECT_GT(high, 1.0 - 1e-3);
}

}  // namespace
}  // namespace cbbg
