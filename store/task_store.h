#pragma once
// Where a run keeps each finished (arm, seed) task, so a killed run can resume: per task a
// record of its trials (index.run), its steps.csv rows (index.steps.csv) and its learnt
// weights (index.weights.txt). A task's record
// is written last and atomically (temporary file, then rename), so a record that exists is
// complete, and so are its rows.

#include <filesystem>
#include <stdexcept>
#include <string>

#include "cbbg/records/experiment_results.h"
#include "cbbg/records/task_storage.h"

namespace cbbg::store {

using records::SeedRun;

// A task record of an earlier cbbg (an earlier record format), which this one does not read: its
// run cannot be continued, only started again.
class EarlierTaskRecord : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

class TaskStore final : public records::TaskStorage {
 public:
  // Keeps tasks in `directory`, created if missing.
  explicit TaskStore(std::filesystem::path directory);

  // Fills `run` from a task finished earlier; false when the task has no record. Throws
  // EarlierTaskRecord for a record of an earlier format, std::runtime_error naming the record
  // to remove for one that is not a record.
  bool load(std::size_t task, SeedRun& run) const override;
  // Whether the task has a record (finished).
  bool has(std::size_t task) const;
  // Where the task's rows are written while it runs, and where they stay once it is saved.
  std::filesystem::path pending_steps_path(std::size_t task) const override;
  std::filesystem::path steps_path(std::size_t task) const;
  // Keeps the task's rows and writes its record.
  void save(std::size_t task, const SeedRun& run) const override;

  const std::filesystem::path& directory() const { return directory_; }

 private:
  std::filesystem::path record_path(std::size_t task) const;
  std::filesystem::path weights_path(std::size_t task) const;

  std::filesystem::path directory_;
};

// How many of the tasks 0 .. count-1 kept in `tasks` have a record (are finished), read
// without creating or changing anything (cbbg status).
std::size_t finished_tasks(const std::filesystem::path& tasks, std::size_t count);

// Before a resume or a merge, which ends by removing `tasks`: throws config::ConfigError naming
// the first entry below it that is not a task file of cbbg's (a user's, to move away).
void check_own_tasks(const std::filesystem::path& tasks);
// Removes cbbg's task files below `tasks`, and the folders they leave empty; a user's file
// that arrived since the check stays, with its folders.
void remove_own_tasks(const std::filesystem::path& tasks);

// A task's record as text; every number in shortest round-trip form, so it reads back to the
// same bits. The steps rows are not part of it.
std::string serialize_run(const SeedRun& run);
// Throws std::runtime_error naming `source` for a record that is not one.
SeedRun parse_run(const std::string& text, const std::string& source);

}  // namespace cbbg::store
