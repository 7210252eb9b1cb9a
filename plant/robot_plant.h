#pragma once
// The interface every robot plant offers the closed loop (diagrams/closed_loop.h): torque in,
// named signals out, a reset to an initial pitch at the start of each trial, and what a replay
// draws of it. The Simbody and the analytic plant implement it; so can a user's own plant (a
// cart-pole, say).

#include <limits>
#include <string>
#include <vector>

#include "cbbg/framework/block.h"
#include "cbbg/framework/context.h"
#include "cbbg/plant/plant_drawing.h"
#include "cbbg/plant/plant_ports.h"
#include "cbbg/plant/plant_signals.h"

namespace cbbg::plant {

// Whether a library plant declares the input "disturbance" (plant_ports.h). Declared, it must
// be connected or fixed as every input is; the closed loop does so when push.force or
// push.pitch_torque asks for it. Not declared, the motors are the only forces but gravity's.
enum class DisturbanceInput { kNone, kDeclared };

/// RobotPlant: a robot balanced through wheel torque, as a block.
///
/// | port   | dir | size | meaning                                                       |
/// |--------|-----|------|---------------------------------------------------------------|
/// | torque | in  | 2    | tau_l, tau_r: motor torques body -> wheel, N m                |
/// | state  | out | n    | the signals signals() names (two-wheeler: plant_ports.h's 10) |
/// | disturbance | in | 2 | optional: F at the centre of mass, N; pitch torque, N m        |
///
/// A subclass declares both ports with these names, names its state output's signals when
/// they are not the two-wheeler's (plant_signals.h says which the loop needs), states its
/// drawing when it is not a two-wheeler of the default size, and implements reset. The closed
/// loop checks the ports and the names.
class RobotPlant : public Block {
 public:
  const InputPort& torque_input() const { return input_port("torque"); }
  const OutputPort& state_output() const { return output_port("state"); }
  // The input "disturbance" (plant_ports.h's DisturbanceIndex), or null for a plant that
  // takes none: a push from outside (push.force, push.pitch_torque) needs it.
  const InputPort* disturbance_input() const { return find_input_port("disturbance"); }

  // Puts the robot at theta_b = initial_pitch, at rest, at the origin, in `context` (a
  // context of the root diagram). Only rewrites this block's state.
  virtual void reset(Context& context, double initial_pitch) const = 0;

  // The name of each entry of the state output, in order: the two-wheeler's by default.
  virtual std::vector<std::string> signals() const { return two_wheeler_signals(); }

  // The signals of signals() that steps.csv records every logged tick, after the loop's own
  // columns and the pose, named as here: none by default (yaw_rate, say, or a cart-pole's
  // cart position). The pose and a name steps.csv already has are refused when the loop
  // builds.
  virtual std::vector<std::string> logged_signals() const { return {}; }

  // The wheels' radius, m: what turns wheel angles into distance (a trial's mean forward
  // speed). NaN, the default, for a plant that does not say; those figures are then NaN.
  virtual double wheel_radius() const { return std::numeric_limits<double>::quiet_NaN(); }

  // What the replay page draws of it (plant_drawing.h): by default the two-wheeler of the
  // default robot (plant.* as docs/model.md §1 gives them). A plant of other sizes or of
  // another shape (a cart and a pole) states its own.
  virtual PlantDrawing drawing() const { return PlantDrawing{}; }

 protected:
  explicit RobotPlant(std::string name) : Block(std::move(name)) {}

  // Declares the input "disturbance" when `disturbance` asks for it; null when it does not.
  const InputPort* declare_disturbance_input(DisturbanceInput disturbance) {
    if (disturbance != DisturbanceInput::kDeclared) return nullptr;
    return &declare_input_port("disturbance", kDisturbanceSize,
                               "F at the centre of mass along the heading, N; pitch torque, N m");
  }
};

}  // namespace cbbg::plant
