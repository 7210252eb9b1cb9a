#pragma once
// What an experiment produces: per (arm, seed) task a SeedRun, and all of them in
// ExperimentResults, arm-major, with the schema that says what they hold (schema.h). The
// store (store/) writes and reads them by the schema alone.

#include <optional>
#include <string>
#include <vector>

#include "cbbg/records/learnt_state.h"
#include "cbbg/records/schema.h"
#include "cbbg/records/trial_outcome.h"

namespace cbbg::records {

// A value a protocol records by name: a figure of a seed (SeedRun::figures), or one of a trial's
// own columns (TrialRecord::values); none when the seed or trial has none (exp3's
// trials_to_skill where max_trials came first).
struct NamedValue {
  std::string name;  // any text but a line break
  std::optional<double> value{};
  bool operator==(const NamedValue&) const = default;
};
using SeedFigure = NamedValue;

struct TrialRecord {
  int trial = 0;  // from 1
  double k1 = 0.0;
  TrialOutcome outcome;
  // The protocol's own columns of this trial (ResultsSchema::trial_columns), by name (exp3's
  // actor_alone: whether the learnt actor alone balanced after it).
  std::vector<NamedValue> values{};
  // The value named `name`, or none.
  std::optional<double> value(const std::string& name) const;
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
  // Failed or diverged trials before the first success; all of them if none succeeded.
  int failures_before_success = 0;
  bool succeeded = false;
  // steps.csv rows after their header line (steps_csv_header), every log.decimation-th tick,
  // when no TaskStorage keeps them.
  std::string steps_csv;
  // The learnt actor evaluated from each of evaluation.angles (empty for an arm that learns
  // nothing, and under a protocol that does not evaluate).
  std::vector<EvaluationRecord> evaluation;
  // The weights learnt by the end of the run (none for an arm that learns nothing, nor when
  // they stopped being finite: then weights_diverged).
  std::optional<LearntWeights> weights;
  bool weights_diverged = false;
  // The protocol's own figures (ResultsSchema::figures), by name.
  std::vector<SeedFigure> figures;
  // The figure named `name`: every run's own (failures_before_success, succeeded, as
  // records::run_figures declares them) or one of `figures`; none when the run has none.
  std::optional<double> figure(const std::string& name) const;
};

struct ExperimentResults {
  std::string experiment;  // exp1, exp2 or the one arm's name
  ResultsSchema schema;    // what the results hold, the protocol's declaration
  // steps.csv's header line, the arms' plant's signals: the file's whole text when no task
  // logged a row.
  std::string steps_header;
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

}  // namespace cbbg::records
