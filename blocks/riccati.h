#pragma once
// The continuous-time algebraic Riccati equation of linear-quadratic regulation.

#include <Eigen/Core>

namespace cbbg::blocks {

// The stabilising solution X = X' >= 0 of
//   A' X + X A - X B R^-1 B' X + Q = 0,
// so that u = -R^-1 B' X x minimises the integral of x' Q x + u' R u for x' = A x + B u.
// Computed from the stable invariant subspace of the Hamiltonian [[A, -B R^-1 B'],
// [-Q, -A']] and polished by Newton–Kleinman steps. Throws std::invalid_argument when the
// sizes disagree, Q is not symmetric, R is not symmetric positive definite, or no
// stabilising solution exists ((A, B) not stabilisable or (A, Q) with unobservable
// imaginary-axis modes).
Eigen::MatrixXd solve_continuous_riccati(const Eigen::MatrixXd& A, const Eigen::MatrixXd& B,
                                         const Eigen::MatrixXd& Q, const Eigen::MatrixXd& R);

// The residual A' X + X A - X B R^-1 B' X + Q, for checking a solution.
Eigen::MatrixXd riccati_residual(const Eigen::MatrixXd& A, const Eigen::MatrixXd& B,
                                 const Eigen::MatrixXd& Q, const Eigen::MatrixXd& R,
                                 const Eigen::MatrixXd& X);

}  // namespace cbbg::blocks
