#pragma once
// The values of the registered sections (a protocol's, a user's: config/declared_keys.h),
// carried in the typed parameter tree beside the tree's own sections, so a protocol or a
// user's factory below the edge reads its own struct from the tree:
//
//   const DlqrParams dlqr = cbbg::config::read_section<DlqrParams>(parameters.own, "dlqr");

#include <map>
#include <string>
#include <string_view>

#include "cbbg/config/config.h"

namespace cbbg::config {

class OwnSections {
 public:
  // Every registered key's value, by full key ("dlqr.q_theta").
  std::map<std::string, Value, std::less<>> values;

  // The value of `key`, what read_section's archive asks for. Throws std::logic_error for
  // a key no section registered.
  const Value& value(std::string_view key) const;

  bool operator==(const OwnSections&) const = default;
};

}  // namespace cbbg::config
