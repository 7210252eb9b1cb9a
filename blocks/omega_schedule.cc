#include "cbbg/blocks/omega_schedule.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "cbbg/blocks/parameter_checks.h"
#include "cbbg/framework/block_context.h"

namespace cbbg::blocks {

OmegaMode parse_omega_mode(std::string_view text) {
  if (text == "schedule") return OmegaMode::kSchedule;
  if (text == "zero") return OmegaMode::kZero;
  if (text == "one") return OmegaMode::kOne;
  if (text == "constant") return OmegaMode::kConstant;
  throw std::invalid_argument("omega.mode must be schedule, zero, one or constant; got '" +
                              std::string(text) + "'");
}

std::string_view to_string(OmegaMode mode) {
  switch (mode) {
    case OmegaMode::kZero:
      return "zero";
    case OmegaMode::kOne:
      return "one";
    case OmegaMode::kConstant:
      return "constant";
    case OmegaMode::kSchedule:
      break;
  }
  return "schedule";
}

void OmegaParams::validate() const {
  check_declared(*this, kSection);
  if (mode != OmegaMode::kSchedule && mode != OmegaMode::kZero && mode != OmegaMode::kOne &&
      mode != OmegaMode::kConstant) {
    throw std::invalid_argument(
        "omega.mode must be schedule, zero, one or constant; got the "
        "value " +
        std::to_string(static_cast<int>(mode)));
  }
  if (mode == OmegaMode::kConstant) {
    check_bounds("omega constant", constant, interval(0.0, 1.0));
  }
}

OmegaSchedule::OmegaSchedule(std::string name, const OmegaParams& params, double period)
    : Block(std::move(name)), params_(params) {
  params_.validate();
  check_period(period);
  declare_discrete_state("ticks", Vector::Zero(1), StateLifetime::kPersistent);
  declare_output_port<&OmegaSchedule::calc_omega>("omega", 1, {}, "omega(t)");
  declare_periodic_update<&OmegaSchedule::count_tick>(
      period, 0.0, UpdateWrites::kInPlace);  // reads the count, then writes it
}

void OmegaSchedule::calc_omega(const BlockContext& context, VectorRef omega) const {
  omega[0] = omega_at(context.discrete_state()[0]);
}

EventStatus OmegaSchedule::count_tick(BlockContext& context, VectorRef next) const {
  next[0] = context.discrete_state()[0] + 1.0;
  return EventStatus::succeeded();
}

double OmegaSchedule::omega_at(double ticks) const {
  switch (params_.mode) {
    case OmegaMode::kZero:
      return 0.0;
    case OmegaMode::kOne:
      return 1.0;
    case OmegaMode::kConstant:
      return params_.constant;
    case OmegaMode::kSchedule:
      break;
  }
  return std::max(0.0, 1.0 - std::exp(-(ticks - params_.n2) / params_.n3));
}

double OmegaSchedule::ticks(const Context& context) const {
  return context.discrete_state(*this)[0];
}

codegen::CCalculation OmegaSchedule::c_calculation(int, const Context&) const {
  switch (params_.mode) {
    case OmegaMode::kZero:
      return {{}, "  out[0] = 0;\n"};
    case OmegaMode::kOne:
      return {{}, "  out[0] = 1;\n"};
    case OmegaMode::kConstant:
      return {{codegen::c_number("omega", params_.constant)}, "  out[0] = $omega;\n"};
    case OmegaMode::kSchedule:
      break;
  }
  // std::max(0.0, rise): (0 < rise ? rise : 0).
  return {{codegen::c_number("n2", params_.n2), codegen::c_number("n3", params_.n3)},
          "  const real rise = (real)1 - CBBG_EXP(-(@ticks[0] - $n2) / $n3);\n"
          "  out[0] = (real)0 < rise ? rise : (real)0;\n"};
}

codegen::CCalculation OmegaSchedule::c_update(int, const Context&) const {
  return {{}, "  @@ticks[0] = @ticks[0] + (real)1;\n"};
}

}  // namespace cbbg::blocks
