#include "cbbg/framework/primitives/step_source.h"

#include <cmath>
#include <stdexcept>
#include <utility>

#include "cbbg/framework/block_context.h"
#include "cbbg/framework/number_text.h"
#include "cbbg/framework/primitives/argument_checks.h"

namespace cbbg {

StepSource::StepSource(std::string name, double initial_value, double final_value, double step_time)
    : StepSource(std::move(name), Vector::Constant(1, initial_value),
                 Vector::Constant(1, final_value), step_time) {}

StepSource::StepSource(std::string name, const Vector& initial_value, const Vector& final_value,
                       double step_time)
    : Block(std::move(name)),
      initial_value_(initial_value),
      final_value_(final_value),
      step_time_(step_time) {
  const std::string label = primitive_checks::label("StepSource", this->name());
  const int size = primitive_checks::checked_size(label, static_cast<int>(initial_value.size()));
  if (final_value.size() != initial_value.size()) {
    throw std::invalid_argument(
        label + ": the final value has size " + std::to_string(final_value.size()) +
        "; it must have the initial value's size, " + std::to_string(initial_value.size()));
  }
  primitive_checks::check_finite(label, "initial value", initial_value);
  primitive_checks::check_finite(label, "final value", final_value);
  if (!std::isfinite(step_time)) {
    throw std::invalid_argument(label + ": step time " + format_number(step_time) +
                                " must be finite");
  }
  declare_output_port<&StepSource::calc_y>(
      "y", size, {}, "the initial value before the step time, the final value from it on");
}

void StepSource::calc_y(const BlockContext& context, VectorRef y) const {
  y = context.time() < step_time_ ? initial_value_ : final_value_;
}

}  // namespace cbbg
