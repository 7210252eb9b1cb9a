#include "cbbg/blocks/external_push.h"

#include "cbbg/blocks/parameter_checks.h"
#include "cbbg/framework/block_context.h"

namespace cbbg::blocks {

ExternalPush::ExternalPush(std::string name, const PushParams& params, double period)
    : Block(std::move(name)), params_(params) {
  params_.validate();
  check_period(period);
  declare_discrete_state("push", Vector::Zero(2), StateLifetime::kPerTrial);
  pulse_ = declare_parameter(
      "pulse", (Vector(4) << params_.start, params_.duration, params_.force, params_.pitch_torque)
                   .finished());
  declare_output_port<&ExternalPush::calc_disturbance>(
      "disturbance", 2, {}, "F at the centre of mass, N; torque on the body about the axle, N m",
      OutputSources::kDiscreteState);
  declare_periodic_update<&ExternalPush::update_push>(period, 0.0,
                                                      UpdateWrites::kInPlace);  // writes only
}

void ExternalPush::calc_disturbance(const BlockContext& context, VectorRef disturbance) const {
  disturbance = context.discrete_state();
}

EventStatus ExternalPush::update_push(BlockContext& context, VectorRef next) const {
  const auto pulse = context.parameter(pulse_);
  PushParams push = params_;
  push.start = pulse[0];
  push.duration = pulse[1];
  const bool on = push.on_at(context.time());
  next[0] = on ? pulse[2] : 0.0;
  next[1] = on ? pulse[3] : 0.0;
  return EventStatus::succeeded();
}

}  // namespace cbbg::blocks
