#include "cbbg/replay/trial_log.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <fstream>
#include <map>
#include <string_view>
#include <tuple>

namespace cbbg::replay {
namespace {

std::vector<std::string_view> split(std::string_view line) {
  std::vector<std::string_view> fields;
  for (std::size_t start = 0;;) {
    const std::size_t comma = line.find(',', start);
    fields.push_back(line.substr(start, comma - start));
    if (comma == std::string_view::npos) return fields;
    start = comma + 1;
  }
}

// A CSV file read line by line, with its header's columns by name.
class CsvFile {
 public:
  explicit CsvFile(const std::filesystem::path& path) : path_(path), in_(path) {
    if (!in_) throw InputError(path_.string() + ": cannot be read (is this a results directory?)");
    std::string header;
    if (!std::getline(in_, header)) throw InputError(path_.string() + ": empty, no header");
    const auto names = split(header);
    for (std::size_t i = 0; i < names.size(); ++i) columns_[std::string(names[i])] = i;
  }

  bool has(const std::string& name) const { return columns_.contains(name); }

  std::size_t column(const std::string& name) const {
    const auto found = columns_.find(name);
    if (found == columns_.end()) {
      throw InputError(path_.string() + ": no column '" + name + "' (a replay needs it)");
    }
    return found->second;
  }

  // The next row's fields, or false at the end. Throws on a row of another width.
  bool next(std::vector<std::string_view>& fields) {
    if (!std::getline(in_, line_)) return false;
    ++line_number_;
    fields = split(line_);
    if (fields.size() != columns_.size()) {
      fail("has " + std::to_string(fields.size()) + " fields; the header has " +
           std::to_string(columns_.size()));
    }
    return true;
  }

  double number(std::string_view field, const char* name) const {
    double value = 0.0;
    const auto [end, error] = std::from_chars(field.data(), field.data() + field.size(), value);
    if (error != std::errc() || end != field.data() + field.size()) {
      fail(std::string(name) + " is '" + std::string(field) + "', not a number");
    }
    return value;
  }

  long long integer(std::string_view field, const char* name) const {
    long long value = 0;
    const auto [end, error] = std::from_chars(field.data(), field.data() + field.size(), value);
    if (error != std::errc() || end != field.data() + field.size()) {
      fail(std::string(name) + " is '" + std::string(field) + "', not a whole number");
    }
    return value;
  }

  [[noreturn]] void fail(const std::string& what) const {
    throw InputError(path_.string() + ": line " + std::to_string(line_number_) + ": " + what);
  }

 private:
  std::filesystem::path path_;
  std::ifstream in_;
  std::map<std::string, std::size_t> columns_;
  std::string line_;
  long long line_number_ = 1;  // the header's
};

using Key = std::tuple<std::string, long long, int>;

// Drops the ticks from the first whose pose is not finite (a diverged trial's end).
void keep_finite_pose(TrialLog& log) {
  std::size_t keep = 0;
  while (keep < log.t.size() && std::isfinite(log.theta_b[keep]) &&
         std::isfinite(log.phi_l[keep]) && std::isfinite(log.phi_r[keep]) &&
         std::isfinite(log.x[keep]) && std::isfinite(log.y[keep]) && std::isfinite(log.yaw[keep])) {
    ++keep;
  }
  for (int c = 0; c < TrialLog::kColumns; ++c) log.column(c).resize(keep);
}

}  // namespace

std::vector<TrialEntry> read_trial_entries(const std::filesystem::path& trials_csv) {
  CsvFile file(trials_csv);
  const std::size_t arm = file.column("arm");
  const std::size_t seed = file.column("seed");
  const std::size_t trial = file.column("trial");
  const std::size_t status = file.column("status");
  std::vector<TrialEntry> entries;
  for (std::vector<std::string_view> fields; file.next(fields);) {
    entries.push_back({std::string(fields[arm]), file.integer(fields[seed], "seed"),
                       static_cast<int>(file.integer(fields[trial], "trial")),
                       std::string(fields[status])});
  }
  return entries;
}

std::vector<TrialLog> read_trial_logs(const std::filesystem::path& steps_csv,
                                      const std::vector<TrialEntry>& wanted) {
  CsvFile file(steps_csv);
  const std::size_t arm = file.column("arm");
  const std::size_t seed = file.column("seed");
  const std::size_t trial = file.column("trial");
  // A pose signal the plant does not have (or an older cbbg did not log) is absent: 0.
  constexpr std::size_t kAbsent = static_cast<std::size_t>(-1);
  std::size_t columns[TrialLog::kColumns];
  for (int c = 0; c < TrialLog::kColumns; ++c) {
    const std::string name = TrialLog::kColumnNames[c];
    const bool pose = name == "x" || name == "y" || name == "yaw";
    columns[c] = pose && !file.has(name) ? kAbsent : file.column(name);
  }

  std::vector<TrialLog> logs(wanted.size());
  std::map<Key, std::size_t> index;
  for (std::size_t i = 0; i < wanted.size(); ++i) {
    logs[i].entry = wanted[i];
    index[{wanted[i].arm, wanted[i].seed, wanted[i].trial}] = i;
  }
  for (std::vector<std::string_view> fields; file.next(fields);) {
    const auto found = index.find({std::string(fields[arm]), file.integer(fields[seed], "seed"),
                                   static_cast<int>(file.integer(fields[trial], "trial"))});
    if (found == index.end()) continue;
    TrialLog& log = logs[found->second];
    for (int c = 0; c < TrialLog::kColumns; ++c) {
      log.column(c).push_back(
          columns[c] == kAbsent ? 0.0 : file.number(fields[columns[c]], TrialLog::kColumnNames[c]));
    }
  }
  for (TrialLog& log : logs) {
    keep_finite_pose(log);
    if (log.t.empty()) {
      throw InputError(steps_csv.string() + ": no ticks of " + log.entry.arm + ", seed " +
                       std::to_string(log.entry.seed) + ", trial " +
                       std::to_string(log.entry.trial) +
                       " (was it run with log.decimation: 0, or cut short?)");
    }
  }
  return logs;
}

std::vector<TrialEntry> choose_trials(const std::vector<TrialEntry>& entries,
                                      const TrialChoice& choice) {
  if (entries.empty()) throw InputError("trials.csv has no trials");
  const std::string arm = choice.arm.value_or(entries.front().arm);
  std::vector<TrialEntry> of_arm;
  std::string arms;
  for (const TrialEntry& entry : entries) {
    if (entry.arm == arm) of_arm.push_back(entry);
    if (arms.find("'" + entry.arm + "'") == std::string::npos) {
      arms += arms.empty() ? "" : ", ";
      arms += "'" + entry.arm + "'";
    }
  }
  if (of_arm.empty()) throw ChoiceError("--arm: no arm '" + arm + "' in this run; it has " + arms);
  const long long seed = choice.seed.value_or(of_arm.front().seed);
  std::vector<TrialEntry> of_seed;
  for (const TrialEntry& entry : of_arm) {
    if (entry.seed == seed) of_seed.push_back(entry);
  }
  if (of_seed.empty()) {
    throw ChoiceError("--seed: arm '" + arm + "' has no seed " + std::to_string(seed) +
                      "; its seeds are " + std::to_string(of_arm.front().seed) + " to " +
                      std::to_string(of_arm.back().seed));
  }
  if (choice.trials.empty()) return default_trials(of_seed);
  std::vector<TrialEntry> chosen;
  for (const int number : choice.trials) {
    const auto found = std::find_if(of_seed.begin(), of_seed.end(),
                                    [number](const TrialEntry& e) { return e.trial == number; });
    if (found == of_seed.end()) {
      throw ChoiceError("--trial: arm '" + arm + "', seed " + std::to_string(seed) +
                        " has trials 1 to " + std::to_string(of_seed.back().trial) + "; got " +
                        std::to_string(number));
    }
    chosen.push_back(*found);
  }
  return chosen;
}

std::vector<TrialEntry> default_trials(const std::vector<TrialEntry>& of_seed) {
  std::vector<TrialEntry> chosen{of_seed.front()};
  auto add = [&chosen](const TrialEntry& entry) {
    if (entry.trial != chosen.back().trial && entry.trial != chosen.front().trial) {
      chosen.push_back(entry);
    }
  };
  const auto success = std::find_if(of_seed.begin(), of_seed.end(),
                                    [](const TrialEntry& e) { return e.status == "success"; });
  if (success != of_seed.end()) add(*success);
  add(of_seed.back());
  return chosen;
}

}  // namespace cbbg::replay
