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
      : Block(std::move(name)) {
    const double k_b = p.sampler.k_b;
    const auto& actor_action = declare_input_port("actor_action", 1);
    const auto& temperature = declare_input_port("temperature", 1);
    declare_discrete_state("u", cbbg::Vector::Constant(1, 0.5), cbbg::StateLifetime::kPerTrial);
    declare_output_port(
        "exploration_action", 1,
        [=, &actor_action, &temperature](const cbbg::BlockContext& c, cbbg::VectorRef a) {
          const double width = k_b * c.input(temperature)[0];
          a[0] = c.input(actor_action)[0] + width * (2.0 * c.discrete_state()[0] - 1.0);
        },
        {&actor_action, &temperature});
    const cbbg::UpdateFunction draw = [](cbbg::BlockContext& c, cbbg::VectorRef next) {
      next[0] = cbbg::draw_uniform(c.random_generator());
      return cbbg::EventStatus::succeeded();
    };
    declare_initialization_update(draw);
    declare_periodic_update(p.trial.period, 0.0, draw);
  }
};

}  // namespace own_blocks
