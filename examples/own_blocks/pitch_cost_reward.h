#pragma once
// A reward of our own for the task's reward slot: the pitch's share of the failure angle,
// as a cost, r = -|theta_b| / failure_angle (in [-1, 0]), and -1 when the trial fails.

#include <cmath>
#include <string>

#include <cbbg/blocks/measured_signals.h>
#include <cbbg/framework/block.h>
#include <cbbg/framework/block_context.h>
#include <cbbg/parameters/parameters.h>

namespace own_blocks {

class PitchCostReward final : public cbbg::Block {
 public:
  PitchCostReward(std::string name, const cbbg::parameters::Parameters& p)
      : Block(std::move(name)), failure_angle_(p.trial.failure_angle) {
    measured_ = &declare_input_port("measured", cbbg::blocks::kMeasuredSize);
    failed_ = &declare_input_port("failed", 1);
    declare_output_port<&PitchCostReward::calc_reward>("reward", 1, {measured_, failed_});
  }

 private:
  // "reward": -1 when the trial fails, else -|theta_b| / failure_angle.
  void calc_reward(const cbbg::BlockContext& c, cbbg::VectorRef r) const {
    const double pitch = c.input(*measured_)[cbbg::blocks::kMeasuredThetaB];
    r[0] = c.input(*failed_)[0] > 0.5 ? -1.0 : -std::abs(pitch) / failure_angle_;
  }

  double failure_angle_;
  const cbbg::InputPort* measured_;
  const cbbg::InputPort* failed_;
};

}  // namespace own_blocks
