#include "cbbg/diagrams/basal_ganglia.h"

#include <limits>
#include <stdexcept>

#include "cbbg/diagrams/controller_slots.h"
#include "cbbg/diagrams/slot_check.h"
#include "cbbg/framework/diagram_builder.h"
#include "cbbg/framework/primitives/constant_source.h"

namespace cbbg::diagrams {
namespace {

// The paper's blocks around `features`.
BasalGangliaBlocks paper_blocks(std::shared_ptr<Block> features, const BasalGangliaParams& params,
                                const std::string& owner) {
  check_slot_block(features.get(), owner, "x", "features");
  const int n = features->output_port("features").size();
  BasalGangliaBlocks blocks;
  blocks.features = std::move(features);
  blocks.critic = std::make_shared<blocks::Critic>("critic", n, params.critic, params.period);
  blocks.actor = std::make_shared<blocks::Actor>("actor", n, params.actor, params.period);
  if (params.exploration) {
    blocks.tropism = std::make_shared<blocks::Tropism>("tropism", params.tropism);
    blocks.exploration =
        std::make_shared<blocks::BoltzmannSampler>("sampler", params.sampler, params.period);
    blocks.entropy = std::make_shared<blocks::Entropy>("entropy", params.entropy);
  }
  return blocks;
}

void check_blocks(const BasalGangliaBlocks& blocks, const std::string& owner) {
  check_slot_block(blocks.features.get(), owner, "x", "features");
  const int n = blocks.features->output_port("features").size();
  check_slot(blocks.critic.get(), critic_contract(n));
  check_slot(blocks.actor.get(), actor_contract(n));
  const int exploring =
      (blocks.tropism != nullptr) + (blocks.exploration != nullptr) + (blocks.entropy != nullptr);
  if (exploring == 0) return;
  if (exploring != 3) {
    throw std::invalid_argument(owner +
                                ": tropism, exploration and entropy come together, or none");
  }
  check_slot(blocks.tropism.get(), tropism_contract());
  check_slot(blocks.exploration.get(), exploration_contract());
  check_slot(blocks.entropy.get(), entropy_contract());
}

// The block's input `name` as the diagram's, if it reads it; else null.
const InputPort* export_if_read(DiagramBuilder& builder, const Block& block, const char* name) {
  const InputPort* input = block.find_input_port(name);
  return input == nullptr ? nullptr : &builder.export_input(*input, name);
}

}  // namespace

BasalGanglia::BasalGanglia(std::string name, std::shared_ptr<Block> features,
                           const BasalGangliaParams& params)
    : BasalGanglia(name,
                   paper_blocks(std::move(features), params, "basal ganglia '" + name + "'")) {}

BasalGanglia::BasalGanglia(std::string name, BasalGangliaBlocks blocks) : Diagram(std::move(name)) {
  check_blocks(blocks, "basal ganglia '" + this->name() + "'");
  DiagramBuilder builder(*this);
  const Block& phi = builder.add(std::move(blocks.features));
  const Block& critic = builder.add(std::move(blocks.critic));
  const Block& actor = builder.add(std::move(blocks.actor));
  critic_ = &critic;
  actor_ = &actor;
  const OutputPort& features = phi.output_port("features");
  const OutputPort& td_error = critic.output_port("td_error");
  connect_if_read(builder, features, critic, "features");
  connect_if_read(builder, features, actor, "features");
  connect_if_read(builder, td_error, actor, "td_error");
  const Exploration exploration = add_exploration(builder, blocks);
  connect_if_read(builder, exploration.action, actor, "exploration_action");

  state_ = &builder.export_input(phi.input_port("x"), "state");
  reward_ = export_if_read(builder, critic, "reward");
  failed_ = export_if_read(builder, critic, "failed");
  supervisor_action_ = export_if_read(builder, actor, "supervisor_action");
  omega_ = export_if_read(builder, actor, "omega");
  actor_action_ = &builder.export_output(actor.output_port("actor_action"), "actor_action");
  exploration_action_ = &builder.export_output(exploration.action, "exploration_action");
  value_ = &builder.export_output(critic.output_port("value"), "value");
  td_error_ = &builder.export_output(td_error, "td_error");
  temperature_ = &builder.export_output(exploration.temperature, "temperature");
  entropy_ = &builder.export_output(exploration.entropy, "entropy");
  builder.build_into();
}

BasalGanglia::Exploration BasalGanglia::add_exploration(DiagramBuilder& builder,
                                                        BasalGangliaBlocks& blocks) {
  const OutputPort& actor_action = actor_->output_port("actor_action");
  if (blocks.exploration == nullptr) {
    // Without exploration there is no temperature: the telemetry shows NaN, not a number.
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const OutputPort& none =
        builder.emplace<ConstantSource>("no_exploration", Vector::Constant(1, nan))
            .output_port("y");
    return {actor_action, none, none};
  }
  const Block& tropism = builder.add(std::move(blocks.tropism));
  const Block& sampler = builder.add(std::move(blocks.exploration));
  const Block& entropy = builder.add(std::move(blocks.entropy));
  tropism_ = &tropism;
  const OutputPort& temperature = tropism.output_port("temperature");
  connect_if_read(builder, critic_->output_port("value"), tropism, "value");
  connect_if_read(builder, actor_action, sampler, "actor_action");
  connect_if_read(builder, temperature, sampler, "temperature");
  connect_if_read(builder, temperature, entropy, "temperature");
  return {sampler.output_port("exploration_action"), temperature, entropy.output_port("entropy")};
}

}  // namespace cbbg::diagrams
