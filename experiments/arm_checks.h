#pragma once
// Before any work, what a run's arms will be: each is built once from the run's parameters,
// so a factory that refuses them (a user's supervisor whose Riccati equation has no
// solution) is the user's mistake, reported at the edge rather than as a failed run that
// --resume could never finish; and what each learner would store fits what a weights file
// and a task record hold (blocks::kMaxFeatures).

#include "cbbg/config/parameters.h"

namespace cbbg::experiments {

// Builds the closed loop of every arm `parameters.run` runs (experiment_arms), each once.
// Throws config::ConfigError naming the arm and the factory's reason, or the arm, its
// feature count, its layout's keys and the limit.
void check_arms_build(const config::Parameters& parameters);

}  // namespace cbbg::experiments
