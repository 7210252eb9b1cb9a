#pragma once
// transfer: train once, evaluate many. Each arm and seed trains once, as transfer.training's
// protocol does (exp3: until its learnt actor alone balances from every exp3.angles; exp1:
// until its first success), and is evaluated as that protocol evaluates it (evaluation.csv).
// Then what it learnt (an arm that learns nothing: its closed loop) is evaluated from each of
// evaluation.angles under each of transfer.conditions: a setting of the evaluation, the
// robot, its sensors or the pushes, which the training never sees. Per condition C the run
// records two figures (figures.csv's columns): balanced@C, the evaluation runs that balanced,
// and evaluated@C, those run (none for a learner whose weights diverged). Trained as exp3, it
// also records skilled and trials_to_skill (none where the skill never came, which a paired
// comparison counts as max_trials + 1).
//
// Since the training does not depend on the evaluation, a condition's figures are those of
// the training protocol run with that setting: a sweep over evaluation.* keys, which trains
// again at every point, in one training. An arm that learns nothing (pd_only) is the same
// closed loop under every seed: a condition's evaluation of it that drew no random number
// (no noise) runs once and the other seeds take its records (shared_evaluations.h).

#include <string>
#include <vector>

#include "cbbg/diagrams/arms.h"
#include "cbbg/experiments/parallel_runs.h"
#include "cbbg/experiments/seed_run.h"
#include "cbbg/parameters/parameters.h"

namespace cbbg::experiments {

struct TransferCondition {
  std::string name;                   // the transfer.conditions entry, "evaluation.noise_std=0.05"
  parameters::Parameters parameters;  // the run's, with the entry's settings
  // The settings are the run's own values: its figures are those of the run's evaluation
  // (SeedRun::evaluation), which it takes instead of evaluating the same again.
  bool changes_nothing = false;
};

// The conditions of `p`, each applied to it and validated as a run's parameters are. Throws
// config::ConfigError naming the entry (transfer.conditions[i]) when it sets a key outside
// the evaluation, the robot, its sensors, the pushes and the registered sections, or makes
// parameters no run would take.
std::vector<TransferCondition> transfer_conditions(const parameters::Parameters& p);

// The conditions, and before any training, every arm's plant sees the robot each condition
// changes (evaluation_conditions.h). Throws config::ConfigError.
std::vector<TransferCondition> check_transfer(const parameters::Parameters& p,
                                              const std::vector<diagrams::Arm>& arms);

// The transfer protocol over `arms`, the results named "transfer".
ExperimentResults run_transfer(const parameters::Parameters& p,
                               const std::vector<diagrams::Arm>& arms,
                               const ExperimentOptions& options = {});

}  // namespace cbbg::experiments
