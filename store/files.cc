#include "cbbg/store/files.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "cbbg/store/output_guard.h"

namespace cbbg::store {

void write_atomically(const std::filesystem::path& path, const std::string& text) {
  write_atomically(path, [&text](std::ostream& out) { out << text; });
}

void write_atomically(const std::filesystem::path& path,
                      const std::function<void(std::ostream& out)>& write) {
  // Tagged as cbbg's temporary (store/output_guard.h), so a resume or a merge removes it.
  const std::filesystem::path temporary = temporary_beside(path);
  {
    std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
    write(out);
    out.flush();
    if (!out) {
      const std::string reason = std::strerror(errno);
      std::error_code ignored;
      std::filesystem::remove(temporary, ignored);
      throw std::runtime_error("cannot write '" + path.string() + "': " + reason);
    }
  }
  std::error_code error;
  std::filesystem::rename(temporary, path, error);
  if (error) {
    std::filesystem::remove(temporary, error);
    throw std::runtime_error("cannot write '" + path.string() + "': " + error.message());
  }
}

void remove_tree(const std::filesystem::path& path) {
  std::error_code error;
  std::filesystem::remove_all(path, error);
  // Another cbbg clearing the same stale leftover (two shards starting at once) may have
  // removed part of it first: gone is what was wanted.
  std::error_code unknown;
  if (error == std::errc::no_such_file_or_directory && !std::filesystem::exists(path, unknown)) {
    return;
  }
  if (error) {
    throw std::runtime_error("cannot remove " + quoted_path(path) + ": " + error.message());
  }
}

std::string quoted_path(const std::filesystem::path& path) {
  // Built by appends: GCC 12 warns falsely (-Wrestrict) on "'" + text + "'".
  std::string text = "'";
  text += path.string();
  text += '\'';
  return text;
}

std::string read_text(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error("cannot read '" + path.string() + "'");
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

std::string text_hash(const std::string& text) {
  std::uint64_t hash = 0xcbf29ce484222325ULL;
  for (const char c : text) {
    hash ^= static_cast<unsigned char>(c);
    hash *= 0x100000001b3ULL;
  }
  char hex[17];
  std::snprintf(hex, sizeof hex, "%016llx", static_cast<unsigned long long>(hash));
  return hex;
}

}  // namespace cbbg::store
