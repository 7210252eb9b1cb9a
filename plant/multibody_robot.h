#pragma once
// The robot as a Simbody multibody system (the reference model), with Simbody kept out of
// this header so that code including it needs no special compile flags.
//
// Model (plant/simbody/robot_model.h): a level base moves on the ground in x, y and yaw at
// axle height R; the body pitches on a revolute joint about the axle; each wheel's angle is
// measured from the base (absolute, not relative to the body). Rolling without slip (no
// forward slip at either wheel, no sideways slip) is built into the base's mobilizer
// (plant.simbody_model = rolling, the default) or held by three NoSlip1D constraints on
// wheels that turn on their own joints (constrained, the reference). Gravity; viscous
// friction mu_l phi' (wheel-ground) and mu_w (phi' - theta_b') (axle, between wheel and
// body); motor torques +tau on a wheel and -tau on the body.
//
// MultibodyRobot is built once and only read afterwards; a MultibodyRobotRun holds one
// trajectory's Simbody state and integrator. Runs of one robot must stay in one thread:
// Simbody's System is not safe to realise from two threads at once, even for separate
// States (tried: two threads stepping two runs of one shared System gave results that
// differed from the same runs done one after the other, by up to 4e-6).

#include <memory>

#include <Eigen/Core>

#include "cbbg/plant/robot_params.h"

namespace cbbg::plant {

namespace simbody {
class RobotModel;
}  // namespace simbody

class MultibodyRobot {
 public:
  // Validates `params` with RobotParams::validate_rigid_bodies.
  explicit MultibodyRobot(const RobotParams& params);
  ~MultibodyRobot();
  MultibodyRobot(const MultibodyRobot&) = delete;
  MultibodyRobot& operator=(const MultibodyRobot&) = delete;

  const RobotParams& params() const { return params_; }

 private:
  friend class MultibodyRobotRun;

  RobotParams params_;
  std::unique_ptr<const simbody::RobotModel> model_;
};

// One trajectory of a MultibodyRobot: a Simbody state advanced by the error-controlled
// integrator params().simbody_integrator at params().accuracy, with the motor torques held between
// calls (no interpolation: every advance_to lands exactly on its end time).
class MultibodyRobotRun {
 public:
  // Starts at rest, upright, at the origin, at time zero, with no torque.
  explicit MultibodyRobotRun(std::shared_ptr<const MultibodyRobot> robot);
  MultibodyRobotRun(const MultibodyRobotRun&) = delete;
  MultibodyRobotRun& operator=(const MultibodyRobotRun&) = delete;
  ~MultibodyRobotRun();

  // Puts the robot in `state` (layout of plant_ports.h) at `time`, keeping the torques.
  // The yaw rate and the base's velocity follow from the wheel rates (rolling without
  // slip), so the yaw-rate element is not read.
  void set_state(double time, const Eigen::Ref<const Eigen::VectorXd>& state);
  // Applied as given (saturation is the plant's job) until the next call.
  void set_torque(double tau_left, double tau_right);
  // A push from outside, held likewise: a horizontal force at the body's centre of mass along
  // the heading, N, and a torque on the body about the axle, N m.
  void set_disturbance(double force, double pitch_torque);
  // Integrates to `end_time` (>= time()). Simbody's exceptions pass through.
  void advance_to(double end_time);

  const MultibodyRobot& robot() const { return *robot_; }
  double time() const;
  // The state in the layout of plant_ports.h (10 values).
  void get_state(Eigen::Ref<Eigen::VectorXd> state) const;
  // Simbody's kinetic plus gravitational energy, zero with every mass centre at axle height
  // (the same zero as plant::mechanical_energy).
  double mechanical_energy() const;

 private:
  struct Integration;

  std::shared_ptr<const MultibodyRobot> robot_;
  std::unique_ptr<Integration> integration_;
};

}  // namespace cbbg::plant
