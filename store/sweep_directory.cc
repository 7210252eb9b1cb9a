#include "cbbg/store/sweep_directory.h"

#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <sstream>

#include "cbbg/config/config.h"
#include "cbbg/config/program_name.h"
#include "cbbg/store/fault_point.h"
#include "cbbg/store/files.h"
#include "cbbg/store/output_guard.h"
#include "cbbg/store/run_directory.h"
#include "cbbg/store/task_store.h"

namespace cbbg::store {
namespace fs = std::filesystem;
namespace {

std::string sweep_marker(const std::string& config_yaml, bool figures) {
  std::string marker = "cbbg-sweep 1\nconfig ";
  marker += text_hash(config_yaml);
  marker += figures ? "\nfigures 1\n" : "\nfigures 0\n";
  return marker;
}

bool present(const fs::path& path) {
  std::error_code error;
  return fs::exists(fs::symlink_status(path, error));
}

// Builds TARGET.partial under a private name and renames it into place, so that it never
// exists without its marker; false when another shard's got there first.
bool try_create(const fs::path& work, const std::string& config_yaml, bool figures) {
  const fs::path staging = temporary_beside(work);
  std::error_code error;
  fs::create_directories(staging / "tasks", error);
  if (error) {
    throw std::runtime_error("cannot create " + quoted_path(work) + ": " + error.message());
  }
  write_atomically(staging / "config.yaml", config_yaml);
  write_atomically(staging / kSweepWorkMarker, sweep_marker(config_yaml, figures));
  fs::rename(staging, work, error);
  if (!error) return true;
  fs::remove_all(staging);
  if (present(work)) return false;
  throw std::runtime_error("cannot create " + quoted_path(work) + ": " + error.message());
}

void check_is_sweep(const fs::path& work, const fs::path& target) {
  if (present(work / kWorkMarker)) {
    throw config::ConfigError(
        quoted_path(work) + " holds an interrupted cbbg run, not a sweep: " + "continue it with " +
        config::program_name() + " run --resume " + target.string());
  }
  if (!present(work / kSweepWorkMarker)) {
    throw config::ConfigError(quoted_path(work) +
                              " is in the way and is not a cbbg sweep's; move it away");
  }
}

// Renames `from` to `to` unless something is at `to` (even an empty directory, which a plain
// rename would replace).
void rename_no_replace(const fs::path& from, const fs::path& to) {
  if (::renameat2(AT_FDCWD, from.c_str(), AT_FDCWD, to.c_str(), RENAME_NOREPLACE) != 0) {
    throw std::runtime_error("cannot move " + quoted_path(from) + " to " + quoted_path(to) + ": " +
                             std::strerror(errno));
  }
}

}  // namespace

std::string point_name(std::size_t point, std::size_t points) {
  const std::size_t width = std::max<std::size_t>(3, std::to_string(points).size());
  std::string name = std::to_string(point + 1);
  return std::string(width - std::min(width, name.size()), '0') + name;
}

SweepDirectory::SweepDirectory(const fs::path& target) : target_(target) {
  if (target_.filename().empty()) target_ = target_.parent_path();
  work_ = target_;
  work_ += ".partial";
}

SweepDirectory SweepDirectory::open_shard(const fs::path& target, const std::string& config_yaml,
                                          bool figures, int shard, int shards) {
  if (target.empty()) throw config::ConfigError("--out needs a directory path");
  SweepDirectory directory(target);
  if (present(directory.target_)) {
    throw config::ConfigError("--out " + quoted_path(directory.target_) +
                              " exists; a sweep writes a new directory (merged results stay "
                              "where they are)");
  }
  std::error_code error;
  fs::create_directories(directory.work_.parent_path(), error);
  // A shard killed while it made TARGET.partial left its staging, whoever made it since.
  remove_stale_staging(directory.work_);
  // false when another shard made it first: then this one joins it.
  if (!present(directory.work_)) try_create(directory.work_, config_yaml, figures);
  check_is_sweep(directory.work_, directory.target_);
  const std::string marker = read_text(directory.work_ / kSweepWorkMarker);
  if (marker == sweep_marker(config_yaml, !figures)) {
    throw config::ConfigError(quoted_path(directory.work_) + "'s shards were started " +
                              (figures ? "with --no-figures" : "without --no-figures") +
                              "; give every shard the same options");
  }
  if (marker != sweep_marker(config_yaml, figures)) {
    throw config::ConfigError(quoted_path(directory.work_) +
                              " belongs to a different sweep (its config.yaml differs); give "
                              "every shard the same config, grid and options, or another --out");
  }
  directory.shard_name_ = std::to_string(shard);
  directory.shard_name_ += "-of-";
  directory.shard_name_ += std::to_string(shards);
  std::string lock_file = ".cbbg-shard-";
  lock_file += directory.shard_name_;
  lock_file += ".lock";
  std::string what = directory.work_.string();
  what += " (shard ";
  what += std::to_string(shard);
  what += "/";
  what += std::to_string(shards);
  what += ")";
  directory.lock_.emplace(directory.work_ / lock_file, what);
  // Other shards may be writing: only the leftovers of writers that are gone.
  remove_temporaries(directory.work_, Leftovers::kStale);
  return directory;
}

SweepDirectory SweepDirectory::open_existing(const fs::path& target, bool lock) {
  if (target.empty()) throw config::ConfigError("give the sweep's --out directory");
  SweepDirectory directory(target);
  if (present(directory.target_ / kSweepWorkMarker)) {
    // Renamed into place by a merge that was stopped before it had cleaned up.
    directory.published_ = true;
    if (lock) directory.lock_.emplace(directory.target_ / kLockFile, directory.target_.string());
    if (lock) remove_temporaries(directory.target_);
    return directory;
  }
  if (!present(directory.work_)) {
    if (present(directory.target_ / kResultsMarker) && !present(directory.target_ / "sweep.csv")) {
      throw config::ConfigError(
          quoted_path(directory.target_) + " holds the results of a " + config::program_name() +
          " run, not of a sweep; merge is for sweeps (" + config::program_name() + " run --grid)");
    }
    if (present(directory.target_ / kResultsMarker)) {
      throw config::ConfigError(quoted_path(directory.target_) + " is merged already");
    }
    throw config::ConfigError("no sweep at " + quoted_path(directory.target_) + ": " +
                              quoted_path(directory.work_) + " does not exist");
  }
  check_is_sweep(directory.work_, directory.target_);
  if (!lock) return directory;
  if (present(directory.target_)) {  // the merge publishes there: refused before any work
    throw config::ConfigError(quoted_path(directory.target_) + " exists and was not made by " +
                              config::program_name() +
                              " merge; the merged results go there: " + "move it away, then merge");
  }
  std::error_code error;
  for (const auto& entry : fs::directory_iterator(directory.work_, error)) {
    const std::string name = entry.path().filename().string();
    if (name.rfind(".cbbg-shard-", 0) == 0 && DirectoryLock::held(entry.path())) {
      throw config::ConfigError("shard " + name.substr(12, name.size() - 17) + " of " +
                                quoted_path(directory.target_) +
                                " is still running; merge when every shard has finished");
    }
  }
  check_own_tasks(directory.work_ / "tasks");  // before the lock: a refusal writes nothing
  directory.lock_.emplace(directory.work_ / kLockFile, directory.work_.string());
  remove_stale_staging(directory.work_);
  remove_temporaries(directory.work_);  // every shard has ended: none is writing
  return directory;
}

std::string SweepDirectory::config_yaml() const { return read_text(work_ / "config.yaml"); }

bool SweepDirectory::figures() const {
  return read_text(work_ / kSweepWorkMarker).find("\nfigures 1\n") != std::string::npos;
}

fs::path SweepDirectory::tasks(std::size_t point, std::size_t points) const {
  return work_ / "tasks" / point_name(point, points);
}

fs::path SweepDirectory::point_results(std::size_t point, std::size_t points) const {
  return work_ / "points" / point_name(point, points);
}

void SweepDirectory::record_failure(const std::string& message) const {
  std::error_code error;
  fs::create_directories(work_ / "failed", error);
  write_atomically(work_ / "failed" / (shard_name_ + ".txt"), message + '\n');
}

void SweepDirectory::clear_failure() const {
  std::error_code error;
  fs::remove(work_ / "failed" / (shard_name_ + ".txt"), error);
}

std::vector<std::pair<std::string, std::string>> SweepDirectory::failures() const {
  std::vector<std::pair<std::string, std::string>> found;
  std::error_code error;
  for (const auto& entry : fs::directory_iterator(work_ / "failed", error)) {
    std::string name = entry.path().stem().string();
    std::replace(name.begin(), name.end(), '-', ' ');
    std::string text = read_text(entry.path());
    if (!text.empty() && text.back() == '\n') text.pop_back();
    found.emplace_back(name, text);
  }
  std::sort(found.begin(), found.end());
  return found;
}

void SweepDirectory::commit() {
  if (!published_) {
    refuse_temporaries(work_);
    fault_point("commit:marker");
    write_atomically(work_ / kResultsMarker, "cbbg-results 1\n");
    fault_point("commit:publish");
    rename_no_replace(work_, target_);
    published_ = true;
  }
  fault_point("commit:clean");
  remove_own_tasks(target_ / "tasks");
  remove_tree(target_ / "failed");
  std::error_code error;
  for (const auto& entry : fs::directory_iterator(target_, error)) {
    const std::string name = entry.path().filename().string();
    if (name.rfind(".cbbg-shard-", 0) == 0) fs::remove(entry.path(), error);
  }
  fs::remove(target_ / kLockFile, error);
  fault_point("commit:unmark");
  if (!fs::remove(target_ / kSweepWorkMarker, error) && error) {
    throw std::runtime_error("cannot remove " + quoted_path(target_ / kSweepWorkMarker) + ": " +
                             error.message());
  }
}

}  // namespace cbbg::store
