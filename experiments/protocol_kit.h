#pragma once
// What a protocol is made of: one seed of an arm (its learning loop and the runner of its
// trials), the next trial from trial.theta0, the end of a run (weights kept, the run
// evaluated), and the run of a per-seed body for every (arm, seed). exp1 and exp3 are written
// with these; so is a protocol of the user's (protocols.h registers it by name).

#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "cbbg/diagrams/arms.h"
#include "cbbg/experiments/learnt_weights.h"
#include "cbbg/experiments/parallel_runs.h"
#include "cbbg/experiments/seed_run.h"
#include "cbbg/experiments/training_disturbances.h"
#include "cbbg/experiments/trial_runner.h"
#include "cbbg/parameters/parameters.h"

namespace cbbg::experiments {

// `parameters` with the root seed `seed`: an evaluation after a seed's training uses its
// streams.
parameters::Parameters with_seed(parameters::Parameters parameters, long long seed);

// Where a run's weights come from: its arm, seed, trials and plant.kind.
WeightsProvenance provenance(const parameters::Parameters& p, const SeedRun& run);

// Keeps what was learnt, unless it stopped being finite (a diverged learner): then the run
// says so instead, and nothing evaluates or saves it.
void keep_weights(LearntWeights weights, SeedRun& run);

// `weights` tested from each of evaluation.angles under `training`'s evaluation.* conditions
// (evaluation_conditions.h) with the streams of `seed`: the arm's actor alone with them (no
// exploration, no supervisor, frozen), as `cbbg eval` runs it (nothing for an arm without a
// policy), or, without weights, the arm's closed loop as it is (pd_only: the supervisor
// alone).
std::vector<EvaluationRecord> evaluate_weights(const parameters::Parameters& training,
                                               const diagrams::Arm& arm,
                                               const LearntWeights* weights, long long seed);

// evaluate_weights' records, and whether they are every seed's (PolicyEvaluation::seed_free).
struct SeedEvaluation {
  std::vector<EvaluationRecord> records;
  bool seed_free = true;
};
SeedEvaluation evaluate_seed(const parameters::Parameters& training, const diagrams::Arm& arm,
                             const LearntWeights* weights, long long seed);

// What `run` leaves, tested so with its seed: its learnt weights, or, for an arm that learns
// nothing, its closed loop; nothing for a learner whose weights diverged.
std::vector<EvaluationRecord> evaluate_run(const parameters::Parameters& training,
                                           const diagrams::Arm& arm, const SeedRun& run);

// What `loop` learnt by now in `context`, kept (keep_weights); nothing for a loop that learns
// nothing.
void keep_learnt(const parameters::Parameters& p, const diagrams::ClosedLoop& loop,
                 const Context& context, SeedRun& run);

// The end of a run: what was learnt is kept (keep_learnt), and the run evaluated
// (evaluate_run) into SeedRun::evaluation.
void finish_run(const parameters::Parameters& p, const diagrams::Arm& arm,
                const diagrams::ClosedLoop& loop, const Context& context, SeedRun& run);

// The arm's learning loop: built for training.*'s disturbances (training_loop_parameters).
// Throws config::ConfigError naming training.push_force for a plant no push from outside
// reaches.
diagrams::ClosedLoop learning_loop(const parameters::Parameters& p, const diagrams::Arm& arm);

// Has `runner`'s trials, in `loop`, meet training.*'s disturbances, drawn by `disturbances`
// (a seed's, shared by the runners that carry on one another); nothing for null. Throws
// config::ConfigError when `loop` lacks what they need.
void meet_training(TrialRunner& runner, const diagrams::ClosedLoop& loop,
                   const std::shared_ptr<TrainingDisturbances>& disturbances);

// One seed of an arm: its learning closed loop (learning_loop) and the runner of its trials,
// which meet training.*'s disturbances, started from the initial weights when there are some.
// Run its trials through run_trial (or next_trial with the SeedLoop): under
// training.body_mass_spread each runs in a loop of its own robot, and `runner` refuses them.
struct SeedLoop {
  SeedLoop(const parameters::Parameters& p, const diagrams::Arm& arm,
           const TelemetryOptions& telemetry, const LearntWeights* initial_weights, long long seed);
  // The arm `arm`'s loop carrying on `before`'s learning (Context::continue_from) and its
  // training disturbances' draws: a change of protocol halfway (exp2's operant trials).
  SeedLoop(const parameters::Parameters& p, const diagrams::Arm& arm,
           const TelemetryOptions& telemetry, const SeedLoop& before);

  // Trial number `trial` from `theta0` for `duration`, in `loop` as the protocol set up its
  // context (k1); under training.body_mass_spread in a loop built for the trial's robot
  // (TrainingDisturbances::trial_robot) that carries on this one's learning, its parameters
  // and its random streams, and hands them back after the trial (runner.telemetry() then
  // keeps no trial's ticks).
  TrialOutcome run_trial(double theta0, double duration, int trial);

  diagrams::ClosedLoop loop;
  TrialRunner runner;  // runs `loop`: declared after it
  // The seed's training disturbances (null when training.* disturbs nothing), shared with a
  // loop that carries on from this one.
  std::shared_ptr<TrainingDisturbances> disturbances;

 private:
  void meet_disturbances();
  TrialOutcome run_on_trial_robot(double theta0, double duration, int trial);

  parameters::Parameters parameters_;
  diagrams::Arm arm_;
  TelemetryOptions telemetry_;
  long long seed_;
};

// The next trial from trial.theta0 (or `theta0`), for trial.duration, k1 fixed: of a seed's
// SeedLoop, or of a runner of the protocol's own.
TrialRecord next_trial(const parameters::Parameters& p, SeedLoop& seed, int trial);
TrialRecord next_trial(const parameters::Parameters& p, SeedLoop& seed, int trial, double theta0);
TrialRecord next_trial(const parameters::Parameters& p, TrialRunner& runner, int trial);
TrialRecord next_trial(const parameters::Parameters& p, TrialRunner& runner, int trial,
                       double theta0);

// One seed of one arm under a protocol: fills `run` (its arm and seed set).
using PerSeed =
    std::function<void(const parameters::Parameters&, const diagrams::Arm&, const TelemetryOptions&,
                       const LearntWeights* initial_weights, SeedRun&)>;

// `per_seed` for every (arm, seed), in options.jobs threads, the results named `protocol`.
// Throws std::invalid_argument before any work for an arm name that is not a name or is
// given twice, and config::ConfigError for an evaluation an arm's plant would not see.
ExperimentResults run_per_arm(const std::string& protocol, const PerSeed& per_seed,
                              const parameters::Parameters& p,
                              const std::vector<diagrams::Arm>& arms,
                              const ExperimentOptions& options);

}  // namespace cbbg::experiments
