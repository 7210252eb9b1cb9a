#pragma once
// Algebraic Riccati equations of linear-quadratic regulation, continuous and discrete time.

#include <Eigen/Core>

namespace cbbg::control {

// The stabilising solution X = X' >= 0 of the continuous-time algebraic Riccati equation
//   A' X + X A - X B R^-1 B' X + Q = 0,
// so that u = -R^-1 B' X x minimises the integral of x' Q x + u' R u for x' = A x + B u.
// Computed from the stable invariant subspace of the Hamiltonian [[A, -B R^-1 B'],
// [-Q, -A']] and polished by Newton–Kleinman steps. Throws std::invalid_argument when the
// sizes disagree, a value is not finite, Q is not symmetric, R is not symmetric positive
// definite, or no stabilising solution exists ((A, B) not stabilisable or (A, Q) with
// unobservable imaginary-axis modes).
Eigen::MatrixXd solve_continuous_riccati(const Eigen::MatrixXd& A, const Eigen::MatrixXd& B,
                                         const Eigen::MatrixXd& Q, const Eigen::MatrixXd& R);

// The stabilising solution X = X' >= 0 of the discrete-time algebraic Riccati equation
//   A' X A - X - A' X B (R + B' X B)^-1 B' X A + Q = 0,
// so that u[k] = -(R + B' X B)^-1 B' X A x[k] minimises the sum of x' Q x + u' R u for
// x[k+1] = A x[k] + B u[k]. Computed by the structured doubling algorithm (Chu, Fan, Lin,
// 2005), which needs no inverse of A, and polished by Newton–Hewer steps. Throws
// std::invalid_argument as solve_continuous_riccati does; here no stabilising solution
// means (A, B) not stabilisable or (A, Q) with unobservable modes on the unit circle.
Eigen::MatrixXd solve_discrete_riccati(const Eigen::MatrixXd& A, const Eigen::MatrixXd& B,
                                       const Eigen::MatrixXd& Q, const Eigen::MatrixXd& R);

// A' X + X A - X B R^-1 B' X + Q, zero at a solution of the continuous equation.
Eigen::MatrixXd continuous_riccati_residual(const Eigen::MatrixXd& A, const Eigen::MatrixXd& B,
                                            const Eigen::MatrixXd& Q, const Eigen::MatrixXd& R,
                                            const Eigen::MatrixXd& X);

// A' X A - X - A' X B (R + B' X B)^-1 B' X A + Q, zero at a solution of the discrete
// equation.
Eigen::MatrixXd discrete_riccati_residual(const Eigen::MatrixXd& A, const Eigen::MatrixXd& B,
                                          const Eigen::MatrixXd& Q, const Eigen::MatrixXd& R,
                                          const Eigen::MatrixXd& X);

}  // namespace cbbg::control
