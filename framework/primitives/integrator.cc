#include "cbbg/framework/primitives/integrator.h"

#include "cbbg/framework/block_context.h"
#include "cbbg/framework/primitives/argument_checks.h"

namespace cbbg {

using primitive_checks::label;

Integrator::Integrator(std::string name, int size)
    // `name` copied, not moved: the size's check reads it too.
    : Integrator(name,
                 Vector::Zero(primitive_checks::checked_size(label("Integrator", name), size))) {}

Integrator::Integrator(std::string name, const Vector& initial_value) : Block(std::move(name)) {
  const std::string block = label("Integrator", this->name());
  const int size = primitive_checks::checked_size(block, static_cast<int>(initial_value.size()));
  primitive_checks::check_finite(block, "initial value", initial_value);
  u_ = &declare_input_port("u", size, "the rate");
  declare_continuous_state<&Integrator::calc_derivatives>(initial_value);
  declare_output_port<&Integrator::calc_y>("y", size, {}, "the integral");
}

void Integrator::calc_derivatives(const BlockContext& context, VectorRef x_dot) const {
  x_dot = context.input(*u_);
}

void Integrator::calc_y(const BlockContext& context, VectorRef y) const {
  y = context.continuous_state();
}

}  // namespace cbbg
