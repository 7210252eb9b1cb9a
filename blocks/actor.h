#pragma once

#include <string>
#include <string_view>

#include "cbbg/blocks/learner.h"
#include "cbbg/codegen/c_calculation.h"
#include "cbbg/framework/block.h"
#include "cbbg/framework/context.h"
#include "cbbg/framework/parameters.h"

namespace cbbg::blocks {

// Config key actor.rule: how the actor's weights learn (docs/model.md §2.11).
enum class ActorRule {
  kImproved,  // "improved": paper eq. 11, the TD error modulates the supervised error too
  kWeighted,  // "weighted": paper eq. 7, Rosenstein & Barto's supervised actor-critic
};

// "improved" or "weighted"; anything else throws naming actor.rule.
ActorRule parse_actor_rule(std::string_view text);
std::string_view to_string(ActorRule rule);

// Config keys actor.*.
struct ActorParams {
  double alpha = 0.1;                     // actor.alpha: learning rate, > 0
  ActorRule rule = ActorRule::kImproved;  // actor.rule
  // Not a config key: a frozen actor acts but never changes theta (the learnt-actor
  // evaluation, ControllerOptions::learning).
  bool frozen = false;

  static constexpr const char* kSection = "actor";
  template <class Archive>
  void describe(Archive& a) {
    a.number("alpha", alpha, "actor learning rate", kPositive);
    a.choice(
        "rule", rule, "improved (paper eq. 11) | weighted (eq. 7)",
        Choices<ActorRule>{{"improved", ActorRule::kImproved}, {"weighted", ActorRule::kWeighted}});
  }
  // Throws naming the key unless alpha is finite and > 0 and rule is one of the two.
  void validate() const;
};

/// Actor: the action network a_A = theta . phi(s) and its learning rule (docs/model.md §2.3,
/// §2.11).
///
/// | port               | dir | size | meaning                                 |
/// |--------------------|-----|------|-----------------------------------------|
/// | features           | in  | n    | phi(s_t)                                |
/// | td_error           | in  | 1    | delta_{t-1}, from the Critic            |
/// | supervisor_action  | in  | 1    | a_S(t), the supervisor's action         |
/// | exploration_action | in  | 1    | a_E(t), the sampler's action            |
/// | omega              | in  | 1    | omega(t), the mixing factor             |
/// | actor_action       | out | 1    | a_A(t) = theta . phi(s_t)               |
///
/// "actor_action" reads only the features, so the mixer's loop through the sampler is not
/// algebraic. The periodic update at tick t learns from the transition s_{t-1} -> s_t with
/// delta = delta_{t-1} and the values it stored at t-1 (phi, a_S, a_E, a_A, omega):
///   improved: theta <- theta + alpha delta [omega (a_E - a_S) + (a_S - a_A)] phi
///             (= alpha delta (a - a_A) phi with a the mixed action);
///   weighted: theta <- theta + omega alpha delta (a_E - a_A) phi
///                            + (1 - omega) alpha (a_S - a_A) phi
///             (the supervised term does not depend on delta);
/// then stores this tick's values. Nothing is learnt on the first tick of a trial. theta
/// starts at 0; a new trial (Context::reset_trial_state) forgets the previous tick and keeps
/// theta. A frozen actor skips the update of theta.
/// Parameters: alpha = actor.alpha, rule = actor.rule, the period trial.period; n is the
/// feature count.
///
/// Discrete state: weights theta (n, persistent); per trial: previous_features phi(s_{t-1})
/// (n), previous_actions (a_S, a_E, a_A, omega at t-1), has_previous (1).
class Actor final : public Block, public Learner, public codegen::EmitsC {
 public:
  Actor(std::string name, int num_features, const ActorParams& params, double period);

  // "actor_action" and the update as C (cbbg export; codegen::EmitsC).
  codegen::CCalculation c_calculation(int output, const Context& context) const override;
  codegen::CCalculation c_update(int update, const Context& context) const override;

  Role learner_role() const override { return Role::kActor; }
  const Block& learner_block() const override { return *this; }
  int num_features() const override { return num_features_; }
  // The learnt weights theta in `context`.
  ConstVectorView weights(const Context& context) const;
  VectorView mutable_weights(Context& context) const;

 private:
  // "actor_action": a_A(t) = theta . phi(s_t).
  void calc_action(const BlockContext& context, VectorRef action) const;
  // The learning rule of the class comment for the last transition, then this tick's values
  // stored for the next one. Writes in place: every part is read before it is written.
  EventStatus learn(BlockContext& context, VectorRef next) const;

  int num_features_;
  ActorParams params_;
  const InputPort* features_;
  const InputPort* td_error_;
  const InputPort* supervisor_action_;
  const InputPort* exploration_action_;
  const InputPort* omega_;
  const OutputPort* action_;
  StatePart weights_;
  StatePart previous_features_;
  StatePart previous_actions_;
  StatePart has_previous_;
};

}  // namespace cbbg::blocks
