#pragma once
// An EventStatus keeps its reason as a pointer to text that lives for the program (a literal,
// in C++); a reason given from Python is copied here once and lives as long.

#include <string>

namespace cbbg::python {

// `reason`'s text, at an address that stays valid until the program ends.
const char* lasting_reason(const std::string& reason);

}  // namespace cbbg::python
