#pragma once
// A results' figures per seed and the statistics over the seeds, as every reader of results
// (summary.json, sweep.csv, the console) takes them from the schema: every run's own figures
// (failures_before_success, succeeded) and the protocol's (ResultsSchema::figures).

#include <optional>
#include <string>
#include <vector>

#include "cbbg/records/experiment_results.h"

namespace cbbg::store {

// The figure `name` of the results' schema, or of every run; nullptr for neither.
const records::Figure* find_figure(const records::ExperimentResults& results,
                                   const std::string& name);

// Per seed of arm `arm`, the figure's value (none where the seed has none).
std::vector<std::optional<double>> seed_values(const records::ExperimentResults& results,
                                               std::size_t arm, const records::Figure& figure);

// The values a median, min or max ranks, sorted: a missing one as beyond every other
// (infinity) under Missing::kBeyondMaxTrials, else left out.
std::vector<double> ranked(const std::vector<std::optional<double>>& values,
                           records::Missing missing);
// The median of sorted values (the mean of the middle two for an even count); NaN for none.
double middle(const std::vector<double>& sorted);

}  // namespace cbbg::store
