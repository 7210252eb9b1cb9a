#pragma once
// What the closed loop asks of a controller, any diagram of the library's or a user's: the
// ports it feeds and reads, and what it finds inside (the learners whose weights the
// protocols keep, the layout its blocks describe).

#include <string>
#include <vector>

#include "cbbg/blocks/feature_layout.h"
#include "cbbg/blocks/learner.h"
#include "cbbg/blocks/tropism.h"
#include "cbbg/framework/diagram.h"

namespace cbbg::diagrams {

// Required: input "measured" (6, blocks/measured_signals.h) and output "action" (1).
// Optional: inputs "reward" and "failed" (1 each: a learner's), any of the diagnostic
// outputs (1 each), which the telemetry records (NaN for those it lacks), and an output
// "reward" (1) for a controller that makes its own reward (the loop then records it, and
// builds no reward of its own).
inline constexpr const char* kControllerDiagnostics[] = {
    "supervisor_action", "actor_action", "exploration_action", "omega", "value", "td_error",
    "temperature",       "entropy"};

// Throws std::invalid_argument naming the controller and the port unless its ports are
// those above: a required port missing, a size that differs, or an input the closed loop
// does not feed (it would read nothing).
void check_controller_ports(const Diagram& controller);

// The learning blocks the protocols read and write (weights files, exp2's annealing of k1),
// found anywhere in the controller: its critic and actor by their interface
// (blocks::Learner, a user's own too), its tropism by type; null where it has none.
struct LearnerBlocks {
  const blocks::Learner* critic = nullptr;
  const blocks::Learner* actor = nullptr;
  const blocks::Tropism* tropism = nullptr;  // null without exploration
  bool learns() const { return actor != nullptr; }
};

// What a controller holds, found by walking its blocks in the order they were built.
struct ControllerSurvey {
  LearnerBlocks learner;
  // What its blocks say gives its features their meaning (normaliser.*, rbf.* for the
  // presets), and their notes for a weights file.
  blocks::FeatureLayout layout;
  std::vector<std::string> layout_notes;
};

// Throws std::invalid_argument when the controller has two learners of a kind.
ControllerSurvey survey_controller(const Diagram& controller);

}  // namespace cbbg::diagrams
