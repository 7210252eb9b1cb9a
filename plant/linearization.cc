#include "cbbg/plant/linearization.h"

#include <functional>

#include "cbbg/plant/robot_dynamics.h"

namespace cbbg::plant {
namespace {

// Central differences: their error is O(h^2) in the model's third derivatives plus
// O(eps / h) rounding; h = 1e-5 keeps both near 1e-10 for this robot.
constexpr double kStep = 1e-5;

using Dynamics = std::function<Eigen::VectorXd(const Eigen::VectorXd& x, const Eigen::VectorXd& u)>;

LinearModel jacobians(const Dynamics& f, int state_size, int input_size) {
  const Eigen::VectorXd x0 = Eigen::VectorXd::Zero(state_size);
  const Eigen::VectorXd u0 = Eigen::VectorXd::Zero(input_size);
  LinearModel model{Eigen::MatrixXd(state_size, state_size),
                    Eigen::MatrixXd(state_size, input_size)};
  for (int j = 0; j < state_size; ++j) {
    const Eigen::VectorXd step = kStep * Eigen::VectorXd::Unit(state_size, j);
    model.A.col(j) = (f(x0 + step, u0) - f(x0 - step, u0)) / (2.0 * kStep);
  }
  for (int j = 0; j < input_size; ++j) {
    const Eigen::VectorXd step = kStep * Eigen::VectorXd::Unit(input_size, j);
    model.B.col(j) = (f(x0, u0 + step) - f(x0, u0 - step)) / (2.0 * kStep);
  }
  return model;
}

}  // namespace

LinearModel linearize_upright(const RobotParams& params) {
  params.validate();
  const Dynamics f = [&params](const Eigen::VectorXd& x, const Eigen::VectorXd& u) {
    const Coordinates q = x.head<3>();
    const Coordinates q_dot = x.tail<3>();
    Eigen::VectorXd x_dot(6);
    x_dot << q_dot, accelerations(params, q, q_dot, Torques(u[0], u[1]));
    return x_dot;
  };
  return jacobians(f, 6, 2);
}

LinearModel linearize_planar_upright(const RobotParams& params) {
  params.validate();
  const Dynamics f = [&params](const Eigen::VectorXd& x, const Eigen::VectorXd& u) {
    const Coordinates q(x[0], x[1], x[1]);
    const Coordinates q_dot(x[2], x[3], x[3]);
    const Coordinates q_ddot = accelerations(params, q, q_dot, Torques(u[0], u[0]));
    Eigen::VectorXd x_dot(4);
    x_dot << x[2], x[3], q_ddot[0], (q_ddot[1] + q_ddot[2]) / 2.0;
    return x_dot;
  };
  return jacobians(f, 4, 1);
}

}  // namespace cbbg::plant
