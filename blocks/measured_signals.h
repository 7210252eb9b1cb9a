#pragma once
// Layout of the "measured" signal the Sensors block outputs and the controller's blocks read.

namespace cbbg::blocks {

// Port "measured" (size 6), in the order of plant/plant_ports.h.
enum MeasuredIndex : int {
  kMeasuredThetaB = 0,   // body pitch, rad
  kMeasuredThetaBDot,    // body pitch rate, rad/s
  kMeasuredPhiLeft,      // left wheel angle, rad
  kMeasuredPhiRight,     // right wheel angle, rad
  kMeasuredPhiLeftDot,   // left wheel rate, rad/s
  kMeasuredPhiRightDot,  // right wheel rate, rad/s
  kMeasuredSize
};

}  // namespace cbbg::blocks
