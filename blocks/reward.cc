#include "blocks/reward.h"

#include "blocks/measured_signals.h"
#include "blocks/parameter_checks.h"
#include "framework/block_context.h"

namespace cbbg::blocks {
namespace {

enum RewardState : int { kPreviousSurface = 0, kHasPrevious, kRewardStateSize };

}  // namespace

void RewardParams::validate() const {
  check_finite("reward.a1", a1);
  check_finite("reward.a2", a2);
}

Reward::Reward(std::string name, const RewardParams& params, double period)
    : Block(std::move(name)), params_(params) {
  params_.validate();
  check_period(period);
  const InputPort& measured = declare_input_port("measured", kMeasuredSize, "measured signals");
  const InputPort& failed = declare_input_port("failed", 1, "1 when the trial fails");
  declare_discrete_state(Vector::Zero(kRewardStateSize));
  auto surface = [this, &measured](const BlockContext& context) {
    const auto y = context.input(measured);
    return params_.a1 * y[kMeasuredThetaB] + params_.a2 * y[kMeasuredThetaBDot];
  };
  declare_output_port(
      "reward", 1,
      [surface, &failed](const BlockContext& context, VectorRef reward) {
        const auto state = context.discrete_state();
        if (context.input(failed)[0] > 0.5) {
          reward[0] = -1.0;
        } else if (state[kHasPrevious] == 0.0) {
          reward[0] = 0.0;
        } else {
          const double s = surface(context);
          const double s_previous = state[kPreviousSurface];
          reward[0] = s * s <= s_previous * s_previous ? 0.0 : -1.0;
        }
      },
      {&measured, &failed}, "r_{t-1}: 0 if s^2 did not grow, -1 if it did or on failure");
  declare_periodic_update(period, 0.0, [surface](BlockContext& context, VectorRef next) {
    next[kPreviousSurface] = surface(context);
    next[kHasPrevious] = 1.0;
    return EventStatus::succeeded();
  });
}

void Reward::start_trial(Context& context) const { context.discrete_state(*this).setZero(); }

}  // namespace cbbg::blocks
