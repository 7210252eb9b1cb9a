#pragma once
// The names a run is given: the protocols `experiment` may name and the presets `arms` may,
// each from its own table (diagrams::presets() for the presets), checked before any work.
// A library run of its own arms needs no such names.

#include <string>
#include <vector>

#include "cbbg/parameters/parameters.h"

namespace cbbg::experiments {

// A protocol `experiment` may name, and what it measures (`cbbg list`).
struct ProtocolName {
  std::string name;
  std::string meaning;
};
// exp1, exp2, exp3 and the registered protocols (protocols.h), with their meanings.
std::vector<ProtocolName> protocol_names();

// Before any work: `experiment` names a protocol or an arm preset, and every entry of `arms`
// an arm preset (diagrams::arm_names). Each throws config::ConfigError naming the key, what
// is allowed and what was given.
void check_experiment_name(const std::string& experiment);
void check_arm_names(const std::vector<std::string>& arms);
void check_run_names(const parameters::RunParams& run);

}  // namespace cbbg::experiments
