#pragma once
// A linear time-invariant system in state-space form, continuous or discrete time, as
// Drake's LinearSystem: what c2d (discretize.h) and linearize (linearize.h) return.

#include <Eigen/Core>

namespace cbbg::control {

// Continuous time (time_period == 0):  x' = A x + B u,         y = C x + D u.
// Discrete time (time_period > 0):     x[k+1] = A x[k] + B u[k], y[k] = C x[k] + D u[k],
// with x[k] the state at t0 + k time_period.
// Sizes: A n x n, B n x m, C p x n, D p x m (any of n, m, p may be zero).
struct StateSpace {
  Eigen::MatrixXd A;
  Eigen::MatrixXd B;
  Eigen::MatrixXd C;
  Eigen::MatrixXd D;
  double time_period = 0.0;

  bool is_discrete() const { return time_period > 0.0; }
  Eigen::Index num_states() const { return A.rows(); }
  Eigen::Index num_inputs() const { return B.cols(); }
  Eigen::Index num_outputs() const { return C.rows(); }
};

}  // namespace cbbg::control
