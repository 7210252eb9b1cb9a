#pragma once
// Checks of block parameters beyond their declarations (framework/parameters.h, whose
// check_declared checks those). Each failure throws std::invalid_argument naming the config
// key, the requirement and the value given, e.g. "trial.period must be finite and > 0; got 0".

#include <string>
#include <string_view>

#include "cbbg/framework/parameters.h"

namespace cbbg::blocks {

// Throws "<key> <requirement>; got <value>".
[[noreturn]] void throw_invalid_parameter(std::string_view key, std::string_view requirement,
                                          double value);

// Throws unless `value` is finite and > 0 (the check of a parameter that is not a config key
// of its own block: trial.period, trial.failure_angle, sampler.k_b for the entropy).
void check_positive(std::string_view key, double value);

// The period of a block's periodic update (config key trial.period): finite and > 0.
void check_period(double period);

}  // namespace cbbg::blocks
