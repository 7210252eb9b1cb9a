#include "cbbg/blocks/torque_push.h"

#include "cbbg/blocks/parameter_checks.h"
#include "cbbg/framework/block_context.h"

namespace cbbg::blocks {

TorquePush::TorquePush(std::string name, const PushParams& params, double period)
    : Block(std::move(name)), params_(params) {
  params_.validate();
  check_period(period);
  const InputPort& action = declare_input_port("action", 1, "the held action a, N m");
  declare_discrete_state("push", Vector::Zero(1), StateLifetime::kPerTrial);
  declare_output_port(
      "torque", 1,
      [&action](const BlockContext& context, VectorRef torque) {
        torque[0] = context.input(action)[0] + context.discrete_state()[0];
      },
      {&action}, "a + p, each wheel's torque, N m", OutputSources::kDiscreteState);
  declare_periodic_update(
      period, 0.0,
      [this](BlockContext& context, VectorRef next) {
        next[0] = params_.on_at(context.time()) ? params_.torque : 0.0;
        return EventStatus::succeeded();
      },
      UpdateWrites::kInPlace);  // writes only
}

}  // namespace cbbg::blocks
