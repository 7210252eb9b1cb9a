#include "cbbg/experiments/run_names.h"

#include <algorithm>

#include "cbbg/diagrams/presets.h"
#include "cbbg/experiments/protocols.h"

namespace cbbg::experiments {
namespace {

bool contains(const std::vector<std::string>& names, const std::string& name) {
  return std::find(names.begin(), names.end(), name) != names.end();
}

}  // namespace

std::vector<ProtocolName> protocol_names() {
  std::vector<ProtocolName> names;
  for (const Protocol& protocol : protocols()) names.push_back({protocol.name, protocol.meaning});
  return names;
}

void check_experiment_name(const std::string& experiment) {
  std::vector<std::string> names;
  for (const auto& protocol : protocol_names()) names.push_back(protocol.name);
  for (const auto& arm : diagrams::arm_names()) names.push_back(arm);
  if (!contains(names, experiment)) {
    throw config::ConfigError("experiment must be one of " + config::join(names) + "; got '" +
                              experiment + "'");
  }
}

void check_arm_names(const std::vector<std::string>& arms) {
  const std::vector<std::string> names = diagrams::arm_names();
  for (std::size_t i = 0; i < arms.size(); ++i) {
    if (!contains(names, arms[i])) {
      throw config::ConfigError("arms[" + std::to_string(i) + "] must be one of " +
                                config::join(names) + "; got '" + arms[i] + "'");
    }
  }
}

void check_run_names(const parameters::RunParams& run) {
  check_experiment_name(run.experiment);
  check_arm_names(run.arms);
}

}  // namespace cbbg::experiments
