#include "cbbg/framework/primitives/unit_delay.h"

#include "cbbg/framework/block_context.h"
#include "cbbg/framework/primitives/argument_checks.h"

namespace cbbg {

using primitive_checks::label;

UnitDelay::UnitDelay(std::string name, int size, double period, double offset)
    // `name` copied, not moved: the size's check reads it too.
    : UnitDelay(name, Vector::Zero(primitive_checks::checked_size(label("UnitDelay", name), size)),
                period, offset) {}

UnitDelay::UnitDelay(std::string name, const Vector& initial_value, double period, double offset)
    : Block(std::move(name)) {
  const std::string block = label("UnitDelay", this->name());
  const int size = primitive_checks::checked_size(block, static_cast<int>(initial_value.size()));
  primitive_checks::check_finite(block, "initial value", initial_value);
  primitive_checks::check_period(block, period, offset);
  u_ = &declare_input_port("u", size, "the signal to delay");
  declare_discrete_state("delayed", initial_value, StateLifetime::kPerTrial);
  declare_output_port<&UnitDelay::calc_y>("y", size, {}, "the sample before",
                                          OutputSources::kDiscreteState);
  // In place: it writes only
  declare_periodic_update<&UnitDelay::latch>(period, offset, UpdateWrites::kInPlace);
}

void UnitDelay::calc_y(const BlockContext& context, VectorRef y) const {
  y = context.discrete_state();
}

EventStatus UnitDelay::latch(BlockContext& context, VectorRef next) const {
  next = context.input(*u_);
  return EventStatus::succeeded();
}

}  // namespace cbbg
