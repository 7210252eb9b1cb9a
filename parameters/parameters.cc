#include "cbbg/parameters/parameters.h"

#include <algorithm>
#include <cmath>
#include <set>
#include <stdexcept>
#include <utility>

#include "cbbg/framework/number_text.h"

namespace cbbg::parameters {
namespace {

// The keys the tree itself declares, by path: every other registered key's value is `own`'s.
const std::set<std::string, std::less<>>& tree_keys() {
  static const std::set<std::string, std::less<>> paths = [] {
    std::set<std::string, std::less<>> all;
    for (const config::KeySpec& key : config::declared_keys(Parameters{}, "")) all.insert(key.path);
    return all;
  }();
  return paths;
}

}  // namespace

bool register_tree() {
  static const bool registered = [] {
    config::register_leading_keys(config::declared_keys(Parameters{}, ""));
    return true;
  }();
  return registered;
}

void Parameters::check_inside_failure_angle(const std::string& key, double angle) const {
  if (!(std::abs(angle) < trial.failure_angle)) {
    throw config::ConfigError(
        key + " (" + format_number(angle) + " rad) must lie inside trial.failure_angle (" +
        format_number(trial.failure_angle) + " rad): a trial from there fails at once");
  }
}

void Parameters::check_across_sections() const {
  if (trial.duration < trial.period) {
    throw config::ConfigError("trial.duration (" + format_number(trial.duration) +
                              " s) must be at least one trial.period (" +
                              format_number(trial.period) + " s)");
  }
  check_inside_failure_angle("trial.theta0", trial.theta0);
  for (std::size_t i = 0; i < evaluation.angles.size(); ++i) {
    check_inside_failure_angle("evaluation.angles[" + std::to_string(i) + "]",
                               evaluation.angles[i]);
  }
}

void write_parameters(const Parameters& parameters, config::Config& config) {
  try {
    check_declared(parameters, "");
  } catch (const std::invalid_argument& error) {
    throw config::ConfigError(error.what());
  }
  Parameters copy = parameters;
  config::KeyWriter writer(config, "");
  copy.describe(writer);
  for (const auto& [key, value] : parameters.own.values) config.assign(key, value);
}

Parameters read_parameters(const config::Config& config) {
  Parameters parameters;
  config::KeyReader reader(config, "");
  parameters.describe(reader);
  for (const config::KeySpec& key : config::schema()) {
    if (!tree_keys().contains(key.path)) {
      parameters.own.values.emplace(key.path, config.value(key.path));
    }
  }
  return parameters;
}

}  // namespace cbbg::parameters
