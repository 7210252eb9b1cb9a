#pragma once

#include <string>

#include "cbbg/framework/block.h"
#include "cbbg/framework/context.h"
#include "cbbg/plant/robot_params.h"
#include "cbbg/plant/robot_plant.h"

namespace cbbg::plant {

/// AnalyticPlant: the robot of docs/model.md §1 as its equations of motion (robot_dynamics.h),
/// integrated by the Simulator's error-controlled Dormand–Prince 5(4) stepper (Boost.Odeint)
/// at SimulatorOptions::accuracy (the experiments set it from plant.accuracy).
///
/// | port   | dir | size | meaning                                                          |
/// |--------|-----|------|------------------------------------------------------------------|
/// | torque | in  | 2    | tau_l, tau_r: motor torques body -> wheel, N m (any value; the   |
/// |        |     |      | plant saturates each to [-torque_limit, torque_limit])           |
/// | disturbance | in | 2 | with DisturbanceInput::kDeclared only: F, a horizontal force at   |
/// |        |     |      | the body's centre of mass along the heading, N; tau_ext, a torque |
/// |        |     |      | on the body about the axle, N m (neither saturated)              |
/// | state  | out | 10   | theta_b (rad, > 0 leans forward), theta_b' (rad/s), phi_l, phi_r |
/// |        |     |      | (absolute wheel angles, rad), phi_l', phi_r' (rad/s), x, y (axle |
/// |        |     |      | midpoint, m), yaw (rad), yaw rate (rad/s); see plant_ports.h     |
///
/// Equations: M(q) q'' + N(q, q') = E sat(T) + Q_ext with Q_ext = disturbance_forces(F, tau_ext)
/// (zero without the input),  q = (theta_b, phi_l, phi_r) (see
/// robot_dynamics.h); x' = v cos(yaw), y' = v sin(yaw), yaw' = R (phi_r' - phi_l') / d,
/// v = R (phi_l' + phi_r') / 2 (rolling without slip).
/// Continuous state (9): theta_b, phi_l, phi_r, theta_b', phi_l', phi_r', x, y, yaw. The
/// state output reads only this state, never the torque directly.
/// Parameters: RobotParams (plant.*); the initial pitch (trial.theta0), the rest zero.
/// Errors: a non-finite torque, disturbance or state throws SimulationError naming the block.
class AnalyticPlant final : public RobotPlant {
 public:
  AnalyticPlant(std::string name, const RobotParams& params,
                double initial_pitch = kDefaultInitialPitch,
                DisturbanceInput disturbance = DisturbanceInput::kNone);

  const RobotParams& params() const { return params_; }

  // Puts the robot at theta_b = initial_pitch (trial.theta0), everything else zero. Only
  // rewrites this block's state in `context` (a context of the root diagram).
  void reset(Context& context, double initial_pitch) const override;
  double wheel_radius() const override { return params_.wheel_radius; }
  // The two-wheeler of its parameters (plant.wheel_radius, plant.track_width, plant.com_height).
  PlantDrawing drawing() const override { return two_wheeler_drawing(params_); }
  // Sets the whole state from a vector in the output layout (plant_ports.h); the yaw rate
  // is not stored: it follows from the wheel rates.
  void set_state(Context& context, const Vector& state) const;

 private:
  // "state": the continuous state in the output layout (plant_ports.h), the yaw rate from the
  // wheel rates.
  void calc_state(const BlockContext& context, VectorRef y) const;
  // The equations of motion of the class comment, the torque saturated, the disturbance's
  // forces added when there is one; throws on a non-finite torque or state.
  void calc_derivatives(const BlockContext& context, VectorRef x_dot) const;

  RobotParams params_;
  const InputPort* torque_;
  const InputPort* disturbance_;  // null without DisturbanceInput::kDeclared
};

}  // namespace cbbg::plant
