#pragma once
// Paired comparisons of two arms over the same seeds. With common random numbers seed k
// gives both arms the same streams, so the per-seed difference is the fair comparison: its
// mean with a bootstrap confidence interval, and an exact two-sided sign test.

#include <cstdint>
#include <vector>

namespace cbbg::records {

struct PairedComparison {
  std::vector<double> differences;  // b[k] - a[k], per seed
  double mean = 0.0;
  // Percentile bootstrap interval of the mean (`resamples` resamples of the seeds).
  double ci_low = 0.0;
  double ci_high = 0.0;
  double level = 0.95;
  int positive = 0;  // seeds where b > a
  int negative = 0;  // seeds where b < a
  int ties = 0;
  double sign_test_p = 1.0;  // exact, two-sided, ties dropped
};

// The exact two-sided sign test: twice the smaller binomial(n, 1/2) tail of `positive` among
// `positive + negative` seeds, at most 1 (1 when there are none).
double sign_test_p(int positive, int negative);

// Compares b against a seed by seed (same length, at least one seed). The bootstrap draws
// from a generator seeded with `bootstrap_seed`, so the interval is the same on every run.
PairedComparison compare_paired(const std::vector<double>& a, const std::vector<double>& b,
                                std::uint64_t bootstrap_seed = 1, int resamples = 10000,
                                double level = 0.95);

}  // namespace cbbg::records
