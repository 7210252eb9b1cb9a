#include "cbbg/framework/primitives/deadband.h"

#include "cbbg/framework/block_context.h"
#include "cbbg/framework/primitives/argument_checks.h"

namespace cbbg {

using primitive_checks::label;

Deadband::Deadband(std::string name, double lower, double upper, int size)
    : Block(std::move(name)),
      lower_(Vector::Constant(primitive_checks::checked_size(label("Deadband", this->name()), size),
                              lower)),
      upper_(Vector::Constant(size, upper)) {
  declare_ports(false);
}

Deadband::Deadband(std::string name, Vector lower, Vector upper)
    : Block(std::move(name)), lower_(std::move(lower)), upper_(std::move(upper)) {
  declare_ports(true);
}

void Deadband::declare_ports(bool per_element) {
  primitive_checks::check_limits(label("Deadband", name()), lower_, upper_, per_element);
  const int size = static_cast<int>(lower_.size());
  u_ = &declare_input_port("u", size);
  declare_output_port<&Deadband::calc_y>("y", size, {u_}, "u less the dead zone",
                                         OutputSources::kDiscreteState);
}

void Deadband::calc_y(const BlockContext& context, VectorRef y) const {
  const ConstVectorView input = context.input(*u_);
  for (Eigen::Index i = 0; i < input.size(); ++i) {
    const double v = input[i];
    if (v >= lower_[i] && v <= upper_[i]) {
      y[i] = 0.0;
    } else {
      y[i] = v > upper_[i] ? v - upper_[i] : v - lower_[i];  // NaN falls through
    }
  }
}

}  // namespace cbbg
