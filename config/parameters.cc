#include "cbbg/config/parameters.h"

#include <algorithm>
#include <cmath>
#include <map>
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
    try {
      check_default(key);
    } catch (const ConfigError& error) {
      throw std::invalid_argument(error.what());
    }
    for (const KeySpec& existing : keys()) {
      if (existing.path == key.path) {
        throw std::invalid_argument("config key '" + key.path + "' is declared twice");
      }
    }
  }
  for (KeySpec& key : added) keys().push_back(std::move(key));
}

namespace {
// The words users registered, by key.
std::map<std::string, std::vector<std::string>, std::less<>>& registered_words() {
  static std::map<std::string, std::vector<std::string>, std::less<>> words;
  return words;
}
}  // namespace

std::vector<std::string> with_registered_words(std::string_view key,
                                               std::vector<std::string> words) {
  if (const auto found = registered_words().find(key); found != registered_words().end()) {
    words.insert(words.end(), found->second.begin(), found->second.end());
  }
  return words;
}

void register_choice(std::string_view key, const std::string& word, std::string_view meaning) {
  for (KeySpec& spec : keys()) {  // made, if not yet, before the word is registered
    if (spec.path != key) continue;
    if (spec.kind != Kind::kText || spec.choices.empty()) {
      throw std::invalid_argument("config key '" + spec.path + "' takes no list of words");
    }
    if (std::find(spec.choices.begin(), spec.choices.end(), word) != spec.choices.end()) {
      throw std::invalid_argument("config key '" + spec.path + "' allows '" + word + "' already");
    }
    registered_words()[spec.path].push_back(word);
    spec.choices.push_back(word);
    spec.meaning += " | " + word + (meaning.empty() ? "" : " (" + std::string(meaning) + ")");
    return;
  }
  throw std::invalid_argument("no config key '" + std::string(key) + "'");
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
