#pragma once
// Where a run works and how it commits its results without ever losing data.
//
// A run into TARGET works in TARGET.partial, which holds a marker (.cbbg-run: the config's
// hash and the options that shape the output), a lock (.cbbg-lock, held while the run
// lives), the resolved config it began with (run-config.yaml, written once: the results'
// config.yaml is written by the commit, so no step of it touches what --resume reads) and
// the finished tasks. A finished results directory holds
// the marker .cbbg-results. cbbg writes only into directories it made: --out refuses
// anything that is neither absent nor a finished results directory, and replaces a finished
// one only when asked (RunShape::replace), keeping it until the new results are complete.
//
// The commit, each step of which a kill may interrupt and --resume finishes:
//   1. the result files are written into the work directory (write_result_files);
//   2. the work directory is marked complete (.cbbg-results);
//   3. the work directory becomes TARGET in one atomic step: a rename, or, when it replaces
//      earlier results, an exchange of the two directories (so TARGET is never missing and
//      the old results wait at TARGET.partial);
//   4. the replaced results (unless a file cbbg did not write has joined them), the tasks,
//      run-config.yaml, the lock and last the .cbbg-run marker are removed.
// After step 3 TARGET holds .cbbg-run until step 4 ends: --resume TARGET finishes it.

#include <filesystem>
#include <optional>
#include <string>

#include "cbbg/config/config.h"
#include "cbbg/store/directory_lock.h"

namespace cbbg::store {

inline constexpr const char* kResultsMarker = ".cbbg-results";
inline constexpr const char* kWorkMarker = ".cbbg-run";
inline constexpr const char* kLockFile = ".cbbg-lock";
inline constexpr const char* kRunConfigFile = "run-config.yaml";
inline constexpr const char* kFailureFile = ".cbbg-failure";

// What shapes a run's output besides its config: recorded when the run starts, restored by
// --resume.
struct RunShape {
  bool figures = true;   // figures/ is drawn (cbbg run --no-figures: not)
  bool replays = true;   // figures/ gets the replay pages (cbbg run --no-replay: not)
  bool replace = false;  // a finished results directory at the target may be replaced
};

// What `status` tells of a run, read without locking or writing anything.
struct RunState {
  enum class Phase {
    kRunning,      // TARGET.partial, its lock held by a live run
    kInterrupted,  // TARGET.partial, no live run: --resume continues it
    kPublished,    // TARGET, its commit's cleanup unfinished: --resume finishes it
    kFinished,     // TARGET, finished results
  };
  Phase phase;
  config::Config config;        // the run's
  std::filesystem::path tasks;  // where its finished tasks are kept (kRunning, kInterrupted)
};

class RunDirectory {
 public:
  // The state of a run into `target`; nullopt when neither TARGET nor TARGET.partial holds
  // one (a sweep's, or nothing of cbbg's). Throws config::ConfigError for a config that
  // does not load.
  static std::optional<RunState> inspect(const std::filesystem::path& target);

  // Starts a run into `target`. Throws config::ConfigError, naming the path, when `target` is
  // empty, a file, or a directory that is not a finished results directory (or is one and
  // `shape.replace` is not set), or when TARGET.partial is in the way or in use; and
  // std::runtime_error when the machine refuses to create the work directory.
  static RunDirectory create(const std::filesystem::path& target, const config::Config& config,
                             const RunShape& shape);
  // Continues the interrupted run into `target`: from TARGET.partial, or the last step of an
  // interrupted commit. Throws config::ConfigError with one piece of advice for every state
  // in which there is nothing to resume, and when the work directory's config was edited.
  static RunDirectory resume(const std::filesystem::path& target);

  const std::filesystem::path& work() const { return work_; }
  const std::filesystem::path& target() const { return target_; }
  std::filesystem::path tasks() const { return work_ / "tasks"; }
  // Where the weights learning started from are kept (cbbg run --load-weights), for resume.
  std::filesystem::path initial_weights() const { return work_ / "initial_weights.txt"; }
  const config::Config& config() const { return config_; }
  const RunShape& shape() const { return shape_; }
  // True when only the cleanup of an interrupted commit remains: commit() finishes it.
  bool published() const { return published_; }

  // Steps 2 to 4 above (the result files must be in work()).
  void commit();

  // Keeps `message`, why the run just failed, in the work directory (best effort: a full
  // disk may refuse it) and returns whether the previous try failed with the same message:
  // then --resume would fail the same way again.
  bool record_failure(const std::string& message) const;

 private:
  explicit RunDirectory(std::filesystem::path target);
  void read_marker();
  void remove_replaced() const;

  std::filesystem::path target_;
  std::filesystem::path work_;
  config::Config config_;
  RunShape shape_;
  bool published_ = false;
  std::optional<DirectoryLock> lock_;
};

}  // namespace cbbg::store
