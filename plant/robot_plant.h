#pragma once
// The interface every robot plant offers the closed loop (diagrams/closed_loop.h): torque in,
// state out, and a reset to an initial pitch at the start of each trial. The Simbody and the
// analytic plant implement it; so can a user's own plant.

#include <limits>
#include <string>

#include "cbbg/framework/block.h"
#include "cbbg/framework/context.h"
#include "cbbg/plant/plant_ports.h"

namespace cbbg::plant {

/// RobotPlant: a two-wheeled robot as a block.
///
/// | port   | dir | size | meaning                                                    |
/// |--------|-----|------|------------------------------------------------------------|
/// | torque | in  | 2    | tau_l, tau_r: motor torques body -> wheel, N m             |
/// | state  | out | 10   | the state of plant_ports.h (pitch first, then wheels, pose) |
///
/// A subclass declares both ports with these names and sizes (the closed loop checks them)
/// and implements reset.
class RobotPlant : public Block {
 public:
  const InputPort& torque_input() const { return input_port("torque"); }
  const OutputPort& state_output() const { return output_port("state"); }

  // Puts the robot at theta_b = initial_pitch, at rest, at the origin, in `context` (a
  // context of the root diagram). Only rewrites this block's state.
  virtual void reset(Context& context, double initial_pitch) const = 0;

  // Whether the plant is built from the robot parameters (plant.*, robot_params.h), as the
  // Simbody and the analytic plant are. An evaluation on a changed robot
  // (evaluation.body_mass_scale, evaluation.com_height_scale) changes those parameters, so
  // it reaches only such a plant, and refuses a plant that would not see it.
  virtual bool built_from_robot_params() const { return false; }

  // The wheels' radius, m: what turns wheel angles into distance (a trial's mean forward
  // speed). NaN, the default, for a plant that does not say; those figures are then NaN.
  virtual double wheel_radius() const { return std::numeric_limits<double>::quiet_NaN(); }

 protected:
  explicit RobotPlant(std::string name) : Block(std::move(name)) {}
};

}  // namespace cbbg::plant
