#pragma once
// Zero-order-hold discretisation of a continuous-time linear system.

#include <Eigen/Core>

#include "cbbg/framework/control/state_space.h"

namespace cbbg::control {

// The exact discrete-time model of `continuous` (time_period 0) with its input held
// constant over each period h (a zero-order hold, as MATLAB's c2d(sys, h, 'zoh')):
//   Ad = e^(A h),  Bd = (integral from 0 to h of e^(A s) ds) B,  Cd = C,  Dd = D,
// read from the exponential of the augmented matrix [[A, B], [0, 0]] h, whose top row is
// [Ad, Bd]. The result has time_period h. C and D may be empty (0 x 0) for a system
// without outputs. Throws std::invalid_argument when h is not positive and finite, the
// system is already discrete, a value is not finite, or the sizes disagree.
StateSpace c2d(const StateSpace& continuous, double h);

// The same for x' = A x + B u alone: C and D come back with no rows.
StateSpace c2d(const Eigen::MatrixXd& A, const Eigen::MatrixXd& B, double h);

}  // namespace cbbg::control
