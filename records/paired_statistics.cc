#include "cbbg/records/paired_statistics.h"

#include <algorithm>
#include <cmath>
#include <random>
#include <stdexcept>

#include <boost/math/distributions/binomial.hpp>

namespace cbbg::records {

double sign_test_p(int positive, int negative) {
  const int n = positive + negative;
  if (n == 0) return 1.0;
  const boost::math::binomial_distribution<double> fair(n, 0.5);
  const double tail = boost::math::cdf(fair, std::min(positive, negative));
  return std::min(1.0, 2.0 * tail);
}

PairedComparison compare_paired(const std::vector<double>& a, const std::vector<double>& b,
                                std::uint64_t bootstrap_seed, int resamples, double level) {
  if (a.size() != b.size() || a.empty()) {
    throw std::invalid_argument("compare_paired: two lists of the same seeds are needed; got " +
                                std::to_string(a.size()) + " and " + std::to_string(b.size()));
  }
  if (resamples < 1 || !(level > 0.0 && level < 1.0)) {
    throw std::invalid_argument("compare_paired: resamples >= 1 and 0 < level < 1 are needed");
  }
  PairedComparison result;
  result.level = level;
  const auto n = a.size();
  for (std::size_t k = 0; k < n; ++k) {
    const double d = b[k] - a[k];
    result.differences.push_back(d);
    result.mean += d / static_cast<double>(n);
    result.positive += d > 0.0 ? 1 : 0;
    result.negative += d < 0.0 ? 1 : 0;
    result.ties += d == 0.0 ? 1 : 0;
  }
  result.sign_test_p = sign_test_p(result.positive, result.negative);
  // Indices drawn from the generator's raw output (not a distribution object, whose
  // algorithm the standard leaves open), so every library gives the same interval.
  std::mt19937_64 generator(bootstrap_seed);
  std::vector<double> means(static_cast<std::size_t>(resamples));
  for (double& mean : means) {
    double sum = 0.0;
    for (std::size_t k = 0; k < n; ++k) sum += result.differences[generator() % n];
    mean = sum / static_cast<double>(n);
  }
  std::sort(means.begin(), means.end());
  const double tail = (1.0 - level) / 2.0;
  const auto last = static_cast<double>(resamples - 1);
  result.ci_low = means[static_cast<std::size_t>(std::floor(tail * last))];
  result.ci_high = means[static_cast<std::size_t>(std::ceil((1.0 - tail) * last))];
  return result;
}

}  // namespace cbbg::records
