#pragma once
// The robot's equations of motion (docs/model.md §1), shared by the analytic plant, the
// linearisation and the tests: M(q) q'' + N(q, q') = E T.
//
// q = (theta_b, phi_l, phi_r), T = (tau_l, tau_r), E = [[-1, -1], [1, 0], [0, 1]].
// With s = sin theta_b, c = cos theta_b, rho = R / d, psi' = rho (phi_r' - phi_l'),
// M_eff = M L^2 + J_x - J_z and K = M_eff s^2 + J_z + 2 I_d:
//   m11 = M L^2 + J_y;  m12 = m13 = M L R c / 2
//   m22 = m_l R^2 + J_w + M R^2 / 4 + rho^2 K;  m33 = m_r R^2 + J_w + M R^2 / 4 + rho^2 K
//   m23 = M R^2 / 4 - rho^2 K
//   n1 = -M g L s - M_eff psi'^2 s c + 2 mu_w theta_b' - mu_w (phi_l' + phi_r')
//   n2 = +M_eff rho^2 (phi_l' - phi_r') theta_b' sin(2 theta_b) - (M L R / 2) theta_b'^2 s
//        - M L R rho s psi' phi_r' + (mu_l + mu_w) phi_l' - mu_w theta_b'
//   n3 = -M_eff rho^2 (phi_l' - phi_r') theta_b' sin(2 theta_b) - (M L R / 2) theta_b'^2 s
//        + M L R rho s psi' phi_l' + (mu_r + mu_w) phi_r' - mu_w theta_b'
// K is the yaw inertia about the axle midpoint: the body's J_z c^2 + J_x s^2, its mass's
// M L^2 s^2 and the wheels' diameters' 2 I_d.
//
// Two differences from the paper's equations, both acting only while the robot turns (psi' != 0):
// - the terms -/+ M L R rho s psi' phi' of n2 and n3 come from the sideways momentum of the
//   leaning body, M L s psi', turning with the yaw rate. The no-slip constraints on x and y
//   are not integrable, so substituting them into the Lagrangian (as the paper's derivation does)
//   loses these terms; Lagrange's equations with the constraints (or the Simbody model)
//   keep them. They do no work, so an energy test cannot see them; the turning comparison
//   with the Simbody plant does.
// - J_x and I_d (see RobotParams). With J_x = J_z, I_d = 0 and those two terms removed,
//   these are the paper's equations letter for letter.
//
// The planar pose follows from rolling without slip: forward speed v = R (phi_l' + phi_r') / 2,
// x' = v cos psi, y' = v sin psi, yaw rate psi' as above.

#include <Eigen/Core>

#include "cbbg/plant/robot_params.h"

namespace cbbg::plant {

using Coordinates = Eigen::Vector3d;  // (theta_b, phi_l, phi_r), or their rates
using Torques = Eigen::Vector2d;      // (tau_l, tau_r)

Eigen::Matrix3d mass_matrix(const RobotParams& params, double theta_b);
// N(q, q'): gravity, centrifugal and Coriolis terms, and viscous friction.
Coordinates bias_forces(const RobotParams& params, const Coordinates& q, const Coordinates& q_dot);
// E: how the motor torques enter the three equations.
Eigen::Matrix<double, 3, 2> torque_input_matrix();
// q'' = M(q)^-1 (E T - N(q, q')). T is used as given (saturation is the plant's job).
Coordinates accelerations(const RobotParams& params, const Coordinates& q, const Coordinates& q_dot,
                          const Torques& torque);

// The generalised forces of a horizontal force `force` at the body's centre of mass, along
// the heading, and a torque `pitch_torque` on the body about the axle. By virtual work on the
// centre of mass's travel along the heading, R (phi_l + phi_r) / 2 + L sin theta_b:
//   Q = (F L cos theta_b + tau_ext, F R / 2, F R / 2).
Coordinates disturbance_forces(const RobotParams& params, double theta_b, double force,
                               double pitch_torque);
// The same with `external` generalised forces (disturbance_forces) beside the motors'.
Coordinates accelerations(const RobotParams& params, const Coordinates& q, const Coordinates& q_dot,
                          const Torques& torque, const Coordinates& external);

// Kinetic plus gravitational energy, zero with the body's centre of mass at axle height:
// q'^T M(q) q' / 2 + M g L cos theta_b. Constant when friction and torques are off.
double mechanical_energy(const RobotParams& params, const Coordinates& q, const Coordinates& q_dot);

// psi' = R (phi_r' - phi_l') / d.
double yaw_rate(const RobotParams& params, double phi_left_dot, double phi_right_dot);
// v = R (phi_l' + phi_r') / 2.
double forward_speed(const RobotParams& params, double phi_left_dot, double phi_right_dot);

// Each torque clipped to [-limit, limit].
Torques saturate_torque(const Torques& torque, double limit);

}  // namespace cbbg::plant
