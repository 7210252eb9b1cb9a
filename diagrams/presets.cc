#include "cbbg/diagrams/presets.h"

#include <stdexcept>

namespace cbbg::diagrams {
namespace {

ControllerOptions cbbg_options() { return {}; }

ControllerOptions with_rule(blocks::ActorRule rule) {
  ControllerOptions options;
  options.actor_rule = rule;
  return options;
}

ControllerOptions basal_ganglia_only() {
  ControllerOptions options;
  options.supervisor = false;
  options.omega = blocks::OmegaMode::kOne;
  return options;
}

ControllerOptions cerebellum_drives() {
  ControllerOptions options;
  options.omega = blocks::OmegaMode::kZero;
  return options;
}

ControllerOptions supervisor_alone() {
  ControllerOptions options;
  options.basal_ganglia = false;
  options.omega = blocks::OmegaMode::kZero;
  return options;
}

std::vector<Preset> make_presets() {
  return {
      {"cbbg", "cerebellum + basal ganglia: omega rises from 0 to 1 (docs/model.md §2.7)",
       cbbg_options()},
      {"cbbg_weighted", "as cbbg, with the weighted actor rule (paper eq. 7)",
       with_rule(blocks::ActorRule::kWeighted)},
      {"bg_only", "basal ganglia alone: omega = 1, no supervisor (the traditional actor-critic)",
       basal_ganglia_only()},
      {"cb_only", "omega = 0: the supervisor drives, the actor learns from it alone",
       cerebellum_drives()},
      {"pd_only", "the supervisor alone, no learning", supervisor_alone()},
      {kLearntActor,
       "a learnt actor alone: omega = 1, no exploration, no supervisor, frozen (evaluation)",
       learnt_actor(cbbg_options())},
  };
}

}  // namespace

const std::vector<Preset>& presets() {
  static const std::vector<Preset> table = make_presets();
  return table;
}

std::vector<std::string> arm_names() {
  std::vector<std::string> names;
  for (const auto& row : presets()) {
    if (row.name != kLearntActor) names.push_back(row.name);
  }
  for (const ArmName& registered : registered_arms()) names.push_back(registered.name);
  return names;
}

std::vector<std::string> diagram_names() {
  std::vector<std::string> names;
  for (const auto& row : presets()) names.push_back(row.name);
  for (const ArmName& registered : registered_arms()) names.push_back(registered.name);
  return names;
}

const Preset& preset(std::string_view name) {
  std::string known;
  for (const auto& row : presets()) {
    if (row.name == name) return row;
    known += (known.empty() ? "" : ", ") + row.name;
  }
  throw std::invalid_argument("unknown diagram '" + std::string(name) + "'; the presets are " +
                              known);
}

ControllerOptions learnt_actor(ControllerOptions options) {
  options.supervisor = false;
  options.basal_ganglia = true;
  options.omega = blocks::OmegaMode::kOne;
  options.critic_learns = options.actor_learns = false;
  options.exploration = false;
  options.slots.omega = {};  // a user's omega would not be 1
  return options;
}

ClosedLoop build_preset(std::string_view name, const parameters::Parameters& parameters,
                        const ClosedLoopOptions& loop) {
  return closed_loop_factory(std::string(name), preset(name).options, loop)(parameters);
}

Arm make_arm(std::string name, const ControllerOptions& options, const ClosedLoopOptions& loop) {
  Arm arm;
  arm.learner = closed_loop_factory(name, options, loop);
  if (options.basal_ganglia) {
    arm.policy = closed_loop_factory(name + "_" + kLearntActor, learnt_actor(options), loop);
  }
  arm.name = std::move(name);
  return arm;
}

Arm make_arm(std::string name, ControllerFactory learner, ControllerFactory policy,
             const ClosedLoopOptions& loop) {
  Arm arm;
  arm.learner = closed_loop_factory(name, std::move(learner), loop);
  if (policy) {
    arm.policy = closed_loop_factory(name + "_" + kLearntActor, std::move(policy), loop);
  }
  arm.name = std::move(name);
  return arm;
}

Arm preset_arm(std::string_view name, const ClosedLoopOptions& loop) {
  if (name == kLearntActor) {
    throw std::invalid_argument(std::string(kLearntActor) +
                                " evaluates an arm's learnt actor; it is not an arm");
  }
  return make_arm(std::string(name), preset(name).options, loop);
}

}  // namespace cbbg::diagrams
