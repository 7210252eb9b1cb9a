#pragma once
// Linear-quadratic regulators, as Drake's LinearQuadraticRegulator and
// DiscreteTimeLinearQuadraticRegulator.

#include <Eigen/Core>

namespace cbbg::control {

// The optimal state feedback u = -K x and the cost-to-go x' S x of its quadratic cost.
struct LqrResult {
  Eigen::MatrixXd K;  // m x n
  Eigen::MatrixXd S;  // n x n, symmetric
};

// For x' = A x + B u minimising the integral of x' Q x + u' R u: S the stabilising solution
// of A' S + S A - S B R^-1 B' S + Q = 0 (solve_continuous_riccati), K = R^-1 B' S, so the
// eigenvalues of A - B K have negative real parts. Throws std::invalid_argument as
// solve_continuous_riccati does.
LqrResult lqr(const Eigen::MatrixXd& A, const Eigen::MatrixXd& B, const Eigen::MatrixXd& Q,
              const Eigen::MatrixXd& R);

// For x[k+1] = A x[k] + B u[k] minimising the sum of x' Q x + u' R u: S the stabilising
// solution of A' S A - S - A' S B (R + B' S B)^-1 B' S A + Q = 0 (solve_discrete_riccati),
// K = (R + B' S B)^-1 B' S A, so the eigenvalues of A - B K lie inside the unit circle.
// Throws std::invalid_argument as solve_discrete_riccati does.
LqrResult discrete_lqr(const Eigen::MatrixXd& A, const Eigen::MatrixXd& B, const Eigen::MatrixXd& Q,
                       const Eigen::MatrixXd& R);

}  // namespace cbbg::control
