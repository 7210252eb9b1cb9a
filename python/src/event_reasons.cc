#include "event_reasons.h"

#include <mutex>
#include <set>

namespace cbbg::python {

const char* lasting_reason(const std::string& reason) {
  // A set's nodes never move, and a program has few distinct reasons.
  static std::mutex mutex;
  static std::set<std::string> reasons;
  const std::lock_guard<std::mutex> lock(mutex);
  return reasons.insert(reason).first->c_str();
}

}  // namespace cbbg::python
