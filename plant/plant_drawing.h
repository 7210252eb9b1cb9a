#pragma once
// What the replay page (replay/) draws of a plant: its shapes and their sizes, which the plant
// states itself (RobotPlant::drawing). Two wheels on an axle, a cart on them if the plant has
// one, and a body that pitches about a pivot: the axle of a two-wheeler, the top of a cart
// for a cart-pole. A plant with a model file of its own draws the model's shapes instead
// (ModelDrawing).
//
//            body (pitches by the pitch signal about the pivot; its mass at com_height)
//             |
//   +---------+---------+  <- pivot, cart_height above the axle (0: no cart, the axle)
//   |  cart (does not   |
//   |  pitch)           |
//   +---(o)-------(o)---+  <- axle, wheel_radius above the ground; track_width apart

#include <array>
#include <string>
#include <vector>

#include "cbbg/plant/robot_params.h"

namespace cbbg::plant {

// A robot drawn from its model file's own shapes (a MuJoCo plant's) instead of the two-wheeler
// below: a tree of bodies, each placed on its parent as the file places it at rest and moved
// by its joints. A joint moves with the logged signal it names (the pitch, a wheel, the pose:
// what steps.csv keeps); every other joint stays at rest. Frames are the model's: z up,
// orientations as unit quaternions (w, x, y, z).
struct DrawnJoint {
  enum class Kind { kHinge, kSlide };
  Kind kind = Kind::kHinge;
  std::array<double, 3> axis{0.0, 1.0, 0.0};    // in its body's frame
  std::array<double, 3> anchor{0.0, 0.0, 0.0};  // a point of a hinge's axis, body's frame
  std::string signal;  // the plant signal that logs its angle or position; empty: at rest
  double rest = 0.0;   // the value at which the body sits where the file places it

  bool operator==(const DrawnJoint&) const = default;
};

struct DrawnBody {
  int parent = -1;                                        // an earlier body's index; -1: the ground
  std::array<double, 3> position{0.0, 0.0, 0.0};          // in the parent's frame, at rest
  std::array<double, 4> orientation{1.0, 0.0, 0.0, 0.0};  // in the parent's frame, at rest
  std::vector<DrawnJoint> joints;                         // applied in order, as the model's are

  bool operator==(const DrawnBody&) const = default;
};

struct DrawnShape {
  // A mesh is drawn as the box its model fits to it.
  enum class Kind { kBox, kSphere, kCapsule, kCylinder, kEllipsoid };
  Kind kind = Kind::kBox;
  int body = 0;  // index into ModelDrawing::bodies; -1: fixed to the ground
  // Half-sizes, m: box and ellipsoid (x, y, z); sphere (radius); capsule and cylinder
  // (radius, half-length along its z).
  std::array<double, 3> size{0.0, 0.0, 0.0};
  std::array<double, 3> position{0.0, 0.0, 0.0};          // in its body's frame
  std::array<double, 4> orientation{1.0, 0.0, 0.0, 0.0};  // in its body's frame
  std::array<double, 4> colour{0.5, 0.5, 0.5, 1.0};       // red, green, blue, opacity: 0 to 1

  bool operator==(const DrawnShape&) const = default;
};

struct ModelDrawing {
  std::vector<DrawnBody> bodies;
  std::vector<DrawnShape> shapes;

  bool empty() const { return bodies.empty() && shapes.empty(); }
  bool operator==(const ModelDrawing&) const = default;
};

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
  // A model's own bodies and shapes; when it has any, the page draws them instead of the
  // shapes above.
  ModelDrawing model{};

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
