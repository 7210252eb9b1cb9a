#pragma once
// A critic of our own for the critic slot: TD(0) whose step on each feature shrinks with the
// feature mass that feature has seen. It learns two parts, kept across trials and so in
// weights files, task records, resume and evaluations: the weights w and the visits v.
//
//   delta = r + gamma V'(s_t) - w . phi(s_{t-1}),  V'(s_t) = 0 if failed else w . phi(s_t)
//   v <- v + phi(s_{t-1});  w <- w + beta delta phi(s_{t-1}) / (1 + v)   (element by element)

#include <memory>
#include <string>

#include <cbbg/blocks/learner.h>
#include <cbbg/framework/block.h>
#include <cbbg/framework/block_context.h>
#include <cbbg/parameters/parameters.h>

namespace own_blocks {

class VisitCritic final : public cbbg::Block, public cbbg::blocks::Learner {
 public:
  // `learns` false: act, never change w or v (an evaluation of what was learnt).
  VisitCritic(std::string name, int num_features, const cbbg::parameters::Parameters& p,
              bool learns)
      : Block(std::move(name)),
        num_features_(num_features),
        beta_(p.critic.beta),
        gamma_(p.critic.gamma),
        learns_(learns) {
    using cbbg::StateLifetime;
    features_ = &declare_input_port("features", num_features);
    reward_ = &declare_input_port("reward", 1);
    failed_ = &declare_input_port("failed", 1);
    const cbbg::Vector zeros = cbbg::Vector::Zero(num_features);
    weights_ = declare_discrete_state("weights", zeros, StateLifetime::kPersistent);
    visits_ = declare_discrete_state("visits", zeros, StateLifetime::kPersistent);
    previous_ = declare_discrete_state("previous", zeros, StateLifetime::kPerTrial);
    started_ = declare_discrete_state("started", cbbg::Vector::Zero(1), StateLifetime::kPerTrial);
    declare_output_port<&VisitCritic::calc_value>("value", 1, {features_});
    declare_output_port<&VisitCritic::calc_td_error>("td_error", 1, {features_, reward_, failed_});
    declare_periodic_update<&VisitCritic::learn>(p.trial.period, 0.0);
  }

  Role learner_role() const override { return Role::kCritic; }
  const Block& learner_block() const override { return *this; }
  int num_features() const override { return num_features_; }

 private:
  // delta of the header comment for the last transition; 0 before the first.
  double delta(const cbbg::BlockContext& c) const {
    const auto x = c.discrete_state();
    if (started_.of(x)[0] == 0.0) return 0.0;
    const double next = c.input(*failed_)[0] > 0.5 ? 0.0 : weights_.of(x).dot(c.input(*features_));
    return c.input(*reward_)[0] + gamma_ * next - weights_.of(x).dot(previous_.of(x));
  }
  // "value": w . phi(s_t).
  void calc_value(const cbbg::BlockContext& c, cbbg::VectorRef v) const {
    v[0] = weights_.of(c.discrete_state()).dot(c.input(*features_));
  }
  // "td_error": delta.
  void calc_td_error(const cbbg::BlockContext& c, cbbg::VectorRef d) const { d[0] = delta(c); }
  // The rule of the header comment for the last transition (when it learns), then phi(s_t)
  // kept for the next one.
  cbbg::EventStatus learn(cbbg::BlockContext& c, cbbg::VectorRef next) const {
    const auto x = c.discrete_state();
    if (started_.of(x)[0] != 0.0 && learns_) {
      visits_.of(next) = visits_.of(x) + previous_.of(x);
      weights_.of(next) = weights_.of(x).array() + beta_ * delta(c) * previous_.of(x).array() /
                                                       (1.0 + visits_.of(next).array());
    }
    previous_.of(next) = c.input(*features_);
    started_.of(next)[0] = 1.0;
    return cbbg::EventStatus::succeeded();
  }

  int num_features_;
  double beta_;
  double gamma_;
  bool learns_;
  const cbbg::InputPort* features_;
  const cbbg::InputPort* reward_;
  const cbbg::InputPort* failed_;
  cbbg::StatePart weights_;
  cbbg::StatePart visits_;
  cbbg::StatePart previous_;
  cbbg::StatePart started_;
};

}  // namespace own_blocks
