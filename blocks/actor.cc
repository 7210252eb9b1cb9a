#include "cbbg/blocks/actor.h"

#include <stdexcept>
#include <vector>

#include "cbbg/blocks/parameter_checks.h"
#include "cbbg/framework/block_context.h"

namespace cbbg::blocks {
namespace {

// The actions of the previous tick, in the part "previous_actions".
enum PreviousAction : int {
  kSupervisorAction = 0,
  kExplorationAction,
  kActorAction,
  kOmega,
  kPreviousActionsSize
};

}  // namespace

ActorRule parse_actor_rule(std::string_view text) {
  if (text == "improved") return ActorRule::kImproved;
  if (text == "weighted") return ActorRule::kWeighted;
  throw std::invalid_argument("actor.rule must be improved or weighted; got '" + std::string(text) +
                              "'");
}

std::string_view to_string(ActorRule rule) {
  return rule == ActorRule::kWeighted ? "weighted" : "improved";
}

void ActorParams::validate() const { check_declared(*this, kSection); }

Actor::Actor(std::string name, int num_features, const ActorParams& params, double period)
    : Block(std::move(name)), num_features_(num_features), params_(params) {
  if (num_features < 1) {
    throw std::invalid_argument("block '" + path() + "': the actor needs at least 1 feature; got " +
                                std::to_string(num_features));
  }
  params_.validate();
  check_period(period);
  const int n = num_features_;
  features_ = &declare_input_port("features", n, "phi(s_t)");
  td_error_ = &declare_input_port("td_error", 1, "delta_{t-1}");
  supervisor_action_ = &declare_input_port("supervisor_action", 1, "a_S(t)");
  exploration_action_ = &declare_input_port("exploration_action", 1, "a_E(t)");
  omega_ = &declare_input_port("omega", 1, "omega(t)");
  weights_ = declare_discrete_state("weights", Vector::Zero(n), StateLifetime::kPersistent);
  previous_features_ =
      declare_discrete_state("previous_features", Vector::Zero(n), StateLifetime::kPerTrial);
  previous_actions_ = declare_discrete_state("previous_actions", Vector::Zero(kPreviousActionsSize),
                                             StateLifetime::kPerTrial);
  has_previous_ = declare_discrete_state("has_previous", Vector::Zero(1), StateLifetime::kPerTrial);
  action_ = &declare_output_port<&Actor::calc_action>("actor_action", 1, {features_},
                                                      "a_A(t) = theta . phi(s_t)");
  declare_periodic_update<&Actor::learn>(period, 0.0, UpdateWrites::kInPlace);
}

void Actor::calc_action(const BlockContext& context, VectorRef action) const {
  action[0] = weights_.of(context.discrete_state()).dot(context.input(*features_));
}

EventStatus Actor::learn(BlockContext& context, VectorRef next) const {
  const auto state = context.discrete_state();
  if (has_previous_.of(state)[0] != 0.0 && !params_.frozen) {
    const auto previous = previous_actions_.of(state);
    const double delta = context.input(*td_error_)[0];
    const double a_s = previous[kSupervisorAction];
    const double a_e = previous[kExplorationAction];
    const double a_a = previous[kActorAction];
    const double w = previous[kOmega];
    const double alpha = params_.alpha;
    const double step = params_.rule == ActorRule::kImproved
                            ? alpha * delta * (w * (a_e - a_s) + (a_s - a_a))
                            : w * alpha * delta * (a_e - a_a) + (1.0 - w) * alpha * (a_s - a_a);
    weights_.of(next) = weights_.of(state) + step * previous_features_.of(state);
  }
  previous_features_.of(next) = context.input(*features_);
  auto stored = previous_actions_.of(next);
  stored[kSupervisorAction] = context.input(*supervisor_action_)[0];
  stored[kExplorationAction] = context.input(*exploration_action_)[0];
  stored[kActorAction] = context.output(*action_)[0];  // a_A at t, before learning
  stored[kOmega] = context.input(*omega_)[0];
  has_previous_.of(next)[0] = 1.0;
  return EventStatus::succeeded();
}

codegen::CCalculation Actor::c_calculation(int, const Context&) const {
  return {{}, codegen::c_dot("out[0]", "@weights", "in0", num_features_)};
}

ConstVectorView Actor::weights(const Context& context) const {
  return ConstVectorView(context.discrete_state(*this).data() + weights_.offset, weights_.size);
}

VectorView Actor::mutable_weights(Context& context) const {
  return VectorView(context.discrete_state(*this).data() + weights_.offset, weights_.size);
}

codegen::CCalculation Actor::c_update(int, const Context&) const {
  // in0 features, in1 td_error, in2 a_S, in3 a_E, in4 omega; out0 a_A: the update's steps.
  const std::string n = std::to_string(num_features_);
  codegen::CCalculation c;
  c.body = "  int i;\n";
  if (!params_.frozen) {
    c.constants = {codegen::c_number("alpha", params_.alpha)};
    c.body +=
        "  if (@has_previous[0] != 0) {\n    const real delta = in1[0];\n"
        "    const real a_s = @previous_actions[0], a_e = @previous_actions[1];\n"
        "    const real a_a = @previous_actions[2], w = @previous_actions[3];\n";
    c.body += params_.rule == ActorRule::kImproved
                  ? "    const real step = $alpha * delta * (w * (a_e - a_s) + (a_s - a_a));\n"
                  : "    const real step = w * $alpha * delta * (a_e - a_a) + ((real)1 - w) * "
                    "$alpha * (a_s - a_a);\n";
    c.body += "    for (i = 0; i < " + n +
              "; ++i) @@weights[i] = @weights[i] + step * @previous_features[i];\n  }\n";
  }
  c.body += "  for (i = 0; i < " + n + "; ++i) @@previous_features[i] = in0[i];\n" +
            "  @@previous_actions[0] = in2[0];\n  @@previous_actions[1] = in3[0];\n"
            "  @@previous_actions[2] = out0[0];\n  @@previous_actions[3] = in4[0];\n"
            "  @@has_previous[0] = 1;\n";
  return c;
}

}  // namespace cbbg::blocks
