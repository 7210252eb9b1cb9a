#include "cbbg/config/own_sections.h"

#include <stdexcept>

namespace cbbg::config {

const Value& OwnSections::value(std::string_view key) const {
  const auto found = values.find(key);
  if (found == values.end()) {
    throw std::logic_error("no registered section declares the key '" + std::string(key) +
                           "'; register_section before making the config");
  }
  return found->second;
}

}  // namespace cbbg::config
