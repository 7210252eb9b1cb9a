#pragma once
// Internal to the plant library and not installed: the robot as a Simbody multibody system,
// in either formulation plant.simbody_model offers, behind MultibodyRobot. It includes
// Simbody, so every file that includes it is compiled with NDEBUG undefined and as C++17
// (see plant/CMakeLists.txt).
//
// Both formulations share the frames (x forward, y to the left, z up), a massless-or-light
// level base moving on the ground in x, y and yaw at axle height R, the body pitching on a
// revolute joint about the axle, gravity, and the motor torques +tau on a wheel and -tau on
// the body. They differ in how rolling without slip is enforced:
// - NoSlipModel: each wheel turns on its own revolute joint and three NoSlip1D constraints
//   hold the contacts (no forward slip at either wheel, no sideways slip of the base);
// - RollingModel: the base's mobilizer is rolling itself (rolling_base_mobilizer.h), so the
//   tree needs no constraint at all.

#include <memory>

#include <Simbody.h>
#include <Eigen/Core>

#include "cbbg/plant/robot_params.h"

namespace cbbg::plant::simbody {

class RobotModel {
 public:
  virtual ~RobotModel() = default;
  RobotModel(const RobotModel&) = delete;
  RobotModel& operator=(const RobotModel&) = delete;

  const SimTK::MultibodySystem& system() const { return system_; }
  // The state realised to Topology, for an integrator to start from.
  const SimTK::State& default_state() const { return default_state_; }

  // Writes `y` (the layout of plant_ports.h) into the state's q and u. The yaw rate and the
  // base's velocity follow from the wheel rates (rolling without slip); y's yaw rate is not read.
  virtual void set_state(SimTK::State& state, const Eigen::Ref<const Eigen::VectorXd>& y) const = 0;
  virtual void get_state(const SimTK::State& state, Eigen::Ref<Eigen::VectorXd> y) const = 0;
  // Held in discrete variables: a change invalidates the cached forces of `state`.
  virtual void set_torque(SimTK::State& state, double tau_left, double tau_right) const = 0;
  // Held in discrete variables too: a horizontal force at the body's centre of mass along the
  // heading, N, and a torque on the body about the axle, N m (plant_ports.h's DisturbanceIndex).
  void set_disturbance(SimTK::State& state, double force, double pitch_torque) const;

 protected:
  explicit RobotModel(const RobotParams& params);
  // Called last by each formulation's constructor, once every body and force is in place:
  // adds the disturbance's force element on `body`, pitching on the level `base`.
  void finish_topology(const SimTK::MobilizedBody& base, const SimTK::MobilizedBody& body);

  // A Pin turns about its frames' common z axis; this rotation takes that axis to the base's
  // y axis (the axle), so a positive pin angle rotates about +y: the body leans forward (+x)
  // and a wheel rolls forward.
  static SimTK::Transform axle_frame(const SimTK::Vec3& origin);
  // The body, with its inertia shifted to the axle (the Pin's origin).
  static SimTK::Body::Rigid body_on_axle(const RobotParams& params);
  static SimTK::Body::Rigid wheel(const RobotParams& params);

  RobotParams params_;
  SimTK::MultibodySystem system_;
  SimTK::SimbodyMatterSubsystem matter_;
  SimTK::GeneralForceSubsystem forces_;
  SimTK::Force::DiscreteForces motors_;

 private:
  class BodyPush;
  const BodyPush* push_ = nullptr;  // owned by its force element in forces_
  SimTK::State default_state_;
};

// The formulation params.simbody_model names.
std::unique_ptr<const RobotModel> make_robot_model(const RobotParams& params);
std::unique_ptr<const RobotModel> make_no_slip_model(const RobotParams& params);
std::unique_ptr<const RobotModel> make_rolling_model(const RobotParams& params);

}  // namespace cbbg::plant::simbody
