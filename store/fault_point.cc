#include "cbbg/store/fault_point.h"

#include <unistd.h>

#include <atomic>
#include <cstdlib>
#include <string>
#include <string_view>

namespace cbbg::store {

void fault_point(const char* step) {
  static const char* chosen = std::getenv("CBBG_FAULT_AT");
  if (chosen == nullptr) return;
  const std::string_view spec(chosen);
  const auto at = spec.find('@');
  if (spec.substr(0, at) != step) return;
  const long wanted = at == std::string_view::npos ? 1 : std::atol(chosen + at + 1);
  static std::atomic<long> reached{0};
  if (++reached == wanted) ::_exit(kFaultExitCode);
}

}  // namespace cbbg::store
