#include "cbbg/framework/primitives/pid_controller.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <utility>

#include "cbbg/framework/block_context.h"
#include "cbbg/framework/number_text.h"
#include "cbbg/framework/primitives/argument_checks.h"

namespace cbbg {
namespace {

void check_gain(const std::string& label, const char* what, double gain) {
  if (!std::isfinite(gain) || gain < 0.0) {
    throw std::invalid_argument(label + ": " + what + " " + format_number(gain) +
                                " must be finite and >= 0");
  }
}

}  // namespace

PidController::PidController(std::string name, const Params& params, double period, int size,
                             double offset)
    : Block(std::move(name)), params_(params), period_(period) {
  const std::string label = primitive_checks::label("PidController", this->name());
  check_gain(label, "kp", params.kp);
  check_gain(label, "ki", params.ki);
  check_gain(label, "kd", params.kd);
  if (std::isnan(params.u_min) || params.u_min == std::numeric_limits<double>::infinity()) {
    throw std::invalid_argument(label + ": u_min " + format_number(params.u_min) +
                                " must be a number below inf (-inf for no lower limit)");
  }
  if (std::isnan(params.u_max) || params.u_max == -std::numeric_limits<double>::infinity()) {
    throw std::invalid_argument(label + ": u_max " + format_number(params.u_max) +
                                " must be a number above -inf (inf for no upper limit)");
  }
  if (params.u_min > params.u_max) {
    throw std::invalid_argument(label + ": u_min " + format_number(params.u_min) +
                                " is above u_max " + format_number(params.u_max) +
                                "; u_min must be <= u_max");
  }
  primitive_checks::check_period(label, period, offset);
  primitive_checks::checked_size(label, size);

  e_ = &declare_input_port("e", size, "the error, reference - measurement");
  integral_ = declare_discrete_state("integral", Vector::Zero(size), StateLifetime::kPerTrial);
  previous_error_ =
      declare_discrete_state("previous_error", Vector::Zero(size), StateLifetime::kPerTrial);
  command_ = declare_discrete_state(
      "command", Vector::Constant(size, std::clamp(0.0, params.u_min, params.u_max)),
      StateLifetime::kPerTrial);
  started_ = declare_discrete_state("started", Vector::Zero(1), StateLifetime::kPerTrial);
  declare_output_port<&PidController::calc_u>(
      "u", size, {}, "the command u_k, held until the next sample", OutputSources::kDiscreteState);
  declare_periodic_update<&PidController::sample>(period, offset);
}

void PidController::calc_u(const BlockContext& context, VectorRef u) const {
  u = command_.of(context.discrete_state());
}

EventStatus PidController::sample(BlockContext& context, VectorRef next) const {
  const ConstVectorView error = context.input(*e_);
  const ConstVectorView state = context.discrete_state();
  const bool started = started_.of(state)[0] != 0.0;
  const Params& p = params_;
  for (Eigen::Index i = 0; i < error.size(); ++i) {
    const double e_k = error[i];  // 1.
    const double integral = state[integral_.offset + i];
    const double e_previous = started ? state[previous_error_.offset + i] : e_k;
    const double derivative = (e_k - e_previous) / period_;             // 2.
    const double v = p.kp * e_k + p.ki * integral + p.kd * derivative;  // 3.
    next[command_.offset + i] = std::clamp(v, p.u_min, p.u_max);        // 4.
    const bool winds_up = (v > p.u_max && e_k > 0.0) || (v < p.u_min && e_k < 0.0);
    next[integral_.offset + i] = winds_up ? integral : integral + period_ * e_k;  // 5.
    next[previous_error_.offset + i] = e_k;                                       // 6.
  }
  next[started_.offset] = 1.0;
  return EventStatus::succeeded();
}

}  // namespace cbbg
