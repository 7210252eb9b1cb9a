#include "cbbg/store/run_directory.h"

#include <fcntl.h>
#include <stdio.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

#include <sstream>
#include <stdexcept>
#include <utility>

#include "cbbg/config/program_name.h"
#include "cbbg/store/fault_point.h"
#include "cbbg/store/files.h"
#include "cbbg/store/output_guard.h"
#include "cbbg/store/sweep_directory.h"
#include "cbbg/store/task_store.h"

namespace cbbg::store {
namespace fs = std::filesystem;
namespace {

bool has(const fs::path& directory, const char* marker) {
  std::error_code error;
  return fs::is_directory(directory, error) && fs::exists(directory / marker, error);
}

std::string work_marker(const std::string& config_hash, const RunShape& shape) {
  return std::string("cbbg-run 1\nconfig ") + config_hash + "\nfigures " +
         (shape.figures ? "1" : "0") + "\nreplays " + (shape.replays ? "1" : "0") + "\nreplace " +
         (shape.replace ? "1" : "0") + "\n";
}

// What a finished results directory holds that cbbg wrote: these files, and in weights/ and
// figures/ files of these endings. Anything else there is the user's.
constexpr const char* kResultFiles[] = {kResultsMarker, "config.yaml", "schema.json",
                                        "summary.json", "trials.csv",  "evaluation.csv",
                                        "figures.csv",  "steps.csv"};
constexpr std::pair<const char*, const char*> kResultFolders[] = {{"weights", ".txt"},
                                                                  {"figures", ".png"},
                                                                  {"figures", ".svg"},
                                                                  {"figures", ".dot"},
                                                                  {"figures", ".html"}};

// Whether `inner`, in the results folder `folder`, is a file cbbg writes there: one of the
// folder's endings, its manifest, or a killed write's leftover.
bool is_own_file(const std::string& folder, const fs::directory_entry& inner) {
  if (is_temporary(inner.path()) || inner.path().filename() == kManifestFile) return true;
  for (const auto& [own_folder, ending] : kResultFolders) {
    if (folder == own_folder && inner.is_regular_file() && inner.path().extension() == ending) {
      return true;
    }
  }
  return false;
}

bool is_own_entry(const fs::path& directory, const fs::directory_entry& entry) {
  if (is_temporary(entry.path())) return true;  // a killed write's leftover, cbbg's own
  const std::string name = entry.path().filename().string();
  for (const char* file : kResultFiles) {
    if (name == file && entry.is_regular_file()) return true;
  }
  if (!entry.is_directory()) return false;
  std::error_code error;
  for (const auto& inner : fs::directory_iterator(directory / name, error)) {
    if (!is_own_file(name, inner)) return false;
  }
  return name == "weights" || name == "figures";
}

// The first entry of a results directory that cbbg did not write, or "".
std::string foreign_entry(const fs::path& directory) {
  std::error_code error;
  for (const auto& entry : fs::directory_iterator(directory, error)) {
    if (!is_own_entry(directory, entry)) return entry.path().filename().string();
  }
  return "";
}

// Refuses a target that cbbg may not write: anything but nothing or finished results.
void check_target(const fs::path& target, bool replace) {
  std::error_code error;
  const auto status = fs::status(target, error);
  if (!fs::exists(status)) return;
  if (!fs::is_directory(status)) {
    throw config::ConfigError("--out " + quoted_path(target) + " is a file; give a directory path");
  }
  if (has(target, kWorkMarker)) {
    throw config::ConfigError("--out " + quoted_path(target) +
                              " holds a run whose commit was interrupted; finish it with "
                              "--resume " +
                              target.string());
  }
  if (!has(target, kResultsMarker)) {
    throw config::ConfigError("--out " + quoted_path(target) + " exists and was not made by " +
                              config::program_name() + " run; " + config::program_name() +
                              " never replaces what it did not make: give a new path");
  }
  if (!replace) {
    throw config::ConfigError("--out " + quoted_path(target) +
                              " holds the results of an earlier run; add --replace to replace "
                              "them (they are kept until the new results are complete)");
  }
  if (const std::string foreign = foreign_entry(target); !foreign.empty()) {
    throw config::ConfigError("--out " + quoted_path(target) + " holds '" + foreign +
                              "', which cbbg did not write; move it away before --replace");
  }
}

// The one piece of advice for a work directory that is in the way of a new run.
void check_work_free(const fs::path& work, const fs::path& target) {
  std::error_code error;
  if (!fs::exists(fs::symlink_status(work, error))) return;
  if (has(work, kSweepWorkMarker)) {
    throw config::ConfigError(quoted_path(work) + " holds a sweep's unfinished tasks: continue " +
                              "it with the same " + config::program_name() +
                              " run --grid command, or see " + config::program_name() + " status " +
                              target.string());
  }
  if (!has(work, kWorkMarker)) {
    throw config::ConfigError(
        quoted_path(work) + " is in the way and was not made by cbbg; move it " +
        "away (cbbg works there while it runs into " + quoted_path(target) + ")");
  }
  if (DirectoryLock::held(work / kLockFile)) {
    throw config::ConfigError(quoted_path(work) + " is in use by another " +
                              config::program_name() + " run; wait for it to end");
  }
  throw config::ConfigError(
      quoted_path(work) + " holds an interrupted run: continue it with --resume " +
      target.string() + ", or remove " + quoted_path(work) + " to start anew");
}

// The config a run in `work` began with: run-config.yaml, or config.yaml for a run begun by
// an earlier release.
fs::path run_config_file(const fs::path& work) {
  std::error_code error;
  if (!fs::exists(work / kRunConfigFile, error) && fs::exists(work / "config.yaml", error)) {
    return work / "config.yaml";
  }
  return work / kRunConfigFile;
}

void create_parent(const fs::path& path) {
  const fs::path parent = path.parent_path();
  std::error_code error;
  if (!parent.empty() && !fs::is_directory(parent, error) &&
      !fs::create_directories(parent, error) && error) {
    throw std::runtime_error("cannot create " + quoted_path(parent) + ": " + error.message());
  }
}

// Swaps two directories in one atomic step (Linux renameat2, RENAME_EXCHANGE).
void exchange(const fs::path& a, const fs::path& b) {
  if (::renameat2(AT_FDCWD, a.c_str(), AT_FDCWD, b.c_str(), RENAME_EXCHANGE) != 0) {
    throw std::runtime_error("cannot swap " + quoted_path(a) + " and " + quoted_path(b) + ": " +
                             std::strerror(errno));
  }
}

void rename_or_throw(const fs::path& from, const fs::path& to) {
  std::error_code error;
  fs::rename(from, to, error);
  if (error) {
    throw std::runtime_error("cannot move " + quoted_path(from) + " to " + quoted_path(to) + ": " +
                             error.message());
  }
}

}  // namespace

RunDirectory::RunDirectory(fs::path target) : target_(std::move(target)) {
  if (target_.filename().empty()) target_ = target_.parent_path();
  work_ = target_;
  work_ += ".partial";
}

RunDirectory RunDirectory::create(const fs::path& target, const config::Config& config,
                                  const RunShape& shape) {
  if (target.empty()) throw config::ConfigError("--out needs a directory path");
  check_target(target, shape.replace);
  RunDirectory directory(target);
  check_work_free(directory.work_, directory.target_);
  create_parent(directory.work_);
  remove_stale_staging(directory.work_);
  // Built under a private name and renamed into place, so TARGET.partial never exists
  // without its marker.
  const fs::path staging = temporary_beside(directory.work_);
  std::error_code error;
  fs::create_directories(staging / "tasks", error);
  if (error) {
    throw std::runtime_error("cannot create " + quoted_path(directory.work_) + ": " +
                             error.message());
  }
  directory.lock_.emplace(staging / kLockFile, directory.work_.string());
  const std::string yaml = config.to_yaml();
  write_atomically(staging / kRunConfigFile, yaml);
  write_atomically(staging / kWorkMarker, work_marker(text_hash(yaml), shape));
  fs::rename(staging, directory.work_, error);
  if (error) {
    fs::remove_all(staging);
    check_work_free(directory.work_, directory.target_);  // another run got there first
    throw std::runtime_error("cannot create " + quoted_path(directory.work_) + ": " +
                             error.message());
  }
  directory.config_ = config;
  directory.shape_ = shape;
  return directory;
}

std::optional<RunState> RunDirectory::inspect(const fs::path& target) {
  const RunDirectory directory(target);
  RunState state{RunState::Phase::kFinished, {}, {}};
  if (has(directory.work_, kWorkMarker)) {
    state.phase = DirectoryLock::held(directory.work_ / kLockFile) ? RunState::Phase::kRunning
                                                                   : RunState::Phase::kInterrupted;
    state.config.merge_file(run_config_file(directory.work_));
    state.tasks = directory.tasks();
    return state;
  }
  if (has(directory.target_, kWorkMarker)) {
    state.phase = RunState::Phase::kPublished;
  } else if (!has(directory.target_, kResultsMarker) || has(directory.target_, "sweep.csv")) {
    return std::nullopt;
  }
  state.config.merge_file(directory.target_ / "config.yaml");
  return state;
}

RunDirectory RunDirectory::resume(const fs::path& target) {
  if (target.empty()) {
    throw config::ConfigError("--resume needs the results directory of the interrupted run");
  }
  RunDirectory directory(target);
  if (has(directory.target_, kWorkMarker)) {
    // Published (commit step 3), not yet cleaned up: only step 4 remains.
    directory.lock_.emplace(directory.target_ / kLockFile, directory.target_.string());
    remove_temporaries(directory.target_);
    directory.published_ = true;
    directory.config_.merge_file(directory.target_ / "config.yaml");
    return directory;
  }
  const fs::path& work = directory.work_;
  std::error_code error;
  if (fs::exists(fs::symlink_status(work, error))) {
    if (!has(work, kWorkMarker)) {
      throw config::ConfigError(quoted_path(work) +
                                " is in the way and was not made by cbbg; move it away");
    }
    directory.lock_.emplace(work / kLockFile, work.string());
    remove_temporaries(work);  // the killed run's half-written files: redone from its tasks
    remove_stale_staging(work);
    check_own_tasks(work / "tasks");
    directory.read_marker();
    check_target(directory.target_, directory.shape_.replace);
    return directory;
  }
  if (has(directory.target_, kResultsMarker)) {
    throw config::ConfigError("nothing to resume: " + quoted_path(directory.target_) +
                              " holds finished results");
  }
  throw config::ConfigError("nothing to resume: neither " + quoted_path(work) + " nor " +
                            quoted_path(directory.target_) + " holds an interrupted run");
}

void RunDirectory::read_marker() {
  std::istringstream marker(read_text(work_ / kWorkMarker));
  std::string word;
  std::string hash;
  int version = 0;
  int figures = 1;
  int replays = 1;
  int replace = 0;
  marker >> word >> version;
  for (std::string key; marker >> key;) {
    if (key == "config") marker >> hash;
    if (key == "figures") marker >> figures;
    if (key == "replays") marker >> replays;
    if (key == "replace") marker >> replace;
  }
  if (word != "cbbg-run" || version != 1 || hash.empty()) {
    throw config::ConfigError(quoted_path(work_ / kWorkMarker) + " is not a cbbg run marker");
  }
  std::error_code error;
  const fs::path config_file = run_config_file(work_);
  if (!fs::is_regular_file(config_file, error) || text_hash(read_text(config_file)) != hash) {
    throw config::ConfigError(quoted_path(config_file) +
                              " is not the config the run began with (it was edited or "
                              "removed); put it back, or remove " +
                              quoted_path(work_) + " and start anew");
  }
  config_.merge_file(config_file);
  shape_.figures = figures != 0;
  shape_.replays = replays != 0;
  shape_.replace = replace != 0;
}

void RunDirectory::remove_replaced() const {
  // After an exchange the work path holds the replaced results: cbbg's own, by their marker.
  if (!has(work_, kResultsMarker) || has(work_, kWorkMarker)) return;
  // Something of the user's arrived there since the run began: leave it all to them.
  if (!foreign_entry(work_).empty()) return;
  std::error_code error;
  fs::remove_all(work_, error);
  if (error) {
    throw std::runtime_error("cannot remove the replaced results " + quoted_path(work_) + ": " +
                             error.message());
  }
}

bool RunDirectory::record_failure(const std::string& message) const {
  const fs::path file = work_ / kFailureFile;
  std::error_code error;
  const bool repeated = fs::is_regular_file(file, error) && read_text(file) == message + "\n";
  try {
    write_atomically(file, message + "\n");
  } catch (const std::exception&) {  // the message is advice; the run's data is what matters
  }
  return repeated;
}

void RunDirectory::commit() {
  if (!published_) {
    remove_tree(work_ / kFailureFile);
    refuse_temporaries(work_);
    fault_point("commit:marker");
    write_atomically(work_ / kResultsMarker, "cbbg-results 1\n");
    fault_point("commit:publish");
    if (has(target_, kResultsMarker)) {
      exchange(work_, target_);  // TARGET always holds complete results; the old ones move here
    } else {
      rename_or_throw(work_, target_);
    }
    published_ = true;
  }
  fault_point("commit:clean");
  remove_replaced();
  remove_own_tasks(target_ / "tasks");
  remove_tree(target_ / "initial_weights.txt");
  remove_tree(target_ / kRunConfigFile);
  fault_point("commit:unmark");
  std::error_code error;
  fs::remove(target_ / kLockFile, error);
  if (!fs::remove(target_ / kWorkMarker, error) && error) {
    throw std::runtime_error("cannot remove " + quoted_path(target_ / kWorkMarker) + ": " +
                             error.message());
  }
}

}  // namespace cbbg::store
