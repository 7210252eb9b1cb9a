#pragma once
// sweep.csv: one row per grid point and arm, with the grid's values and the headline figure
// of the protocol's schema over the seeds (failures_before_success unless it names another);
// and the evaluation's balance rate.

#include <string>
#include <vector>

#include "cbbg/config/sweep.h"
#include "cbbg/records/experiment_results.h"

namespace cbbg::store {

// Columns: point, each swept key, arm, seeds, succeeded (seeds with a successful trial), the
// headline's median, min and max over the seeds, then the evaluation's runs over the seeds
// and angles (exp1, exp3), those that balanced, and their ratio, the balance rate (empty
// without runs). `results[p]` is grid point p's.
std::string sweep_csv(const config::Sweep& sweep,
                      const std::vector<records::ExperimentResults>& results);

}  // namespace cbbg::store
