#pragma once
// Linear models of the robot about the upright equilibrium (theta_b = 0, at rest, no torque),
// taken from the same equations the analytic plant integrates (robot_dynamics.h).

#include <Eigen/Core>

#include "cbbg/plant/robot_params.h"

namespace cbbg::plant {

// x' = A x + B u.
struct LinearModel {
  Eigen::MatrixXd A;
  Eigen::MatrixXd B;
};

// x = (theta_b, phi_l, phi_r, theta_b', phi_l', phi_r'), u = (tau_l, tau_r).
LinearModel linearize_upright(const RobotParams& params);

// Both wheels driven by one command a (tau_l = tau_r = a), so the robot moves in a straight
// line: x = (theta_b, phi, theta_b', phi') with phi = (phi_l + phi_r) / 2, u = a.
LinearModel linearize_planar_upright(const RobotParams& params);

}  // namespace cbbg::plant
