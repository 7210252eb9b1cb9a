#include "cbbg/plant/robot_params.h"

#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>

#include "cbbg/framework/number_text.h"

namespace cbbg::plant {

void RobotParams::validate() const { check_declared(*this, kSection); }

void RobotParams::validate_rigid_bodies() const {
  validate();
  const double jx = body_roll_inertia;
  const double jy = body_pitch_inertia;
  const double jz = body_yaw_inertia;
  if (jx > jy + jz || jy > jx + jz || jz > jx + jy) {
    throw std::invalid_argument(
        "plant.body_roll_inertia, plant.body_pitch_inertia and plant.body_yaw_inertia (about "
        "the centre of mass) must each be at most the sum of the other two, as for any rigid "
        "body; got " +
        format_number(jx) + ", " + format_number(jy) + ", " + format_number(jz));
  }
  if (2.0 * wheel_diametral_inertia < wheel_inertia) {
    throw std::invalid_argument(
        "plant.wheel_diametral_inertia must be at least half of plant.wheel_inertia, as for "
        "any rigid wheel; got " +
        format_number(wheel_diametral_inertia) +
        " with plant.wheel_inertia = " + format_number(wheel_inertia));
  }
}

}  // namespace cbbg::plant
