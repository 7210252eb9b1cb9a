#include "cbbg/store/json_text.h"

#include <cmath>
#include <stdexcept>

#include "cbbg/framework/number_text.h"

namespace cbbg::store {
namespace {

// Levels whose objects are laid out one key per line (when they hold containers).
constexpr int kOpenLevels = 3;

void write(std::string& out, const Json& value, int level);

void write_scalar(std::string& out, const Json& value) {
  if (value.is_number_float()) {
    const double number = value.get<double>();
    if (std::isfinite(number)) {
      append_number(out, number);
    } else {
      out += "null";
    }
    return;
  }
  out += value.dump(-1, ' ', false, Json::error_handler_t::replace);
}

bool holds_containers(const Json& value) {
  for (const auto& item : value) {
    if (item.is_structured()) return true;
  }
  return false;
}

void write_inline(std::string& out, const Json& value) {
  if (!value.is_structured()) return write_scalar(out, value);
  const bool object = value.is_object();
  out += object ? '{' : '[';
  bool first = true;
  for (const auto& [key, item] : value.items()) {
    if (!first) out += ", ";
    first = false;
    if (object) {
      write_scalar(out, Json(key));
      out += ": ";
    }
    write_inline(out, item);
  }
  out += object ? '}' : ']';
}

void write_open(std::string& out, const Json& value, int level) {
  const bool object = value.is_object();
  const std::string indent(2 * (level + 1), ' ');
  out += object ? "{\n" : "[\n";
  bool first = true;
  for (const auto& [key, item] : value.items()) {
    if (!first) out += ",\n";
    first = false;
    out += indent;
    if (object) {
      write_scalar(out, Json(key));
      out += ": ";
    }
    if (object) {
      write(out, item, level + 1);
    } else {
      write_inline(out, item);  // an array's objects, one per line
    }
  }
  out += '\n' + std::string(2 * level, ' ') + (object ? '}' : ']');
}

void write(std::string& out, const Json& value, int level) {
  const bool open = value.is_structured() && !value.empty() && holds_containers(value) &&
                    (value.is_array() ? value.front().is_object() : level < kOpenLevels);
  if (open) {
    write_open(out, value, level);
  } else {
    write_inline(out, value);
  }
}

}  // namespace

std::string json_text(const Json& document) {
  std::string out;
  write(out, document, 0);
  out += '\n';
  return out;
}

Json parse_json(const std::string& text, const std::string& source) {
  try {
    return Json::parse(text);
  } catch (const Json::parse_error& error) {
    throw std::runtime_error(source + ": not JSON (byte " + std::to_string(error.byte) + ")");
  }
}

}  // namespace cbbg::store
