#include "cbbg/diagrams/basal_ganglia.h"

#include <limits>

#include "cbbg/diagrams/slot_check.h"
#include "cbbg/framework/diagram_builder.h"
#include "cbbg/framework/primitives/constant_source.h"

namespace cbbg::diagrams {

BasalGanglia::BasalGanglia(std::string name, std::shared_ptr<Block> features,
                           const BasalGangliaParams& params)
    : Diagram(std::move(name)) {
  check_slot_block(features.get(), "basal ganglia '" + this->name() + "'", "x", "features");
  DiagramBuilder builder(*this);
  const Block& phi = builder.add(std::move(features));
  const int n = phi.output_port("features").size();
  auto& critic = builder.emplace<blocks::Critic>("critic", n, params.critic, params.period);
  auto& actor = builder.emplace<blocks::Actor>("actor", n, params.actor, params.period);
  critic_ = &critic;
  actor_ = &actor;
  builder.connect(phi.output_port("features"), critic.input_port("features"));
  builder.connect(phi.output_port("features"), actor.input_port("features"));
  builder.connect(critic.output_port("td_error"), actor.input_port("td_error"));

  const OutputPort* exploration = &actor.output_port("action");
  const OutputPort* temperature = nullptr;
  const OutputPort* entropy = nullptr;
  if (params.exploration) {
    auto& tropism = builder.emplace<blocks::Tropism>("tropism", params.tropism);
    auto& sampler =
        builder.emplace<blocks::BoltzmannSampler>("sampler", params.sampler, params.period);
    auto& entropy_block = builder.emplace<blocks::Entropy>("entropy", params.entropy);
    tropism_ = &tropism;
    builder.connect(critic.output_port("value"), tropism.input_port("value"));
    builder.connect(actor.output_port("action"), sampler.input_port("actor_action"));
    builder.connect(tropism.output_port("temperature"), sampler.input_port("temperature"));
    builder.connect(tropism.output_port("temperature"), entropy_block.input_port("temperature"));
    exploration = &sampler.output_port("action");
    temperature = &tropism.output_port("temperature");
    entropy = &entropy_block.output_port("entropy");
  } else {
    // Without exploration there is no temperature: the telemetry shows NaN, not a number.
    const double nan = std::numeric_limits<double>::quiet_NaN();
    temperature = entropy =
        &builder.emplace<ConstantSource>("no_exploration", Vector::Constant(1, nan))
             .output_port("y");
  }
  builder.connect(*exploration, actor.input_port("exploration_action"));

  state_ = &builder.export_input(phi.input_port("x"), "state");
  reward_ = &builder.export_input(critic.input_port("reward"));
  failed_ = &builder.export_input(critic.input_port("failed"));
  supervisor_action_ = &builder.export_input(actor.input_port("supervisor_action"));
  omega_ = &builder.export_input(actor.input_port("omega"));
  actor_action_ = &builder.export_output(actor.output_port("action"), "actor_action");
  exploration_action_ = &builder.export_output(*exploration, "exploration_action");
  value_ = &builder.export_output(critic.output_port("value"));
  td_error_ = &builder.export_output(critic.output_port("td_error"));
  temperature_ = &builder.export_output(*temperature, "temperature");
  entropy_ = &builder.export_output(*entropy, "entropy");
  builder.build_into();
}

}  // namespace cbbg::diagrams
