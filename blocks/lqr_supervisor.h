#pragma once

#include <array>
#include <string>

#include <Eigen/Core>

#include "cbbg/codegen/c_calculation.h"
#include "cbbg/framework/block.h"
#include "cbbg/framework/parameters.h"
#include "cbbg/plant/linearization.h"
#include "cbbg/plant/robot_params.h"

namespace cbbg::blocks {

// Config keys supervisor.lqr_* of the LQR supervisor (supervisor.kind: lqr).
struct LqrSupervisorParams {
  // supervisor.lqr_q: diagonal state weights on (theta_b, phi, theta_b', phi'), each >= 0.
  std::array<double, 4> lqr_q{100.0, 1.0, 1.0, 1.0};
  double lqr_r = 1.0;  // supervisor.lqr_r: torque weight, > 0

  static constexpr const char* kSection = "supervisor";
  template <class Archive>
  void describe(Archive& a) {
    a.numbers("lqr_q", lqr_q, "LQR state weights on (theta_b, phi, theta_b', phi')", kNonNegative);
    a.number("lqr_r", lqr_r, "LQR weight on the torque", kPositive);
  }

  // Throws naming the key unless every value is finite and in its range.
  void validate() const;
};

/// LqrSupervisor: a drop-in replacement of PdSupervisor whose gains come from linear-quadratic
/// regulation of the linearised robot instead of from config.
///
/// | port     | dir | size | meaning                                         |
/// |----------|-----|------|-------------------------------------------------|
/// | measured | in  | 6    | the Sensors output (measured_signals.h)          |
/// | action   | out | 1    | a_S, N m, both wheels (the plant saturates it)  |
///
/// Equations: x = (theta_b, phi, theta_b', phi') with phi = (phi_l + phi_r) / 2,
/// a_S = -K x, K = R^-1 B' X, X the stabilising solution of the continuous-time algebraic
/// Riccati equation A' X + X A - X B R^-1 B' X + Q = 0 (control::lqr, framework/control/lqr.h)
/// for the robot linearised upright with both wheels driven alike
/// (plant::linearize_planar_upright, or the linearisation of another plant, 4 states and 1
/// input in that order), Q = diag(q), R = r.
/// K is computed once, at construction.
/// Parameters: the plant's linearisation, q = supervisor.lqr_q, r = supervisor.lqr_r.
class LqrSupervisor final : public Block, public codegen::EmitsC {
 public:
  // Designed for `planar`, a plant linearised as plant::linearize_planar_upright is
  // (x = (theta_b, phi, theta_b', phi'), u = the torque on both wheels): the plant in the loop's
  // (diagrams/plant_kinds.h).
  LqrSupervisor(std::string name, const plant::LinearModel& planar,
                const LqrSupervisorParams& params);
  // Designed for the two-wheeler `robot`.
  LqrSupervisor(std::string name, const plant::RobotParams& robot,
                const LqrSupervisorParams& params);

  // K, 1 x 4, on (theta_b, phi, theta_b', phi').
  const Eigen::RowVector4d& gain() const { return gain_; }

  // a_S = -K x as C, K a constant (cbbg export --omega with supervisor.kind: lqr).
  codegen::CCalculation c_calculation(int output, const Context& context) const override;

 private:
  // "action": a_S = -K x.
  void calc_action(const BlockContext& context, VectorRef action) const;

  Eigen::RowVector4d gain_;
  const InputPort* measured_;
};

}  // namespace cbbg::blocks
