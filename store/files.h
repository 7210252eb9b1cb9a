#pragma once
// Small file operations every part of the store shares.

#include <cstdint>
#include <filesystem>
#include <functional>
#include <ostream>
#include <string>

namespace cbbg::store {

// Writes `text` to `path` through a temporary file beside it and a rename, so `path` is
// never half-written; safe from several threads. Throws std::runtime_error naming `path` with
// the system's reason.
void write_atomically(const std::filesystem::path& path, const std::string& text);
// The same for a file too large to hold as one text: `write` streams it into the temporary.
void write_atomically(const std::filesystem::path& path,
                      const std::function<void(std::ostream& out)>& write);

// Removes `path` and everything below it (nothing when absent); throws std::runtime_error
// "cannot remove 'path': reason" when the machine refuses.
void remove_tree(const std::filesystem::path& path);

// 'path', quoted as messages name paths.
std::string quoted_path(const std::filesystem::path& path);

// The whole file; throws std::runtime_error naming `path` when it cannot be read.
std::string read_text(const std::filesystem::path& path);

// A 64-bit FNV-1a hash of `text`, as 16 hex digits: what a work directory records of its
// config, so a resume notices an edited one.
std::string text_hash(const std::string& text);

}  // namespace cbbg::store
