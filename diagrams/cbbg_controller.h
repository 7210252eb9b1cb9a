#pragma once
// The CB-BG controller (the paper's Fig. 5): a cerebellum and a basal ganglia, coordinated
// by omega and mixed into one action. Which parts it has, and which blocks fill its slots,
// are ControllerOptions: the named presets (presets.h) are rows of options, and a user's
// ablation is one more set of options, with no edit of the library.

#include <memory>
#include <optional>
#include <string>

#include "cbbg/blocks/actor.h"
#include "cbbg/blocks/omega_schedule.h"
#include "cbbg/diagrams/basal_ganglia.h"
#include "cbbg/diagrams/cerebellum.h"
#include "cbbg/diagrams/controller_slots.h"
#include "cbbg/framework/diagram.h"
#include "cbbg/parameters/parameters.h"

namespace cbbg {
class DiagramBuilder;
}

namespace cbbg::diagrams {

// Independent choices; each preset of presets.h is one set of them.
struct ControllerOptions {
  // The cerebellum. False: no supervisor; a_S = 0 (the actor-critic alone).
  bool supervisor = true;
  // False: no basal ganglia; the supervisor drives alone (a = a_S) and nothing learns.
  bool basal_ganglia = true;
  // omega: kSchedule (omega.n2, omega.n3), kZero (the supervisor drives), kOne (the basal
  // ganglia drive), kConstant (omega_constant throughout). slots.omega replaces it.
  blocks::OmegaMode omega = blocks::OmegaMode::kSchedule;
  double omega_constant = 0.5;  // kConstant's omega, in [0, 1]
  // The actor's learning rule; unset: actor.rule (the library's actor only).
  std::optional<blocks::ActorRule> actor_rule;
  // False: that learner acts but never changes what it learns (frozen; a user's block is told
  // by SlotRequest::learns); the other learns on.
  bool critic_learns = true;
  bool actor_learns = true;
  // False: no exploration; a_E = a_A, and T and E are NaN.
  bool exploration = true;
  ControllerSlots slots;

  // Throws std::invalid_argument for choices that make no controller (no supervisor and no
  // basal ganglia) and for an omega_constant outside [0, 1] (with kConstant).
  void validate() const;
};

/// CbbgController: measured state (and the task's reward and failure) in, the action out.
///
/// | port               | dir | size | meaning                                       |
/// |--------------------|-----|------|-----------------------------------------------|
/// | measured           | in  | 6    | the Sensors output (blocks/measured_signals.h) |
/// | reward             | in  | 1    | r_{t-1} (only with basal ganglia)              |
/// | failed             | in  | 1    | 1 when s_t is terminal (only with basal ganglia) |
/// | action             | out | 1    | a = omega a_E + (1 - omega) a_S, N m           |
/// | supervisor_action  | out | 1    | a_S (0 without a supervisor)                   |
/// | actor_action       | out | 1    | a_A                                            |
/// | exploration_action | out | 1    | a_E                                            |
/// | omega              | out | 1    | omega                                          |
/// | value              | out | 1    | V(s_t)                                         |
/// | td_error           | out | 1    | delta_{t-1}                                    |
/// | temperature        | out | 1    | T                                              |
/// | entropy            | out | 1    | E, bits                                        |
///
/// Without basal ganglia the outputs from actor_action on are NaN, except omega = 0.
/// Blocks: "cerebellum" (Cerebellum) or the constant "no_supervisor"; "normaliser",
/// "basal_ganglia" (BasalGanglia: "features", "critic", "actor", "tropism", "sampler" (the
/// exploration slot's), "entropy"), "omega", "mixer": each its slot's block
/// (controller_slots.h). The closed loop needs none of these names: any diagram with these
/// ports is a controller (closed_loop.h). "reward" and "failed" are inputs only when a block
/// reads them.
class CbbgController final : public Diagram {
 public:
  CbbgController(std::string name, const parameters::Parameters& parameters,
                 const ControllerOptions& options);

  const InputPort& measured() const { return *measured_; }
  // Null when no block reads it: a supervisor alone needs neither.
  const InputPort* reward() const { return reward_; }
  const InputPort* failed() const { return failed_; }
  const OutputPort& action() const { return output_port("action"); }

  // Null where the options leave them out.
  const Cerebellum* cerebellum() const { return cerebellum_; }
  const BasalGanglia* basal_ganglia() const { return basal_ganglia_; }

 private:
  // Adds normaliser, basal ganglia, omega and mixer, and exports their outputs.
  void add_basal_ganglia(DiagramBuilder& builder, const parameters::Parameters& parameters,
                         const ControllerOptions& options, const OutputPort& supervisor_action);
  // Exports the supervisor's action as the action; the learning outputs are NaN.
  void add_supervisor_alone(DiagramBuilder& builder, const OutputPort& supervisor_action);

  const InputPort* measured_ = nullptr;
  const InputPort* reward_ = nullptr;
  const InputPort* failed_ = nullptr;
  const Cerebellum* cerebellum_ = nullptr;
  const BasalGanglia* basal_ganglia_ = nullptr;
};

}  // namespace cbbg::diagrams
