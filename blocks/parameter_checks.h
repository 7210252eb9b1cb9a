#pragma once
// Checks of block parameters against their allowed ranges. Each failure throws
// std::invalid_argument naming the config key (docs/model.md §4), the allowed range and the
// value given, e.g. "critic.gamma must be in (0, 1]; got 1.5".

#include <string>
#include <string_view>

#include "framework/number_text.h"

namespace cbbg::blocks {

// Throws "<key> <requirement>; got <value>".
[[noreturn]] void throw_invalid_parameter(std::string_view key, std::string_view requirement,
                                          double value);

// Throws unless `value` is finite.
void check_finite(std::string_view key, double value);
// Throws unless `value` is finite and > 0.
void check_positive(std::string_view key, double value);
// Throws unless `value` is finite and >= 0.
void check_non_negative(std::string_view key, double value);

// An interval of the real line, open or closed at each end, as messages print it.
struct Interval {
  double lower;
  bool lower_closed;
  double upper;
  bool upper_closed;

  bool contains(double value) const;
  // "(0, 1]", "[0, 1)".
  std::string text() const;
};

// Throws unless `value` is finite and inside `interval`.
void check_in(std::string_view key, double value, const Interval& interval);

// The period of a block's periodic update (config key trial.period): finite and > 0.
void check_period(double period);

}  // namespace cbbg::blocks
