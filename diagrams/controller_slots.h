#pragma once
// The slots of the CB-BG controller: every block of the paper's Fig. 5, each filled by a
// user's block or by the one its section's `kind` key names, with the port contract the
// controller checks when it builds (check_slot: one line naming the slot, the block, the port
// and what is expected). A slot's block reads any of the inputs its slot feeds, and nothing
// else; it must have the outputs its slot reads (more are left unread).

#include "cbbg/diagrams/block_factory.h"
#include "cbbg/diagrams/slot_check.h"

namespace cbbg::diagrams {

// The blocks that fill the controller's slots; an empty factory takes the parameters' own.
// n is the features' size (SlotRequest::num_features).
struct ControllerSlots {
  // Input "measured" (6, blocks/measured_signals.h), output "action" (1): a_S. Default:
  // supervisor.kind's (blocks::PdSupervisor or blocks::LqrSupervisor).
  BlockFactory supervisor;
  // Input "measured" (6), output "x": the state the basal ganglia sees, in the units its
  // features expect. Robot-specific. Default: blocks::Normaliser (normaliser.*).
  BlockFactory normaliser;
  // Input "x", output "features": what critic and actor share. Default: blocks::RbfFeatures
  // (rbf.*).
  BlockFactory features;
  // Feeds "features" (n), "reward" (1: r_{t-1}), "failed" (1: s_t terminal); reads "value"
  // (1: V(s_t)) and "td_error" (1: delta_{t-1}). A blocks::Learner of Role::kCritic has what it
  // learns kept (weights files, resume, exp2, eval); it must not learn when
  // SlotRequest::learns is false. Default: blocks::Critic, learning by critic.kind's rule
  // (td_lambda, td0).
  BlockFactory critic;
  // Feeds "features" (n), "td_error" (1), "supervisor_action" (1: a_S), "omega" (1),
  // "exploration_action" (1: a_E); reads "actor_action" (1: a_A), which must not depend on
  // "exploration_action" (the sampler reads a_A: an algebraic loop otherwise). A
  // blocks::Learner of Role::kActor, as the critic. Default: blocks::Actor (actor.*).
  BlockFactory actor;
  // Feeds "actor_action" (1) and "temperature" (1: T); reads "exploration_action" (1: a_E).
  // Its block is named "sampler": its random generator is seeded from that path, so two arms
  // that differ elsewhere draw the same noise (common random numbers) as long as it draws
  // the same count of numbers per tick from context.random_generator() and nothing else.
  // Default: exploration.kind's (boltzmann: blocks::BoltzmannSampler; gaussian:
  // blocks::GaussianExploration; ou: blocks::OuExploration).
  BlockFactory exploration;
  // Feeds "value" (1: V); reads "temperature" (1: T). Default: blocks::Tropism (tropism.*;
  // exp2 anneals its k1).
  BlockFactory tropism;
  // Feeds "temperature" (1); reads "entropy" (1: E, bits). Default: blocks::Entropy.
  BlockFactory entropy;
  // Feeds "exploration_action" (1), "supervisor_action" (1), "omega" (1); reads "action" (1:
  // the action applied). Default: blocks::Mixer, a = omega a_E + (1 - omega) a_S.
  BlockFactory mixer;
  // No input, output "omega" (1): omega(t), in [0, 1]. Default: blocks::OmegaSchedule, in
  // ControllerOptions::omega's mode. Set, it replaces that mode.
  BlockFactory omega;
};

// The contracts check_slot checks, for features of size `num_features`.
SlotContract critic_contract(int num_features);
SlotContract actor_contract(int num_features);
SlotContract exploration_contract();
SlotContract tropism_contract();
SlotContract entropy_contract();
SlotContract mixer_contract();

}  // namespace cbbg::diagrams
