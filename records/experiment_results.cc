#include "cbbg/records/experiment_results.h"

namespace cbbg::records {
namespace {

std::optional<double> find_value(const std::vector<NamedValue>& values, const std::string& name) {
  for (const NamedValue& value : values) {
    if (value.name == name) return value.value;
  }
  return std::nullopt;
}

}  // namespace

const char* to_string(TrialStatus status) {
  switch (status) {
    case TrialStatus::kSuccess:
      return "success";
    case TrialStatus::kFailed:
      return "failed";
    case TrialStatus::kDiverged:
      return "diverged";
    case TrialStatus::kStopped:
      return "stopped";
  }
  return "unknown";
}

std::optional<double> TrialRecord::value(const std::string& name) const {
  return find_value(values, name);
}

std::optional<double> SeedRun::figure(const std::string& name) const {
  if (name == "failures_before_success") return failures_before_success;
  if (name == "succeeded") return succeeded ? 1.0 : 0.0;
  return find_value(figures, name);
}

}  // namespace cbbg::records
