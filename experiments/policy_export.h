#pragma once
// A learnt policy as dependency-free C99 (`cbbg export`): the actor of the arm that learnt the
// weights, with the features and the normaliser it reads, from the measured signals
// (blocks/measured_signals.h) to the action a_A; every block on the way writes its own C
// (codegen::EmitsC).

#include "cbbg/codegen/c_export.h"
#include "cbbg/codegen/c_learner_export.h"
#include "cbbg/diagrams/closed_loop.h"
#include "cbbg/experiments/learnt_weights.h"
#include "cbbg/parameters/parameters.h"

namespace cbbg::experiments {

// The C of `policy`'s actor output "actor_action" with `weights` loaded, as a function of the
// controller's inputs it reads (the measured signals):
//   NAME_real NAME_step(const NAME_real measured[NAME_MEASURED_SIZE]);
// Throws std::invalid_argument when the loop has no actor or a block on the way cannot be
// written as C (naming it), and what load_learnt_weights throws.
codegen::CSources export_policy(const parameters::Parameters& parameters,
                                const diagrams::ClosedLoopFactory& policy,
                                const LearntWeights& weights,
                                const codegen::CExportOptions& options);

// The same for the controller of `learner` (an arm's loop that learns) as it acts with omega
// held at `omega` and no exploration: its output "action", a = omega a_A + (1 - omega) a_S
// for the CB-BG controller, with the supervisor and the mixer written by their blocks. Throws
// std::invalid_argument naming what the controller lacks (an output "action",
// "actor_action", "exploration_action" or "omega") or a block that cannot be written as C.
codegen::CSources export_mixed_policy(const parameters::Parameters& parameters,
                                      const diagrams::ClosedLoopFactory& learner,
                                      const LearntWeights& weights, double omega,
                                      codegen::CExportOptions options);

// The C of the whole online learner of `learner` (an arm's loop that learns) with `weights`
// loaded, from the sensors' measured signals to the controller's action, with the state and
// the updates of every block on the way and of the failure slot, whose update ends a trial
// (codegen/c_learner_export.h):
//   int NAME_step(NAME_learner *learner, const NAME_real measured[NAME_MEASURED_SIZE],
//                 NAME_real *action);
// Its generators start as parameters.run.seed's; it steps at trial.period. Throws
// std::invalid_argument naming a block that cannot be written as C or what the controller
// lacks (an output "action"), and what load_learnt_weights throws.
codegen::CSources export_learner(const parameters::Parameters& parameters,
                                 const diagrams::ClosedLoopFactory& learner,
                                 const LearntWeights& weights, codegen::CLearnerOptions options);

// The same for `loop` as `context` (a context of loop.diagram) holds it: its state,
// parameters and generators at that moment. options.period must be the loop's tick.
codegen::CSources export_learner(const diagrams::ClosedLoop& loop, const Context& context,
                                 codegen::CLearnerOptions options);

}  // namespace cbbg::experiments
