#include "cbbg/store/sweep_results.h"

#include <algorithm>
#include <cmath>
#include <functional>

#include "cbbg/framework/number_text.h"
#include "cbbg/store/results_writer.h"
#include "cbbg/store/seed_figures.h"
#include "cbbg/store/sweep_directory.h"

namespace cbbg::store {

namespace {

// The evaluation runs (exp1, exp3) of one arm over the seeds, and how many balanced.
struct Evaluated {
  int runs = 0;
  int balanced = 0;
};

Evaluated evaluated(const records::ExperimentResults& point, std::size_t arm) {
  Evaluated count;
  for (std::size_t s = 0; s < point.seeds.size(); ++s) {
    for (const records::EvaluationRecord& record : point.run(arm, s).evaluation) {
      ++count.runs;
      count.balanced += record.outcome.status == records::TrialStatus::kSuccess ? 1 : 0;
    }
  }
  return count;
}

// The figures of one arm at one grid point, after the point's name and values.
void append_arm_figures(const records::ExperimentResults& point, std::size_t arm,
                        const std::function<void(const std::string&)>& column) {
  const records::Figure& headline =
      *find_figure(point, point.schema.headline_name());  // check_schema: it is one
  const std::vector<double> sorted = ranked(seed_values(point, arm, headline), headline.missing);
  int succeeded = 0;
  for (std::size_t s = 0; s < point.seeds.size(); ++s) {
    succeeded += point.run(arm, s).succeeded ? 1 : 0;
  }
  const auto text = [](double value) { return std::isfinite(value) ? format_number(value) : ""; };
  column(point.arms[arm]);
  column(std::to_string(point.seeds.size()));
  column(std::to_string(succeeded));
  column(text(middle(sorted)));
  column(text(sorted.empty() ? NAN : sorted.front()));
  column(text(sorted.empty() ? NAN : sorted.back()));
  const Evaluated evaluation = evaluated(point, arm);
  column(std::to_string(evaluation.runs));
  column(std::to_string(evaluation.balanced));
  column(evaluation.runs == 0
             ? std::string()
             : format_number(static_cast<double>(evaluation.balanced) / evaluation.runs));
}

}  // namespace

std::string sweep_csv(const config::Sweep& sweep,
                      const std::vector<records::ExperimentResults>& results) {
  const std::string name = results.front().schema.headline_name();
  std::string csv = "point";
  // Appended piece by piece: GCC 12 warns falsely (-Wrestrict) on chains of operator+.
  const std::function<void(const std::string&)> column = [&csv](const std::string& text) {
    csv += ',';
    csv += text;
  };
  for (const auto& axis : sweep.axes()) column(csv_field(axis.key));
  for (const char* fixed : {"arm", "seeds", "succeeded"}) column(fixed);
  for (const char* suffix : {"_median", "_min", "_max"}) column(name + suffix);
  for (const char* evaluation : {"evaluated", "balanced", "balance_rate"}) column(evaluation);
  csv += '\n';
  for (std::size_t p = 0; p < results.size(); ++p) {
    const records::ExperimentResults& point = results[p];
    for (std::size_t a = 0; a < point.arms.size(); ++a) {
      csv += point_name(p, results.size());
      for (const std::string& value : sweep.values(p)) column(csv_field(value));
      append_arm_figures(point, a, column);
      csv += '\n';
    }
  }
  return csv;
}

}  // namespace cbbg::store
