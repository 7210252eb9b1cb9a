#include "cbbg/config/parameters.h"

#include <cmath>
#include <stdexcept>
#include <utility>

#include "cbbg/config/declared_keys.h"
#include "cbbg/framework/number_text.h"

namespace cbbg::config {
namespace {

std::vector<KeySpec> built_in_keys() { return declared_keys(Parameters{}, ""); }

// Every key: the built-in tree's, then the sections users registered.
std::vector<KeySpec>& keys() {
  static std::vector<KeySpec> all = built_in_keys();
  return all;
}

// How many of keys() the built-in tree declares; the registered sections' follow.
std::size_t built_in_count() {
  static const std::size_t count = built_in_keys().size();
  return count;
}

}  // namespace

const std::vector<KeySpec>& schema() { return keys(); }

void register_keys(std::vector<KeySpec> added) {
  for (const KeySpec& key : added) {
    for (const KeySpec& existing : keys()) {
      if (existing.path == key.path) {
        throw std::invalid_argument("config key '" + key.path + "' is declared twice");
      }
    }
  }
  for (KeySpec& key : added) keys().push_back(std::move(key));
}

void Parameters::check_across_sections() const {
  if (trial.duration < trial.period) {
    throw ConfigError("trial.duration (" + format_number(trial.duration) +
                      " s) must be at least one trial.period (" + format_number(trial.period) +
                      " s)");
  }
  auto inside = [this](const std::string& key, double angle) {
    if (!(std::abs(angle) < trial.failure_angle)) {
      throw ConfigError(
          key + " (" + format_number(angle) + " rad) must lie inside trial.failure_angle (" +
          format_number(trial.failure_angle) + " rad): a trial from there fails at once");
    }
  };
  inside("trial.theta0", trial.theta0);
  for (const auto& [key, angles] : {std::pair{"evaluation.angles", &evaluation.angles},
                                    std::pair{"exp3.angles", &exp3.angles}}) {
    for (std::size_t i = 0; i < angles->size(); ++i) {
      inside(std::string(key) + "[" + std::to_string(i) + "]", (*angles)[i]);
    }
  }
}

void write_parameters(const Parameters& parameters, Config& config) {
  try {
    check_declared(parameters, "");
  } catch (const std::invalid_argument& error) {
    throw ConfigError(error.what());
  }
  Parameters copy = parameters;
  KeyWriter writer(config, "");
  copy.describe(writer);
  for (const auto& [key, value] : parameters.own.values) config.assign(key, value);
}

Parameters read_parameters(const Config& config) {
  Parameters parameters;
  KeyReader reader(config, "");
  parameters.describe(reader);
  for (std::size_t k = built_in_count(); k < keys().size(); ++k) {
    parameters.own.values.emplace(keys()[k].path, config.value(keys()[k].path));
  }
  return parameters;
}

}  // namespace cbbg::config
