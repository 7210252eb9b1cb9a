#include "cbbg/framework/primitives/zero_order_hold.h"

#include <algorithm>

#include "cbbg/framework/block_context.h"

namespace cbbg {

ZeroOrderHold::ZeroOrderHold(std::string name, int size, double period, double offset)
    : ZeroOrderHold(std::move(name), Vector::Zero(std::max(size, 0)), period, offset) {}

ZeroOrderHold::ZeroOrderHold(std::string name, const Vector& initial_value, double period,
                             double offset)
    : Block(std::move(name)) {
  const int size = static_cast<int>(initial_value.size());
  const InputPort& u = declare_input_port("u", size, "the signal to sample");
  declare_discrete_state("held", initial_value, StateLifetime::kPerTrial);
  declare_output_port(
      "y", size, [](const BlockContext& context, VectorRef y) { y = context.discrete_state(); }, {},
      "the held sample", OutputSources::kDiscreteState);
  declare_periodic_update(
      period, offset,
      [&u](BlockContext& context, VectorRef next) {
        next = context.input(u);
        return EventStatus::succeeded();
      },
      UpdateWrites::kInPlace);  // writes only
}

}  // namespace cbbg
