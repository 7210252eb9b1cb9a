#pragma once
// The experiments (docs/model.md §3) over many seeds, in parallel threads (parallel_runs.h),
// over any arms: an arm is a name and the closed-loop factories of diagrams/presets.h, so a
// user's own diagram gets every protocol the presets get.
//
//   exp1   per arm and seed: trials until the first success (or max_trials); then the
//          arm's learnt actor alone (an arm that learns nothing: its closed loop as it is)
//          from each of evaluation.angles, under evaluation.*'s conditions
//          (evaluation_conditions.h)
//   exp3   per arm and seed: trials past the first success until the learnt actor alone
//          (frozen, no exploration, no supervisor) balances from every exp3.angles, tested
//          after every trial under the training's conditions; max_trials caps it; then the
//          evaluation of exp1
//   evaluate  per arm and seed: no training; the weights of cbbg run --load-weights (an arm
//          that learns nothing: its closed loop) evaluated as exp1 evaluates what it learnt
//   exp2   per seed: one trial of the coordinated arm (cbbg), then the operant arm (bg_only:
//          omega = 1) carrying on what was learnt, with k1 from the annealing schedule, for
//          exp2.trials trials
//
// Each is declared in its own file (exp1.cc, exp2.cc, exp3.cc, evaluate.cc, transfer.cc) as a
// user's protocol is (protocols.h), written with the pieces of protocol_kit.h.
//
// Common random numbers: a block's random stream comes from the seed and its path below the
// closed loop (framework/context.h), so seed k gives every arm of a comparison the same
// streams where their blocks have the same paths.

#include <optional>
#include <string>
#include <vector>

#include "cbbg/diagrams/presets.h"
#include "cbbg/experiments/parallel_runs.h"
#include "cbbg/experiments/protocol_kit.h"
#include "cbbg/experiments/protocols.h"
#include "cbbg/experiments/seed_run.h"
#include "cbbg/parameters/parameters.h"

namespace cbbg::experiments {

// The protocols take the run's typed parameters (diagrams::validated_parameters makes them
// from a config, once) and hand them to every closed loop they build.

// exp1's and exp3's seed of one arm (protocol_kit.h's PerSeed), for a protocol that trains as
// they do. exp1: trials until the first success (or max_trials), then finish_run. exp3: trials
// go on past the first success until the learnt actor alone passes exp3's test (or
// max_trials); an arm that learns nothing has no actor and stops at its first success.
void run_until_success(const parameters::Parameters& p, const diagrams::Arm& arm,
                       const TelemetryOptions& telemetry, const LearntWeights* initial_weights,
                       SeedRun& run);
// exp3's records the test after each trial as the trial's actor_alone, and the figures
// trials_to_skill and failures_to_skill.
void run_until_skill(const parameters::Parameters& p, const diagrams::Arm& arm,
                     const TelemetryOptions& telemetry, const LearntWeights* initial_weights,
                     SeedRun& run);

// exp3's training alone, for a protocol that records its own figures of it (transfer): the
// test after each trial (none for an arm without an actor), and when the skill came.
struct SkillTest {
  std::vector<std::optional<bool>> passed;  // per trial
  std::optional<int> trials;                // the trial after which the actor alone balanced
  std::optional<int> failures;              // the failed trials before it
};
SkillTest train_until_skill(const parameters::Parameters& p, const diagrams::Arm& arm,
                            const TelemetryOptions& telemetry, const LearntWeights* initial_weights,
                            SeedRun& run);
// Throws config::ConfigError unless every exp3.angles entry lies inside trial.failure_angle:
// what exp3's training tests from (exp3's check, and transfer's when it trains as exp3).
void check_skill_angles(const parameters::Parameters& p);

// exp1's results schema (the default's, with the paper's figures on the paper's robot), which
// an arm run alone has too.
ResultsSchema exp1_schema(const parameters::Parameters& parameters);

// exp1 for each arm, over the parameters' seeds.
ExperimentResults run_exp1(const parameters::Parameters& parameters,
                           const std::vector<diagrams::Arm>& arms,
                           const ExperimentOptions& options = {});

// exp3 for each arm, over the parameters' seeds.
ExperimentResults run_exp3(const parameters::Parameters& parameters,
                           const std::vector<diagrams::Arm>& arms,
                           const ExperimentOptions& options = {});

// evaluate, for each arm over the parameters' seeds: no training; the weights learning would
// start from (options.initial_weights, cbbg run --load-weights) evaluated as exp1 evaluates
// what it learnt, or the closed loop of an arm that learns nothing. Throws config::ConfigError
// before any work for an arm that learns when there are no initial weights.
ExperimentResults run_evaluation(const parameters::Parameters& parameters,
                                 const std::vector<diagrams::Arm>& arms,
                                 const ExperimentOptions& options = {});
// Its check before any work (Protocol::check).
void check_evaluation(const parameters::Parameters& parameters,
                      const std::vector<diagrams::Arm>& arms, const LearntWeights* initial_weights);

// exp2: trial 1 in `coordinated`'s closed loop, the later trials in `operant`'s, which
// carries on the learning of trial 1 (Context::continue_from). The results name the arm
// `coordinated.name`.
ExperimentResults run_exp2(const parameters::Parameters& parameters,
                           const diagrams::Arm& coordinated, const diagrams::Arm& operant,
                           const ExperimentOptions& options = {});

}  // namespace cbbg::experiments
