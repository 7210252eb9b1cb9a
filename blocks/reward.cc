#include "cbbg/blocks/reward.h"

#include <stdexcept>
#include <string>

#include "cbbg/blocks/measured_signals.h"
#include "cbbg/blocks/parameter_checks.h"
#include "cbbg/framework/block_context.h"

namespace cbbg::blocks {

RewardKind parse_reward_kind(std::string_view text) {
  if (text == "sliding") return RewardKind::kSliding;
  if (text == "quadratic") return RewardKind::kQuadratic;
  throw std::invalid_argument("reward.kind must be sliding or quadratic; got '" +
                              std::string(text) + "'");
}

std::string_view to_string(RewardKind kind) {
  return kind == RewardKind::kQuadratic ? "quadratic" : "sliding";
}

void RewardParams::validate() const {
  check_declared(*this, kSection);
  if (q.size() != 3) {
    throw std::invalid_argument(
        "reward.q must be a list of 3 numbers (on theta_b^2, theta_b'^2, phi'^2); got a list of " +
        std::to_string(q.size()));
  }
}

Reward::Reward(std::string name, const RewardParams& params, double period)
    : Block(std::move(name)), params_(params) {
  params_.validate();
  check_period(period);
  measured_ = &declare_input_port("measured", kMeasuredSize, "measured signals");
  failed_ = &declare_input_port("failed", 1, "1 when the trial fails");
  previous_surface_ =
      declare_discrete_state("previous_surface", Vector::Zero(1), StateLifetime::kPerTrial);
  has_previous_ = declare_discrete_state("has_previous", Vector::Zero(1), StateLifetime::kPerTrial);
  declare_output_port<&Reward::calc_reward>(
      "reward", 1, {measured_, failed_},
      "r_{t-1}: 0 if s^2 did not grow, -1 if it did or on failure");
  declare_periodic_update<&Reward::remember_surface>(period, 0.0,
                                                     UpdateWrites::kInPlace);  // reads no state
}

void Reward::calc_reward(const BlockContext& context, VectorRef reward) const {
  const auto state = context.discrete_state();
  if (context.input(*failed_)[0] > 0.5) {
    reward[0] = -1.0;
  } else if (has_previous_.of(state)[0] == 0.0) {
    reward[0] = 0.0;
  } else {
    const double s = surface(context);
    const double s_previous = previous_surface_.of(state)[0];
    reward[0] = s * s <= s_previous * s_previous ? 0.0 : -1.0;
  }
}

EventStatus Reward::remember_surface(BlockContext& context, VectorRef next) const {
  previous_surface_.of(next)[0] = surface(context);
  has_previous_.of(next)[0] = 1.0;
  return EventStatus::succeeded();
}

double Reward::surface(const BlockContext& context) const {
  const auto y = context.input(*measured_);
  const double s = params_.a1 * y[kMeasuredThetaB] + params_.a2 * y[kMeasuredThetaBDot];
  if (params_.k_phi == 0.0) return s;  // the paper's surface, bit for bit
  return s + params_.k_phi * (y[kMeasuredPhiLeftDot] + y[kMeasuredPhiRightDot]) / 2.0;
}

// C statements declaring `s`, the sliding surface of the measured signals in0, as surface()
// computes it.
std::string Reward::c_surface(std::vector<codegen::CConstant>& constants) const {
  constants = {codegen::c_number("a1", params_.a1), codegen::c_number("a2", params_.a2)};
  std::string body = "  real s = $a1 * in0[" + std::to_string(kMeasuredThetaB) + "] + $a2 * in0[" +
                     std::to_string(kMeasuredThetaBDot) + "];\n";
  if (params_.k_phi == 0.0) return body;
  constants.push_back(codegen::c_number("k_phi", params_.k_phi));
  return body + "  s = s + $k_phi * (in0[" + std::to_string(kMeasuredPhiLeftDot) + "] + in0[" +
         std::to_string(kMeasuredPhiRightDot) + "]) / (real)2;\n";
}

codegen::CCalculation Reward::c_calculation(int, const Context&) const {
  // in0 measured, in1 failed.
  codegen::CCalculation c;
  c.body = "  if (in1[0] > 0.5) {\n    out[0] = -1;\n  } else if (@has_previous[0] == 0) {\n" +
           std::string("    out[0] = 0;\n  } else {\n") + c_surface(c.constants) +
           "    out[0] = s * s <= @previous_surface[0] * @previous_surface[0] ? 0 : -1;\n  }\n";
  return c;
}

codegen::CCalculation Reward::c_update(int, const Context&) const {
  codegen::CCalculation c;
  c.body = c_surface(c.constants) + "  @@previous_surface[0] = s;\n  @@has_previous[0] = 1;\n";
  return c;
}

}  // namespace cbbg::blocks
