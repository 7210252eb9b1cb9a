#pragma once
// What a protocol's results hold, declared by the protocol (protocols.h): its own per-trial
// columns (trials.csv, after the columns every trial has), its per-seed figures (figures.csv,
// summary.json, sweep.csv, the console), and what the console and the plots show. Everything
// that writes or reads results (store/, the commands, the plotting script, Python) goes by the
// schema alone, which a results directory records in schema.json.
//
//   ResultsSchema{
//       .figures = {{.name = "warm_up_trials",
//                    .type = ValueType::kInteger,
//                    .meaning = "trials from the first angle until one succeeded",
//                    .paired = true}}}

#include <string>
#include <utility>
#include <vector>

namespace cbbg::records {

enum class ValueType { kInteger, kNumber, kFlag };
const char* to_string(ValueType type);

// A column of a protocol's own per-trial records, read from TrialRecord::values by name (a
// record without it: an empty cell).
struct Column {
  std::string name;  // a word of letters, digits and '_'
  ValueType type = ValueType::kNumber;
  std::string meaning{};
};

// How summary.json shows a figure, per arm: summed over the seeds (in "figures"), listed per
// seed (null where a seed has none) with the statistics named in FigureStatistics, or not at all
// (figures.csv and sweep.csv only).
enum class FigureSummary { kSum, kList, kNone };
const char* to_string(FigureSummary summary);

// How a seed without a value counts where every seed needs one: not at all (sums and medians
// over the seeds that have one), or as beyond every other (it ranks last in a median, min or
// max, null when it decides one; max_trials + 1 in a paired comparison).
enum class Missing { kNotCounted, kBeyondMaxTrials };
const char* to_string(Missing missing);

// summary.json's keys for a listed figure's statistics over the seeds; empty: not shown. The
// count is of the seeds with a value (a flag: of those where it holds).
struct FigureStatistics {
  std::string count{};
  std::string median{};
  std::string min{};
  std::string max{};
};

// A figure a protocol records once per seed (SeedRun::figures), by name.
struct Figure {
  std::string name;  // any text but a line break
  ValueType type = ValueType::kNumber;
  std::string meaning{};
  FigureSummary summary = FigureSummary::kSum;
  FigureStatistics statistics{};  // for FigureSummary::kList
  // Compared seed by seed, the first arm against each other, in summary.json's "paired".
  bool paired = false;
  Missing missing = Missing::kNotCounted;
  // When set, the console shows a line per arm: the seeds with a value, their median and
  // range, and this text ("trials until the actor alone balances").
  std::string console{};
};

// What the console shows after a run.
enum class ConsoleTable {
  kHeadline,  // per arm, the headline's median and range over the seeds
  kTrials,    // per trial, over the seeds: k1, mean temperature and entropy, runs that balanced
};

struct ResultsSchema {
  std::vector<Column> trial_columns{};
  // evaluation.csv and summary.json's "evaluation": the run's learnt actor evaluated per angle.
  bool evaluates = true;
  std::vector<Figure> figures{};
  // Whether summary.json compares failures_before_success (every run's: the failed trials
  // before its first success) seed by seed, the first arm against each other.
  bool pairs_failures = true;
  // sweep.csv's and the console's figure per seed: one of `figures`, or (empty)
  // failures_before_success.
  std::string headline{};
  ConsoleTable console = ConsoleTable::kHeadline;
  // The drawings `cbbg plot` makes of the results (plot_results.py's names: "pitch",
  // "failures", "skill", "annealing", "evaluation", "figures"); none: nothing to draw.
  std::vector<std::string> plots{"pitch", "failures"};
  // Reference figures per arm (the paper's failures before the first success), which
  // summary.json shows under "paper" for the arms that ran.
  std::vector<std::pair<std::string, int>> reference{};

  // The figure named `name`, or nullptr.
  const Figure* figure(const std::string& name) const;
  // The headline's name: `headline`, or failures_before_success.
  std::string headline_name() const;
};

// Every run's own figures, which every schema has before its protocol's: the failed trials
// before the first success (listed, with median, min and max), and whether one came (counted
// as num_succeeded).
const std::vector<Figure>& run_figures();

// Throws std::invalid_argument naming `protocol` when the schema cannot be written (a column
// name that is not a word, a figure name that is empty or holds a line break or is one of every
// run's own (failures_before_success, succeeded), two of one name, a headline or plot that is
// not one).
void check_schema(const ResultsSchema& schema, const std::string& protocol);

}  // namespace cbbg::records
