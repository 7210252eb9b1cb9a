#include "store/results_writer.h"

#include "store/task_store.h"
#include "store/weights_file.h"

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

// The paper's failures before the first success (Fig. 11), for summary.json.
struct PaperReference {
  const char* arm;
  int failures;
};
constexpr PaperReference kPaper[] = {{"cbbg", 0}, {"bg_only", 8}};

std::string number(double value) {
  if (!std::isfinite(value)) return "nan";
  char buffer[32];
  return std::string(buffer, std::to_chars(buffer, buffer + sizeof buffer, value).ptr);
}

std::string json_number(double value) { return std::isfinite(value) ? number(value) : "null"; }

void write_text(const std::filesystem::path& path, const std::string& text) {
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out << text;
  if (!out) throw std::runtime_error("cannot write '" + path.string() + "'");
}

}  // namespace

double median(std::vector<int> values) {
  std::sort(values.begin(), values.end());
  const std::size_t n = values.size();
  return n % 2 == 1 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
}

std::string trials_csv(const ExperimentResults& results) {
  std::string csv =
      "arm,seed,trial,failed,steps,mean_temperature,mean_entropy,final_theta,status\n";
  for (const SeedRun& run : results.runs) {
    for (const TrialRecord& record : run.trials) {
      const TrialOutcome& outcome = record.outcome;
      csv += run.arm + "," + std::to_string(run.seed) + "," + std::to_string(record.trial) + "," +
             (outcome.status == TrialStatus::kSuccess ? "0" : "1") + "," +
             std::to_string(outcome.steps) + "," + number(outcome.mean_temperature) + "," +
             number(outcome.mean_entropy) + "," + number(outcome.final_theta) + "," +
             to_string(outcome.status) + "\n";
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

std::string summary_json(const ExperimentResults& results, const config::Config& config) {
  std::ostringstream json;
  json << "{\n  \"experiment\": \"" << results.experiment << "\",\n";
  json << "  \"plant\": \"" << config.text("plant.kind") << "\",\n";
  json << "  \"max_trials\": " << config.integer("max_trials") << ",\n";
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
    // The learnt actor alone: per evaluation angle, the seeds whose policy balanced 20 s.
    const auto& first = results.run(a, 0).evaluation;
    if (!first.empty()) {
      json << ",\n      \"evaluation\": {\"theta0\": [";
      for (std::size_t e = 0; e < first.size(); ++e)
        json << (e ? ", " : "") << number(first[e].theta0);
      json << "], \"balanced\": [";
      for (std::size_t e = 0; e < first.size(); ++e) {
        int balanced = 0;
        for (std::size_t s = 0; s < results.seeds.size(); ++s) {
          balanced += results.run(a, s).evaluation[e].outcome.status == TrialStatus::kSuccess;
        }
        json << (e ? ", " : "") << balanced;
      }
      json << "], \"of\": " << results.seeds.size() << "}";
    }
    json << "\n    }";
  }
  json << "\n  },\n  \"paper\": {";
  for (std::size_t p = 0; p < std::size(kPaper); ++p) {
    json << (p ? ", " : "") << "\"" << kPaper[p].arm << "\": " << kPaper[p].failures;
  }
  json << "},\n  \"note\": \"failures_before_success counts failed or diverged trials before the "
          "first success; a seed that never succeeded counts all its trials\"\n}\n";
  return json.str();
}

void write_result_files(const ExperimentResults& results, const config::Config& config,
                        const std::filesystem::path& directory, const TaskStore* store) {
  write_text(directory / "config.yaml", config.to_yaml());
  write_text(directory / "summary.json", summary_json(results, config));
  write_text(directory / "trials.csv", trials_csv(results));
  if (results.experiment != "exp2") {
    write_text(directory / "evaluation.csv", evaluation_csv(results));
  }
  for (const SeedRun& run : results.runs) {
    if (run.weights) {
      save_weights(directory / "weights" / (run.arm + "_seed" + std::to_string(run.seed) + ".txt"),
                   *run.weights);
    }
  }
  if (config.integer("log.decimation") <= 0) return;
  const std::filesystem::path path = directory / "steps.csv";
  std::ofstream steps(path, std::ios::binary | std::ios::trunc);
  steps << steps_csv_header();
  for (std::size_t task = 0; task < results.runs.size(); ++task) {
    if (store == nullptr) {
      steps << results.runs[task].steps_csv;
      continue;
    }
    std::ifstream rows(store->steps_path(task), std::ios::binary);
    if (!rows) throw std::runtime_error("missing '" + store->steps_path(task).string() + "'");
    if (rows.peek() != std::ifstream::traits_type::eof()) steps << rows.rdbuf();
  }
  if (!steps) throw std::runtime_error("cannot write '" + path.string() + "'");
}

RunDirectory::RunDirectory(std::filesystem::path target, config::Config config)
    : target_(std::move(target)), config_(std::move(config)) {
  if (target_.filename().empty()) target_ = target_.parent_path();
  work_ = target_;
  work_ += ".partial";
}

RunDirectory RunDirectory::create(const std::filesystem::path& target,
                                  const config::Config& config) {
  RunDirectory directory(target, config);
  if (std::filesystem::exists(directory.work_)) {
    throw config::ConfigError("'" + directory.work_.string() +
                              "' holds an interrupted run: continue it with --resume " +
                              directory.target_.string() + ", or delete it");
  }
  std::filesystem::create_directories(directory.tasks());
  write_text(directory.work_ / "config.yaml", config.to_yaml());
  return directory;
}

RunDirectory RunDirectory::resume(const std::filesystem::path& target) {
  RunDirectory directory(target, config::Config());
  const std::filesystem::path config_file = directory.work_ / "config.yaml";
  if (!std::filesystem::exists(config_file)) {
    throw config::ConfigError("nothing to resume: '" + directory.work_.string() +
                              "' does not hold an interrupted run");
  }
  directory.config_.merge_file(config_file);
  std::filesystem::create_directories(directory.tasks());
  return directory;
}

void RunDirectory::commit() {
  std::filesystem::remove_all(tasks());
  std::filesystem::path previous;
  if (std::filesystem::exists(target_)) {
    previous = target_;
    previous += ".previous";
    std::filesystem::remove_all(previous);
    std::filesystem::rename(target_, previous);
  }
  std::filesystem::rename(work_, target_);
  if (!previous.empty()) std::filesystem::remove_all(previous);
}

}  // namespace cbbg::store
