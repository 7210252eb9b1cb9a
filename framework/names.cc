#include "cbbg/framework/names.h"

#include <stdexcept>

namespace cbbg {

void check_name(const std::string& owner, const std::string& name, const char* what) {
  bool valid = !name.empty();
  for (const char c : name) {
    const bool allowed =
        (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_';
    valid = valid && allowed;
  }
  if (!valid) {
    throw std::invalid_argument(owner + ": invalid " + what + " '" + name +
                                "': use letters, digits and '_' only");
  }
}

}  // namespace cbbg
