#include "cbbg/plant/multibody_robot.h"

#include <cmath>
#include <memory>
#include <stdexcept>

#include <Simbody.h>

#include "cbbg/plant/simbody/robot_model.h"

namespace cbbg::plant {

MultibodyRobot::MultibodyRobot(const RobotParams& params) : params_(params) {
  params_.validate_rigid_bodies();
  model_ = simbody::make_robot_model(params_);
}

MultibodyRobot::~MultibodyRobot() = default;

namespace {

constexpr double kMinimumStepSize = 1e-12;  // s; steps this short mean the run has failed

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
  Integration(const simbody::RobotModel& model, const RobotParams& params)
      : owned(make_integrator(model.system(), params.simbody_integrator)), integrator(*owned) {
    integrator.setAccuracy(params.accuracy);
    integrator.setConstraintTolerance(params.accuracy);
    // Land exactly on each end time: the torque changes there (zero-order hold).
    integrator.setAllowInterpolation(false);
    // A floor for step-size control: on a failed step Simbody shrinks the step and retries,
    // forever once the state has overflowed unless the step may not fall below a floor.
    integrator.setMinimumStepSize(kMinimumStepSize);
  }
  std::unique_ptr<SimTK::Integrator> owned;
  SimTK::Integrator& integrator;
};

MultibodyRobotRun::MultibodyRobotRun(std::shared_ptr<const MultibodyRobot> robot)
    : robot_(std::move(robot)) {
  if (!robot_) throw std::invalid_argument("MultibodyRobotRun: no robot given");
  integration_ = std::make_unique<Integration>(*robot_->model_, robot_->params_);
  integration_->integrator.initialize(robot_->model_->default_state());
}

MultibodyRobotRun::~MultibodyRobotRun() = default;

void MultibodyRobotRun::set_state(double time, const Eigen::Ref<const Eigen::VectorXd>& y) {
  SimTK::State state = integration_->integrator.getState();  // keeps the torques
  state.setTime(time);
  robot_->model_->set_state(state, y);
  integration_->integrator.initialize(state);
}

void MultibodyRobotRun::set_torque(double tau_left, double tau_right) {
  // Written into the integrator's own state: the torques are discrete variables, whose change
  // invalidates the state's cached forces, so the next step's first stage sees them.
  robot_->model_->set_torque(integration_->integrator.updAdvancedState(), tau_left, tau_right);
}

void MultibodyRobotRun::set_disturbance(double force, double pitch_torque) {
  robot_->model_->set_disturbance(integration_->integrator.updAdvancedState(), force, pitch_torque);
}

void MultibodyRobotRun::advance_to(double end_time) {
  SimTK::Integrator& integrator = integration_->integrator;
  // The first call after initialize() returns at once (start of a continuous interval).
  while (integrator.getTime() < end_time) integrator.stepTo(end_time);
}

double MultibodyRobotRun::time() const { return integration_->integrator.getTime(); }

void MultibodyRobotRun::get_state(Eigen::Ref<Eigen::VectorXd> y) const {
  robot_->model_->get_state(integration_->integrator.getState(), y);
}

double MultibodyRobotRun::mechanical_energy() const {
  const SimTK::MultibodySystem& system = robot_->model_->system();
  const SimTK::State& state = integration_->integrator.getState();
  system.realize(state, SimTK::Stage::Dynamics);
  return system.calcEnergy(state);
}

}  // namespace cbbg::plant
