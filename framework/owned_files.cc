#include "cbbg/framework/owned_files.h"

#include <fstream>

namespace cbbg {
namespace fs = std::filesystem;

std::string non_regular_kind(const fs::path& path) {
  std::error_code error;
  switch (fs::status(path, error).type()) {
    case fs::file_type::directory:
      return "a directory";
    case fs::file_type::fifo:
      return "a FIFO";
    case fs::file_type::socket:
      return "a socket";
    case fs::file_type::block:
    case fs::file_type::character:
      return "a device";
    case fs::file_type::regular:
    case fs::file_type::not_found:
    case fs::file_type::none:
      return "";
    default:
      return "not a regular file";
  }
}

bool carries_tag(const fs::path& path, std::string_view tag) {
  std::error_code error;
  if (!fs::is_regular_file(path, error)) return false;  // never open a FIFO or a device
  std::ifstream in(path, std::ios::binary);
  std::string head(64 * 1024, '\0');
  in.read(head.data(), static_cast<std::streamsize>(head.size()));
  head.resize(static_cast<std::size_t>(in.gcount()));
  return head.find(tag) != std::string::npos;
}

}  // namespace cbbg
