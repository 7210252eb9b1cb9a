#pragma once
// An OS file lock (flock) on a lock file: held while its owner lives, released by the kernel
// when the process ends however it ends, so a stale lock of a dead run never blocks. A lock
// guards whatever its file stands for: a whole work directory (".cbbg-lock" in it), or one
// part of it that a shard of a sweep writes alone.

#include <filesystem>
#include <string>

namespace cbbg::store {

class DirectoryLock {
 public:
  // Takes the lock of `file` (created if missing) for `what` (a path named in messages).
  // Throws config::ConfigError "'what' is in use by another cbbg run (pid N)" when a live
  // process holds it, std::runtime_error when the file cannot be made.
  DirectoryLock(const std::filesystem::path& file, const std::string& what);
  ~DirectoryLock();
  DirectoryLock(DirectoryLock&& other) noexcept;
  DirectoryLock& operator=(DirectoryLock&& other) noexcept;
  DirectoryLock(const DirectoryLock&) = delete;
  DirectoryLock& operator=(const DirectoryLock&) = delete;

  // Whether a live process holds the lock of `file` (false when there is no such file).
  static bool held(const std::filesystem::path& file);

 private:
  int fd_ = -1;
};

}  // namespace cbbg::store
