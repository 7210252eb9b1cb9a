#pragma once
// The named diagrams: one table of ControllerOptions. A preset is a row; an arm is a name
// with the closed loop that learns and the closed loop of its learnt actor alone, which is
// what the protocols (experiments/) compare.
//
//   cbbg           supervisor + basal ganglia, omega scheduled, actor.rule (improved)
//   cbbg_weighted  the same with the weighted rule (paper eq. 7)
//   bg_only        basal ganglia alone: omega = 1, no supervisor (a_S = 0)
//   cb_only        omega = 0: the supervisor drives, the actor learns from it alone
//   pd_only        the supervisor alone, no basal ganglia
//   learnt_actor   an arm's learnt actor alone: omega = 1, no exploration, no supervisor,
//                  weights frozen (evaluation; not an arm)
//
// An ablation in user code is one more set of options:
//
//   diagrams::ControllerOptions mine = diagrams::preset("cbbg").options;
//   mine.slots.supervisor = [](const std::string& name, const parameters::Parameters&) {
//     return std::make_unique<MySupervisor>(name);
//   };
//   const diagrams::Arm arm = diagrams::make_arm("cbbg_mine", mine);

#include <string>
#include <string_view>
#include <vector>

#include "cbbg/diagrams/arms.h"
#include "cbbg/diagrams/cbbg_controller.h"
#include "cbbg/diagrams/closed_loop.h"

namespace cbbg::diagrams {

struct Preset {
  std::string name;
  std::string description;
  ControllerOptions options;
};

inline constexpr const char* kLearntActor = "learnt_actor";

// Every preset, in the order above: the one list of the diagrams' names, from which `cbbg
// list`, the help and the checks of `arms` and `experiment` are made.
const std::vector<Preset>& presets();
// The names of the arms: the presets' (every one but learnt_actor), in the table's order,
// then the registered arms' (arms.h).
std::vector<std::string> arm_names();
// Every diagram `cbbg graph` draws: the presets (learnt_actor too), then the registered arms.
std::vector<std::string> diagram_names();
// The preset named `name`; std::invalid_argument listing the presets for another name.
const Preset& preset(std::string_view name);

// The learnt actor of a controller alone: `options` with omega = 1, no supervisor, no
// exploration and frozen weights, its slots (normaliser, features) kept, an omega slot
// dropped.
ControllerOptions learnt_actor(ControllerOptions options);

// The closed loop of preset `name` (learnt_actor included), named after it.
ClosedLoop build_preset(std::string_view name, const parameters::Parameters& parameters,
                        const ClosedLoopOptions& loop = {});

Arm make_arm(std::string name, const ControllerOptions& options,
             const ClosedLoopOptions& loop = {});
// The arm of a controller of the user's own (closed_loop.h's ports): `learner` is the one
// that runs the trials; `policy`, when given, its learnt actor alone, which the evaluations
// load the learnt weights into (without one, a learning arm's weights are kept but not
// evaluated, and an arm that learns nothing is evaluated as it is).
Arm make_arm(std::string name, ControllerFactory learner, ControllerFactory policy = {},
             const ClosedLoopOptions& loop = {});
// The arm of a preset (not learnt_actor), in a closed loop named after it.
Arm preset_arm(std::string_view name, const ClosedLoopOptions& loop = {});

}  // namespace cbbg::diagrams
