#include "cbbg/framework/number_text.h"

#include <charconv>

namespace cbbg {

char* write_number(char* begin, char* end, double value) {
  return std::to_chars(begin, end, value).ptr;
}

void append_number(std::string& out, double value) {
  char buffer[32];
  out.append(buffer, write_number(buffer, buffer + sizeof buffer, value));
}

std::string format_number(double value) {
  std::string text;
  append_number(text, value);
  return text;
}

}  // namespace cbbg
