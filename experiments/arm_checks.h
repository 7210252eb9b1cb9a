#pragma once
// Before any work, what a run's arms will be: each is built once from the run's parameters,
// so a factory that refuses them (a user's supervisor whose Riccati equation has no
// solution) is the user's mistake, reported at the edge rather than as a failed run that
// --resume could never finish; and what each learner would store fits what a weights file
// and a task record hold (blocks::kMaxFeatures).

#include <cstddef>

#include "cbbg/parameters/parameters.h"

namespace cbbg::experiments {

// Builds the closed loop of every arm `parameters.run` runs (experiment_arms), each once,
// with the runner of its trials. Throws config::ConfigError naming the arm and the
// factory's reason, or the arm, its feature count, its layout's keys and the limit. Returns
// the most memory one task holds, in bytes, as the heap grew building one (0 where the
// allocator does not say, as a sanitizer's: then no memory is checked).
std::size_t check_arms_build(const parameters::Parameters& parameters);

// Before any work: `threads` tasks at once of `task_bytes` each fit in the memory the machine
// has available (Linux /proc/meminfo's MemAvailable; no check where it cannot be read).
// Throws config::ConfigError with the figures and what to lower.
void check_run_memory(std::size_t task_bytes, std::size_t threads);

}  // namespace cbbg::experiments
