#include "cbbg/apps/errors.h"

#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <iostream>
#include <stdexcept>

#include "cbbg/config/config.h"
#include "cbbg/store/files.h"

namespace cbbg::app {
namespace fs = std::filesystem;
using store::quoted_path;
namespace {

// The nearest existing directory at or above `path`.
fs::path existing_ancestor(fs::path path) {
  std::error_code error;
  if (path.empty()) path = ".";
  while (!fs::exists(path, error) && path.has_parent_path() && path != path.parent_path()) {
    path = path.parent_path();
  }
  return fs::exists(path, error) ? path : fs::path(".");
}

void check_writable(const fs::path& directory, const std::string& flag) {
  if (::access(directory.c_str(), W_OK) != 0) {
    throw std::runtime_error(flag + ": cannot write into " + quoted_path(directory) + ": " +
                             std::strerror(errno));
  }
}

}  // namespace

int report_error(int exit_code, const std::string& message) {
  std::cerr << program_name() << ": error: " << message << "\n";
  return exit_code;
}

std::string describe(const std::exception& error) {
  if (const auto* filesystem = dynamic_cast<const fs::filesystem_error*>(&error)) {
    return "cannot use " + quoted_path(filesystem->path1()) + ": " + filesystem->code().message();
  }
  if (dynamic_cast<const std::bad_alloc*>(&error) != nullptr) return "out of memory";
  return error.what();
}

void check_output_file(const fs::path& path, const std::string& flag) {
  std::error_code error;
  if (path.empty()) throw config::ConfigError(flag + " needs a file path");
  if (fs::is_directory(path, error)) {
    throw config::ConfigError(flag + " " + quoted_path(path) + " is a directory; give a file path");
  }
  const fs::path parent = path.has_parent_path() ? path.parent_path() : fs::path(".");
  if (!fs::is_directory(parent, error)) {
    throw config::ConfigError(flag + " " + quoted_path(path) + ": the directory " +
                              quoted_path(parent) + " does not exist");
  }
  check_writable(parent, flag);
}

void check_output_directory(const fs::path& path, const std::string& flag) {
  std::error_code error;
  if (path.empty()) throw config::ConfigError(flag + " needs a directory path");
  if (fs::exists(path, error) && !fs::is_directory(path, error)) {
    throw config::ConfigError(flag + " " + quoted_path(path) + " is a file, not a directory");
  }
  check_writable(existing_ancestor(path), flag);
}

}  // namespace cbbg::app
