#include "config/parameters.h"

#include <stdexcept>

#include "config/declared_keys.h"

namespace cbbg::config {
namespace {

// Every key: the built-in tree's, then the sections users registered.
std::vector<KeySpec>& keys() {
  static std::vector<KeySpec> all = declared_keys(Parameters{}, "");
  return all;
}

}  // namespace

const std::vector<std::string>& diagram_names() {
  static const std::vector<std::string> names{"cbbg", "cbbg_weighted", "bg_only", "cb_only",
                                              "pd_only"};
  return names;
}

std::vector<std::string> experiment_names() {
  std::vector<std::string> names{"exp1", "exp2", "exp3"};
  for (const auto& name : diagram_names()) names.push_back(name);
  return names;
}

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

Parameters read_parameters(const Config& config) {
  Parameters parameters;
  KeyReader reader(config, "");
  parameters.describe(reader);
  return parameters;
}

}  // namespace cbbg::config
