#include "cbbg/store/results_writer.h"

#include "cbbg/config/parameters.h"
#include "cbbg/diagrams/plant_kinds.h"
#include "cbbg/experiments/paired_statistics.h"
#include "cbbg/experiments/protocols.h"
#include "cbbg/store/fault_point.h"
#include "cbbg/store/files.h"
#include "cbbg/store/task_store.h"
#include "cbbg/store/weights_file.h"

#include <algorithm>
#include <charconv>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace cbbg::store {

using experiments::EvaluationRecord;
using experiments::SeedRun;
using experiments::steps_csv_header;
using experiments::to_string;
using experiments::TrialOutcome;
using experiments::TrialRecord;
using experiments::TrialStatus;
namespace {

std::string number(double value) {
  if (!std::isfinite(value)) return "nan";
  char buffer[32];
  return std::string(buffer, std::to_chars(buffer, buffer + sizeof buffer, value).ptr);
}

std::string json_number(double value) { return std::isfinite(value) ? number(value) : "null"; }

// The learnt actor alone: per evaluation angle, the seeds whose policy balanced for a whole
// trial, of the seeds that have a policy ("" when none has: no key).
std::string evaluation_json(const ExperimentResults& results, std::size_t arm) {
  const std::vector<experiments::EvaluationRecord>* angles = nullptr;
  int evaluated = 0;
  for (std::size_t s = 0; s < results.seeds.size(); ++s) {
    const auto& evaluation = results.run(arm, s).evaluation;
    if (evaluation.empty()) continue;
    ++evaluated;
    if (angles == nullptr) angles = &evaluation;
  }
  if (angles == nullptr) return "";
  std::string json = ",\n      \"evaluation\": {\"theta0\": [";
  for (std::size_t e = 0; e < angles->size(); ++e) {
    json += (e ? ", " : "") + number((*angles)[e].theta0);
  }
  json += "], \"balanced\": [";
  for (std::size_t e = 0; e < angles->size(); ++e) {
    int balanced = 0;
    for (std::size_t s = 0; s < results.seeds.size(); ++s) {
      const auto& evaluation = results.run(arm, s).evaluation;
      balanced += e < evaluation.size() && evaluation[e].outcome.status == TrialStatus::kSuccess;
    }
    json += (e ? ", " : "") + std::to_string(balanced);
  }
  return json + "], \"of\": " + std::to_string(evaluated) + "}";
}

// Per seed, whether its weights stopped being finite ("" when none did: no key).
std::string weights_diverged_json(const ExperimentResults& results, std::size_t arm) {
  std::string flags;
  bool any = false;
  for (std::size_t s = 0; s < results.seeds.size(); ++s) {
    const bool diverged = results.run(arm, s).weights_diverged;
    any = any || diverged;
    flags += std::string(s ? ", " : "") + (diverged ? "true" : "false");
  }
  return any ? ",\n      \"weights_diverged\": [" + flags + "]" : "";
}

// exp3's skill per seed: trials and failures to it, null where max_trials came first;
// the median and range count a seed that never got there as beyond every other.
std::string skill_json(const ExperimentResults& results, std::size_t arm) {
  std::ostringstream trials;
  std::ostringstream failures;
  std::vector<double> sorted;
  int reached = 0;
  for (std::size_t s = 0; s < results.seeds.size(); ++s) {
    const SeedRun& run = results.run(arm, s);
    const char* comma = s ? ", " : "";
    trials << comma;
    failures << comma;
    if (run.trials_to_skill) {
      trials << *run.trials_to_skill;
      failures << run.failures_to_skill.value_or(0);
      ++reached;
    } else {
      trials << "null";
      failures << "null";
    }
    sorted.push_back(run.trials_to_skill ? *run.trials_to_skill : INFINITY);
  }
  std::sort(sorted.begin(), sorted.end());
  const std::size_t n = sorted.size();
  const double middle = n % 2 == 1 ? sorted[n / 2] : 0.5 * (sorted[n / 2 - 1] + sorted[n / 2]);
  std::ostringstream json;
  json << ",\n      \"trials_to_skill\": [" << trials.str() << "],\n      \"failures_to_skill\": ["
       << failures.str() << "],\n      \"num_skilled\": " << reached
       << ",\n      \"skill_median\": " << json_number(middle)
       << ",\n      \"skill_min\": " << json_number(sorted.front())
       << ",\n      \"skill_max\": " << json_number(sorted.back());
  return json.str();
}

// A text as a JSON string.
std::string json_text(const std::string& text) {
  std::string json = "\"";
  for (const char c : text) {
    if (c == '"' || c == '\\') json += '\\';
    json += c;
  }
  json += '"';
  return json;
}

// The names of the runs' own figures (SeedRun::figures), the first run's order. Throws
// std::runtime_error when two runs name different figures (their columns would differ).
std::vector<std::string> figure_names(const ExperimentResults& results) {
  std::vector<std::string> names;
  const SeedRun* first = nullptr;
  for (const SeedRun& run : results.runs) {
    std::vector<std::string> own;
    for (const auto& figure : run.figures) own.push_back(figure.name);
    if (first == nullptr) {
      first = &run;
      names = own;
    } else if (own != names) {
      throw std::runtime_error("the runs of " + results.experiment + " record different figures (" +
                               first->arm + " seed " + std::to_string(first->seed) + " and " +
                               run.arm + " seed " + std::to_string(run.seed) + ")");
    }
  }
  return names;
}

double figure_of(const SeedRun& run, const std::string& name) {
  for (const auto& figure : run.figures) {
    if (figure.name == name) return figure.value;
  }
  return NAN;
}

// Per arm, each of the runs' own figures summed over the seeds ("" when there are none).
std::string figures_json(const ExperimentResults& results, std::size_t arm) {
  const std::vector<std::string> names = figure_names(results);
  if (names.empty()) return "";
  std::string json = ",\n      \"figures\": {";
  for (std::size_t f = 0; f < names.size(); ++f) {
    double total = 0.0;
    for (std::size_t s = 0; s < results.seeds.size(); ++s) {
      total += figure_of(results.run(arm, s), names[f]);
    }
    if (f > 0) json += ", ";
    json += json_text(names[f]);
    json += ": ";
    json += json_number(total);
  }
  return json + "}";
}

// One figure per seed of arm `arm`: exp1's failures before success, exp3's trials to the
// skill (max_trials + 1 where it was not reached), or one of the runs' own figures.
std::vector<double> per_seed(const ExperimentResults& results, std::size_t arm,
                             const std::string& figure, long long max_trials) {
  std::vector<double> values;
  for (std::size_t s = 0; s < results.seeds.size(); ++s) {
    const SeedRun& run = results.run(arm, s);
    if (figure == "trials_to_skill") {
      values.push_back(static_cast<double>(run.trials_to_skill.value_or(max_trials + 1)));
    } else if (figure == "failures_before_success") {
      values.push_back(run.failures_before_success);
    } else {
      values.push_back(figure_of(run, figure));
    }
  }
  return values;
}

// The first arm against every other, seed by seed (common random numbers).
std::string paired_json(const ExperimentResults& results, const config::Config& config) {
  const experiments::ResultsShape& shape = experiments::results_shape(results.experiment);
  if (results.arms.size() < 2 || !shape.paired) return "";
  std::vector<std::string> figures{"failures_before_success"};
  if (shape.skill) figures.push_back("trials_to_skill");
  for (const std::string& name : figure_names(results)) {
    if (shape.pairs_figure && shape.pairs_figure(name)) figures.push_back(name);
  }
  const auto max_trials = config::read_parameters(config).run.max_trials;
  std::ostringstream json;
  json << "  \"paired\": [";
  const char* separator = "\n";
  for (std::size_t b = 1; b < results.arms.size(); ++b) {
    for (const std::string& figure : figures) {
      const experiments::PairedComparison c = experiments::compare_paired(
          per_seed(results, 0, figure, max_trials), per_seed(results, b, figure, max_trials));
      json << separator << "    {\"a\": \"" << results.arms[0] << "\", \"b\": \"" << results.arms[b]
           << "\", \"figure\": " << json_text(figure) << ", \"mean_b_minus_a\": " << number(c.mean)
           << ", \"ci95\": [" << number(c.ci_low) << ", " << number(c.ci_high)
           << "], \"b_greater\": " << c.positive << ", \"b_less\": " << c.negative
           << ", \"ties\": " << c.ties << ", \"sign_test_p\": " << number(c.sign_test_p) << "}";
      separator = ",\n";
    }
  }
  json << "\n  ],\n";
  return json.str();
}

// The paper's figures of the arms that ran (ResultsShape::paper), on the paper's robot; ""
// when there are none.
std::string paper_json(const ExperimentResults& results, const config::Parameters& parameters) {
  if (!diagrams::same_robot(parameters.plant.kind, "simbody")) return "";
  std::string json;
  for (const auto& [arm, failures] : experiments::results_shape(results.experiment).paper) {
    if (std::find(results.arms.begin(), results.arms.end(), arm) == results.arms.end()) continue;
    json += (json.empty() ? "" : ", ") + json_text(arm) + ": " + std::to_string(failures);
  }
  return json.empty() ? "" : "  \"paper\": {" + json + "},\n";
}

// A task's steps rows start with their header line; a task stored by the previous release,
// without one, has the two-wheeler's. The first line of task `task`'s rows, "" without rows.
std::string first_steps_line(const SeedRun& run, const TaskStore* store, std::size_t task) {
  if (store == nullptr) return run.steps_csv.substr(0, run.steps_csv.find('\n'));
  std::ifstream rows(store->steps_path(task), std::ios::binary);
  if (!rows) throw std::runtime_error("missing '" + store->steps_path(task).string() + "'");
  std::string line;
  std::getline(rows, line);
  return line;
}

bool is_steps_header(const std::string& line) { return line.starts_with("arm,seed,trial,t,"); }

// The header line the rows after `first_line` have, "" for no rows.
std::string steps_header_of(const std::string& first_line) {
  if (first_line.empty()) return "";
  return is_steps_header(first_line) ? first_line + "\n" : steps_csv_header();
}

// steps.csv: one header, then every task's rows in task order. Throws std::runtime_error
// when two tasks' plants give different signals (their rows would not share columns).
void write_steps_csv(const ExperimentResults& results, const std::filesystem::path& path,
                     const TaskStore* store) {
  std::vector<bool> has_header(results.runs.size());
  std::string header;
  for (std::size_t task = 0; task < results.runs.size(); ++task) {
    const std::string first = first_steps_line(results.runs[task], store, task);
    has_header[task] = is_steps_header(first);
    const std::string own = steps_header_of(first);
    if (header.empty()) header = own;
    if (!own.empty() && own != header) {
      throw std::runtime_error(
          "cannot write '" + path.string() + "': the arms' plants give different signals (" +
          header.substr(0, header.size() - 1) + " against " + own.substr(0, own.size() - 1) + ")");
    }
  }
  write_atomically(path, [&](std::ostream& steps) {
    steps << (header.empty() ? steps_csv_header() : header);
    for (std::size_t task = 0; task < results.runs.size(); ++task) {
      if (store == nullptr) {
        const std::string& text = results.runs[task].steps_csv;
        const std::size_t skip = has_header[task] ? text.find('\n') + 1 : 0;
        steps.write(text.data() + skip, static_cast<std::streamsize>(text.size() - skip));
        continue;
      }
      std::ifstream rows(store->steps_path(task), std::ios::binary);
      std::string skipped;
      if (has_header[task]) std::getline(rows, skipped);
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
  const experiments::ResultsShape& shape = experiments::results_shape(results.experiment);
  const bool skill = shape.skill;
  const bool oscillation = shape.oscillation;
  std::string csv = "arm,seed,trial,failed,steps,mean_temperature,mean_entropy,final_theta,status";
  if (skill) csv += ",actor_alone";
  if (oscillation) csv += ",pitch_rms,pitch_peak_to_peak,mean_forward_speed";
  csv += '\n';
  for (const SeedRun& run : results.runs) {
    for (const TrialRecord& record : run.trials) {
      const TrialOutcome& outcome = record.outcome;
      csv += run.arm + "," + std::to_string(run.seed) + "," + std::to_string(record.trial) + "," +
             (outcome.status == TrialStatus::kSuccess ? "0" : "1") + "," +
             std::to_string(outcome.steps) + "," + number(outcome.mean_temperature) + "," +
             number(outcome.mean_entropy) + "," + number(outcome.final_theta) + "," +
             to_string(outcome.status);
      if (skill) {
        csv += ',';
        if (record.actor_alone_passed) csv += *record.actor_alone_passed ? '1' : '0';
      }
      if (oscillation) {
        for (const double figure :
             {outcome.pitch_rms, outcome.pitch_peak_to_peak, outcome.mean_forward_speed}) {
          csv += ',';
          csv += number(figure);
        }
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
  const std::vector<std::string> names = figure_names(results);
  std::string csv = "arm,seed";
  for (const std::string& name : names) {
    csv += ',';
    csv += csv_field(name);
  }
  csv += '\n';
  for (const SeedRun& run : results.runs) {
    csv += run.arm + "," + std::to_string(run.seed);
    for (const auto& figure : run.figures) {
      csv += ',';
      csv += number(figure.value);
    }
    csv += '\n';
  }
  return csv;
}

std::string summary_json(const ExperimentResults& results, const config::Config& config) {
  const config::Parameters parameters = config::read_parameters(config);
  std::ostringstream json;
  json << "{\n  \"experiment\": \"" << results.experiment << "\",\n";
  json << "  \"plant\": \"" << parameters.plant.kind << "\",\n";
  json << "  \"max_trials\": " << parameters.run.max_trials << ",\n";
  json << "  \"seeds\": [";
  for (std::size_t s = 0; s < results.seeds.size(); ++s)
    json << (s ? ", " : "") << results.seeds[s];
  json << "],\n  \"arms\": {";
  for (std::size_t a = 0; a < results.arms.size(); ++a) {
    std::vector<int> failures;
    std::string succeeded;
    int num_succeeded = 0;
    for (std::size_t s = 0; s < results.seeds.size(); ++s) {
      const SeedRun& run = results.run(a, s);
      failures.push_back(run.failures_before_success);
      succeeded += std::string(s ? ", " : "") + (run.succeeded ? "true" : "false");
      num_succeeded += run.succeeded ? 1 : 0;
    }
    json << (a ? "," : "") << "\n    \"" << results.arms[a] << "\": {\n";
    json << "      \"failures_before_success\": [";
    for (std::size_t s = 0; s < failures.size(); ++s) json << (s ? ", " : "") << failures[s];
    json << "],\n      \"succeeded\": [" << succeeded << "],\n";
    json << "      \"num_succeeded\": " << num_succeeded << ",\n";
    json << "      \"median\": " << json_number(median(failures)) << ",\n";
    json << "      \"min\": " << *std::min_element(failures.begin(), failures.end()) << ",\n";
    json << "      \"max\": " << *std::max_element(failures.begin(), failures.end());
    json << evaluation_json(results, a) << weights_diverged_json(results, a)
         << figures_json(results, a);
    if (experiments::results_shape(results.experiment).skill) json << skill_json(results, a);
    json << "\n    }";
  }
  json << "\n  },\n" << paired_json(results, config) << paper_json(results, parameters);
  json << "  \"note\": \"failures_before_success counts failed or diverged trials before the "
          "first success; a seed that never succeeded counts all its trials\"\n}\n";
  return json.str();
}

config::Config recorded_config(const ExperimentResults& results, config::Config config) {
  if (!results.compares_arms) return config;
  config::Parameters parameters = config::read_parameters(config);
  parameters.run.arms = results.arms;
  config::write_parameters(parameters, config);
  return config;
}

void write_result_files(const ExperimentResults& results, const config::Config& config,
                        const std::filesystem::path& directory, const TaskStore* store) {
  write_atomically(directory / "config.yaml", recorded_config(results, config).to_yaml());
  write_atomically(directory / "summary.json", summary_json(results, config));
  fault_point("commit:results");  // a kill here leaves half the files: resume rewrites them
  write_atomically(directory / "trials.csv", trials_csv(results));
  if (experiments::results_shape(results.experiment).evaluates) {
    write_atomically(directory / "evaluation.csv", evaluation_csv(results));
  }
  if (!figure_names(results).empty()) {
    write_atomically(directory / "figures.csv", figures_csv(results));
  }
  for (const SeedRun& run : results.runs) {
    if (run.weights) {
      save_weights(directory / "weights" / (run.arm + "_seed" + std::to_string(run.seed) + ".txt"),
                   *run.weights);
    }
  }
  if (config::read_parameters(config).log.decimation <= 0) return;
  write_steps_csv(results, directory / "steps.csv", store);
}

}  // namespace cbbg::store
