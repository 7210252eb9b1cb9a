#pragma once
// What the replay page (replay/) draws of a plant: its shapes and their sizes, which the plant
// states itself (RobotPlant::drawing). Two wheels on an axle, a cart on them if the plant has
// one, and a body that pitches about a pivot: the axle of a two-wheeler, the top of a cart
// for a cart-pole.
//
//            body (pitches by the pitch signal about the pivot; its mass at com_height)
//             |
//   +---------+---------+  <- pivot, cart_height above the axle (0: no cart, the axle)
//   |  cart (does not   |
//   |  pitch)           |
//   +---(o)-------(o)---+  <- axle, wheel_radius above the ground; track_width apart

#include "cbbg/plant/robot_params.h"

namespace cbbg::plant {

struct PlantDrawing {
  // The wheels, turned by the wheel signals.
  double wheel_radius = 0.15;  // m
  double track_width = 0.44;   // centre to centre, across the heading, m
  // A cart on the axle that does not pitch; none when cart_length is 0.
  double cart_length = 0.0;  // along the heading, m
  double cart_height = 0.0;  // axle to its top, where the body's pivot is, m
  // The body, a box from the pivot up, pitching about the pivot.
  double body_length = 0.8;      // pivot to its top, m
  double body_thickness = 0.14;  // along the heading, m
  double body_width = 0.308;     // across the heading, m
  double com_height = 0.4;       // pivot to its centre of mass, m

  bool operator==(const PlantDrawing&) const = default;
};

// The two-wheeler of `robot`: no cart, a body twice its centre of mass's height, 0.7 of the
// track wide. The default PlantDrawing is that of the default robot (plant.* at
// docs/model.md §1's values).
inline PlantDrawing two_wheeler_drawing(const RobotParams& robot) {
  PlantDrawing drawing;
  drawing.wheel_radius = robot.wheel_radius;
  drawing.track_width = robot.track_width;
  drawing.body_length = 2.0 * robot.com_height;
  drawing.body_width = 0.7 * robot.track_width;
  drawing.com_height = robot.com_height;
  return drawing;
}

}  // namespace cbbg::plant
