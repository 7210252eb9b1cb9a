#include "cbbg/plant/robot_dynamics.h"

#include <algorithm>
#include <cmath>

#include <Eigen/Cholesky>

namespace cbbg::plant {
namespace {

// M L^2 + J_x - J_z: how the yaw inertia about the axle grows with sin^2 theta_b.
double yaw_inertia_growth(const RobotParams& p) {
  return p.body_mass * p.com_height * p.com_height + p.body_roll_inertia - p.body_yaw_inertia;
}

}  // namespace

Eigen::Matrix3d mass_matrix(const RobotParams& p, double theta_b) {
  const double s = std::sin(theta_b);
  const double c = std::cos(theta_b);
  const double rho = p.wheel_radius / p.track_width;
  const double r2 = p.wheel_radius * p.wheel_radius;
  const double yaw_inertia =
      yaw_inertia_growth(p) * s * s + p.body_yaw_inertia + 2.0 * p.wheel_diametral_inertia;
  const double coupling = p.body_mass * p.com_height * p.wheel_radius * c / 2.0;
  const double wheel =
      p.wheel_mass * r2 + p.wheel_inertia + p.body_mass * r2 / 4.0 + rho * rho * yaw_inertia;
  const double cross = p.body_mass * r2 / 4.0 - rho * rho * yaw_inertia;
  Eigen::Matrix3d m;
  m << p.body_mass * p.com_height * p.com_height + p.body_pitch_inertia, coupling, coupling,  //
      coupling, wheel, cross,                                                                 //
      coupling, cross, wheel;
  return m;
}

Coordinates bias_forces(const RobotParams& p, const Coordinates& q, const Coordinates& q_dot) {
  const double s = std::sin(q[0]);
  const double c = std::cos(q[0]);
  const double rho = p.wheel_radius / p.track_width;
  const double theta_dot = q_dot[0];
  const double phi_l_dot = q_dot[1];
  const double phi_r_dot = q_dot[2];
  const double psi_dot = rho * (phi_r_dot - phi_l_dot);
  const double growth = yaw_inertia_growth(p);
  const double mu_w = p.axle_friction;
  const double mu_g = p.wheel_ground_friction;
  const double gyro =
      growth * rho * rho * (phi_l_dot - phi_r_dot) * theta_dot * std::sin(2.0 * q[0]);
  const double pitch_centrifugal =
      p.body_mass * p.com_height * p.wheel_radius / 2.0 * theta_dot * theta_dot * s;
  // Sideways momentum of the leaning body, turned by the yaw rate (rolling constraint forces).
  const double sideways = p.body_mass * p.com_height * p.wheel_radius * rho * s * psi_dot;
  Coordinates n;
  n[0] = -p.body_mass * p.gravity * p.com_height * s - growth * psi_dot * psi_dot * s * c +
         2.0 * mu_w * theta_dot - mu_w * (phi_l_dot + phi_r_dot);
  n[1] = gyro - pitch_centrifugal - sideways * phi_r_dot + (mu_g + mu_w) * phi_l_dot -
         mu_w * theta_dot;
  n[2] = -gyro - pitch_centrifugal + sideways * phi_l_dot + (mu_g + mu_w) * phi_r_dot -
         mu_w * theta_dot;
  return n;
}

Eigen::Matrix<double, 3, 2> torque_input_matrix() {
  Eigen::Matrix<double, 3, 2> e;
  e << -1.0, -1.0,  //
      1.0, 0.0,     //
      0.0, 1.0;
  return e;
}

Coordinates accelerations(const RobotParams& p, const Coordinates& q, const Coordinates& q_dot,
                          const Torques& torque) {
  const Coordinates generalised_force = torque_input_matrix() * torque - bias_forces(p, q, q_dot);
  return mass_matrix(p, q[0]).llt().solve(generalised_force);
}

Coordinates disturbance_forces(const RobotParams& p, double theta_b, double force,
                               double pitch_torque) {
  const double along_heading = force * p.wheel_radius / 2.0;
  return {force * p.com_height * std::cos(theta_b) + pitch_torque, along_heading, along_heading};
}

Coordinates accelerations(const RobotParams& p, const Coordinates& q, const Coordinates& q_dot,
                          const Torques& torque, const Coordinates& external) {
  const Coordinates generalised_force =
      torque_input_matrix() * torque - bias_forces(p, q, q_dot) + external;
  return mass_matrix(p, q[0]).llt().solve(generalised_force);
}

double mechanical_energy(const RobotParams& p, const Coordinates& q, const Coordinates& q_dot) {
  const double kinetic = 0.5 * q_dot.dot(mass_matrix(p, q[0]) * q_dot);
  return kinetic + p.body_mass * p.gravity * p.com_height * std::cos(q[0]);
}

double yaw_rate(const RobotParams& p, double phi_left_dot, double phi_right_dot) {
  return p.wheel_radius * (phi_right_dot - phi_left_dot) / p.track_width;
}

double forward_speed(const RobotParams& p, double phi_left_dot, double phi_right_dot) {
  return p.wheel_radius * (phi_left_dot + phi_right_dot) / 2.0;
}

Torques saturate_torque(const Torques& torque, double limit) {
  return torque.cwiseMax(-limit).cwiseMin(limit);
}

}  // namespace cbbg::plant
