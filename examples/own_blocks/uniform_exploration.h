#pragma once
// An exploration of our own for the exploration slot: the actor's action plus uniform noise,
// a_E = a_A + w (2u - 1), u ~ U(0, 1), w = sampler.k_b times the temperature. It draws one
// number per tick from its own generator (seeded from its path, "sampler"), so arms that
// differ elsewhere draw the same u's: common random numbers.

#include <cmath>
#include <string>

#include <cbbg/framework/block.h>
#include <cbbg/framework/block_context.h>
#include <cbbg/framework/random.h>
#include <cbbg/parameters/parameters.h>

namespace own_blocks {

class UniformExploration final : public cbbg::Block {
 public:
  UniformExploration(std::string name, const cbbg::parameters::Parameters& p)
      : Block(std::move(name)), k_b_(p.sampler.k_b) {
    actor_action_ = &declare_input_port("actor_action", 1);
    temperature_ = &declare_input_port("temperature", 1);
    declare_discrete_state("u", cbbg::Vector::Constant(1, 0.5), cbbg::StateLifetime::kPerTrial);
    declare_output_port<&UniformExploration::calc_exploration_action>(
        "exploration_action", 1, {actor_action_, temperature_});
    declare_initialization_update<&UniformExploration::draw>();
    declare_periodic_update<&UniformExploration::draw>(p.trial.period, 0.0);
  }

 private:
  // "exploration_action": a_A + w (2u - 1), the u of the last draw.
  void calc_exploration_action(const cbbg::BlockContext& c, cbbg::VectorRef a) const {
    const double width = k_b_ * c.input(*temperature_)[0];
    a[0] = c.input(*actor_action_)[0] + width * (2.0 * c.discrete_state()[0] - 1.0);
  }
  // A new u from the block's own generator: at the start and at every tick.
  cbbg::EventStatus draw(cbbg::BlockContext& c, cbbg::VectorRef next) const {
    next[0] = cbbg::draw_uniform(c.random_generator());
    return cbbg::EventStatus::succeeded();
  }

  double k_b_;
  const cbbg::InputPort* actor_action_;
  const cbbg::InputPort* temperature_;
};

}  // namespace own_blocks
