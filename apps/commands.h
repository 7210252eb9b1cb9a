#pragma once
// The subcommands of `cbbg`. Each returns the process exit code: 0 done, 1 failed while
// running, 2 bad input (config, command line).

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "cbbg/config/config.h"
#include "cbbg/config/sweep.h"
#include "cbbg/parameters/parameters.h"

namespace cbbg::app {

struct RunOptions {
  std::optional<std::string> experiment;  // unset: the config's
  std::filesystem::path config_file;      // empty: defaults only
  std::vector<std::string> sets;          // key.path=value overrides, in order
  std::optional<std::string> seeds;       // as typed; unset: the config's
  std::optional<std::string> seed;        // as typed; unset: the config's
  int jobs = 1;
  std::filesystem::path out = "results";
  std::optional<std::filesystem::path> resume;  // set: continue the interrupted run into it
  std::filesystem::path load_weights;           // non-empty: learning starts from these weights
  std::filesystem::path save_weights;           // non-empty: the one learning run's weights go here
  bool figures = true;
  bool replays = true;               // figures/ gets a replay page per arm (its first seed)
  bool replace = false;              // a finished results directory at --out may be replaced
  std::vector<std::string> grid;     // KEY=V1,V2,... axes of a sweep, in order
  std::optional<std::string> shard;  // "K/N" as typed: run only that shard of the sweep
  bool check = false;  // check everything a run checks before any work, then stop (--check)
};
int run_command(const RunOptions& options);
// The typed parameters of a run's (or a grid point's) config, with everything a run checks
// before any work: the edge below which nothing reads the config again. Throws
// config::ConfigError.
parameters::Parameters checked_parameters(const config::Config& config);
// Before any work: every arm of the run built once (experiments/arm_checks.h), and `jobs`
// of its tasks (`arms` x seeds) at once within the machine's memory. Throws
// config::ConfigError.
void check_arms_and_memory(const parameters::Parameters& parameters, std::size_t arms, int jobs);
// cbbg run as a sweep (apps/sweep_command.cc): `base` and `sweep` resolved from `options`.
int sweep_command(const RunOptions& options, const config::Config& base,
                  const config::Sweep& sweep);

struct GraphOptions {
  std::string diagram;  // empty: the config's first arm
  std::filesystem::path config_file;
  std::vector<std::string> sets;
  std::filesystem::path output;
  std::optional<int> max_depth;  // unset: every level
  bool show_telemetry = false;
};
int graph_command(const GraphOptions& options);

int plot_command(const std::filesystem::path& directory);

struct ReplayOptions {
  std::filesystem::path directory;  // a results directory
  std::optional<std::string> arm;   // unset: its first arm
  std::optional<long long> seed;    // unset: the arm's first seed
  std::vector<int> trials;          // empty: the first, the first successful and the last
  std::filesystem::path output;     // the page
};
int replay_command(const ReplayOptions& options);
// A sweep's work directory: merged into one results directory, or its tasks counted.
int merge_command(const std::filesystem::path& target);
int status_command(const std::filesystem::path& target);
// `keys_markdown`: only the config keys, as the Markdown table of docs/parameters.md.
int list_command(bool keys_markdown = false);

}  // namespace cbbg::app
