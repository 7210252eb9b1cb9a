#pragma once
// Where a sweep (cbbg run --grid) works, how its shards share that place, and how the merge
// commits it. Every shard of a sweep is given the same --out TARGET and may run at the same
// time as the others, on one machine or on a cluster's shared filesystem:
//
//   TARGET.partial/  .cbbg-sweep-run  marker: the hash of config.yaml, whether to draw figures
//                    config.yaml      the base config and its sweep: section
//                    tasks/POINT/     each grid point's finished tasks (store::TaskStore)
//                    failed/          one file per shard that stopped on an error
//                    .cbbg-shard-K-of-N.lock   held by shard K of N while it runs
//                    .cbbg-lock       held by the merge
//   TARGET/          .cbbg-results, config.yaml, sweep.csv, figures/sweep_KEY.png, and
//                    points/POINT/, each a results directory of the usual layout (without
//                    figures: a sweep's figures are the sweep's)
//
// A shard locks only its own lock file and writes only its own tasks' records, each written
// atomically, so shards never wait for each other and a shard run again after a kill or a
// preemption redoes only its unfinished tasks.

#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "cbbg/store/directory_lock.h"

namespace cbbg::store {

inline constexpr const char* kSweepWorkMarker = ".cbbg-sweep-run";

class SweepDirectory {
 public:
  // Creates TARGET.partial for the sweep whose config.yaml is `config_yaml`, or joins it
  // when another shard of the same sweep made it first, and takes shard `shard`'s lock.
  // Throws config::ConfigError naming the path when TARGET holds anything, when
  // TARGET.partial is not a sweep's or is another sweep's (its config differs), or when the
  // shard is running elsewhere.
  // `figures`: whether the merge draws DIR/figures (cbbg run --no-figures: not); every shard
  // of a sweep must agree on it, as on the config.
  static SweepDirectory open_shard(const std::filesystem::path& target,
                                   const std::string& config_yaml, bool figures, int shard,
                                   int shards);
  // TARGET.partial of a sweep, for reading (cbbg status) or, with `lock`, for the merge,
  // which must run alone: refused while any shard holds its lock.
  static SweepDirectory open_existing(const std::filesystem::path& target, bool lock);

  const std::filesystem::path& target() const { return target_; }
  const std::filesystem::path& work() const { return work_; }
  std::string config_yaml() const;
  // Whether the merge draws the sweep's figures (recorded by the first shard).
  bool figures() const;
  // Where grid point `point` (from 0) of `points` keeps its tasks, and its results.
  std::filesystem::path tasks(std::size_t point, std::size_t points) const;
  std::filesystem::path point_results(std::size_t point, std::size_t points) const;
  // failed/SHARD.txt: the error that stopped this shard, for cbbg status.
  void record_failure(const std::string& message) const;
  // Clears this shard's failure record (it is running again).
  void clear_failure() const;
  // Each failed shard's name and error.
  std::vector<std::pair<std::string, std::string>> failures() const;
  // True when a merge renamed the work directory into place but was stopped before it had
  // cleaned up: commit() finishes it.
  bool published() const { return published_; }
  // Marks the work directory complete and renames it to TARGET (never over anything), then
  // removes the tasks, the failure records, the locks and last the marker. The result files
  // must be in work(). A kill at any point leaves a state the next merge finishes.
  void commit();

 private:
  explicit SweepDirectory(const std::filesystem::path& target);

  std::filesystem::path target_;
  std::filesystem::path work_;
  std::string shard_name_;  // "K-of-N"; empty for the merge
  bool published_ = false;
  std::optional<DirectoryLock> lock_;
};

// "001", "002", ...: a grid point's folder name, wide enough for `points`.
std::string point_name(std::size_t point, std::size_t points);

}  // namespace cbbg::store
