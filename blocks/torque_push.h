#pragma once

#include <string>

#include "cbbg/blocks/push_params.h"
#include "cbbg/framework/block.h"

namespace cbbg::blocks {

/// TorquePush: a disturbance through the motors, as a torque pulse (push.torque) added to the
/// held action of both wheels. The motors' limit bounds the sum, so it models a command
/// fault more than a blow: ExternalPush is the push from outside.
///
/// | port   | dir | size | meaning                                    |
/// |--------|-----|------|--------------------------------------------|
/// | action | in  | 1    | a, the held (zero-order hold) action, N m  |
/// | torque | out | 1    | a + p, the torque each wheel gets, N m     |
///
/// Equations: at each tick t_k = k Ts the periodic update sets
///   p = torque if start <= t_k < start + duration (PushParams::on_at), else 0
/// (comparisons within the simulator's 1e-9 * max(1, |t|) of simultaneity) and p holds until
/// t_{k+1}. The push therefore switches only at tick instants, where the action does too: the
/// torque is piecewise constant between ticks and both plants integrate it exactly. It starts
/// at the first tick at or after `start` and covers the ticks before start + duration. The
/// plant saturates the sum a + p (plant.torque_limit).
/// Parameters: PushParams, the period Ts = trial.period.
///
/// Discrete state: [p].
class TorquePush final : public Block {
 public:
  TorquePush(std::string name, const PushParams& params, double period);

 private:
  // "torque": a + p.
  void calc_torque(const BlockContext& context, VectorRef torque) const;
  // p = torque if the push is on at this tick, else 0. Writes only.
  EventStatus update_push(BlockContext& context, VectorRef next) const;

  PushParams params_;
  const InputPort* action_;
};

}  // namespace cbbg::blocks
