#pragma once
// The interface every robot plant offers the closed loop (diagrams/closed_loop.h): torque in,
// state out, and a reset to an initial pitch at the start of each trial. The Simbody and the
// analytic plant implement it; so can a user's own plant.

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

 protected:
  explicit RobotPlant(std::string name) : Block(std::move(name)) {}
};

}  // namespace cbbg::plant
