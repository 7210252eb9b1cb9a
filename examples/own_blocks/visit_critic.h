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
      : Block(std::move(name)), num_features_(num_features) {
    using cbbg::StateLifetime;
    const double beta = p.critic.beta, gamma = p.critic.gamma;
    const auto& features = declare_input_port("features", num_features);
    const auto& reward = declare_input_port("reward", 1);
    const auto& failed = declare_input_port("failed", 1);
    const cbbg::Vector zeros = cbbg::Vector::Zero(num_features);
    const auto weights = declare_discrete_state("weights", zeros, StateLifetime::kPersistent);
    const auto visits = declare_discrete_state("visits", zeros, StateLifetime::kPersistent);
    const auto previous = declare_discrete_state("previous", zeros, StateLifetime::kPerTrial);
    const auto started =
        declare_discrete_state("started", cbbg::Vector::Zero(1), StateLifetime::kPerTrial);
    auto delta = [=, &features, &reward, &failed](const cbbg::BlockContext& c) {
      const auto x = c.discrete_state();
      if (started.of(x)[0] == 0.0) return 0.0;
      const double next = c.input(failed)[0] > 0.5 ? 0.0 : weights.of(x).dot(c.input(features));
      return c.input(reward)[0] + gamma * next - weights.of(x).dot(previous.of(x));
    };
    declare_output_port("value", 1,
                        [=, &features](const cbbg::BlockContext& c, cbbg::VectorRef v) {
                          v[0] = weights.of(c.discrete_state()).dot(c.input(features));
                        },
                        {&features});
    declare_output_port(
        "td_error", 1, [delta](const cbbg::BlockContext& c, cbbg::VectorRef d) { d[0] = delta(c); },
        {&features, &reward, &failed});
    declare_periodic_update(
        p.trial.period, 0.0, [=, &features](cbbg::BlockContext& c, cbbg::VectorRef next) {
          const auto x = c.discrete_state();
          if (started.of(x)[0] != 0.0 && learns) {
            visits.of(next) = visits.of(x) + previous.of(x);
            weights.of(next) = weights.of(x).array() + beta * delta(c) * previous.of(x).array() /
                                                           (1.0 + visits.of(next).array());
          }
          previous.of(next) = c.input(features);
          started.of(next)[0] = 1.0;
          return cbbg::EventStatus::succeeded();
        });
  }

  Role learner_role() const override { return Role::kCritic; }
  const Block& learner_block() const override { return *this; }
  int num_features() const override { return num_features_; }

 private:
  int num_features_;
};

}  // namespace own_blocks
