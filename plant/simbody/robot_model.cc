#include "cbbg/plant/simbody/robot_model.h"

namespace cbbg::plant::simbody {

using SimTK::Vec3;

RobotModel::RobotModel(const RobotParams& params)
    : params_(params), matter_(system_), forces_(system_), motors_(forces_, matter_) {
  // Potential energy zero at axle height, as in plant::mechanical_energy.
  SimTK::Force::Gravity(forces_, matter_, -SimTK::ZAxis, params.gravity, params.wheel_radius);
}

SimTK::Transform RobotModel::axle_frame(const Vec3& origin) {
  return SimTK::Transform(SimTK::Rotation(-SimTK::Pi / 2, SimTK::XAxis), origin);
}

// MassProperties take the inertia about the body origin (the axle): shift the central one.
SimTK::Body::Rigid RobotModel::body_on_axle(const RobotParams& p) {
  const Vec3 centre(0, 0, p.com_height);
  const SimTK::Inertia central(p.body_roll_inertia, p.body_pitch_inertia, p.body_yaw_inertia);
  return SimTK::Body::Rigid(SimTK::MassProperties(
      p.body_mass, centre, central.shiftFromMassCenter(-centre, p.body_mass)));
}

SimTK::Body::Rigid RobotModel::wheel(const RobotParams& p) {
  return SimTK::Body::Rigid(SimTK::MassProperties(
      p.wheel_mass, Vec3(0),
      SimTK::Inertia(p.wheel_diametral_inertia, p.wheel_inertia, p.wheel_diametral_inertia)));
}

std::unique_ptr<const RobotModel> make_robot_model(const RobotParams& params) {
  switch (params.simbody_model) {
    case SimbodyModel::kNoSlipConstraints:
      return make_no_slip_model(params);
    case SimbodyModel::kRollingBase:
      break;
  }
  return make_rolling_model(params);
}

}  // namespace cbbg::plant::simbody
