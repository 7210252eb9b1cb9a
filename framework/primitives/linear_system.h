#pragma once

#include <string>

#include <Eigen/Core>

#include "cbbg/framework/block.h"

namespace cbbg {

/// LinearSystem: the continuous-time state-space model
///
///     x' = A x + B u,    y = C x + D u,    x(0) = x0,
///
/// with n >= 1 states, m >= 1 inputs and p >= 1 outputs: A is n x n, B n x m, C p x n and
/// D p x m. The simulator integrates x with its other continuous state (simulator.h step 3,
/// to its accuracy).
///
/// | port | dir | size | meaning   |
/// |------|-----|------|-----------|
/// | u    | in  | m    | the input |
/// | y    | out | p    | C x + D u |
///
/// y reads u directly (direct feedthrough) only when D has a nonzero element; with D = 0 it
/// reads the state alone, so the system can close a feedback loop through blocks that feed
/// through. x is continuous state: Context::reset_trial_state keeps it, Context::reset_state
/// puts x0 back.
class LinearSystem final : public Block {
 public:
  // Throws std::invalid_argument naming the block and the argument unless the sizes agree as
  // above and every element is finite (check_state_space).
  LinearSystem(std::string name, const Eigen::MatrixXd& A, const Eigen::MatrixXd& B,
               const Eigen::MatrixXd& C, const Eigen::MatrixXd& D, const Vector& initial_state);
  // x0 = 0.
  LinearSystem(std::string name, const Eigen::MatrixXd& A, const Eigen::MatrixXd& B,
               const Eigen::MatrixXd& C, const Eigen::MatrixXd& D);

  const Eigen::MatrixXd& A() const { return A_; }
  const Eigen::MatrixXd& B() const { return B_; }
  const Eigen::MatrixXd& C() const { return C_; }
  const Eigen::MatrixXd& D() const { return D_; }
  // Whether y reads u: D has a nonzero element.
  bool has_direct_feedthrough() const { return feedthrough_; }

 private:
  // x' = A x + B u.
  void calc_derivatives(const BlockContext& context, VectorRef derivatives) const;
  // "y": C x + D u (C x alone when D = 0).
  void calc_y(const BlockContext& context, VectorRef y) const;

  Eigen::MatrixXd A_;
  Eigen::MatrixXd B_;
  Eigen::MatrixXd C_;
  Eigen::MatrixXd D_;
  bool feedthrough_;
  const InputPort* u_;
};

// The checks of LinearSystem and DiscreteLinearSystem: A square with n >= 1 rows, B with n
// rows and m >= 1 columns, C with n columns and p >= 1 rows, D p x m, x0 of size n, every
// element finite. Throws std::invalid_argument "<label>: <what is wrong>; <what is allowed>".
void check_state_space(const std::string& label, const Eigen::MatrixXd& A, const Eigen::MatrixXd& B,
                       const Eigen::MatrixXd& C, const Eigen::MatrixXd& D,
                       const Vector& initial_state);

}  // namespace cbbg
