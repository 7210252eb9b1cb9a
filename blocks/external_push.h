#pragma once

#include <string>

#include "cbbg/blocks/push_params.h"
#include "cbbg/framework/block.h"

namespace cbbg::blocks {

/// ExternalPush: a disturbance from outside the robot, for a plant's input "disturbance"
/// (plant/plant_ports.h): a pulse of horizontal force at the body's centre of mass
/// (push.force) and of torque on the body about the axle (push.pitch_torque). Unlike
/// TorquePush it does not pass through the motors, so their limit does not bound it.
///
/// | port        | dir | size | meaning                                      |
/// |-------------|-----|------|----------------------------------------------|
/// | disturbance | out | 2    | F, N; tau_ext, N m (zero outside the pulse)  |
///
/// Equations: at each tick t_k = k Ts the periodic update sets
///   (F, tau_ext) = (force, pitch_torque) if PushParams::on_at(t_k), else (0, 0)
/// and holds it until t_{k+1}, exactly as TorquePush does with its torque.
/// Parameters: PushParams, the period Ts = trial.period. Context parameter "pulse" (4:
/// start, duration, force, pitch_torque; PushParams' by default), which the update reads, so
/// that each trial can be pushed differently (training.push_force draws one per trial).
///
/// Discrete state: [F, tau_ext].
class ExternalPush final : public Block {
 public:
  ExternalPush(std::string name, const PushParams& params, double period);

 private:
  // "disturbance": the held [F, tau_ext] of the discrete state.
  void calc_disturbance(const BlockContext& context, VectorRef disturbance) const;
  // (F, tau_ext) of the context's pulse if it is on at this tick, else (0, 0). Writes only.
  EventStatus update_push(BlockContext& context, VectorRef next) const;

  PushParams params_;
  int pulse_;  // the context parameter's index
};

}  // namespace cbbg::blocks
