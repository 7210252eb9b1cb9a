#pragma once
// Where a run's finished tasks are kept between runs, so a killed run resumes where it stopped
// (store::TaskStore keeps them on disk; experiments/parallel_runs.h runs the tasks).

#include <cstddef>
#include <filesystem>

#include "cbbg/records/experiment_results.h"

namespace cbbg::records {

// Where finished tasks are kept between runs (store::TaskStore keeps them on disk).
class TaskStorage {
 public:
  virtual ~TaskStorage() = default;
  // Fills `run` from a task finished earlier; false when the task has no record.
  virtual bool load(std::size_t task, SeedRun& run) const = 0;
  // Where the task's steps.csv rows go while it runs.
  virtual std::filesystem::path pending_steps_path(std::size_t task) const = 0;
  // Keeps the finished task (its record and its rows).
  virtual void save(std::size_t task, const SeedRun& run) const = 0;
};

}  // namespace cbbg::records
