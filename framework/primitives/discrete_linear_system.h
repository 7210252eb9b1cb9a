#pragma once

#include <string>

#include <Eigen/Core>

#include "cbbg/framework/block.h"

namespace cbbg {

/// DiscreteLinearSystem: the discrete-time state-space model, updated every `period` h from
/// `offset` t_0 (t_k = t_0 + k h):
///
///     x_{k+1} = A x_k + B u_k,    y = C x + D u,    x_0 = x0,
///
/// with n >= 1 states, m >= 1 inputs and p >= 1 outputs: A is n x n, B n x m, C p x n and
/// D p x m. u_k is the input at t_k (the value every update at t_k reads, simulator.h step
/// 2); x_{k+1} is held from t_k until t_{k+1}. y is evaluated from the held state and the
/// present input, so with D = 0 it is held too.
///
/// | port | dir | size | meaning   |
/// |------|-----|------|-----------|
/// | u    | in  | m    | the input |
/// | y    | out | p    | C x + D u |
///
/// y reads u directly (direct feedthrough) only when D has a nonzero element; with D = 0 it
/// reads the state alone, so the system can close a feedback loop. x is the discrete-state
/// part "x", StateLifetime::kPerTrial: each trial starts again from x0.
class DiscreteLinearSystem final : public Block {
 public:
  // Throws std::invalid_argument naming the block and the argument unless the sizes agree as
  // above, every element is finite (check_state_space, linear_system.h), the period is
  // positive and finite and the offset finite and >= 0.
  DiscreteLinearSystem(std::string name, const Eigen::MatrixXd& A, const Eigen::MatrixXd& B,
                       const Eigen::MatrixXd& C, const Eigen::MatrixXd& D,
                       const Vector& initial_state, double period, double offset = 0.0);

  const Eigen::MatrixXd& A() const { return A_; }
  const Eigen::MatrixXd& B() const { return B_; }
  const Eigen::MatrixXd& C() const { return C_; }
  const Eigen::MatrixXd& D() const { return D_; }
  // Whether y reads u: D has a nonzero element.
  bool has_direct_feedthrough() const { return feedthrough_; }

 private:
  // "y": C x + D u (C x alone when D = 0).
  void calc_y(const BlockContext& context, VectorRef y) const;
  // x_{k+1} = A x_k + B u_k.
  EventStatus step(BlockContext& context, VectorRef next) const;

  Eigen::MatrixXd A_;
  Eigen::MatrixXd B_;
  Eigen::MatrixXd C_;
  Eigen::MatrixXd D_;
  bool feedthrough_;
  const InputPort* u_;
};

}  // namespace cbbg
