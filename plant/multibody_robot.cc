#include "plant/multibody_robot.h"

#include <cmath>
#include <memory>
#include <stdexcept>

#include <Simbody.h>

#include "plant/plant_ports.h"
#include "plant/robot_dynamics.h"

namespace cbbg::plant {
namespace {

using SimTK::MobilizedBody;
using SimTK::Vec3;

// Frames: x forward, y to the left, z up. A Pin turns about its frames' common z axis; this
// rotation takes that axis to the base's y axis (the axle), so a positive pin angle rotates
// about +y: the body leans forward (+x) and a wheel rolls forward.
SimTK::Transform axle_frame(const Vec3& origin) {
  return SimTK::Transform(SimTK::Rotation(-SimTK::Pi / 2, SimTK::XAxis), origin);
}

// Viscous friction: -mu_l phi' on each wheel against the ground, and -mu_w (phi' - theta_b')
// on each wheel with the opposite torque on the body (the axle bearings).
class ViscousFriction final : public SimTK::Force::Custom::Implementation {
 public:
  ViscousFriction(const MobilizedBody::Pin& body, const MobilizedBody::Pin& wheel_left,
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

}  // namespace

struct MultibodyRobot::Model {
  explicit Model(const RobotParams& p)
      : matter(system),
        forces(system),
        base(matter.Ground(), SimTK::Transform(Vec3(0, 0, p.wheel_radius)), SimTK::Body::Massless(),
             SimTK::Transform()),
        body(base, axle_frame(Vec3(0)), body_mass_properties(p), axle_frame(Vec3(0))),
        wheel_left(base, axle_frame(Vec3(0, p.track_width / 2, 0)), wheel_mass_properties(p),
                   axle_frame(Vec3(0))),
        wheel_right(base, axle_frame(Vec3(0, -p.track_width / 2, 0)), wheel_mass_properties(p),
                    axle_frame(Vec3(0))),
        motors(forces, matter) {
    // Potential energy zero at axle height, as in plant::mechanical_energy.
    SimTK::Force::Gravity(forces, matter, -SimTK::ZAxis, p.gravity, p.wheel_radius);
    SimTK::Force::Custom(forces, new ViscousFriction(body, wheel_left, wheel_right,
                                                     p.wheel_ground_friction, p.axle_friction));
    // No slip: each wheel's material point at its contact has no forward velocity, and the
    // (non-spinning) base has no sideways velocity. A sideways constraint on a spinning wheel
    // would be wrong while turning and moving at once.
    const Vec3 left_contact(0, p.track_width / 2, -p.wheel_radius);
    const Vec3 right_contact(0, -p.track_width / 2, -p.wheel_radius);
    SimTK::Constraint::NoSlip1D(base, left_contact, SimTK::UnitVec3(SimTK::XAxis), matter.Ground(),
                                wheel_left);
    SimTK::Constraint::NoSlip1D(base, right_contact, SimTK::UnitVec3(SimTK::XAxis), matter.Ground(),
                                wheel_right);
    SimTK::Constraint::NoSlip1D(base, Vec3(0, 0, -p.wheel_radius), SimTK::UnitVec3(SimTK::YAxis),
                                matter.Ground(), base);
    default_state = system.realizeTopology();
  }

  // MassProperties take the inertia about the body origin (the axle): shift the central one.
  static SimTK::Body::Rigid body_mass_properties(const RobotParams& p) {
    const Vec3 centre(0, 0, p.com_height);
    const SimTK::Inertia central(p.body_roll_inertia, p.body_pitch_inertia, p.body_yaw_inertia);
    return SimTK::Body::Rigid(SimTK::MassProperties(
        p.body_mass, centre, central.shiftFromMassCenter(-centre, p.body_mass)));
  }
  static SimTK::Body::Rigid wheel_mass_properties(const RobotParams& p) {
    return SimTK::Body::Rigid(SimTK::MassProperties(
        p.wheel_mass, Vec3(0),
        SimTK::Inertia(p.wheel_diametral_inertia, p.wheel_inertia, p.wheel_diametral_inertia)));
  }

  SimTK::MultibodySystem system;
  SimTK::SimbodyMatterSubsystem matter;
  SimTK::GeneralForceSubsystem forces;
  MobilizedBody::Planar base;  // q = (yaw, x, y), u = their rates
  MobilizedBody::Pin body;     // q = theta_b
  MobilizedBody::Pin wheel_left;
  MobilizedBody::Pin wheel_right;
  SimTK::Force::DiscreteForces motors;
  SimTK::State default_state;
};

MultibodyRobot::MultibodyRobot(const RobotParams& params) : params_(params) {
  params_.validate_rigid_bodies();
  model_ = std::make_unique<Model>(params_);
}

MultibodyRobot::~MultibodyRobot() = default;

namespace {

std::unique_ptr<SimTK::Integrator> make_integrator(const SimTK::MultibodySystem& system,
                                                   SimbodyIntegrator kind) {
  switch (kind) {
    case SimbodyIntegrator::kRungeKutta3:
      return std::make_unique<SimTK::RungeKutta3Integrator>(system);
    case SimbodyIntegrator::kVerlet:
      return std::make_unique<SimTK::VerletIntegrator>(system);
    case SimbodyIntegrator::kMerson:
      break;
  }
  return std::make_unique<SimTK::RungeKuttaMersonIntegrator>(system);
}

}  // namespace

struct MultibodyRobotRun::Integration {
  Integration(const MultibodyRobot::Model& model, const RobotParams& params)
      : owned(make_integrator(model.system, params.simbody_integrator)), integrator(*owned) {
    integrator.setAccuracy(params.accuracy);
    integrator.setConstraintTolerance(params.accuracy);
    // Land exactly on each end time: the torque changes there (zero-order hold).
    integrator.setAllowInterpolation(false);
  }
  std::unique_ptr<SimTK::Integrator> owned;
  SimTK::Integrator& integrator;
};

MultibodyRobotRun::MultibodyRobotRun(std::shared_ptr<const MultibodyRobot> robot)
    : robot_(std::move(robot)) {
  if (!robot_) throw std::invalid_argument("MultibodyRobotRun: no robot given");
  integration_ = std::make_unique<Integration>(*robot_->model_, robot_->params_);
  integration_->integrator.initialize(robot_->model_->default_state);
}

MultibodyRobotRun::~MultibodyRobotRun() = default;

void MultibodyRobotRun::set_state(double time, const Eigen::Ref<const Eigen::VectorXd>& y) {
  const MultibodyRobot::Model& model = *robot_->model_;
  const RobotParams& p = robot_->params_;
  SimTK::State state = integration_->integrator.getState();  // keeps the torques
  state.setTime(time);
  const double yaw = y[kYaw];
  const double v = forward_speed(p, y[kPhiLeftDot], y[kPhiRightDot]);
  model.base.setQ(state, Vec3(yaw, y[kX], y[kY]));
  model.base.setU(state, Vec3(yaw_rate(p, y[kPhiLeftDot], y[kPhiRightDot]), v * std::cos(yaw),
                              v * std::sin(yaw)));
  model.body.setOneQ(state, 0, y[kThetaB]);
  model.body.setOneU(state, 0, y[kThetaBDot]);
  model.wheel_left.setOneQ(state, 0, y[kPhiLeft]);
  model.wheel_left.setOneU(state, 0, y[kPhiLeftDot]);
  model.wheel_right.setOneQ(state, 0, y[kPhiRight]);
  model.wheel_right.setOneU(state, 0, y[kPhiRightDot]);
  integration_->integrator.initialize(state);
}

void MultibodyRobotRun::set_torque(double tau_left, double tau_right) {
  const MultibodyRobot::Model& model = *robot_->model_;
  // Written into the integrator's own state: DiscreteForces keeps them in discrete
  // variables, whose change invalidates the state's cached forces, so the next step's first
  // stage sees the new torques.
  SimTK::State& state = integration_->integrator.updAdvancedState();
  model.motors.setOneMobilityForce(state, model.wheel_left, SimTK::MobilizerUIndex(0), tau_left);
  model.motors.setOneMobilityForce(state, model.wheel_right, SimTK::MobilizerUIndex(0), tau_right);
  model.motors.setOneMobilityForce(state, model.body, SimTK::MobilizerUIndex(0),
                                   -(tau_left + tau_right));
}

void MultibodyRobotRun::advance_to(double end_time) {
  SimTK::Integrator& integrator = integration_->integrator;
  // The first call after initialize() returns at once (start of a continuous interval).
  while (integrator.getTime() < end_time) integrator.stepTo(end_time);
}

double MultibodyRobotRun::time() const { return integration_->integrator.getTime(); }

void MultibodyRobotRun::get_state(Eigen::Ref<Eigen::VectorXd> y) const {
  const MultibodyRobot::Model& model = *robot_->model_;
  const SimTK::State& state = integration_->integrator.getState();
  const Vec3& pose = model.base.getQ(state);
  y[kThetaB] = model.body.getOneQ(state, 0);
  y[kThetaBDot] = model.body.getOneU(state, 0);
  y[kPhiLeft] = model.wheel_left.getOneQ(state, 0);
  y[kPhiRight] = model.wheel_right.getOneQ(state, 0);
  y[kPhiLeftDot] = model.wheel_left.getOneU(state, 0);
  y[kPhiRightDot] = model.wheel_right.getOneU(state, 0);
  y[kX] = pose[1];
  y[kY] = pose[2];
  y[kYaw] = pose[0];
  y[kYawRate] = model.base.getU(state)[0];
}

double MultibodyRobotRun::mechanical_energy() const {
  const MultibodyRobot::Model& model = *robot_->model_;
  const SimTK::State& state = integration_->integrator.getState();
  model.system.realize(state, SimTK::Stage::Dynamics);
  return model.system.calcEnergy(state);
}

}  // namespace cbbg::plant
