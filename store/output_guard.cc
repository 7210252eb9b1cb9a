#include "cbbg/store/output_guard.h"

#include <signal.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <fstream>
#include <optional>
#include <sstream>

#include "cbbg/config/config.h"
#include "cbbg/config/program_name.h"
#include "cbbg/store/files.h"

namespace cbbg::store {
namespace fs = std::filesystem;
namespace {

constexpr const char* kManifestHeader = "cbbg-written 1";

bool all_digits(std::string_view text) {
  return !text.empty() &&
         std::all_of(text.begin(), text.end(), [](char c) { return c >= '0' && c <= '9'; });
}

// NAME.tmp-PID-N: the temporaries of cbbg before they carried kTemporaryTag.
bool is_legacy_temporary(const std::string& name) {
  const auto at = name.rfind(".tmp-");
  if (at == std::string::npos || at == 0) return false;
  const std::string_view rest = std::string_view(name).substr(at + 5);
  const auto dash = rest.find('-');
  return dash != std::string_view::npos && all_digits(rest.substr(0, dash)) &&
         all_digits(rest.substr(dash + 1));
}

const std::string& host_name() {
  static const std::string name = [] {
    char buffer[256] = {};
    if (::gethostname(buffer, sizeof buffer - 1) != 0) return std::string("host");
    return std::string(buffer);
  }();
  return name;
}

bool process_runs(long long pid) {
  return pid > 0 && (::kill(static_cast<pid_t>(pid), 0) == 0 || errno == EPERM);
}

// What /proc/PID/stat says of process `pid`: its state (field 3) and its start time in clock
// ticks after boot (field 22), which no later process with the same pid shares.
struct ProcessStat {
  char state = '?';
  long long start = -1;
};
std::optional<ProcessStat> process_stat(long long pid) {
  std::ifstream stat("/proc/" + std::to_string(pid) + "/stat");
  std::string text;
  if (!std::getline(stat, text)) return std::nullopt;
  const auto name_end = text.rfind(')');  // the command's name may hold spaces and ')'
  if (name_end == std::string::npos) return std::nullopt;
  std::istringstream fields(text.substr(name_end + 1));
  ProcessStat process;
  fields >> process.state;
  std::string skipped;
  for (int field = 4; field < 22; ++field) fields >> skipped;
  if (!(fields >> process.start)) return std::nullopt;
  return process;
}

// This process's identity in its temporaries' names: "PID.START".
const std::string& own_identity() {
  static const std::string identity = [] {
    const long long pid = ::getpid();
    const auto stat = process_stat(pid);
    return std::to_string(pid) + "." + std::to_string(stat ? stat->start : 0);
  }();
  return identity;
}

// Whether the writer named "PID.START" (or "PID", before names carried the start) is gone:
// no such process, a zombie, or another process that has its pid since (another start).
bool writer_gone(const std::string& identity) {
  const auto dot = identity.find('.');
  const std::string pid = identity.substr(0, dot);
  if (!all_digits(pid)) return false;
  const auto stat = process_stat(std::stoll(pid));
  if (!stat) return !process_runs(std::stoll(pid));  // no /proc: the pid alone
  if (stat->state == 'Z' || stat->state == 'X') return true;
  if (dot == std::string::npos) return false;
  const std::string start = identity.substr(dot + 1);
  return !all_digits(start) || std::stoll(start) != stat->start;
}

}  // namespace

fs::path temporary_beside(const fs::path& path) {
  static std::atomic<long long> counter{0};
  // Built by appends: GCC 12 warns falsely (-Wrestrict) on "." + text + ....
  std::string name = ".";
  name += path.filename().string();
  name += kTemporaryTag;
  name += host_name();
  name += '-';
  name += own_identity();
  name += '-';
  name += std::to_string(counter++);
  return path.parent_path() / name;
}

bool is_temporary(const fs::path& name) {
  const std::string text = name.filename().string();
  return text.find(kTemporaryTag) != std::string::npos || is_legacy_temporary(text);
}

bool is_stale_temporary(const fs::path& name) {
  const std::string text = name.filename().string();
  const auto tag = text.find(kTemporaryTag);
  if (tag == std::string::npos) return is_legacy_temporary(text);
  // HOST-PID.START-N after the tag (HOST-PID-N before); the host may hold dashes, so it is
  // split from the right.
  const std::string rest = text.substr(tag + std::string_view(kTemporaryTag).size());
  const auto last = rest.rfind('-');
  if (last == std::string::npos || last == 0) return false;
  const auto before = rest.rfind('-', last - 1);
  if (before == std::string::npos) return false;
  return rest.substr(0, before) == host_name() &&
         writer_gone(rest.substr(before + 1, last - before - 1));
}

int remove_temporaries(const fs::path& directory, Leftovers which) {
  std::vector<fs::path> found;
  std::error_code error;
  for (fs::recursive_directory_iterator it(directory, error), end; !error && it != end;
       it.increment(error)) {
    const bool leftover =
        which == Leftovers::kAll ? is_temporary(it->path()) : is_stale_temporary(it->path());
    if (!leftover) continue;
    found.push_back(it->path());
    if (it->is_directory(error)) it.disable_recursion_pending();
  }
  for (const fs::path& path : found) remove_tree(path);
  return static_cast<int>(found.size());
}

void remove_stale_staging(const fs::path& path) {
  std::string prefix = ".";
  prefix += path.filename().string();
  prefix += kTemporaryTag;
  const fs::path parent = path.has_parent_path() ? path.parent_path() : fs::path(".");
  std::error_code error;
  for (const auto& entry : fs::directory_iterator(parent, error)) {
    const std::string name = entry.path().filename().string();
    if (name.rfind(prefix, 0) == 0 && is_stale_temporary(entry.path())) remove_tree(entry.path());
  }
}

std::optional<fs::path> find_temporary(const fs::path& directory) {
  std::error_code error;
  for (fs::recursive_directory_iterator it(directory, error), end; !error && it != end;
       it.increment(error)) {
    if (is_temporary(it->path())) return it->path();
  }
  return std::nullopt;
}

void refuse_temporaries(const fs::path& directory) {
  if (const auto temporary = find_temporary(directory)) {
    throw std::runtime_error("not publishing " + quoted_path(directory) + ": it holds " +
                             quoted_path(*temporary) +
                             ", a half-written file of cbbg's; run the command again");
  }
}

void check_replaceable_file(const fs::path& path, const std::string& flag, std::string_view tag) {
  if (const std::string kind = non_regular_kind(path); !kind.empty()) {
    throw config::ConfigError(flag + " " + quoted_path(path) + " is " + kind +
                              "; give a regular file's path");
  }
  std::error_code error;
  if (fs::exists(fs::symlink_status(path, error)) && !carries_tag(path, tag)) {
    throw config::ConfigError(flag + " " + quoted_path(path) + " exists and " +
                              config::program_name() + " did not write it; " +
                              config::program_name() +
                              " never replaces a file of yours: give a new path");
  }
}

Manifest::Manifest(fs::path directory) : directory_(std::move(directory)) {
  std::ifstream in(directory_ / kManifestFile);
  std::string line;
  if (!std::getline(in, line) || line != kManifestHeader) return;  // none: nothing is cbbg's
  while (std::getline(in, line)) {
    if (!line.empty()) names_.push_back(line);
  }
}

bool Manifest::lists(const std::string& name) const {
  return std::find(names_.begin(), names_.end(), name) != names_.end();
}

void Manifest::check_writable(const std::vector<std::string>& names,
                              const std::string& flag) const {
  for (const std::string& name : names) {
    const fs::path path = directory_ / name;
    if (const std::string kind = non_regular_kind(path); !kind.empty()) {
      throw config::ConfigError(flag + ": " + quoted_path(path) + " is " + kind +
                                "; move it away, " + config::program_name() +
                                " writes a file there");
    }
    std::error_code error;
    if (fs::exists(fs::symlink_status(path, error)) && !lists(name)) {
      throw config::ConfigError(flag + ": " + quoted_path(path) + " exists and " +
                                config::program_name() + " did not write it; " +
                                config::program_name() +
                                " never replaces a file of yours: move it away");
    }
  }
}

void Manifest::add(const std::vector<std::string>& names) {
  for (const std::string& name : names) {
    if (!lists(name)) names_.push_back(name);
  }
  save();
}

void Manifest::save() const {
  std::string text = std::string(kManifestHeader) + "\n";
  for (const std::string& name : names_) text += name + "\n";
  write_atomically(directory_ / kManifestFile, text);
}

}  // namespace cbbg::store
