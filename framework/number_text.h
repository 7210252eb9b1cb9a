#pragma once
// Numbers as text everywhere cbbg writes them (CSV, YAML, JSON, DOT, messages): the shortest
// text that reads back as the same double, so files round-trip bit for bit.

#include <string>

namespace cbbg {

std::string format_number(double value);
void append_number(std::string& out, double value);
// Writes into [begin, end) (32 characters always suffice) and returns the end. Never
// allocates: for per-tick logging.
char* write_number(char* begin, char* end, double value);

}  // namespace cbbg
