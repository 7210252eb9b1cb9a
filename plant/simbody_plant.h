#pragma once

#include <memory>
#include <string>

#include "cbbg/framework/block.h"
#include "cbbg/framework/context.h"
#include "cbbg/plant/robot_params.h"
#include "cbbg/plant/robot_plant.h"

namespace cbbg::plant {

/// SimbodyPlant: the reference model of the robot, a 3-D Simbody multibody system
/// (multibody_robot.h): body and two wheels on revolute joints about the axle, rolling
/// without slip, yaw free. It advances itself between the simulator's instants with the
/// torque held (zero-order hold), by the Simbody integrator plant.simbody_integrator
/// (Runge–Kutta–Merson by default; Runge–Kutta 3 or Verlet) at plant.accuracy.
///
/// | port   | dir | size | meaning                                                          |
/// |--------|-----|------|------------------------------------------------------------------|
/// | torque | in  | 2    | tau_l, tau_r: motor torques body -> wheel, N m (any value; the   |
/// |        |     |      | plant saturates each to [-torque_limit, torque_limit])           |
/// | disturbance | in | 2 | with DisturbanceInput::kDeclared only: F, a horizontal force at   |
/// |        |     |      | the body's centre of mass along the heading, N; tau_ext, a torque |
/// |        |     |      | on the body about the axle, N m (held like the torque)            |
/// | state  | out | 10   | theta_b (rad, > 0 leans forward), theta_b' (rad/s), phi_l, phi_r |
/// |        |     |      | (absolute wheel angles, rad), phi_l', phi_r' (rad/s), x, y (axle |
/// |        |     |      | midpoint, m), yaw (rad), yaw rate (rad/s); see plant_ports.h     |
///
/// Equations: Simbody's, of the same mechanics as robot_dynamics.h (a test holds the two to
/// 1e-6 rad); motor torque +tau on a wheel, -tau on the body; viscous friction mu_l phi'
/// (wheel-ground) and mu_w (phi' - theta_b') (axle); the disturbance as a force applied at the
/// body's mass centre and a torque on the body, never through the motors.
/// Continuous state (10): the state output itself. Each Context's scratch holds its own
/// multibody system, built once when the context is created, with a Simbody state and
/// integrator. (One system shared by all contexts would be cheaper, but Simbody's System is
/// not safe to realise from two threads at once, and contexts may run in parallel.) When
/// the context's state or time differs from where the scratch left it (reset, set_state,
/// Context::reset_all_state, a restored or cloned context), the scratch restarts its
/// integrator from the context's state; a reset rebuilds nothing.
/// Parameters: RobotParams (plant.*, validated with validate_rigid_bodies); the initial
/// pitch (trial.theta0), the rest zero.
/// Errors: a non-finite torque, disturbance or state, or a Simbody failure, throws SimulationError
/// naming the block.
class SimbodyPlant final : public RobotPlant {
 public:
  SimbodyPlant(std::string name, const RobotParams& params,
               double initial_pitch = kDefaultInitialPitch,
               DisturbanceInput disturbance = DisturbanceInput::kNone);
  ~SimbodyPlant() override;

  const RobotParams& params() const { return params_; }

  // Puts the robot at theta_b = initial_pitch (trial.theta0), everything else zero. Only
  // rewrites this block's state in `context` (a context of the root diagram).
  void reset(Context& context, double initial_pitch) const override;
  double wheel_radius() const override { return params_.wheel_radius; }
  // The two-wheeler of its parameters (plant.wheel_radius, plant.track_width, plant.com_height).
  PlantDrawing drawing() const override { return two_wheeler_drawing(params_); }
  // Sets the whole state from a vector in the output layout (plant_ports.h); the yaw rate
  // is not read: it follows from the wheel rates.
  void set_state(Context& context, const Vector& state) const;

  // Simbody's own kinetic plus gravitational energy of the robot in `context`, zero with
  // every mass centre at axle height (the zero of plant::mechanical_energy).
  double multibody_energy(Context& context) const;

  std::unique_ptr<BlockScratch> make_scratch() const override;

 private:
  class Scratch;

  // "state": the continuous state itself.
  void calc_state(const BlockContext& context, VectorRef y) const;
  // Advances the multibody system to `end_time` with the saturated torque (and the
  // disturbance) held, restarting the scratch's run first when the context moved elsewhere.
  void advance(BlockContext& context, double end_time) const;

  Scratch& synced_scratch(Context& context) const;

  RobotParams params_;
  const InputPort* torque_;
  const InputPort* disturbance_;  // null without DisturbanceInput::kDeclared
};

}  // namespace cbbg::plant
