#include "plant/robot_params.h"

#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>

#include "framework/number_text.h"

namespace cbbg::plant {
namespace {

void require_positive(const char* key, double value) {
  if (!(std::isfinite(value) && value > 0.0)) {
    throw std::invalid_argument(std::string("plant.") + key + " must be positive and finite; got " +
                                format_number(value));
  }
}

void require_non_negative(const char* key, double value) {
  if (!(std::isfinite(value) && value >= 0.0)) {
    throw std::invalid_argument(std::string("plant.") + key +
                                " must be non-negative and finite; got " + format_number(value));
  }
}

}  // namespace

void RobotParams::validate() const {
  require_positive("wheel_mass", wheel_mass);
  require_positive("body_mass", body_mass);
  require_positive("wheel_radius", wheel_radius);
  require_positive("track_width", track_width);
  require_positive("com_height", com_height);
  require_positive("wheel_inertia", wheel_inertia);
  require_positive("body_pitch_inertia", body_pitch_inertia);
  require_positive("body_yaw_inertia", body_yaw_inertia);
  require_positive("body_roll_inertia", body_roll_inertia);
  require_non_negative("wheel_diametral_inertia", wheel_diametral_inertia);
  require_non_negative("gravity", gravity);
  require_non_negative("wheel_ground_friction", wheel_ground_friction);
  require_non_negative("axle_friction", axle_friction);
  require_positive("torque_limit", torque_limit);
  if (!(std::isfinite(accuracy) && accuracy > 0.0 && accuracy < 1.0)) {
    throw std::invalid_argument("plant.accuracy must be in (0, 1); got " + format_number(accuracy));
  }
}

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
