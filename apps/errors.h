#pragma once
// How every subcommand reports what went wrong: one line "cbbg: error: ..." on stderr (a
// user's program's own name for "cbbg"), exit 2
// for what the user typed (config::ConfigError), 1 for what the machine refused.

#include <exception>
#include <filesystem>
#include <string>

#include "cbbg/config/program_name.h"

namespace cbbg::app {

inline constexpr int kUserError = 2;
inline constexpr int kMachineError = 1;

// Prints the line and returns `exit_code`.
int report_error(int exit_code, const std::string& message);

// The name the lines start with: "cbbg", or a user's program's own (run_cli sets it).
using config::program_name;
using config::set_program_name;

// The exception's message in the project's words: a filesystem error names its path and the
// system's reason ("cannot use 'x': Read-only file system"), not the library's text.
std::string describe(const std::exception& error);

// Before any work: `path` can be written as a file. Throws config::ConfigError naming `flag`
// when it is a directory or its directory does not exist, std::runtime_error when the
// machine refuses writing there (read-only, permission).
void check_output_file(const std::filesystem::path& path, const std::string& flag);
// The same for a directory that will be created if missing (with its parents).
void check_output_directory(const std::filesystem::path& path, const std::string& flag);

}  // namespace cbbg::app
