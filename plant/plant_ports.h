#pragma once
// The ports every robot plant shares, so plants swap in any diagram.

namespace cbbg::plant {

// Input port "torque" (size 2): motor torques, body -> wheel, N m.
enum TorqueIndex : int { kTauLeft = 0, kTauRight = 1, kTorqueSize = 2 };

// Input port "disturbance" (size 2), on a plant that takes one (RobotPlant::disturbance_input):
// forces on the robot from outside, which do not pass through its motors or their limit.
enum DisturbanceIndex : int {
  kPushForce = 0,    // horizontal force at the body's centre of mass, along the heading, N
  kPushPitchTorque,  // torque on the body about the axle, N m; > 0 leans it forward
  kDisturbanceSize
};

// Output port "state" (size 10).
enum StateIndex : int {
  kThetaB = 0,   // body pitch, rad; > 0 leans forward (+x)
  kThetaBDot,    // body pitch rate, rad/s
  kPhiLeft,      // left wheel absolute angle, rad
  kPhiRight,     // right wheel absolute angle, rad
  kPhiLeftDot,   // left wheel rate, rad/s
  kPhiRightDot,  // right wheel rate, rad/s
  kX,            // axle midpoint x, m
  kY,            // axle midpoint y, m
  kYaw,          // heading, rad
  kYawRate,      // heading rate, rad/s
  kStateSize
};

}  // namespace cbbg::plant
