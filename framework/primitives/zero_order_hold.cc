#include "cbbg/framework/primitives/zero_order_hold.h"

#include <algorithm>

#include "cbbg/framework/block_context.h"
#include "cbbg/framework/short_vectors.h"

namespace cbbg {

ZeroOrderHold::ZeroOrderHold(std::string name, int size, double period, double offset)
    : ZeroOrderHold(std::move(name), Vector::Zero(std::max(size, 0)), period, offset) {}

ZeroOrderHold::ZeroOrderHold(std::string name, const Vector& initial_value, double period,
                             double offset)
    : Block(std::move(name)) {
  const int size = static_cast<int>(initial_value.size());
  u_ = &declare_input_port("u", size, "the signal to sample");
  declare_discrete_state("held", initial_value, StateLifetime::kPerTrial);
  declare_output_port<&ZeroOrderHold::calc_y>("y", size, {}, "the held sample",
                                              OutputSources::kDiscreteState);
  // In place: it writes only
  declare_periodic_update<&ZeroOrderHold::sample>(period, offset, UpdateWrites::kInPlace);
}

void ZeroOrderHold::calc_y(const BlockContext& context, VectorRef y) const {
  copy_values(context.discrete_state().data(), y.size(), y.data());
}

EventStatus ZeroOrderHold::sample(BlockContext& context, VectorRef next) const {
  copy_values(context.input(*u_).data(), next.size(), next.data());
  return EventStatus::succeeded();
}

}  // namespace cbbg
