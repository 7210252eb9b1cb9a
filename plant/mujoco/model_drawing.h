#pragma once
// A MuJoCo model's drawing for the replay page (plant_drawing.h's ModelDrawing): its bodies
// and the shapes MuJoCo's own viewer shows by default.

#include "cbbg/plant/plant_drawing.h"

struct mjModel_;  // MuJoCo's model (mujoco/mjmodel.h), kept out of this header

namespace cbbg::plant {

// The bodies of `model` (all but the world) and the shapes of its geoms in groups 0 to 2 that
// are seen (opacity above 0); planes and height fields are left to the page's ground. A joint
// follows the signal its jointpos sensor is named; in a model without sensors, a hinge or
// slide joint its own name (as the plant's signals are); the joint `pitch_joint` (an index)
// follows "pitch" if nothing else logs it.
ModelDrawing model_drawing(const mjModel_* model, int pitch_joint);

}  // namespace cbbg::plant
