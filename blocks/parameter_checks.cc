#include "blocks/parameter_checks.h"

#include <cmath>
#include <sstream>
#include <stdexcept>

namespace cbbg::blocks {

void throw_invalid_parameter(std::string_view key, std::string_view requirement, double value) {
  throw std::invalid_argument(std::string(key) + " " + std::string(requirement) + "; got " +
                              format_number(value));
}

void check_finite(std::string_view key, double value) {
  if (!std::isfinite(value)) throw_invalid_parameter(key, "must be finite", value);
}

void check_positive(std::string_view key, double value) {
  if (!std::isfinite(value) || value <= 0.0) {
    throw_invalid_parameter(key, "must be finite and > 0", value);
  }
}

void check_non_negative(std::string_view key, double value) {
  if (!std::isfinite(value) || value < 0.0) {
    throw_invalid_parameter(key, "must be finite and >= 0", value);
  }
}

bool Interval::contains(double value) const {
  const bool above = lower_closed ? value >= lower : value > lower;
  const bool below = upper_closed ? value <= upper : value < upper;
  return above && below;
}

std::string Interval::text() const {
  std::string text(lower_closed ? "[" : "(");
  text += format_number(lower);
  text += ", ";
  text += format_number(upper);
  text += upper_closed ? "]" : ")";
  return text;
}

void check_in(std::string_view key, double value, const Interval& interval) {
  // NaN fails both comparisons, so it is rejected here too.
  if (!std::isfinite(value) || !interval.contains(value)) {
    throw_invalid_parameter(key, "must be in " + interval.text(), value);
  }
}

void check_period(double period) { check_positive("trial.period", period); }

}  // namespace cbbg::blocks
