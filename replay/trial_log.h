#pragma once
// What a replay shows of a results directory: its trials (trials.csv) and, for the chosen
// ones, the logged ticks (steps.csv) of the signals the page draws.

#include <filesystem>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace cbbg::replay {

// A results directory that lacks what a replay needs, or holds it malformed: the message
// names the file (and the line or column).
class InputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// A choice (--arm, --seed, --trial) the run does not have; the message names the flag.
class ChoiceError : public std::invalid_argument {
 public:
  using std::invalid_argument::invalid_argument;
};

// One row of trials.csv.
struct TrialEntry {
  std::string arm;
  long long seed = 0;
  int trial = 0;
  std::string status;  // success | failed | diverged
};

// One trial's ticks, from steps.csv. Ticks end at the last one whose pose is finite. A pose
// signal the plant lacks (x, y or yaw; a cart-pole has no y nor yaw) is 0: the replay shows
// the robot where it has no pose, and moving only as far as it has one.
struct TrialLog {
  TrialEntry entry;
  std::vector<double> t, theta_b, phi_l, phi_r, x, y, yaw, a;

  // The columns above by their steps.csv names, t first: what the reader fills and the page
  // shows, listed once.
  static constexpr int kColumns = 8;
  static constexpr const char* kColumnNames[kColumns] = {"t", "theta_b", "phi_l", "phi_r",
                                                         "x", "y",       "yaw",   "a"};
  std::vector<double>& column(int index) { return this->*kMembers[index]; }
  const std::vector<double>& column(int index) const { return this->*kMembers[index]; }

 private:
  static constexpr std::vector<double> TrialLog::*kMembers[kColumns] = {
      &TrialLog::t, &TrialLog::theta_b, &TrialLog::phi_l, &TrialLog::phi_r,
      &TrialLog::x, &TrialLog::y,       &TrialLog::yaw,   &TrialLog::a};
};

// The rows of DIR/trials.csv, in file order. Throws InputError naming the file.
std::vector<TrialEntry> read_trial_entries(const std::filesystem::path& trials_csv);

// The ticks of each wanted trial from steps.csv, in one pass, in the order of `wanted`.
// Throws InputError naming the file: missing, without a column the page needs (x, y and yaw
// may be absent), malformed, or without rows for a wanted trial.
std::vector<TrialLog> read_trial_logs(const std::filesystem::path& steps_csv,
                                      const std::vector<TrialEntry>& wanted);

// Which trials of a run to show: empty means the run's first arm, that arm's first seed, and
// default_trials of them.
struct TrialChoice {
  std::optional<std::string> arm;
  std::optional<long long> seed;
  std::vector<int> trials;
};

// The entries `choice` picks, in its order. Throws ChoiceError naming the flag and what the
// run has, or InputError for a trials.csv without trials.
std::vector<TrialEntry> choose_trials(const std::vector<TrialEntry>& entries,
                                      const TrialChoice& choice);

// Of one arm's seed (its trials in order): the first trial, the first successful one and the
// last (exp2's late trials), each once.
std::vector<TrialEntry> default_trials(const std::vector<TrialEntry>& of_seed);

}  // namespace cbbg::replay
