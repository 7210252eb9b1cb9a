#include "cbbg/config/own_sections.h"

#include <stdexcept>
#include <utility>
#include <vector>

#include "cbbg/config/declared_keys.h"

namespace cbbg::config {

const Value& OwnSections::value(std::string_view key) const {
  const auto found = values.find(key);
  if (found == values.end()) {
    throw std::logic_error("no registered section declares the key '" + std::string(key) +
                           "'; register_section before making the config");
  }
  return found->second;
}

namespace {

std::vector<std::pair<std::string, SectionCheck>>& section_checks() {
  static std::vector<std::pair<std::string, SectionCheck>> checks;
  return checks;
}

}  // namespace

void register_section_check(const std::string& name, SectionCheck check) {
  if (!check) throw std::invalid_argument("section '" + name + "': the check is empty");
  section_checks().emplace_back(name, std::move(check));
}

void unregister_section_check(const std::string& name) {
  std::erase_if(section_checks(), [&name](const auto& entry) { return entry.first == name; });
}

void check_own_sections(const OwnSections& own) {
  for (const auto& [name, check] : section_checks()) {
    try {
      check(own);
    } catch (const std::invalid_argument& error) {
      throw ConfigError(error.what());
    }
  }
}

}  // namespace cbbg::config
