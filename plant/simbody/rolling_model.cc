// The default formulation (plant.simbody_model = rolling): the base rolls on the custom
// mobilizer of rolling_base_mobilizer.h, the body pitches on a revolute joint, and the tree
// has no constraint. It is the same mechanics as NoSlipModel, cheaper to solve: Simbody's
// constrained forward dynamics (G M^-1 G^T, solved at every stage) is most of that model's
// cost.
//
// The base body is the two wheels: their mass, their inertia about a diameter and, as an
// equivalent, their spin. A wheel is axisymmetric, so its spin changes no mass
// distribution: its only part in the dynamics is the kinetic energy J_w phi'^2 / 2,
// with phi' = (v -+ psi' d / 2) / R, and its gyroscopic torque, which is about the heading
// (a roll torque) and is taken by the level base. Summed over both wheels,
//   J_w (phi_l'^2 + phi_r'^2) / 2 = (2 J_w / R^2) v^2 / 2 + (J_w d^2 / (2 R^2)) psi'^2 / 2,
// which is the kinetic energy of a mass 2 J_w / R^2 at the base's origin with a yaw inertia
// J_w d^2 / (2 R^2), which the base body adds to the wheels' own. Forces on a wheel's spin
// act on its wheel rate, the base's generalized speed.

#include <cmath>
#include <stdexcept>

#include "cbbg/plant/plant_ports.h"
#include "cbbg/plant/robot_dynamics.h"
#include "cbbg/plant/simbody/robot_model.h"
#include "cbbg/plant/simbody/rolling_base_mobilizer.h"

namespace cbbg::plant::simbody {
namespace {

using SimTK::MobilizedBody;
using SimTK::MobilizerUIndex;
using SimTK::Vec3;

const MobilizerUIndex kLeftRate(0);
const MobilizerUIndex kRightRate(1);

// Viscous friction, as in NoSlipModel: -mu_l phi' on each wheel's rate against the ground,
// -mu_w (phi' - theta_b') between each wheel and the body.
class WheelFriction final : public SimTK::Force::Custom::Implementation {
 public:
  WheelFriction(const MobilizedBody& base, const MobilizedBody::Pin& body, double ground,
                double axle)
      : base_(base), body_(body), ground_(ground), axle_(axle) {}

  void calcForce(const SimTK::State& state, SimTK::Vector_<SimTK::SpatialVec>&,
                 SimTK::Vector_<Vec3>&, SimTK::Vector& mobility_forces) const override {
    const double theta_dot = body_.getOneU(state, 0);
    require_finite(theta_dot);
    double axle_torque = 0.0;
    for (const MobilizerUIndex rate : {kLeftRate, kRightRate}) {
      const double phi_dot = base_.getOneU(state, rate);
      require_finite(phi_dot);
      const double slip = phi_dot - theta_dot;
      base_.applyOneMobilityForce(state, rate, -ground_ * phi_dot - axle_ * slip, mobility_forces);
      axle_torque += axle_ * slip;
    }
    body_.applyOneMobilityForce(state, 0, axle_torque, mobility_forces);
  }
  SimTK::Real calcPotentialEnergy(const SimTK::State&) const override { return 0.0; }

 private:
  // Without constraints to fail on them, Simbody's error control would halve its step
  // forever once a rate overflows (a NaN error estimate is never too large): stop there.
  static void require_finite(double rate) {
    if (!std::isfinite(rate)) throw std::overflow_error("a wheel or pitch rate overflowed");
  }

  MobilizedBody base_;
  MobilizedBody::Pin body_;
  double ground_;
  double axle_;
};

// The base body: both wheels, at -+d/2 on the axle, with their spin as its equivalent mass
// and yaw inertia (see the top of this file). The base never rolls or pitches, so only its
// mass and its yaw inertia act; its roll and pitch inertias are set equal to the yaw
// inertia, which makes the inertia a rigid body's.
SimTK::Body::Rigid wheels_on_base(const RobotParams& p) {
  const double r2 = p.wheel_radius * p.wheel_radius;
  const double half_track = p.track_width / 2.0;
  const double wheels_yaw =
      2.0 * (p.wheel_diametral_inertia + p.wheel_mass * half_track * half_track);
  const double spin_yaw = p.wheel_inertia * p.track_width * p.track_width / (2.0 * r2);
  const double yaw = wheels_yaw + spin_yaw;
  const double mass = 2.0 * p.wheel_mass + 2.0 * p.wheel_inertia / r2;
  return SimTK::Body::Rigid(SimTK::MassProperties(mass, Vec3(0), SimTK::Inertia(yaw, yaw, yaw)));
}

RollingBaseMobilizer* rolling_mobilizer(SimTK::SimbodyMatterSubsystem& matter,
                                        const RobotParams& p) {
  return new RollingBaseMobilizer(matter, p);  // owned by the mobilized body
}

class RollingModel final : public RobotModel {
 public:
  explicit RollingModel(const RobotParams& p)
      : RobotModel(p),
        mobilizer_(rolling_mobilizer(matter_, p)),
        base_(matter_.Ground(), mobilizer_, SimTK::Transform(Vec3(0, 0, p.wheel_radius)),
              wheels_on_base(p), SimTK::Transform()),
        body_(base_, axle_frame(Vec3(0)), body_on_axle(p), axle_frame(Vec3(0))) {
    mobilizer_->attach(base_.getMobilizedBodyIndex());
    SimTK::Force::Custom(forces_,
                         new WheelFriction(base_, body_, p.wheel_ground_friction, p.axle_friction));
    finish_topology(base_, body_);
  }

  void set_state(SimTK::State& state, const Eigen::Ref<const Eigen::VectorXd>& y) const override {
    SimTK::Vector& q = state.updQ();
    const SimTK::QIndex first = base_.getFirstQIndex(state);
    const double pose[RollingBaseMobilizer::kQ] = {y[kYaw], y[kX], y[kY], y[kPhiLeft],
                                                   y[kPhiRight]};
    for (int i = 0; i < RollingBaseMobilizer::kQ; ++i) q[first + i] = pose[i];
    base_.setOneU(state, kLeftRate, y[kPhiLeftDot]);
    base_.setOneU(state, kRightRate, y[kPhiRightDot]);
    body_.setOneQ(state, 0, y[kThetaB]);
    body_.setOneU(state, 0, y[kThetaBDot]);
  }

  void get_state(const SimTK::State& state, Eigen::Ref<Eigen::VectorXd> y) const override {
    const SimTK::Vector& q = state.getQ();
    const SimTK::QIndex first = base_.getFirstQIndex(state);
    y[kYaw] = q[first];
    y[kX] = q[first + 1];
    y[kY] = q[first + 2];
    y[kPhiLeft] = q[first + 3];
    y[kPhiRight] = q[first + 4];
    y[kPhiLeftDot] = base_.getOneU(state, kLeftRate);
    y[kPhiRightDot] = base_.getOneU(state, kRightRate);
    y[kYawRate] = yaw_rate(params_, y[kPhiLeftDot], y[kPhiRightDot]);
    y[kThetaB] = body_.getOneQ(state, 0);
    y[kThetaBDot] = body_.getOneU(state, 0);
  }

  void set_torque(SimTK::State& state, double tau_left, double tau_right) const override {
    motors_.setOneMobilityForce(state, base_, kLeftRate, tau_left);
    motors_.setOneMobilityForce(state, base_, kRightRate, tau_right);
    motors_.setOneMobilityForce(state, body_, MobilizerUIndex(0), -(tau_left + tau_right));
  }

 private:
  RollingBaseMobilizer* mobilizer_;  // owned by base_
  MobilizedBody::Custom base_;       // q = (yaw, x, y, phi_l, phi_r), u = (phi_l', phi_r')
  MobilizedBody::Pin body_;          // q = theta_b
};

}  // namespace

std::unique_ptr<const RobotModel> make_rolling_model(const RobotParams& params) {
  return std::make_unique<RollingModel>(params);
}

}  // namespace cbbg::plant::simbody
