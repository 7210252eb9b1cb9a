#pragma once
// The rule for block, port and parameter names: they appear in paths ("a/b.c"), DOT and CSV.

#include <string>

namespace cbbg {

// Throws std::invalid_argument "<owner>: invalid <what> '<name>': ..." unless `name` is
// non-empty and made of letters, digits and '_' only.
void check_name(const std::string& owner, const std::string& name, const char* what);

}  // namespace cbbg
