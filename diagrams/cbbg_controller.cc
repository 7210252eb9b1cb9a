#include "cbbg/diagrams/cbbg_controller.h"

#include <limits>
#include <stdexcept>

#include "cbbg/blocks/lqr_supervisor.h"
#include "cbbg/blocks/mixer.h"
#include "cbbg/blocks/normaliser.h"
#include "cbbg/blocks/pd_supervisor.h"
#include "cbbg/blocks/rbf_features.h"
#include "cbbg/config/parameters.h"
#include "cbbg/diagrams/plant_kinds.h"
#include "cbbg/diagrams/slot_check.h"
#include "cbbg/framework/diagram_builder.h"
#include "cbbg/framework/number_text.h"
#include "cbbg/framework/primitives/constant_source.h"

namespace cbbg::diagrams {
namespace {

std::shared_ptr<Block> configured_supervisor(const std::string& name, const config::Parameters& p) {
  if (p.supervisor.kind == "lqr") {
    return std::make_unique<blocks::LqrSupervisor>(name, planar_linearization(p), p.supervisor.lqr);
  }
  return std::make_unique<blocks::PdSupervisor>(name, p.supervisor.pd);
}

std::shared_ptr<Block> configured_normaliser(const std::string& name, const config::Parameters& p) {
  return std::make_unique<blocks::Normaliser>(name, p.normaliser);
}

std::shared_ptr<Block> configured_features(const std::string& name, const config::Parameters& p) {
  return std::make_unique<blocks::RbfFeatures>(name, p.rbf, p.normaliser.size());
}

// The slot's block: the user's where a factory is given, else the parameters'.
std::shared_ptr<Block> fill_slot(const BlockFactory& user, const BlockFactory& configured,
                                 const std::string& name, const config::Parameters& p) {
  std::shared_ptr<Block> block = user ? user(name, p) : configured(name, p);
  if (!block) throw std::invalid_argument("the factory of slot '" + name + "' returned null");
  return block;
}

const OutputPort& constant(DiagramBuilder& builder, const std::string& name, double value) {
  return builder.emplace<ConstantSource>(name, Vector::Constant(1, value)).output_port("y");
}

BasalGangliaParams basal_ganglia_params(const config::Parameters& p,
                                        const ControllerOptions& options) {
  BasalGangliaParams params;
  params.critic = p.critic;
  params.actor = p.actor;
  if (options.actor_rule) params.actor.rule = *options.actor_rule;
  params.critic.frozen = !options.critic_learns;
  params.actor.frozen = !options.actor_learns;
  params.tropism = p.tropism;
  params.sampler = p.sampler;
  params.entropy = blocks::EntropyParams{p.sampler.k_b};
  params.period = p.trial.period;
  params.exploration = options.exploration;
  return params;
}

// The omega slot's block, or the schedule in the options' mode.
std::shared_ptr<Block> omega_block(const ControllerOptions& options, const config::Parameters& p) {
  if (options.slots.omega) {
    std::shared_ptr<Block> block = options.slots.omega("omega", p);
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

CbbgController::CbbgController(std::string name, const config::Parameters& parameters,
                               const ControllerOptions& options)
    : Diagram(std::move(name)) {
  options.validate();
  DiagramBuilder builder(*this);
  const OutputPort* supervisor_action = nullptr;
  if (options.supervisor) {
    auto& cerebellum = builder.emplace<Cerebellum>(
        "cerebellum",
        fill_slot(options.slots.supervisor, configured_supervisor, "supervisor", parameters));
    cerebellum_ = &cerebellum;
    measured_ = &builder.export_input(cerebellum.measured(), "measured");
    supervisor_action = &cerebellum.action();
  } else {
    supervisor_action = &constant(builder, "no_supervisor", 0.0);
  }
  if (options.basal_ganglia) {
    add_basal_ganglia(builder, parameters, options, *supervisor_action);
  } else {
    add_supervisor_alone(builder, *supervisor_action);
  }
  builder.build_into();
}

void CbbgController::add_basal_ganglia(DiagramBuilder& builder, const config::Parameters& p,
                                       const ControllerOptions& options,
                                       const OutputPort& supervisor_action) {
  const Block& normaliser =
      builder.add(fill_slot(options.slots.normaliser, configured_normaliser, "normaliser", p));
  auto& basal_ganglia = builder.emplace<BasalGanglia>(
      "basal_ganglia", fill_slot(options.slots.features, configured_features, "features", p),
      basal_ganglia_params(p, options));
  const Block& omega = builder.add(omega_block(options, p));
  auto& mixer = builder.emplace<blocks::Mixer>("mixer");
  basal_ganglia_ = &basal_ganglia;

  measured_ = &builder.export_input(normaliser.input_port("measured"), "measured");
  reward_ = &builder.export_input(basal_ganglia.reward());
  failed_ = &builder.export_input(basal_ganglia.failed());
  builder.connect(normaliser.output_port("x"), basal_ganglia.state());
  builder.connect(supervisor_action, basal_ganglia.supervisor_action());
  builder.connect(supervisor_action, mixer.input_port("supervisor_action"));
  builder.connect(omega.output_port("omega"), basal_ganglia.omega());
  builder.connect(omega.output_port("omega"), mixer.input_port("omega"));
  builder.connect(basal_ganglia.exploration_action(), mixer.input_port("exploration_action"));

  builder.export_output(mixer.output_port("action"), "action");
  builder.export_output(supervisor_action, "supervisor_action");
  builder.export_output(basal_ganglia.actor_action(), "actor_action");
  builder.export_output(basal_ganglia.exploration_action(), "exploration_action");
  builder.export_output(omega.output_port("omega"), "omega");
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
