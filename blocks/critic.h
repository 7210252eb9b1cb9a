#pragma once

#include <string>
#include <string_view>

#include "cbbg/blocks/learner.h"
#include "cbbg/codegen/c_calculation.h"
#include "cbbg/framework/block.h"
#include "cbbg/framework/block_context.h"
#include "cbbg/framework/context.h"
#include "cbbg/framework/parameters.h"

namespace cbbg::blocks {

// Config key critic.kind: how the critic learns the value function.
enum class CriticKind {
  kTdLambda,  // "td_lambda": the paper's, TD(lambda) with an eligibility trace
  kTd0,       // "td0": normalised TD(0), without a trace
};

// "td_lambda" or "td0"; anything else throws naming critic.kind.
CriticKind parse_critic_kind(std::string_view text);
std::string_view to_string(CriticKind kind);

// Config keys critic.*.
struct CriticParams {
  CriticKind kind = CriticKind::kTdLambda;  // critic.kind
  double beta = 0.1;                        // critic.beta: learning rate, > 0
  double gamma = 0.8;                       // critic.gamma: discount, in (0, 1]
  double lambda = 0.8;                      // critic.lambda: trace decay, in [0, 1)
  double epsilon = 1e-3;                    // critic.epsilon: td0's normalisation floor, > 0
  // Not a config key: a frozen critic computes V and delta but never changes w (the
  // learnt-actor evaluation, ControllerOptions::learning).
  bool frozen = false;

  static constexpr const char* kSection = "critic";
  template <class Archive>
  void describe(Archive& a) {
    a.choice("kind", kind, "td_lambda (the paper's) | td0 (normalised, no trace)",
             Choices<CriticKind>{{"td_lambda", CriticKind::kTdLambda}, {"td0", CriticKind::kTd0}});
    a.number("beta", beta, "critic learning rate", kPositive);
    a.number("gamma", gamma, "discount, in (0, 1]", interval(0.0, 1.0, kOpen, kClosed));
    a.number("lambda", lambda, "eligibility trace decay, in [0, 1)",
             interval(0.0, 1.0, kClosed, kOpen));
    a.number("epsilon", epsilon, "td0: w += beta delta phi / (epsilon + phi . phi)", kPositive);
  }
  // Throws naming the key unless every value is finite and in its range.
  void validate() const;
};

/// Critic: the value function V(s) = w . phi(s), learnt by TD(lambda), the paper's, or by
/// normalised TD(0) (docs/model.md §2.3, §2.10, §5.4).
///
/// | port     | dir | size | meaning                                              |
/// |----------|-----|------|------------------------------------------------------|
/// | features | in  | n    | phi(s_t)                                             |
/// | reward   | in  | 1    | r_{t-1}, the reward of the transition s_{t-1} -> s_t |
/// | failed   | in  | 1    | 1 when s_t is terminal (the trial fails), else 0     |
/// | value    | out | 1    | V(s_t) = w . phi(s_t)                                |
/// | td_error | out | 1    | delta_{t-1}                                          |
///
/// Equations, at tick t, with the weights w before this tick's update:
///   delta_{t-1} = r_{t-1} + gamma V'(s_t) - w . phi(s_{t-1}),
///   V'(s_t) = 0 if failed else w . phi(s_t);  delta = 0 on the first tick of a trial.
/// The periodic update then learns from that transition and remembers phi(s_t):
///   td_lambda: z <- gamma lambda z + phi(s_{t-1});  w <- w + beta delta_{t-1} z;
///   td0:       w <- w + beta delta_{t-1} phi(s_{t-1}) / (epsilon + phi(s_{t-1}) . phi(s_{t-1})).
/// w starts at 0. A new trial (Context::reset_trial_state) clears z and the previous tick and
/// keeps w. A frozen critic skips the update of z and w.
/// Parameters: the rule critic.kind, beta = critic.beta, gamma = critic.gamma, lambda =
/// critic.lambda (td_lambda), epsilon = critic.epsilon (td0), the period trial.period; n is
/// the feature count (RbfFeatures::num_features).
///
/// Discrete state: weights w (n, persistent); per trial: trace z (n, td_lambda only),
/// previous_features phi(s_{t-1}) (n), has_previous (1).
class Critic final : public Block, public Learner, public codegen::EmitsC {
 public:
  Critic(std::string name, int num_features, const CriticParams& params, double period);

  // Its outputs and updates as C (cbbg export; codegen::EmitsC).
  codegen::CCalculation c_calculation(int output, const Context& context) const override;
  codegen::CCalculation c_update(int update, const Context& context) const override;

  Role learner_role() const override { return Role::kCritic; }
  const Block& learner_block() const override { return *this; }
  int num_features() const override { return num_features_; }
  // The learnt weights w in `context`.
  ConstVectorView weights(const Context& context) const;
  VectorView mutable_weights(Context& context) const;

 private:
  // "value": V(s_t) = w . phi(s_t).
  void calc_value(const BlockContext& context, VectorRef value) const;
  // "td_error": delta_{t-1}, as td_error() computes it.
  void calc_td_error(const BlockContext& context, VectorRef delta) const;
  // The periodic update: learns from the last transition (unless frozen), then remembers
  // phi(s_t) for the next one. Writes in place: every part is read before it is written.
  EventStatus learn(BlockContext& context, VectorRef next) const;
  // delta_{t-1} from the context at tick t (0 without a previous tick).
  double td_error(const BlockContext& context) const;
  // The rule's step on w (and z) from the transition s_{t-1} -> s_t, into `next`.
  void apply_rule(ConstVectorView state, VectorRef next, double delta) const;

  int num_features_;
  CriticParams params_;
  StatePart weights_;
  StatePart trace_;
  StatePart previous_features_;
  StatePart has_previous_;
  const InputPort* features_;
  const InputPort* reward_;
  const InputPort* failed_;
  const OutputPort* td_error_;
};

}  // namespace cbbg::blocks
