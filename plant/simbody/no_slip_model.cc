// The reference formulation (plant.simbody_model = constrained): a planar base, the body and
// each wheel on its own revolute joint, and rolling without slip as three NoSlip1D
// constraints. Each wheel's angle is measured from the base (absolute, not relative to the
// body).

#include <cmath>

#include "cbbg/plant/plant_ports.h"
#include "cbbg/plant/robot_dynamics.h"
#include "cbbg/plant/simbody/robot_model.h"

namespace cbbg::plant::simbody {
namespace {

using SimTK::MobilizedBody;
using SimTK::Vec3;

// Viscous friction: -mu_l phi' on each wheel against the ground, and -mu_w (phi' - theta_b')
// on each wheel with the opposite torque on the body (the axle bearings).
class WheelFriction final : public SimTK::Force::Custom::Implementation {
 public:
  WheelFriction(const MobilizedBody::Pin& body, const MobilizedBody::Pin& wheel_left,
                const MobilizedBody::Pin& wheel_right, double ground, double axle)
      : body_(body), left_(wheel_left), right_(wheel_right), ground_(ground), axle_(axle) {}

  void calcForce(const SimTK::State& state, SimTK::Vector_<SimTK::SpatialVec>&,
                 SimTK::Vector_<Vec3>&, SimTK::Vector& mobility_forces) const override {
    const double theta_dot = body_.getOneU(state, 0);
    const double left_slip = left_.getOneU(state, 0) - theta_dot;
    const double right_slip = right_.getOneU(state, 0) - theta_dot;
    left_.applyOneMobilityForce(state, 0, -ground_ * left_.getOneU(state, 0) - axle_ * left_slip,
                                mobility_forces);
    right_.applyOneMobilityForce(state, 0, -ground_ * right_.getOneU(state, 0) - axle_ * right_slip,
                                 mobility_forces);
    body_.applyOneMobilityForce(state, 0, axle_ * (left_slip + right_slip), mobility_forces);
  }
  SimTK::Real calcPotentialEnergy(const SimTK::State&) const override { return 0.0; }

 private:
  MobilizedBody::Pin body_;
  MobilizedBody::Pin left_;
  MobilizedBody::Pin right_;
  double ground_;
  double axle_;
};

class NoSlipModel final : public RobotModel {
 public:
  explicit NoSlipModel(const RobotParams& p)
      : RobotModel(p),
        base_(matter_.Ground(), SimTK::Transform(Vec3(0, 0, p.wheel_radius)),
              SimTK::Body::Massless(), SimTK::Transform()),
        body_(base_, axle_frame(Vec3(0)), body_on_axle(p), axle_frame(Vec3(0))),
        wheel_left_(base_, axle_frame(Vec3(0, p.track_width / 2, 0)), wheel(p),
                    axle_frame(Vec3(0))),
        wheel_right_(base_, axle_frame(Vec3(0, -p.track_width / 2, 0)), wheel(p),
                     axle_frame(Vec3(0))) {
    SimTK::Force::Custom(forces_, new WheelFriction(body_, wheel_left_, wheel_right_,
                                                    p.wheel_ground_friction, p.axle_friction));
    // No slip: each wheel's material point at its contact has no forward velocity, and the
    // (non-spinning) base has no sideways velocity. A sideways constraint on a spinning wheel
    // would be wrong while turning and moving at once.
    const Vec3 left_contact(0, p.track_width / 2, -p.wheel_radius);
    const Vec3 right_contact(0, -p.track_width / 2, -p.wheel_radius);
    SimTK::Constraint::NoSlip1D(base_, left_contact, SimTK::UnitVec3(SimTK::XAxis),
                                matter_.Ground(), wheel_left_);
    SimTK::Constraint::NoSlip1D(base_, right_contact, SimTK::UnitVec3(SimTK::XAxis),
                                matter_.Ground(), wheel_right_);
    SimTK::Constraint::NoSlip1D(base_, Vec3(0, 0, -p.wheel_radius), SimTK::UnitVec3(SimTK::YAxis),
                                matter_.Ground(), base_);
    finish_topology(base_, body_);
  }

  void set_state(SimTK::State& state, const Eigen::Ref<const Eigen::VectorXd>& y) const override {
    const double yaw = y[kYaw];
    const double v = forward_speed(params_, y[kPhiLeftDot], y[kPhiRightDot]);
    base_.setQ(state, Vec3(yaw, y[kX], y[kY]));
    base_.setU(state, Vec3(yaw_rate(params_, y[kPhiLeftDot], y[kPhiRightDot]), v * std::cos(yaw),
                           v * std::sin(yaw)));
    body_.setOneQ(state, 0, y[kThetaB]);
    body_.setOneU(state, 0, y[kThetaBDot]);
    wheel_left_.setOneQ(state, 0, y[kPhiLeft]);
    wheel_left_.setOneU(state, 0, y[kPhiLeftDot]);
    wheel_right_.setOneQ(state, 0, y[kPhiRight]);
    wheel_right_.setOneU(state, 0, y[kPhiRightDot]);
  }

  void get_state(const SimTK::State& state, Eigen::Ref<Eigen::VectorXd> y) const override {
    const Vec3& pose = base_.getQ(state);
    y[kThetaB] = body_.getOneQ(state, 0);
    y[kThetaBDot] = body_.getOneU(state, 0);
    y[kPhiLeft] = wheel_left_.getOneQ(state, 0);
    y[kPhiRight] = wheel_right_.getOneQ(state, 0);
    y[kPhiLeftDot] = wheel_left_.getOneU(state, 0);
    y[kPhiRightDot] = wheel_right_.getOneU(state, 0);
    y[kX] = pose[1];
    y[kY] = pose[2];
    y[kYaw] = pose[0];
    y[kYawRate] = base_.getU(state)[0];
  }

  void set_torque(SimTK::State& state, double tau_left, double tau_right) const override {
    const SimTK::MobilizerUIndex spin(0);
    motors_.setOneMobilityForce(state, wheel_left_, spin, tau_left);
    motors_.setOneMobilityForce(state, wheel_right_, spin, tau_right);
    motors_.setOneMobilityForce(state, body_, spin, -(tau_left + tau_right));
  }

 private:
  MobilizedBody::Planar base_;  // q = (yaw, x, y), u = their rates
  MobilizedBody::Pin body_;     // q = theta_b
  MobilizedBody::Pin wheel_left_;
  MobilizedBody::Pin wheel_right_;
};

}  // namespace

std::unique_ptr<const RobotModel> make_no_slip_model(const RobotParams& params) {
  return std::make_unique<NoSlipModel>(params);
}

}  // namespace cbbg::plant::simbody
