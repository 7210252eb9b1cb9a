#pragma once
// The paper's two-wheeler as an MJCF model, written from plant.* (RobotParams): the model
// plant.kind mujoco loads when mujoco.model is empty, and the file installed as
// share/cbbg/models/two_wheeler.xml (at the defaults, docs/model.md §1).
//
// Joints: x, y, z slides and a yaw hinge carry a massless base at the axle; the body pitches on
// it (hinge "pitch"), and each wheel turns on it (hinges "left_wheel", "right_wheel"), so a
// wheel's joint angle is its absolute angle. The motors are fixed tendons wheel - pitch (torque
// +tau on the wheel, -tau on the body), saturated by their ctrlrange; the tendons' damping is
// the axle friction, the wheel joints' damping the wheel-ground viscous friction. The wheels
// touch a plane (sliding friction 1) as spheres of their radius, drawn as cylinders: they roll
// while the friction holds and slip where it does not. Roll is not a joint: both wheels stay
// on the ground, and a sphere touches it where the rim would.
// Sensors carry the loop's signal names (plant/plant_signals.h).

#include <string>

#include "cbbg/plant/robot_params.h"

namespace cbbg::plant {

// The MJCF text of the two-wheeler of `robot`: MuJoCo's step 5 ms, Euler.
std::string two_wheeler_mjcf(const RobotParams& robot);

}  // namespace cbbg::plant
