#include "cbbg/plant/simbody/robot_model.h"

#include <memory>

namespace cbbg::plant::simbody {

using SimTK::Vec3;

// The disturbance: (F, tau_ext) held in a discrete variable; F pushes the body's centre of
// mass along the heading (the level base's x axis), tau_ext turns the body about the axle
// (the base's y axis). Nothing is applied while both are zero.
class RobotModel::BodyPush final : public SimTK::Force::Custom::Implementation {
 public:
  BodyPush(const SimTK::GeneralForceSubsystem& forces, const SimTK::MobilizedBody& base,
           const SimTK::MobilizedBody& body, double com_height)
      : forces_(forces),
        matter_(base.getMatterSubsystem()),
        base_(base.getMobilizedBodyIndex()),
        body_(body.getMobilizedBodyIndex()),
        centre_(0, 0, com_height) {}

  void set(SimTK::State& state, double force, double pitch_torque) const {
    forces_.updDiscreteVariable(state, index_).updValue<SimTK::Vec2>() =
        SimTK::Vec2(force, pitch_torque);
  }

  void realizeTopology(SimTK::State& state) const override {
    index_ = forces_.allocateDiscreteVariable(state, SimTK::Stage::Dynamics,
                                              new SimTK::Value<SimTK::Vec2>(SimTK::Vec2(0)));
  }
  void calcForce(const SimTK::State& state, SimTK::Vector_<SimTK::SpatialVec>& body_forces,
                 SimTK::Vector_<Vec3>&, SimTK::Vector&) const override {
    const SimTK::Vec2& push = forces_.getDiscreteVariable(state, index_).getValue<SimTK::Vec2>();
    if (push[0] == 0.0 && push[1] == 0.0) return;
    const SimTK::Rotation& heading = matter_.getMobilizedBody(base_).getBodyRotation(state);
    const SimTK::MobilizedBody& body = matter_.getMobilizedBody(body_);
    body.applyForceToBodyPoint(state, centre_, push[0] * Vec3(heading.x()), body_forces);
    body.applyBodyTorque(state, push[1] * Vec3(heading.y()), body_forces);
  }
  SimTK::Real calcPotentialEnergy(const SimTK::State&) const override { return 0.0; }

 private:
  const SimTK::GeneralForceSubsystem& forces_;
  const SimTK::SimbodyMatterSubsystem& matter_;
  SimTK::MobilizedBodyIndex base_;
  SimTK::MobilizedBodyIndex body_;
  Vec3 centre_;  // in the body's frame, whose z is up when theta_b = 0
  mutable SimTK::DiscreteVariableIndex index_;
};

RobotModel::RobotModel(const RobotParams& params)
    : params_(params), matter_(system_), forces_(system_), motors_(forces_, matter_) {
  // Potential energy zero at axle height, as in plant::mechanical_energy.
  SimTK::Force::Gravity(forces_, matter_, -SimTK::ZAxis, params.gravity, params.wheel_radius);
}

void RobotModel::finish_topology(const SimTK::MobilizedBody& base,
                                 const SimTK::MobilizedBody& body) {
  auto push = std::make_unique<BodyPush>(forces_, base, body, params_.com_height);
  push_ = push.get();
  SimTK::Force::Custom(forces_, push.release());  // the force element owns it
  default_state_ = system_.realizeTopology();
}

void RobotModel::set_disturbance(SimTK::State& state, double force, double pitch_torque) const {
  push_->set(state, force, pitch_torque);
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
