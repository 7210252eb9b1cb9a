#include "cbbg/blocks/critic.h"

#include <stdexcept>
#include <string>

#include "cbbg/blocks/parameter_checks.h"

namespace cbbg::blocks {

CriticKind parse_critic_kind(std::string_view text) {
  if (text == "td_lambda") return CriticKind::kTdLambda;
  if (text == "td0") return CriticKind::kTd0;
  throw std::invalid_argument("critic.kind must be td_lambda or td0; got '" + std::string(text) +
                              "'");
}

std::string_view to_string(CriticKind kind) {
  return kind == CriticKind::kTd0 ? "td0" : "td_lambda";
}

void CriticParams::validate() const { check_declared(*this, kSection); }

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
  weights_ = declare_discrete_state("weights", Vector::Zero(n), StateLifetime::kPersistent);
  if (params_.kind == CriticKind::kTdLambda) {
    trace_ = declare_discrete_state("trace", Vector::Zero(n), StateLifetime::kPerTrial);
  }
  previous_features_ =
      declare_discrete_state("previous_features", Vector::Zero(n), StateLifetime::kPerTrial);
  has_previous_ = declare_discrete_state("has_previous", Vector::Zero(1), StateLifetime::kPerTrial);
  declare_output_port<&Critic::calc_value>("value", 1, {features_}, "V(s_t) = w . phi(s_t)");
  td_error_ = &declare_output_port<&Critic::calc_td_error>(
      "td_error", 1, {features_, reward_, failed_}, "delta_{t-1}");
  declare_periodic_update<&Critic::learn>(
      period, 0.0, UpdateWrites::kInPlace);  // every part is read before it is written
}

void Critic::calc_value(const BlockContext& context, VectorRef value) const {
  value[0] = weights_.of(context.discrete_state()).dot(context.input(*features_));
}

void Critic::calc_td_error(const BlockContext& context, VectorRef delta) const {
  delta[0] = td_error(context);
}

EventStatus Critic::learn(BlockContext& context, VectorRef next) const {
  const auto state = context.discrete_state();
  if (has_previous_.of(state)[0] != 0.0 && !params_.frozen) {
    apply_rule(state, next, context.output(*td_error_)[0]);  // delta at this instant
  }
  previous_features_.of(next) = context.input(*features_);
  has_previous_.of(next)[0] = 1.0;
  return EventStatus::succeeded();
}

double Critic::td_error(const BlockContext& context) const {
  const auto state = context.discrete_state();
  if (has_previous_.of(state)[0] == 0.0) return 0.0;
  const auto w = weights_.of(state);
  const bool failed = context.input(*failed_)[0] > 0.5;
  const double next_value = failed ? 0.0 : w.dot(context.input(*features_));
  return context.input(*reward_)[0] + params_.gamma * next_value -
         w.dot(previous_features_.of(state));
}

void Critic::apply_rule(ConstVectorView state, VectorRef next, double delta) const {
  const auto phi = previous_features_.of(state);
  if (params_.kind == CriticKind::kTd0) {
    const double step = params_.beta * delta / (params_.epsilon + phi.squaredNorm());
    weights_.of(next) = weights_.of(state) + step * phi;
    return;
  }
  trace_.of(next) = params_.gamma * params_.lambda * trace_.of(state) + phi;
  weights_.of(next) = weights_.of(state) + params_.beta * delta * trace_.of(next);
}

ConstVectorView Critic::weights(const Context& context) const {
  return ConstVectorView(context.discrete_state(*this).data() + weights_.offset, weights_.size);
}

VectorView Critic::mutable_weights(Context& context) const {
  return VectorView(context.discrete_state(*this).data() + weights_.offset, weights_.size);
}

codegen::CCalculation Critic::c_calculation(int output, const Context&) const {
  const int n = num_features_;
  if (output == 0) return {{}, codegen::c_dot("out[0]", "@weights", "in0", n)};
  // td_error: in0 features, in1 reward, in2 failed, as td_error() computes it.
  codegen::CCalculation c;
  c.constants = {codegen::c_number("gamma", params_.gamma)};
  c.body = "  if (@has_previous[0] == 0) {\n    out[0] = 0;\n  } else {\n" +
           std::string("    real next_value = 0, previous;\n    if (!(in2[0] > 0.5)) {\n") +
           codegen::c_dot("next_value", "@weights", "in0", n) + "    }\n" +
           codegen::c_dot("previous", "@weights", "@previous_features", n) +
           "    out[0] = in1[0] + $gamma * next_value - previous;\n  }\n";
  return c;
}

codegen::CCalculation Critic::c_update(int, const Context&) const {
  // in0 features; out1 td_error, the delta of this instant. The steps of apply_rule().
  const std::string n = std::to_string(num_features_);
  const std::string each = "    for (i = 0; i < " + n + "; ++i) ";
  codegen::CCalculation c;
  c.body = "  int i;\n";
  if (!params_.frozen) {
    c.body += "  if (@has_previous[0] != 0) {\n    const real delta = out1[0];\n";
    if (params_.kind == CriticKind::kTd0) {
      c.constants = {codegen::c_number("beta", params_.beta),
                     codegen::c_number("epsilon", params_.epsilon)};
      c.body +=
          "    real squared, step;\n" +
          codegen::c_dot("squared", "@previous_features", "@previous_features", num_features_) +
          "    step = $beta * delta / ($epsilon + squared);\n" + each +
          "@@weights[i] = @weights[i] + step * @previous_features[i];\n";
    } else {
      c.constants = {codegen::c_number("decay", params_.gamma * params_.lambda),
                     codegen::c_number("beta", params_.beta)};
      c.body += "    const real step = $beta * delta;\n" + each +
                "@@trace[i] = $decay * @trace[i] + @previous_features[i];\n" + each +
                "@@weights[i] = @weights[i] + step * @@trace[i];\n";
    }
    c.body += "  }\n";
  }
  c.body += "  for (i = 0; i < " + n + "; ++i) @@previous_features[i] = in0[i];\n" +
            "  @@has_previous[0] = 1;\n";
  return c;
}

}  // namespace cbbg::blocks
