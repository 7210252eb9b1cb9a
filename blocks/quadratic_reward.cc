#include "cbbg/blocks/quadratic_reward.h"

#include "cbbg/blocks/measured_signals.h"
#include "cbbg/blocks/parameter_checks.h"
#include "cbbg/framework/block_context.h"

namespace cbbg::blocks {

QuadraticReward::QuadraticReward(std::string name, const RewardParams& params, double period)
    : Block(std::move(name)), params_(params) {
  params_.validate();
  check_period(period);
  measured_ = &declare_input_port("measured", kMeasuredSize, "measured signals");
  failed_ = &declare_input_port("failed", 1, "1 when the trial fails");
  declare_output_port<&QuadraticReward::calc_reward>(
      "reward", 1, {measured_, failed_},
      "r_{t-1} = -(q0 theta_b^2 + q1 theta_b'^2 + q2 phi'^2), -1 on failure");
}

void QuadraticReward::calc_reward(const BlockContext& context, VectorRef reward) const {
  if (context.input(*failed_)[0] > 0.5) {
    reward[0] = -1.0;
    return;
  }
  const auto y = context.input(*measured_);
  const double theta = y[kMeasuredThetaB];
  const double theta_dot = y[kMeasuredThetaBDot];
  const double phi_dot = (y[kMeasuredPhiLeftDot] + y[kMeasuredPhiRightDot]) / 2.0;
  const auto& q = params_.q;
  reward[0] = -(q[0] * theta * theta + q[1] * theta_dot * theta_dot + q[2] * phi_dot * phi_dot);
}

codegen::CCalculation QuadraticReward::c_calculation(int, const Context&) const {
  // in0 measured, in1 failed.
  const auto& q = params_.q;
  const auto at = [](int index) { return "in0[" + std::to_string(index) + "]"; };
  return {
      {codegen::c_number("q0", q[0]), codegen::c_number("q1", q[1]), codegen::c_number("q2", q[2])},
      "  if (in1[0] > 0.5) {\n    out[0] = -1;\n  } else {\n    const real theta = " +
          at(kMeasuredThetaB) + ", theta_dot = " + at(kMeasuredThetaBDot) +
          ";\n    const real phi_dot = (" + at(kMeasuredPhiLeftDot) + " + " +
          at(kMeasuredPhiRightDot) +
          ") / (real)2;\n    out[0] = -($q0 * theta * theta + $q1 * theta_dot * theta_dot + "
          "$q2 * phi_dot * phi_dot);\n  }\n"};
}

}  // namespace cbbg::blocks
