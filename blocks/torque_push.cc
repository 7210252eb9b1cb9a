#include "cbbg/blocks/torque_push.h"

#include "cbbg/blocks/parameter_checks.h"
#include "cbbg/framework/block_context.h"

namespace cbbg::blocks {

TorquePush::TorquePush(std::string name, const PushParams& params, double period)
    : Block(std::move(name)), params_(params) {
  params_.validate();
  check_period(period);
  action_ = &declare_input_port("action", 1, "the held action a, N m");
  declare_discrete_state("push", Vector::Zero(1), StateLifetime::kPerTrial);
  declare_output_port<&TorquePush::calc_torque>(
      "torque", 1, {action_}, "a + p, each wheel's torque, N m", OutputSources::kDiscreteState);
  declare_periodic_update<&TorquePush::update_push>(period, 0.0,
                                                    UpdateWrites::kInPlace);  // writes only
}

void TorquePush::calc_torque(const BlockContext& context, VectorRef torque) const {
  torque[0] = context.input(*action_)[0] + context.discrete_state()[0];
}

EventStatus TorquePush::update_push(BlockContext& context, VectorRef next) const {
  next[0] = params_.on_at(context.time()) ? params_.torque : 0.0;
  return EventStatus::succeeded();
}

}  // namespace cbbg::blocks
