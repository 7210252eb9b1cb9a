#include "cbbg/blocks/external_push.h"

#include "cbbg/blocks/parameter_checks.h"
#include "cbbg/framework/block_context.h"

namespace cbbg::blocks {

ExternalPush::ExternalPush(std::string name, const PushParams& params, double period)
    : Block(std::move(name)), params_(params) {
  params_.validate();
  check_period(period);
  declare_discrete_state("push", Vector::Zero(2), StateLifetime::kPerTrial);
  declare_output_port(
      "disturbance", 2,
      [](const BlockContext& context, VectorRef disturbance) {
        disturbance = context.discrete_state();
      },
      {}, "F at the centre of mass, N; torque on the body about the axle, N m",
      OutputSources::kDiscreteState);
  declare_periodic_update(
      period, 0.0,
      [this](BlockContext& context, VectorRef next) {
        const bool on = params_.on_at(context.time());
        next[0] = on ? params_.force : 0.0;
        next[1] = on ? params_.pitch_torque : 0.0;
        return EventStatus::succeeded();
      },
      UpdateWrites::kInPlace);  // writes only
}

}  // namespace cbbg::blocks
