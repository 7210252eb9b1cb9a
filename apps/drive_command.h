#pragma once
// cbbg drive: a controller against a robot over UDP in real time (realtime/), its results
// directory a run's (trials.csv with the link's figures per trial, steps.csv, summary.json),
// so `cbbg plot` and `cbbg replay` show it. It is `cbbg run` of the protocol realtime with one
// arm and one seed on plant.kind remote. SIGINT or SIGTERM stops it cleanly: zero torque
// sent, the robot told, the trials so far written.

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace cbbg::app {

struct DriveOptions {
  // --controller: an arm (`cbbg list`): cbbg learns on, pd_only is the supervisor alone.
  std::string controller = "cbbg";
  // --policy: the arm's learnt actor alone, frozen, with the weights of --load-weights.
  bool policy = false;
  std::filesystem::path weights_file;   // --load-weights: where learning starts, or the policy
  std::filesystem::path config_file;    // --config; empty: defaults only
  std::vector<std::string> sets;        // --set key.path=value overrides, in order
  std::optional<std::string> robot;     // --robot HOST:PORT; none: remote.host, remote.port
  std::optional<std::string> bind;      // --bind HOST:PORT; none: remote.bind_host, bind_port
  std::filesystem::path key_file;       // --key-file; empty: remote.key_file's
  std::optional<double> duration;       // --duration s: trial.duration
  std::optional<long long> trials;      // --trials: realtime.trials
  std::filesystem::path out = "drive";  // --out
  bool replace = false;
  bool figures = true;
};

// Returns 0 when the trials ran (or a stop was asked), 2 for bad input, 1 when the robot was
// unreachable or the link was lost (the trials until then are written).
int drive_command(const DriveOptions& options);

}  // namespace cbbg::app
