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
  const InputPort& u = declare_input_port("u", size, "the rate");
  declare_continuous_state(initial_value, [&u](const BlockContext& context, VectorRef x_dot) {
    x_dot = context.input(u);
  });
  declare_output_port(
      "y", size, [](const BlockContext& context, VectorRef y) { y = context.continuous_state(); },
      {}, "the integral");
}

}  // namespace cbbg
