#pragma once
// The values of the sections users registered (config/declared_keys.h), carried in the typed
// parameter tree beside the built-in sections, so a user's factory below the edge reads its
// own struct from the tree as the library's factories read theirs:
//
//   const DlqrParams dlqr = cbbg::config::read_section<DlqrParams>(parameters.own, "dlqr");

#include <map>
#include <string>
#include <string_view>
#include <vector>

#include "cbbg/config/config.h"

namespace cbbg::config {

class OwnSections {
 public:
  // Every registered key's value, by full key ("dlqr.q_theta").
  std::map<std::string, Value, std::less<>> values;

  // What read_section's archive asks for: the value of `key`, of its declared kind.
  double number(std::string_view key) const { return std::get<double>(at(key)); }
  long long integer(std::string_view key) const { return std::get<long long>(at(key)); }
  const std::string& text(std::string_view key) const { return std::get<std::string>(at(key)); }
  const std::vector<double>& numbers(std::string_view key) const {
    return std::get<std::vector<double>>(at(key));
  }
  const std::vector<std::string>& names(std::string_view key) const {
    return std::get<std::vector<std::string>>(at(key));
  }
  const std::vector<AnnealingStep>& annealing(std::string_view key) const {
    return std::get<std::vector<AnnealingStep>>(at(key));
  }

  bool operator==(const OwnSections&) const = default;

 private:
  // Throws std::logic_error for a key no section registered.
  const Value& at(std::string_view key) const;
};

}  // namespace cbbg::config
