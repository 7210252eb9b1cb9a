#include "cbbg/framework/primitives/discrete_derivative.h"

#include <algorithm>

#include "cbbg/framework/block_context.h"
#include "cbbg/framework/primitives/argument_checks.h"

namespace cbbg {

DiscreteDerivative::DiscreteDerivative(std::string name, int size, double period,
                                       InitialTransient transient, double offset)
    : Block(std::move(name)), period_(period) {
  const std::string block = primitive_checks::label("DiscreteDerivative", this->name());
  primitive_checks::checked_size(block, size);
  primitive_checks::check_period(block, period, offset);
  u_ = &declare_input_port("u", size, "the signal to differentiate");
  last_ = declare_discrete_state("last", Vector::Zero(size), StateLifetime::kPerTrial);
  before_ = declare_discrete_state("before", Vector::Zero(size), StateLifetime::kPerTrial);
  // Samples stored so far, up to 2; kKeep starts at 2, as if zeros had been sampled.
  const double initial_count = transient == InitialTransient::kSuppress ? 0.0 : 2.0;
  count_ =
      declare_discrete_state("count", Vector::Constant(1, initial_count), StateLifetime::kPerTrial);
  declare_output_port<&DiscreteDerivative::calc_y>(
      "y", size, {}, "the backward difference of the last two samples");
  // In place: it reads and writes its state through `next` alone
  declare_periodic_update<&DiscreteDerivative::sample>(period, offset, UpdateWrites::kInPlace);
}

void DiscreteDerivative::calc_y(const BlockContext& context, VectorRef y) const {
  const ConstVectorView state = context.discrete_state();
  if (count_.of(state)[0] < 2.0) {
    y.setZero();
  } else {
    y = (last_.of(state) - before_.of(state)) / period_;
  }
}

EventStatus DiscreteDerivative::sample(BlockContext& context, VectorRef next) const {
  // `next` holds the current state on entry.
  before_.of(next) = last_.of(next);
  last_.of(next) = context.input(*u_);
  count_.of(next)[0] = std::min(count_.of(next)[0] + 1.0, 2.0);
  return EventStatus::succeeded();
}

}  // namespace cbbg
