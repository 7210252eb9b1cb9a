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
      : Block(std::move(name)) {
    const double failure_angle = p.trial.failure_angle;
    const auto& measured = declare_input_port("measured", cbbg::blocks::kMeasuredSize);
    const auto& failed = declare_input_port("failed", 1);
    declare_output_port("reward", 1,
                        [=, &measured, &failed](const cbbg::BlockContext& c, cbbg::VectorRef r) {
                          const double pitch = c.input(measured)[cbbg::blocks::kMeasuredThetaB];
                          r[0] = c.input(failed)[0] > 0.5 ? -1.0 : -std::abs(pitch) / failure_angle;
                        },
                        {&measured, &failed});
  }
};

}  // namespace own_blocks
