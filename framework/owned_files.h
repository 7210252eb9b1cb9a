#pragma once
// What is at a path cbbg is about to write, and whether cbbg wrote it: every writer asks
// before it replaces anything (a user's file never is; a FIFO or a device is never opened).

#include <filesystem>
#include <string>
#include <string_view>

namespace cbbg {

// The kind of what is at `path` in words ("a FIFO", "a directory"), or "" for a regular file
// or nothing.
std::string non_regular_kind(const std::filesystem::path& path);

// Whether the first 64 KiB of the regular file at `path` hold `tag` (a generator tag cbbg
// writes into every file of that kind). False for anything else, which is never opened.
bool carries_tag(const std::filesystem::path& path, std::string_view tag);

}  // namespace cbbg
