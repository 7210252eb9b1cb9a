#pragma once
// Checks of the primitives' constructor arguments. Each throws std::invalid_argument with a
// message that starts with the block's kind and name ("Saturation 'sat': ..."), names the
// argument and says what is allowed.

#include <cmath>
#include <stdexcept>
#include <string>

#include "cbbg/framework/number_text.h"
#include "cbbg/framework/types.h"

namespace cbbg::primitive_checks {

// "Saturation 'sat'": how every message names the block.
inline std::string label(const char* kind, const std::string& name) {
  return std::string(kind) + " '" + name + "'";
}

// Returns `size`, which must be at least 1 (in a member initializer, before a vector of that
// size is made).
inline int checked_size(const std::string& label, int size) {
  if (size < 1) {
    throw std::invalid_argument(label + ": size " + std::to_string(size) + " must be at least 1");
  }
  return size;
}

// A sample period: positive and finite; an offset: finite and >= 0.
inline void check_period(const std::string& label, double period, double offset) {
  if (!std::isfinite(period) || period <= 0.0) {
    throw std::invalid_argument(label + ": period " + format_number(period) +
                                " must be positive and finite");
  }
  if (!std::isfinite(offset) || offset < 0.0) {
    throw std::invalid_argument(label + ": offset " + format_number(offset) +
                                " must be finite and >= 0");
  }
}

// Every element of `value` (an initial value, say) finite.
inline void check_finite(const std::string& label, const char* what, const Vector& value) {
  for (Eigen::Index i = 0; i < value.size(); ++i) {
    if (!std::isfinite(value[i])) {
      throw std::invalid_argument(label + ": " + what + " " + format_number(value[i]) +
                                  (value.size() > 1 ? " at element " + std::to_string(i) : "") +
                                  " must be finite");
    }
  }
}

// Limits of a clamp or a dead zone, elementwise: at least one element, as many lower as
// upper, lower <= upper, neither NaN, lower below +inf and upper above -inf (an infinite
// limit on its own side means none). `per_element` names the element in messages.
inline void check_limits(const std::string& label, const Vector& lower, const Vector& upper,
                         bool per_element) {
  if (lower.size() != upper.size()) {
    throw std::invalid_argument(label + ": " + std::to_string(lower.size()) + " lower limits and " +
                                std::to_string(upper.size()) +
                                " upper limits; give as many of each");
  }
  if (lower.size() == 0) {
    throw std::invalid_argument(label + ": no limits; give at least one element");
  }
  for (Eigen::Index i = 0; i < lower.size(); ++i) {
    const std::string where = per_element ? " at element " + std::to_string(i) : "";
    if (std::isnan(lower[i]) || (std::isinf(lower[i]) && lower[i] > 0.0)) {
      throw std::invalid_argument(label + ": lower limit " + format_number(lower[i]) + where +
                                  " must be a number below inf (-inf for none)");
    }
    if (std::isnan(upper[i]) || (std::isinf(upper[i]) && upper[i] < 0.0)) {
      throw std::invalid_argument(label + ": upper limit " + format_number(upper[i]) + where +
                                  " must be a number above -inf (inf for none)");
    }
    if (lower[i] > upper[i]) {
      throw std::invalid_argument(label + ": lower limit " + format_number(lower[i]) +
                                  " is above upper limit " + format_number(upper[i]) + where);
    }
  }
}

}  // namespace cbbg::primitive_checks
