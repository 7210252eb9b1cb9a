#pragma once
// What the commands that take a weights file (eval, export) share: the plant the weights were
// learnt on, and the closed loop of the arm's actor alone.

#include <filesystem>
#include <string>
#include <vector>

#include "cbbg/config/config.h"
#include "cbbg/diagrams/closed_loop.h"
#include "cbbg/experiments/learnt_weights.h"

namespace cbbg::app {

// The config of a command that loads `weights`: plant.kind the plant they were learnt on,
// where this program has its kind (else check_weights refuses them on the default); then
// the file `config_file` (none when empty) and the overrides `sets`, which win.
config::Config weights_config(const experiments::LearntWeights& weights,
                              const std::filesystem::path& config_file,
                              const std::vector<std::string>& sets);

// The learnt actor alone of the arm that learnt the weights (a preset's, or one the program
// registered, with its own features and controller); learnt_actor for an arm it does not know.
diagrams::ClosedLoopFactory policy_of(const std::string& arm,
                                      const diagrams::ClosedLoopOptions& loop = {});

}  // namespace cbbg::app
