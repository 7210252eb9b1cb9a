#pragma once
// The one output discipline every command and library entry that writes follows, so a
// user's data is never lost:
//   - a path is written only when it is absent or holds what cbbg wrote there before: a file
//     carrying cbbg's generator tag, or one listed in its directory's manifest (.cbbg-written);
//     anything else is the user's, refused before any work (config::ConfigError naming it);
//   - a target that is not a regular file (FIFO, device, socket, directory) is refused and
//     never opened;
//   - the temporaries of cbbg's atomic writes carry ".cbbg-tmp-" in their names, so a resume
//     or a merge can remove its own leftovers, and a commit can refuse to publish one.

#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "cbbg/framework/owned_files.h"

namespace cbbg::store {

using cbbg::carries_tag;  // framework/owned_files.h: what is at a path, and whether it is cbbg's
using cbbg::non_regular_kind;

// What every temporary name of cbbg holds: .NAME.cbbg-tmp-HOST-PID.START-N files and staging
// folders (START: the process's start, which tells it from a later process with its pid).
inline constexpr const char* kTemporaryTag = ".cbbg-tmp-";
// The manifest of a directory that cbbg shares with its user (figures/, cbbg eval --out).
inline constexpr const char* kManifestFile = ".cbbg-written";

// A temporary name for `path`, beside it and hidden: .NAME.cbbg-tmp-HOST-PID.START-N, unique per
// host, process and call (safe from several threads and from shards on several hosts).
std::filesystem::path temporary_beside(const std::filesystem::path& path);

// Whether `name` is one of cbbg's temporaries (also the NAME.tmp-PID-N of earlier versions).
bool is_temporary(const std::filesystem::path& name);
// Whether `name` is a temporary whose writer is gone: made on this host by a process that no
// longer runs, is a zombie, or whose pid another process has taken since (the name holds
// the writer's pid and start time); another host's are never judged stale.
bool is_stale_temporary(const std::filesystem::path& name);

enum class Leftovers { kAll, kStale };
// Removes cbbg's temporaries below `directory` (every one, or only the stale ones when others
// may be writing there), nothing else; returns how many.
int remove_temporaries(const std::filesystem::path& directory, Leftovers which = Leftovers::kAll);
// The same for the staging folders beside `path` (.NAME.cbbg-tmp-...), always only stale ones.
void remove_stale_staging(const std::filesystem::path& path);
// The first temporary of cbbg below `directory`, if any.
std::optional<std::filesystem::path> find_temporary(const std::filesystem::path& directory);

// A commit's last check: throws std::runtime_error naming the temporary when `directory`
// holds one, so a half-written file never reaches finished results.
void refuse_temporaries(const std::filesystem::path& directory);

// Before any work: `path` (named by `flag` in messages) may be written as a file. It must be
// absent, or a regular file that carries `tag` (cbbg's own, replaced). Throws
// config::ConfigError naming flag and path otherwise.
void check_replaceable_file(const std::filesystem::path& path, const std::string& flag,
                            std::string_view tag);

// The names cbbg wrote into one directory it shares with its user.
class Manifest {
 public:
  explicit Manifest(std::filesystem::path directory);

  bool lists(const std::string& name) const;
  const std::vector<std::string>& names() const { return names_; }
  // Before any work: each of `names` may be written in the directory (absent, or listed).
  // Throws config::ConfigError naming `flag` and the first path that is the user's.
  void check_writable(const std::vector<std::string>& names, const std::string& flag) const;
  // Records `names` as cbbg's (written atomically, before the files themselves, so a kill
  // never leaves a file of cbbg's unlisted).
  void add(const std::vector<std::string>& names);

 private:
  void save() const;

  std::filesystem::path directory_;
  std::vector<std::string> names_;
};

}  // namespace cbbg::store
