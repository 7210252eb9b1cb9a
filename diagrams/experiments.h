#pragma once
// The experiments of SPEC section 3, over many seeds, in parallel threads. Each (arm, seed)
// task builds its own diagram and context, and results land in a slot fixed by the task's
// index, so they are the same whatever the number of threads.
//
//   exp1             per arm and seed: trials until the first success (or max_trials);
//                    then the learnt actor alone (learnt_actor) from each evaluation angle
//   exp2             per seed: one trial of cbbg, then bg_only (omega = 1) with the weights
//                    learnt so far and k1 from the annealing schedule, for exp2.trials trials
//   <diagram name>   exp1's protocol for that one arm

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "config/config.h"
#include "diagrams/trial_runner.h"
#include "diagrams/weights_file.h"

namespace cbbg::diagrams {

struct TrialRecord {
  int trial = 0;  // from 1
  double k1 = 0.0;
  TrialOutcome outcome;
};

// The learnt actor alone from one initial pitch (exp1, learning arms).
struct EvaluationRecord {
  double theta0 = 0.0;
  TrialOutcome outcome;
};

struct SeedRun {
  std::string arm;
  long long seed = 0;
  std::vector<TrialRecord> trials;
  // exp1: failed or diverged trials before the first success; all of them if none succeeded.
  int failures_before_success = 0;
  bool succeeded = false;
  // steps.csv rows (no header), every log.decimation-th tick, when no TaskStore keeps them.
  std::string steps_csv;
  // exp1: the learnt actor evaluated from each of evaluation.angles (empty for pd_only).
  std::vector<EvaluationRecord> evaluation;
  // The weights learnt by the end of the run (none for pd_only).
  std::optional<LearntWeights> weights;
};

struct ExperimentResults {
  std::string experiment;  // exp1, exp2 or a diagram name
  std::vector<std::string> arms;
  std::vector<long long> seeds;
  std::vector<SeedRun> runs;  // arm-major: runs[a * seeds.size() + s]
  const SeedRun& run(std::size_t arm, std::size_t seed) const {
    return runs[arm * seeds.size() + seed];
  }
};

// Called after each finished (arm, seed), from the worker thread that ran it.
using ProgressCallback = std::function<void(const SeedRun&)>;

// The arms the config's experiment runs: exp1's `arms`, exp2's cbbg, or the one diagram.
std::vector<std::string> experiment_arms(const config::Config& config);

class TaskStore;

struct ExperimentOptions {
  int jobs = 1;  // threads (>= 1); the results do not depend on it
  ProgressCallback progress;
  // With a store, each task found finished there is loaded instead of run, each task run is
  // saved there, and its steps rows go to the store's files; without, to SeedRun::steps_csv.
  const TaskStore* store = nullptr;
  // Where learning starts (cbbg run --load-weights); zero weights without.
  const LearntWeights* initial_weights = nullptr;
};

// Runs the experiment the config names.
ExperimentResults run_experiment(const config::Config& config,
                                 const ExperimentOptions& options = {});

}  // namespace cbbg::diagrams
