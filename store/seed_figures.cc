#include "cbbg/store/seed_figures.h"

#include <algorithm>
#include <cmath>

namespace cbbg::store {

using records::Figure;
using records::FigureSummary;
using records::ValueType;

const Figure* find_figure(const records::ExperimentResults& results, const std::string& name) {
  for (const Figure& figure : records::run_figures()) {
    if (figure.name == name) return &figure;
  }
  return results.schema.figure(name);
}

std::vector<std::optional<double>> seed_values(const records::ExperimentResults& results,
                                               std::size_t arm, const Figure& figure) {
  std::vector<std::optional<double>> values;
  for (std::size_t s = 0; s < results.seeds.size(); ++s) {
    values.push_back(results.run(arm, s).figure(figure.name));
  }
  return values;
}

std::vector<double> ranked(const std::vector<std::optional<double>>& values,
                           records::Missing missing) {
  std::vector<double> sorted;
  for (const auto& value : values) {
    if (value) {
      sorted.push_back(*value);
    } else if (missing == records::Missing::kBeyondMaxTrials) {
      sorted.push_back(INFINITY);
    }
  }
  std::sort(sorted.begin(), sorted.end());
  return sorted;
}

double middle(const std::vector<double>& sorted) {
  const std::size_t n = sorted.size();
  if (n == 0) return NAN;
  return n % 2 == 1 ? sorted[n / 2] : 0.5 * (sorted[n / 2 - 1] + sorted[n / 2]);
}

}  // namespace cbbg::store
