#include "store/sweep_results.h"

#include <algorithm>

#include "framework/number_text.h"
#include "store/results_writer.h"
#include "store/sweep_directory.h"

namespace cbbg::store {
namespace {

// A CSV field: quoted when it holds a comma or a quote (a list value, say).
std::string field(const std::string& text) {
  if (text.find_first_of(",\"") == std::string::npos) return text;
  std::string quoted = "\"";
  for (const char c : text) {
    if (c == '"') quoted += '"';
    quoted += c;
  }
  quoted += '"';
  return quoted;
}

}  // namespace

std::string headline_name(const std::string& experiment) {
  return experiment == "exp2" ? "balanced_trials" : "failures_before_success";
}

int headline(const std::string& experiment, const experiments::SeedRun& run) {
  if (experiment != "exp2") return run.failures_before_success;
  return static_cast<int>(std::count_if(run.trials.begin(), run.trials.end(), [](const auto& t) {
    return t.outcome.status == experiments::TrialStatus::kSuccess;
  }));
}

std::string sweep_csv(const config::Sweep& sweep,
                      const std::vector<experiments::ExperimentResults>& results) {
  const std::string name = headline_name(results.front().experiment);
  std::string csv = "point";
  // Appended piece by piece: GCC 12 warns falsely (-Wrestrict) on chains of operator+.
  auto column = [&csv](const std::string& text) {
    csv += ',';
    csv += text;
  };
  for (const auto& axis : sweep.axes()) column(field(axis.key));
  for (const char* fixed : {"arm", "seeds", "succeeded"}) column(fixed);
  for (const char* suffix : {"_median", "_min", "_max"}) column(name + suffix);
  csv += '\n';
  for (std::size_t p = 0; p < results.size(); ++p) {
    const experiments::ExperimentResults& point = results[p];
    for (std::size_t a = 0; a < point.arms.size(); ++a) {
      std::vector<int> figures;
      int succeeded = 0;
      for (std::size_t s = 0; s < point.seeds.size(); ++s) {
        figures.push_back(headline(point.experiment, point.run(a, s)));
        succeeded += point.run(a, s).succeeded ? 1 : 0;
      }
      csv += point_name(p, results.size());
      for (const std::string& value : sweep.values(p)) column(field(value));
      column(point.arms[a]);
      column(std::to_string(point.seeds.size()));
      column(std::to_string(succeeded));
      column(format_number(median(figures)));
      column(std::to_string(*std::min_element(figures.begin(), figures.end())));
      column(std::to_string(*std::max_element(figures.begin(), figures.end())));
      csv += '\n';
    }
  }
  return csv;
}

}  // namespace cbbg::store
