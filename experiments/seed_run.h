#pragma once
// What an experiment produces: per (arm, seed) task a SeedRun, and all of them in
// ExperimentResults, arm-major.

#include <optional>
#include <string>
#include <vector>

#include "cbbg/experiments/learnt_weights.h"
#include "cbbg/experiments/trial_runner.h"

namespace cbbg::experiments {

struct TrialRecord {
  int trial = 0;  // from 1
  double k1 = 0.0;
  TrialOutcome outcome;
  // exp3: whether the learnt actor alone balanced from every exp3.angles after this trial
  // (unset in the other experiments).
  std::optional<bool> actor_alone_passed;
};

// The learnt actor alone from one initial pitch (exp1, learning arms).
struct EvaluationRecord {
  double theta0 = 0.0;
  TrialOutcome outcome;
};

// A figure a protocol records per seed beyond SeedRun's own fields, by name: a column of
// figures.csv, summed per arm in summary.json (transfer: the evaluation runs balanced under
// each of its conditions).
struct SeedFigure {
  std::string name;  // any text but a line break
  double value = 0.0;
  bool operator==(const SeedFigure&) const = default;
};

struct SeedRun {
  std::string arm;
  long long seed = 0;
  std::vector<TrialRecord> trials;
  // Failed or diverged trials before the first success; all of them if none succeeded.
  int failures_before_success = 0;
  bool succeeded = false;
  // exp3: the trial after which the learnt actor alone first balanced from every
  // exp3.angles, and the failed trials before it; unset when max_trials came first.
  std::optional<int> trials_to_skill;
  std::optional<int> failures_to_skill;
  // steps.csv rows after their header line (steps_csv_header), every log.decimation-th tick,
  // when no TaskStorage keeps them.
  std::string steps_csv;
  // exp1: the learnt actor evaluated from each of evaluation.angles (empty for an arm that
  // learns nothing).
  std::vector<EvaluationRecord> evaluation;
  // The weights learnt by the end of the run (none for an arm that learns nothing, nor when
  // they stopped being finite: then weights_diverged).
  std::optional<LearntWeights> weights;
  bool weights_diverged = false;
  // The protocol's own figures, in its order; every seed of a run has the same names.
  std::vector<SeedFigure> figures;
};

struct ExperimentResults {
  std::string experiment;  // exp1, exp2 or the one arm's name
  std::vector<std::string> arms;
  // True when `arms` are the arms the protocol compared (exp1, exp3), which config.yaml's
  // `arms` then records, a user's own arms too; exp2's one arm is not the `arms` key's.
  bool compares_arms = false;
  std::vector<long long> seeds;
  std::vector<SeedRun> runs;  // arm-major: runs[a * seeds.size() + s]
  const SeedRun& run(std::size_t arm, std::size_t seed) const {
    return runs[arm * seeds.size() + seed];
  }
};

}  // namespace cbbg::experiments
