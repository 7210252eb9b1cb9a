#include "cbbg/store/task_store.h"

#include "cbbg/config/config.h"
#include "cbbg/framework/number_text.h"
#include "cbbg/store/fault_point.h"
#include "cbbg/store/files.h"
#include "cbbg/store/output_guard.h"
#include "cbbg/store/weights_file.h"

#include <algorithm>
#include <charconv>
#include <sstream>
#include <stdexcept>

namespace cbbg::store {

using records::EvaluationRecord;
using records::to_string;
using records::TrialOutcome;
using records::TrialRecord;
using records::TrialStatus;
namespace {

constexpr const char* kRecordFormat = "cbbg-task 2";
constexpr const char* kEarlierFormat = "cbbg-task 1";

// Where task `task`'s record is kept in `tasks`.
std::filesystem::path record_file(const std::filesystem::path& tasks, std::size_t task) {
  return tasks / (std::to_string(task) + ".run");
}

double parse_double(const std::string& text, const std::string& source) {
  double value = 0.0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (error != std::errc() || end != text.data() + text.size()) {
    throw std::runtime_error(source + ": '" + text + "' is not a number");
  }
  return value;
}

TrialStatus parse_status(const std::string& text, const std::string& source) {
  for (const TrialStatus status : {TrialStatus::kSuccess, TrialStatus::kFailed,
                                   TrialStatus::kDiverged, TrialStatus::kStopped}) {
    if (text == to_string(status)) return status;
  }
  throw std::runtime_error(source + ": unknown trial status '" + text + "'");
}

void write_outcome(std::ostringstream& out, const TrialOutcome& outcome) {
  out << ' ' << to_string(outcome.status) << ' ' << outcome.steps;
  for (const double figure :
       {outcome.mean_temperature, outcome.mean_entropy, outcome.final_theta, outcome.pitch_rms,
        outcome.pitch_peak_to_peak, outcome.mean_forward_speed}) {
    out << ' ' << format_number(figure);
  }
}

// "-" for none: a value a record may lack.
std::string value_text(const std::optional<double>& value) {
  return value ? format_number(*value) : "-";
}

TrialOutcome read_outcome(std::istringstream& in, const std::string& source) {
  std::string status;
  TrialOutcome outcome;
  in >> status >> outcome.steps;
  outcome.status = parse_status(status, source);
  for (double* figure :
       {&outcome.mean_temperature, &outcome.mean_entropy, &outcome.final_theta, &outcome.pitch_rms,
        &outcome.pitch_peak_to_peak, &outcome.mean_forward_speed}) {
    std::string text;
    in >> text;
    if (!in) throw std::runtime_error(source + ": truncated trial line");
    *figure = parse_double(text, source);
  }
  return outcome;
}

// "VALUE NAME", VALUE "-" for none: the name is the rest of the line, spaces and all.
records::NamedValue read_value(std::istringstream& in, const std::string& source) {
  std::string value;
  in >> value;
  std::string name;
  std::getline(in >> std::ws, name);
  if (name.empty()) throw std::runtime_error(source + ": a value without a name");
  if (value == "-") return {name, std::nullopt};
  return {name, parse_double(value, source)};
}

bool all_digits(const std::string& text) {
  return !text.empty() &&
         std::all_of(text.begin(), text.end(), [](char c) { return c >= '0' && c <= '9'; });
}

// N.run, N.steps.csv, N.steps.csv.pending, N.weights.txt, or a temporary of one.
bool is_task_file(const std::filesystem::path& path) {
  if (is_temporary(path)) return true;
  const std::string name = path.filename().string();
  const auto dot = name.find('.');
  if (dot == std::string::npos || !all_digits(name.substr(0, dot))) return false;
  const std::string kind = name.substr(dot);
  return kind == ".run" || kind == ".steps.csv" || kind == ".steps.csv.pending" ||
         kind == ".weights.txt";
}

// A sweep's tasks/POINT/ folder ("001") or a task file: what a tasks folder holds of cbbg's.
bool is_own_task_entry(const std::filesystem::directory_entry& entry) {
  std::error_code error;
  if (entry.is_directory(error)) return all_digits(entry.path().filename().string());
  return entry.is_regular_file(error) && is_task_file(entry.path());
}

}  // namespace

void check_own_tasks(const std::filesystem::path& tasks) {
  std::error_code error;
  for (std::filesystem::recursive_directory_iterator it(tasks, error), end; !error && it != end;
       it.increment(error)) {
    if (!is_own_task_entry(*it)) {
      throw config::ConfigError(quoted_path(it->path()) +
                                " is not a task file of cbbg's, and the tasks are removed when "
                                "the results are published; move it away first");
    }
  }
}

void remove_own_tasks(const std::filesystem::path& tasks) {
  std::vector<std::filesystem::path> files;
  std::vector<std::filesystem::path> folders;
  std::error_code error;
  for (std::filesystem::recursive_directory_iterator it(tasks, error), end; !error && it != end;
       it.increment(error)) {
    if (it->is_directory(error)) folders.push_back(it->path());
    if (!it->is_directory(error) && is_own_task_entry(*it)) files.push_back(it->path());
  }
  for (const auto& file : files) remove_tree(file);
  folders.insert(folders.begin(), tasks);
  // Deepest first; a folder still holding something of the user's stays.
  for (auto folder = folders.rbegin(); folder != folders.rend(); ++folder) {
    if (std::filesystem::is_empty(*folder, error)) remove_tree(*folder);
  }
}

std::string serialize_run(const SeedRun& run) {
  std::ostringstream out;
  out << kRecordFormat << "\narm " << run.arm << "\nseed " << run.seed << "\nsucceeded "
      << (run.succeeded ? 1 : 0) << "\nfailures_before_success " << run.failures_before_success
      << "\n";
  if (run.weights_diverged) out << "weights_diverged 1\n";
  for (const TrialRecord& record : run.trials) {
    out << "trial " << record.trial << ' ' << format_number(record.k1);
    write_outcome(out, record.outcome);
    out << "\n";
    for (const records::NamedValue& value : record.values) {
      out << "value " << value_text(value.value) << ' ' << value.name << "\n";
    }
  }
  for (const EvaluationRecord& record : run.evaluation) {
    out << "evaluation " << format_number(record.theta0);
    write_outcome(out, record.outcome);
    out << "\n";
  }
  for (const records::SeedFigure& figure : run.figures) {
    out << "figure " << value_text(figure.value) << ' ' << figure.name << "\n";
  }
  out << "end\n";
  return out.str();
}

SeedRun parse_run(const std::string& text, const std::string& source) {
  std::istringstream lines(text);
  std::string line;
  std::getline(lines, line);
  if (line != kRecordFormat) {
    throw std::runtime_error(source + ": not a " + std::string(kRecordFormat) + " record");
  }
  SeedRun run;
  bool ended = false;
  while (std::getline(lines, line)) {
    std::istringstream in(line);
    std::string key;
    in >> key;
    if (key == "arm") {
      in >> run.arm;
    } else if (key == "seed") {
      in >> run.seed;
    } else if (key == "succeeded" || key == "weights_diverged") {
      int flag = 0;
      in >> flag;
      (key == "succeeded" ? run.succeeded : run.weights_diverged) = flag != 0;
    } else if (key == "failures_before_success") {
      in >> run.failures_before_success;
    } else if (key == "trial") {
      TrialRecord record;
      std::string k1;
      in >> record.trial >> k1;
      record.k1 = parse_double(k1, source);
      record.outcome = read_outcome(in, source);
      run.trials.push_back(record);
    } else if (key == "value") {
      if (run.trials.empty()) throw std::runtime_error(source + ": a value before any trial");
      run.trials.back().values.push_back(read_value(in, source));
    } else if (key == "evaluation") {
      EvaluationRecord record;
      std::string theta0;
      in >> theta0;
      record.theta0 = parse_double(theta0, source);
      record.outcome = read_outcome(in, source);
      run.evaluation.push_back(record);
    } else if (key == "figure") {
      run.figures.push_back(read_value(in, source));
    } else if (key == "end") {
      ended = true;
    } else {
      throw std::runtime_error(source + ": unknown line '" + config::shown_text(line) + "'");
    }
    if (!in && key != "end")
      throw std::runtime_error(source + ": malformed line '" + config::shown_text(line) + "'");
  }
  if (!ended) throw std::runtime_error(source + ": the record is incomplete");
  return run;
}

std::size_t finished_tasks(const std::filesystem::path& tasks, std::size_t count) {
  std::size_t finished = 0;
  std::error_code error;
  for (std::size_t task = 0; task < count; ++task) {
    finished += std::filesystem::exists(record_file(tasks, task), error) ? 1 : 0;
  }
  return finished;
}

TaskStore::TaskStore(std::filesystem::path directory) : directory_(std::move(directory)) {
  std::filesystem::create_directories(directory_);
}

std::filesystem::path TaskStore::record_path(std::size_t task) const {
  return record_file(directory_, task);
}

std::filesystem::path TaskStore::pending_steps_path(std::size_t task) const {
  return directory_ / (std::to_string(task) + ".steps.csv.pending");
}

std::filesystem::path TaskStore::weights_path(std::size_t task) const {
  return directory_ / (std::to_string(task) + ".weights.txt");
}

std::filesystem::path TaskStore::steps_path(std::size_t task) const {
  return directory_ / (std::to_string(task) + ".steps.csv");
}

bool TaskStore::has(std::size_t task) const {
  std::error_code error;
  return std::filesystem::exists(record_path(task), error);
}

bool TaskStore::load(std::size_t task, SeedRun& run) const {
  const std::filesystem::path path = record_path(task);
  if (!std::filesystem::exists(path)) return false;
  const std::string text = read_text(path);
  if (text.starts_with(std::string(kEarlierFormat) + "\n")) {
    throw EarlierTaskRecord(quoted_path(path) + " is a task record of an earlier cbbg (" +
                            kEarlierFormat +
                            "), which this one cannot continue: finish the run with the cbbg "
                            "that started it, or start it again in a new directory");
  }
  try {
    SeedRun loaded = parse_run(text, path.string());
    if (loaded.arm != run.arm || loaded.seed != run.seed) {
      throw std::runtime_error(path.string() + ": holds " + loaded.arm + " seed " +
                               std::to_string(loaded.seed) + ", expected " + run.arm + " seed " +
                               std::to_string(run.seed));
    }
    if (std::filesystem::exists(weights_path(task))) {
      loaded.weights = load_weights(weights_path(task));
    }
    run = std::move(loaded);
  } catch (const std::runtime_error& error) {
    // The files are cbbg's own: the way forward is to redo that one task, not the whole run.
    throw std::runtime_error(std::string(error.what()) + "; remove " + quoted_path(path) +
                             " to redo that task (" + run.arm + " seed " +
                             std::to_string(run.seed) + "), then continue as before");
  }
  return true;
}

void TaskStore::save(std::size_t task, const SeedRun& run) const {
  fault_point("task:steps");
  if (std::filesystem::exists(pending_steps_path(task))) {
    std::filesystem::rename(pending_steps_path(task), steps_path(task));
  }
  fault_point("task:weights");
  if (run.weights) save_weights(weights_path(task), *run.weights);
  fault_point("task:record");
  write_atomically(record_path(task), serialize_run(run));
}

}  // namespace cbbg::store
