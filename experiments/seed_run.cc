#include "cbbg/experiments/seed_run.h"

namespace cbbg::experiments {
namespace {

std::optional<double> find_value(const std::vector<NamedValue>& values, const std::string& name) {
  for (const NamedValue& value : values) {
    if (value.name == name) return value.value;
  }
  return std::nullopt;
}

}  // namespace

std::optional<double> TrialRecord::value(const std::string& name) const {
  return find_value(values, name);
}

std::optional<double> SeedRun::figure(const std::string& name) const {
  return find_value(figures, name);
}

}  // namespace cbbg::experiments
