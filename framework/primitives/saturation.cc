#include "cbbg/framework/primitives/saturation.h"

#include "cbbg/framework/block_context.h"
#include "cbbg/framework/primitives/argument_checks.h"

namespace cbbg {

using primitive_checks::label;

Saturation::Saturation(std::string name, double lower, double upper, int size)
    : Block(std::move(name)),
      lower_(Vector::Constant(
          primitive_checks::checked_size(label("Saturation", this->name()), size), lower)),
      upper_(Vector::Constant(size, upper)) {
  declare_ports(false);
}

Saturation::Saturation(std::string name, Vector lower, Vector upper)
    : Block(std::move(name)), lower_(std::move(lower)), upper_(std::move(upper)) {
  declare_ports(true);
}

void Saturation::declare_ports(bool per_element) {
  primitive_checks::check_limits(label("Saturation", name()), lower_, upper_, per_element);
  const int size = static_cast<int>(lower_.size());
  u_ = &declare_input_port("u", size);
  declare_output_port<&Saturation::calc_y>("y", size, {u_}, "u clamped to the limits",
                                           OutputSources::kDiscreteState);
}

void Saturation::calc_y(const BlockContext& context, VectorRef y) const {
  y = context.input(*u_).cwiseMax(lower_).cwiseMin(upper_);
}

}  // namespace cbbg
