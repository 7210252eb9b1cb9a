#include "cbbg/diagrams/cbbg_controller.h"

#include <limits>
#include <optional>
#include <stdexcept>

#include "cbbg/diagrams/configured_blocks.h"
#include "cbbg/diagrams/slot_check.h"
#include "cbbg/framework/diagram_builder.h"
#include "cbbg/framework/number_text.h"
#include "cbbg/framework/primitives/constant_source.h"
#include "cbbg/parameters/parameters.h"

namespace cbbg::diagrams {
namespace {

const OutputPort& constant(DiagramBuilder& builder, const std::string& name, double value) {
  return builder.emplace<ConstantSource>(name, Vector::Constant(1, value)).output_port("y");
}

// The blocks of the basal ganglia's slots, each the user's or the parameters' own.
BasalGangliaBlocks basal_ganglia_blocks(const parameters::Parameters& p,
                                        const ControllerOptions& options) {
  const ControllerSlots& slots = options.slots;
  BasalGangliaBlocks blocks;
  blocks.features = fill_slot("features", slots.features, configured_features, {"features", p});
  check_slot_block(blocks.features.get(), "features slot", "x", "features");
  const int n = blocks.features->output_port("features").size();
  blocks.critic =
      fill_slot("critic", slots.critic, configured_critic, {"critic", p, n, options.critic_learns});
  blocks.actor =
      fill_slot("actor", slots.actor, configured_actor, {"actor", p, n, options.actor_learns});
  if (options.exploration) {
    blocks.tropism = fill_slot("tropism", slots.tropism, configured_tropism, {"tropism", p});
    blocks.exploration =
        fill_slot("exploration", slots.exploration, configured_exploration, {"sampler", p});
    blocks.entropy = fill_slot("entropy", slots.entropy, configured_entropy, {"entropy", p});
  }
  return blocks;
}

// The run's parameters with the options' own choices (the actor's rule): a copy only when
// the options change something.
const parameters::Parameters& with_options(const parameters::Parameters& p,
                                           const ControllerOptions& options,
                                           std::optional<parameters::Parameters>& adjusted) {
  if (!options.actor_rule) return p;
  adjusted = p;
  adjusted->actor.rule = *options.actor_rule;
  return *adjusted;
}

// The omega slot's block, or the schedule in the options' mode.
std::shared_ptr<Block> omega_block(const ControllerOptions& options,
                                   const parameters::Parameters& p) {
  if (options.slots.omega) {
    std::shared_ptr<Block> block = options.slots.omega({"omega", p});
    check_slot_block(block.get(), "omega slot", nullptr, "omega", 1);
    return block;
  }
  blocks::OmegaParams params = p.omega;
  params.mode = options.omega;
  params.constant = options.omega_constant;
  return std::make_unique<blocks::OmegaSchedule>("omega", params, p.trial.period);
}

}  // namespace

void ControllerOptions::validate() const {
  if (!supervisor && !basal_ganglia) {
    throw std::invalid_argument(
        "controller options: with neither a supervisor nor basal ganglia nothing acts; keep "
        "one of them");
  }
  if (omega == blocks::OmegaMode::kConstant && !(omega_constant >= 0.0 && omega_constant <= 1.0)) {
    throw std::invalid_argument("controller options: omega_constant must be in [0, 1]; got " +
                                format_number(omega_constant));
  }
}

CbbgController::CbbgController(std::string name, const parameters::Parameters& parameters,
                               const ControllerOptions& options)
    : Diagram(std::move(name)) {
  options.validate();
  DiagramBuilder builder(*this);
  const OutputPort* supervisor_action = nullptr;
  if (options.supervisor) {
    auto& cerebellum = builder.emplace<Cerebellum>(
        "cerebellum", fill_slot("supervisor", options.slots.supervisor, configured_supervisor,
                                {"supervisor", parameters}));
    cerebellum_ = &cerebellum;
    measured_ = &builder.export_input(cerebellum.measured(), "measured");
    supervisor_action = &cerebellum.action();
  } else {
    supervisor_action = &constant(builder, "no_supervisor", 0.0);
  }
  if (options.basal_ganglia) {
    std::optional<parameters::Parameters> adjusted;
    add_basal_ganglia(builder, with_options(parameters, options, adjusted), options,
                      *supervisor_action);
  } else {
    add_supervisor_alone(builder, *supervisor_action);
  }
  builder.build_into();
}

void CbbgController::add_basal_ganglia(DiagramBuilder& builder, const parameters::Parameters& p,
                                       const ControllerOptions& options,
                                       const OutputPort& supervisor_action) {
  const Block& normaliser = builder.add(
      fill_slot("normaliser", options.slots.normaliser, configured_normaliser, {"normaliser", p}));
  auto& basal_ganglia =
      builder.emplace<BasalGanglia>("basal_ganglia", basal_ganglia_blocks(p, options));
  const Block& omega = builder.add(omega_block(options, p));
  const Block& mixer =
      builder.add(fill_slot("mixer", options.slots.mixer, configured_mixer, {"mixer", p}));
  check_slot(&mixer, mixer_contract());
  basal_ganglia_ = &basal_ganglia;

  measured_ = &builder.export_input(normaliser.input_port("measured"), "measured");
  if (basal_ganglia.reward() != nullptr) reward_ = &builder.export_input(*basal_ganglia.reward());
  if (basal_ganglia.failed() != nullptr) failed_ = &builder.export_input(*basal_ganglia.failed());
  builder.connect(normaliser.output_port("x"), basal_ganglia.state());
  const OutputPort& omega_value = omega.output_port("omega");
  if (const InputPort* learns_towards = basal_ganglia.supervisor_action()) {
    builder.connect(supervisor_action, *learns_towards);
  }
  connect_if_read(builder, supervisor_action, mixer, "supervisor_action");
  if (const InputPort* mixing = basal_ganglia.omega()) builder.connect(omega_value, *mixing);
  connect_if_read(builder, omega_value, mixer, "omega");
  connect_if_read(builder, basal_ganglia.exploration_action(), mixer, "exploration_action");

  builder.export_output(mixer.output_port("action"), "action");
  builder.export_output(supervisor_action, "supervisor_action");
  builder.export_output(basal_ganglia.actor_action(), "actor_action");
  builder.export_output(basal_ganglia.exploration_action(), "exploration_action");
  builder.export_output(omega_value, "omega");
  builder.export_output(basal_ganglia.value(), "value");
  builder.export_output(basal_ganglia.td_error(), "td_error");
  builder.export_output(basal_ganglia.temperature(), "temperature");
  builder.export_output(basal_ganglia.entropy(), "entropy");
}

void CbbgController::add_supervisor_alone(DiagramBuilder& builder,
                                          const OutputPort& supervisor_action) {
  const OutputPort& no_omega = constant(builder, "no_omega", 0.0);
  const OutputPort& not_learning =
      constant(builder, "not_learning", std::numeric_limits<double>::quiet_NaN());
  builder.export_output(supervisor_action, "action");
  builder.export_output(supervisor_action, "supervisor_action");
  for (const char* name : {"actor_action", "exploration_action"}) {
    builder.export_output(not_learning, name);
  }
  builder.export_output(no_omega, "omega");
  for (const char* name : {"value", "td_error", "temperature", "entropy"}) {
    builder.export_output(not_learning, name);
  }
}

}  // namespace cbbg::diagrams
