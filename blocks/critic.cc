#include "blocks/critic.h"

#include <stdexcept>

#include "blocks/parameter_checks.h"

namespace cbbg::blocks {

void CriticParams::validate() const {
  check_positive("critic.beta", beta);
  check_in("critic.gamma", gamma, {0.0, false, 1.0, true});
  check_in("critic.lambda", lambda, {0.0, true, 1.0, false});
}

Critic::Critic(std::string name, int num_features, const CriticParams& params, double period)
    : Block(std::move(name)), num_features_(num_features), params_(params) {
  if (num_features < 1) {
    throw std::invalid_argument("block '" + path() +
                                "': the critic needs at least 1 feature; got " +
                                std::to_string(num_features));
  }
  params_.validate();
  check_period(period);
  const int n = num_features_;
  features_ = &declare_input_port("features", n, "phi(s_t)");
  reward_ = &declare_input_port("reward", 1, "r_{t-1}");
  failed_ = &declare_input_port("failed", 1, "1 when s_t is terminal");
  declare_discrete_state(Vector::Zero(3 * n + 1));
  declare_output_port(
      "value", 1,
      [this, n](const BlockContext& context, VectorRef value) {
        value[0] = context.discrete_state().head(n).dot(context.input(*features_));
      },
      {features_}, "V(s_t) = w . phi(s_t)");
  declare_output_port(
      "td_error", 1,
      [this](const BlockContext& context, VectorRef delta) { delta[0] = td_error(context); },
      {features_, reward_, failed_}, "delta_{t-1}");
  declare_periodic_update(period, 0.0, [this, n](BlockContext& context, VectorRef next) {
    const auto state = context.discrete_state();
    if (state[3 * n] != 0.0) {
      const double delta = td_error(context);
      next.segment(n, n) =
          params_.gamma * params_.lambda * state.segment(n, n) + state.segment(2 * n, n);
      next.head(n) = state.head(n) + params_.beta * delta * next.segment(n, n);
    }
    next.segment(2 * n, n) = context.input(*features_);
    next[3 * n] = 1.0;
    return EventStatus::succeeded();
  });
}

double Critic::td_error(const BlockContext& context) const {
  const int n = num_features_;
  const auto state = context.discrete_state();
  if (state[3 * n] == 0.0) return 0.0;
  const auto w = state.head(n);
  const bool failed = context.input(*failed_)[0] > 0.5;
  const double next_value = failed ? 0.0 : w.dot(context.input(*features_));
  return context.input(*reward_)[0] + params_.gamma * next_value - w.dot(state.segment(2 * n, n));
}

void Critic::start_trial(Context& context) const {
  const int n = num_features_;
  auto state = context.discrete_state(*this);
  state.segment(n, 2 * n).setZero();
  state[3 * n] = 0.0;
}

ConstVectorView Critic::weights(const Context& context) const {
  return ConstVectorView(context.discrete_state(*this).data(), num_features_);
}

VectorView Critic::mutable_weights(Context& context) const {
  return VectorView(context.discrete_state(*this).data(), num_features_);
}

}  // namespace cbbg::blocks
