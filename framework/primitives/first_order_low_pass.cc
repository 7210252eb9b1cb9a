#include "cbbg/framework/primitives/first_order_low_pass.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <utility>

#include "cbbg/framework/block_context.h"
#include "cbbg/framework/number_text.h"
#include "cbbg/framework/primitives/argument_checks.h"

namespace cbbg {

FirstOrderLowPass::FirstOrderLowPass(std::string name, double time_constant, int size)
    : FirstOrderLowPass(std::move(name), time_constant, Vector::Zero(std::max(size, 0))) {}

FirstOrderLowPass::FirstOrderLowPass(std::string name, double time_constant,
                                     const Vector& initial_value)
    : Block(std::move(name)), time_constant_(time_constant) {
  const std::string label = primitive_checks::label("FirstOrderLowPass", this->name());
  if (!std::isfinite(time_constant) || time_constant <= 0.0) {
    throw std::invalid_argument(label + ": time constant " + format_number(time_constant) +
                                " must be positive and finite");
  }
  const int size = primitive_checks::checked_size(label, static_cast<int>(initial_value.size()));
  primitive_checks::check_finite(label, "initial value", initial_value);
  u_ = &declare_input_port("u", size, "the signal to smooth");
  declare_continuous_state<&FirstOrderLowPass::calc_derivatives>(initial_value);
  declare_output_port<&FirstOrderLowPass::calc_y>("y", size, {}, "the smoothed signal");
}

void FirstOrderLowPass::calc_derivatives(const BlockContext& context, VectorRef derivatives) const {
  derivatives = (context.input(*u_) - context.continuous_state()) / time_constant_;
}

void FirstOrderLowPass::calc_y(const BlockContext& context, VectorRef y) const {
  y = context.continuous_state();
}

}  // namespace cbbg
