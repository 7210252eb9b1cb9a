#include "cbbg/store/results_writer.h"

#include "cbbg/framework/number_text.h"
#include "cbbg/parameters/parameters.h"
#include "cbbg/records/paired_statistics.h"
#include "cbbg/store/fault_point.h"
#include "cbbg/store/files.h"
#include "cbbg/store/json_text.h"
#include "cbbg/store/seed_figures.h"
#include "cbbg/store/task_store.h"
#include "cbbg/store/weights_file.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <stdexcept>

namespace cbbg::store {

using records::EvaluationRecord;
using records::SeedRun;
using records::to_string;
using records::TrialOutcome;
using records::TrialRecord;
using records::TrialStatus;
namespace {

using records::Figure;
using records::FigureSummary;
using records::Missing;
using records::ResultsSchema;
using records::ValueType;

std::string number(double value) { return std::isfinite(value) ? format_number(value) : "nan"; }

// A value of `type` as a CSV cell: empty when there is none.
std::string cell(ValueType type, const std::optional<double>& value) {
  if (!value) return "";
  if (type == ValueType::kFlag) return *value != 0.0 ? "1" : "0";
  if (type == ValueType::kInteger && std::isfinite(*value)) {
    return std::to_string(static_cast<long long>(*value));
  }
  return number(*value);
}

// A value of `type` as JSON: null when there is none.
Json json_value(ValueType type, const std::optional<double>& value) {
  if (!value) return nullptr;
  if (type == ValueType::kFlag) return *value != 0.0;
  if (type == ValueType::kInteger && std::isfinite(*value)) {
    return static_cast<long long>(*value);
  }
  return *value;
}

using Statistic = std::string records::FigureStatistics::*;
constexpr Statistic kStatistics[] = {
    &records::FigureStatistics::count, &records::FigureStatistics::median,
    &records::FigureStatistics::min, &records::FigureStatistics::max};

// A listed figure's statistic over the seeds' values: the seeds with one (a flag: where it
// holds), or the median, min or max, a missing value ranked as the figure says.
Json statistic_of(const Figure& figure, const std::vector<std::optional<double>>& values,
                  Statistic statistic) {
  if (statistic == &records::FigureStatistics::count) {
    return std::count_if(values.begin(), values.end(), [&](const auto& value) {
      return value && (figure.type != ValueType::kFlag || *value != 0.0);
    });
  }
  const std::vector<double> sorted = ranked(values, figure.missing);
  const double result = sorted.empty()                                 ? NAN
                        : statistic == &records::FigureStatistics::min ? sorted.front()
                        : statistic == &records::FigureStatistics::max ? sorted.back()
                                                                       : middle(sorted);
  const bool whole =
      figure.type != ValueType::kNumber && statistic != &records::FigureStatistics::median;
  return whole && std::isfinite(result) ? Json(static_cast<long long>(result)) : Json(result);
}

// Listed figures per seed, then their statistics (counts, medians, minima, maxima, in turn).
void add_listed(Json& arm, const ExperimentResults& results, std::size_t a,
                const std::vector<Figure>& figures) {
  for (const Figure& figure : figures) {
    if (figure.summary != FigureSummary::kList) continue;
    Json list = Json::array();
    for (const auto& value : seed_values(results, a, figure)) {
      list.push_back(json_value(figure.type, value));
    }
    arm[figure.name] = list;
  }
  for (const Statistic statistic : kStatistics) {
    for (const Figure& figure : figures) {
      const std::string& key = figure.statistics.*statistic;
      if (figure.summary != FigureSummary::kList || key.empty()) continue;
      arm[key] = statistic_of(figure, seed_values(results, a, figure), statistic);
    }
  }
}

// The learnt actor alone: per evaluation angle, the seeds whose policy balanced for a whole
// trial, of the seeds that have a policy (none when no seed has).
void add_evaluation(Json& arm, const ExperimentResults& results, std::size_t a) {
  const std::vector<records::EvaluationRecord>* angles = nullptr;
  int evaluated = 0;
  for (std::size_t s = 0; s < results.seeds.size(); ++s) {
    const auto& evaluation = results.run(a, s).evaluation;
    if (evaluation.empty()) continue;
    ++evaluated;
    if (angles == nullptr) angles = &evaluation;
  }
  if (angles == nullptr) return;
  Json theta0 = Json::array();
  Json balanced = Json::array();
  for (std::size_t e = 0; e < angles->size(); ++e) {
    theta0.push_back((*angles)[e].theta0);
    int count = 0;
    for (std::size_t s = 0; s < results.seeds.size(); ++s) {
      const auto& evaluation = results.run(a, s).evaluation;
      count += e < evaluation.size() && evaluation[e].outcome.status == TrialStatus::kSuccess;
    }
    balanced.push_back(count);
  }
  arm["evaluation"] = {{"theta0", theta0}, {"balanced", balanced}, {"of", evaluated}};
}

// Per seed, whether its weights stopped being finite (none when no seed's did).
void add_weights_diverged(Json& arm, const ExperimentResults& results, std::size_t a) {
  Json flags = Json::array();
  bool any = false;
  for (std::size_t s = 0; s < results.seeds.size(); ++s) {
    const bool diverged = results.run(a, s).weights_diverged;
    any = any || diverged;
    flags.push_back(diverged);
  }
  if (any) arm["weights_diverged"] = flags;
}

// The summed figures over the seeds that have them (none when the schema sums none).
void add_sums(Json& arm, const ExperimentResults& results, std::size_t a) {
  Json sums = Json::object();
  for (const Figure& figure : results.schema.figures) {
    if (figure.summary != FigureSummary::kSum) continue;
    double total = 0.0;
    for (const auto& value : seed_values(results, a, figure)) total += value.value_or(0.0);
    sums[figure.name] = total;
  }
  if (!sums.empty()) arm["figures"] = sums;
}

Json arm_summary(const ExperimentResults& results, std::size_t a) {
  Json arm = Json::object();
  add_listed(arm, results, a, records::run_figures());
  add_evaluation(arm, results, a);
  add_weights_diverged(arm, results, a);
  add_sums(arm, results, a);
  add_listed(arm, results, a, results.schema.figures);
  return arm;
}

// One figure per seed of arm `arm` for a paired comparison: a missing value beyond every
// count of trials (max_trials + 1), or NaN.
std::vector<double> paired_values(const ExperimentResults& results, std::size_t arm,
                                  const Figure& figure, long long max_trials) {
  std::vector<double> values;
  for (const auto& value : seed_values(results, arm, figure)) {
    const double beyond = figure.missing == Missing::kBeyondMaxTrials
                              ? static_cast<double>(max_trials + 1)
                              : static_cast<double>(NAN);
    values.push_back(value.value_or(beyond));
  }
  return values;
}

// The first arm against every other, seed by seed (common random numbers), on the figures the
// schema pairs; none for one arm.
Json paired_summary(const ExperimentResults& results, long long max_trials) {
  std::vector<Figure> figures;
  if (results.schema.pairs_failures) figures.push_back(records::run_figures().front());
  for (const Figure& figure : results.schema.figures) {
    if (figure.paired) figures.push_back(figure);
  }
  Json paired = Json::array();
  if (results.arms.size() < 2) return paired;
  for (std::size_t b = 1; b < results.arms.size(); ++b) {
    for (const Figure& figure : figures) {
      const records::PairedComparison c =
          records::compare_paired(paired_values(results, 0, figure, max_trials),
                                  paired_values(results, b, figure, max_trials));
      paired.push_back({{"a", results.arms[0]},
                        {"b", results.arms[b]},
                        {"figure", figure.name},
                        {"mean_b_minus_a", c.mean},
                        {"ci95", {c.ci_low, c.ci_high}},
                        {"b_greater", c.positive},
                        {"b_less", c.negative},
                        {"ties", c.ties},
                        {"sign_test_p", c.sign_test_p}});
    }
  }
  return paired;
}

Json schema_figure(const Figure& figure) {
  Json json = {{"name", figure.name},       {"type", records::to_string(figure.type)},
               {"meaning", figure.meaning}, {"summary", records::to_string(figure.summary)},
               {"paired", figure.paired},   {"missing", records::to_string(figure.missing)}};
  Json statistics = Json::object();
  for (const auto& [name, key] : {std::pair{"count", figure.statistics.count},
                                  {"median", figure.statistics.median},
                                  {"min", figure.statistics.min},
                                  {"max", figure.statistics.max}}) {
    if (!key.empty()) statistics[name] = key;
  }
  json["statistics"] = statistics;
  if (!figure.console.empty()) json["console"] = figure.console;
  return json;
}

// A task's steps rows start with their header line. The first line of task `task`'s rows, ""
// without rows.
std::string first_steps_line(const SeedRun& run, const TaskStore* store, std::size_t task) {
  if (store == nullptr) return run.steps_csv.substr(0, run.steps_csv.find('\n'));
  std::ifstream rows(store->steps_path(task), std::ios::binary);
  if (!rows) throw std::runtime_error("missing '" + store->steps_path(task).string() + "'");
  std::string line;
  std::getline(rows, line);
  return line;
}

// steps.csv: one header, then every task's rows in task order (the header alone when no task
// logged a row). Throws std::runtime_error when two tasks' plants give different signals
// (their rows would not share columns).
void write_steps_csv(const ExperimentResults& results, const std::filesystem::path& path,
                     const TaskStore* store) {
  std::string header;
  for (std::size_t task = 0; task < results.runs.size(); ++task) {
    const std::string first = first_steps_line(results.runs[task], store, task);
    if (first.empty()) continue;
    if (header.empty()) header = first;
    if (first != header) {
      throw std::runtime_error("cannot write '" + path.string() +
                               "': the arms' plants give different signals (" + header +
                               " against " + first + ")");
    }
  }
  if (header.empty()) header = results.steps_header.substr(0, results.steps_header.find('\n'));
  write_atomically(path, [&](std::ostream& steps) {
    steps << header << '\n';
    for (std::size_t task = 0; task < results.runs.size(); ++task) {
      if (store == nullptr) {
        const std::string& text = results.runs[task].steps_csv;
        const std::size_t skip = text.empty() ? 0 : text.find('\n') + 1;
        steps.write(text.data() + skip, static_cast<std::streamsize>(text.size() - skip));
        continue;
      }
      std::ifstream rows(store->steps_path(task), std::ios::binary);
      std::string skipped;
      std::getline(rows, skipped);  // its header
      if (rows.peek() != std::ifstream::traits_type::eof()) steps << rows.rdbuf();
    }
  });
}

}  // namespace

std::string csv_field(const std::string& text) {
  if (text.find_first_of(",\"") == std::string::npos) return text;
  std::string field = "\"";
  for (const char c : text) {
    if (c == '"') field += '"';
    field += c;
  }
  field += '"';
  return field;
}

double median(std::vector<int> values) {
  std::sort(values.begin(), values.end());
  const std::size_t n = values.size();
  return n % 2 == 1 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
}

std::string trials_csv(const ExperimentResults& results) {
  const std::vector<records::Column>& columns = results.schema.trial_columns;
  std::string csv = "arm,seed,trial,failed,steps,mean_temperature,mean_entropy,final_theta,status";
  for (const auto& column : columns) {
    csv += ',';
    csv += column.name;
  }
  csv += '\n';
  for (const SeedRun& run : results.runs) {
    for (const TrialRecord& record : run.trials) {
      const TrialOutcome& outcome = record.outcome;
      csv += run.arm + "," + std::to_string(run.seed) + "," + std::to_string(record.trial) + "," +
             (outcome.status == TrialStatus::kSuccess ? "0" : "1") + "," +
             std::to_string(outcome.steps) + "," + number(outcome.mean_temperature) + "," +
             number(outcome.mean_entropy) + "," + number(outcome.final_theta) + "," +
             to_string(outcome.status);
      for (const auto& column : columns) {
        csv += ',';
        csv += cell(column.type, record.value(column.name));
      }
      csv += '\n';
    }
  }
  return csv;
}

std::string evaluation_csv(const ExperimentResults& results) {
  std::string csv = "arm,seed,theta0,balanced,steps,final_theta,status\n";
  for (const SeedRun& run : results.runs) {
    for (const EvaluationRecord& record : run.evaluation) {
      const TrialOutcome& outcome = record.outcome;
      csv += run.arm + "," + std::to_string(run.seed) + "," + number(record.theta0) + "," +
             (outcome.status == TrialStatus::kSuccess ? "1" : "0") + "," +
             std::to_string(outcome.steps) + "," + number(outcome.final_theta) + "," +
             to_string(outcome.status) + "\n";
    }
  }
  return csv;
}

std::string figures_csv(const ExperimentResults& results) {
  std::string csv = "arm,seed";
  for (const Figure& figure : results.schema.figures) {
    csv += ',';
    csv += csv_field(figure.name);
  }
  csv += '\n';
  for (const SeedRun& run : results.runs) {
    csv += run.arm + "," + std::to_string(run.seed);
    for (const Figure& figure : results.schema.figures) {
      csv += ',';
      csv += cell(figure.type, run.figure(figure.name));
    }
    csv += '\n';
  }
  return csv;
}

std::string summary_json(const ExperimentResults& results, const RunFacts& facts) {
  Json summary = {{"experiment", results.experiment},
                  {"plant", facts.plant},
                  {"max_trials", facts.max_trials},
                  {"seeds", results.seeds}};
  Json arms = Json::object();
  for (std::size_t a = 0; a < results.arms.size(); ++a) {
    arms[results.arms[a]] = arm_summary(results, a);
  }
  summary["arms"] = arms;
  if (Json paired = paired_summary(results, facts.max_trials); !paired.empty()) {
    summary["paired"] = paired;
  }
  Json reference = Json::object();
  for (const auto& [arm, failures] : results.schema.reference) {
    if (std::find(results.arms.begin(), results.arms.end(), arm) != results.arms.end()) {
      reference[arm] = failures;
    }
  }
  if (!reference.empty()) summary["paper"] = reference;
  summary["note"] =
      "failures_before_success counts failed or diverged trials before the first success; a "
      "seed that never succeeded counts all its trials";
  return json_text(summary);
}

std::string schema_json(const ExperimentResults& results) {
  const ResultsSchema& schema = results.schema;
  Json columns = Json::array();
  for (const auto& column : schema.trial_columns) {
    columns.push_back({{"name", column.name},
                       {"type", records::to_string(column.type)},
                       {"meaning", column.meaning}});
  }
  Json figures = Json::array();
  for (Figure figure : records::run_figures()) {
    figure.paired = figure.name == "failures_before_success" && schema.pairs_failures;
    figures.push_back(schema_figure(figure));
  }
  for (const Figure& figure : schema.figures) figures.push_back(schema_figure(figure));
  Json reference = Json::object();
  for (const auto& [arm, failures] : schema.reference) reference[arm] = failures;
  return json_text(
      {{"format", "cbbg-schema 1"},
       {"experiment", results.experiment},
       {"trial_columns", columns},
       {"evaluates", schema.evaluates},
       {"figures", figures},
       {"pairs_failures", schema.pairs_failures},
       {"headline", schema.headline_name()},
       {"console", schema.console == records::ConsoleTable::kTrials ? "trials" : "headline"},
       {"plots", schema.plots},
       {"reference", reference}});
}

RunFacts run_facts(const parameters::Parameters& parameters) {
  return {parameters.plant.kind, parameters.run.max_trials, parameters.log.decimation};
}

config::Config recorded_config(const ExperimentResults& results, config::Config config) {
  if (!results.compares_arms) return config;
  config.set("arms=[" + config::join(results.arms) + "]", "the arms the protocol compared");
  return config;
}

namespace {

// The text files of a results directory, in the order they are written.
std::vector<std::pair<std::string, std::string>> result_texts(const ExperimentResults& results,
                                                              const config::Config& config,
                                                              const RunFacts& facts) {
  std::vector<std::pair<std::string, std::string>> texts{
      {"config.yaml", recorded_config(results, config).to_yaml()},
      {"schema.json", schema_json(results)},
      {"summary.json", summary_json(results, facts)},
      {"trials.csv", trials_csv(results)}};
  if (results.schema.evaluates) texts.emplace_back("evaluation.csv", evaluation_csv(results));
  if (!results.schema.figures.empty()) texts.emplace_back("figures.csv", figures_csv(results));
  return texts;
}

}  // namespace

void write_result_files(const ExperimentResults& results, const config::Config& config,
                        const RunFacts& facts, const std::filesystem::path& directory,
                        const TaskStore* store) {
  for (const auto& [name, text] : result_texts(results, config, facts)) {
    write_atomically(directory / name, text);
    // A kill after the summary leaves half the files: resume rewrites them.
    if (name == "summary.json") fault_point("commit:results");
  }
  for (const SeedRun& run : results.runs) {
    if (run.weights) {
      save_weights(directory / "weights" / (run.arm + "_seed" + std::to_string(run.seed) + ".txt"),
                   *run.weights);
    }
  }
  if (facts.log_decimation <= 0) return;
  write_steps_csv(results, directory / "steps.csv", store);
}

}  // namespace cbbg::store
