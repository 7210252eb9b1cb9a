#pragma once
// Runs the (arm, seed) tasks of an experiment in threads. Each task builds its own closed
// loop and context and writes only its own slot of the results, so the results are the same
// whatever the number of threads. A TaskStorage keeps finished tasks, so a killed run
// resumes where it stopped.

#include <cstddef>
#include <filesystem>
#include <functional>

#include "cbbg/experiments/seed_run.h"
#include "cbbg/parameters/parameters.h"
#include "cbbg/records/task_storage.h"

namespace cbbg::experiments {

using records::TaskStorage;

// Called after each finished (arm, seed), from the worker thread that ran it.
using ProgressCallback = std::function<void(const SeedRun&)>;

struct ExperimentOptions {
  int jobs = 1;  // threads (>= 1); the results do not depend on it
  ProgressCallback progress{};
  // With a store, each task found finished there is loaded instead of run, each task run is
  // saved there, and its steps rows go to the store's files; without, to SeedRun::steps_csv.
  const TaskStorage* store = nullptr;
  // Where learning starts (cbbg run --load-weights); zero weights without.
  const LearntWeights* initial_weights = nullptr;
  // When set, only the tasks (index: arm-major, as ExperimentResults::runs) it accepts are
  // loaded or run, as a shard of a sweep does; the others stay empty in the results.
  std::function<bool(std::size_t task)> runs_task{};
};

// One task's work: fills `run` (its arm and seed set), writing steps rows through
// `telemetry`.
using TaskBody = std::function<void(SeedRun& run, const TelemetryOptions& telemetry)>;

// Results for every arm of `arms` and every seed of the parameters (seed, seed + 1, ...,
// `seeds` of them), each task run by `body` in `options.jobs` threads. The first task to
// throw stops the others from starting and is rethrown; an interrupt (Ctrl-C in Python,
// framework/interrupt.h) stops the running ones too, at their simulations' next instant.
ExperimentResults run_tasks(const parameters::Parameters& parameters,
                            const std::vector<std::string>& arms, const TaskBody& body,
                            const ExperimentOptions& options);

}  // namespace cbbg::experiments
