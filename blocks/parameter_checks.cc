#include "cbbg/blocks/parameter_checks.h"

#include <stdexcept>
#include <string>

namespace cbbg::blocks {

void throw_invalid_parameter(std::string_view key, std::string_view requirement, double value) {
  throw std::invalid_argument(std::string(key) + " " + std::string(requirement) + "; got " +
                              format_number(value));
}

void check_positive(std::string_view key, double value) { check_bounds(key, value, kPositive); }

void check_period(double period) { check_positive("trial.period", period); }

}  // namespace cbbg::blocks
