#pragma once
// Arms by name: the presets' (presets.h) and those a user registers, so a program that runs
// cbbg's command line (apps/cli.h) knows its own arms in every command: `arms` and
// --experiment, a sweep, `cbbg eval` of their weights, `cbbg graph` and `cbbg plot`.
//
//   diagrams::ControllerOptions tiles = diagrams::preset("cbbg").options;
//   tiles.slots.features = ...;
//   diagrams::register_arm("cbbg_tiles", "cbbg on tile-coded features", tiles);

#include <string>
#include <string_view>
#include <vector>

#include "cbbg/diagrams/cbbg_controller.h"
#include "cbbg/diagrams/closed_loop.h"

namespace cbbg::diagrams {

// What an experiment compares: a name, the closed loop that learns, and the closed loop of
// its learnt actor alone (empty for an arm without basal ganglia, which learns nothing).
struct Arm {
  std::string name;
  ClosedLoopFactory learner;
  ClosedLoopFactory policy;
};

// A registered arm's name and what it is (`cbbg list`).
struct ArmName {
  std::string name;
  std::string description;
};

// Registers the arm `name` (a config::is_name word no preset or registered arm has) of a
// CB-BG controller with `options`, or of a controller of the user's own (`learner`, and
// `policy`, its learnt actor alone, for an arm that learns), in a task whose slots `task`
// fills (its reward, sensors, failure detector; empty: the parameters' own). Register before
// running the command line. Throws std::invalid_argument.
void register_arm(std::string name, std::string description, ControllerOptions options,
                  TaskSlots task = {});
// Removes the registered arm `name` (a notebook registering it again). Throws
// std::invalid_argument for a name no registered arm has (a preset cannot be removed).
void unregister_arm(std::string_view name);
void register_arm(std::string name, std::string description, ControllerFactory learner,
                  ControllerFactory policy = {}, TaskSlots task = {});

// The registered arms, in registration order.
std::vector<ArmName> registered_arms();

// The arm `name`, a preset's or a registered one, in closed loops with `loop`. Throws
// std::invalid_argument listing the arms for another name.
Arm named_arm(std::string_view name, const ClosedLoopOptions& loop = {});
// named_arm of each.
std::vector<Arm> named_arms(const std::vector<std::string>& names);

}  // namespace cbbg::diagrams
