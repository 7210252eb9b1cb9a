#pragma once

#include <string>

#include "cbbg/blocks/reward.h"
#include "cbbg/codegen/c_calculation.h"
#include "cbbg/framework/block.h"

namespace cbbg::blocks {

/// QuadraticReward: reward.kind quadratic, a graded reward in place of the paper's sliding
/// surface's 0 or -1 (docs/model.md §5.4).
///
/// | port     | dir | size | meaning                                              |
/// |----------|-----|------|------------------------------------------------------|
/// | measured | in  | 6    | the Sensors output (measured_signals.h)               |
/// | failed   | in  | 1    | 1 when the trial fails at this tick, else 0           |
/// | reward   | out | 1    | r_{t-1}, the reward of the transition s_{t-1} -> s_t  |
///
/// Equation: r_{t-1} = -1 if failed, else -(q0 theta_b^2 + q1 theta_b'^2 + q2 phi'^2) of
/// s_t, phi' = (phi_l' + phi_r') / 2 the wheels' mean rate. It remembers nothing, so it
/// rewards the first tick of a trial too.
/// Parameters: q = reward.q (3 numbers, each >= 0); the period trial.period is checked only.
class QuadraticReward final : public Block, public codegen::EmitsC {
 public:
  QuadraticReward(std::string name, const RewardParams& params, double period);

  // Its reward as C (cbbg export; codegen::EmitsC).
  codegen::CCalculation c_calculation(int output, const Context& context) const override;

 private:
  // "reward": -1 on failure, else -(q0 theta_b^2 + q1 theta_b'^2 + q2 phi'^2).
  void calc_reward(const BlockContext& context, VectorRef reward) const;

  RewardParams params_;
  const InputPort* measured_;
  const InputPort* failed_;
};

}  // namespace cbbg::blocks
