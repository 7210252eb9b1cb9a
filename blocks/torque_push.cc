#include "cbbg/blocks/torque_push.h"

#include <algorithm>
#include <cmath>

#include "cbbg/blocks/parameter_checks.h"
#include "cbbg/framework/block_context.h"

namespace cbbg::blocks {

void PushParams::validate() const { check_declared(*this, kSection); }

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
        // The simulator's tolerance for simultaneous instants, so that k Ts rounding never moves
        // the push by a tick.
        const double t = context.time();
        const double tolerance = 1e-9 * std::max(1.0, std::abs(t));
        const bool on =
            t >= params_.start - tolerance && t < params_.start + params_.duration - tolerance;
        next[0] = on ? params_.torque : 0.0;
        return EventStatus::succeeded();
      },
      UpdateWrites::kInPlace);  // writes only
}

}  // namespace cbbg::blocks
