#pragma once
// The figures of a results directory: the plots (plot_results.py, matplotlib) and the block
// diagram of its first arm.

#include <filesystem>
#include <string>
#include <vector>

#include "config/config.h"
#include "framework/graphviz.h"

namespace cbbg::app {

struct FigureOptions {
  bool quiet = false;    // hide the script's list of files written
  bool replays = true;   // the replay pages too (write_run_replays)
  std::string run_name;  // the replays' title; empty: the directory's name
};

// Draws DIR/figures/. A missing Python/matplotlib, Graphviz or replay page is reported as a
// warning: the data files stand on their own. Returns false when a figure could not be made.
bool draw_figures(const std::filesystem::path& directory, const config::Config& config,
                  const FigureOptions& options);

// DIR/figures/replay_<arm>.html per arm of the run: its first seed's first trial, first
// successful trial and last trial. Warns and returns false when they cannot be written.
bool write_run_replays(const std::filesystem::path& directory, const config::Config& config,
                       const std::string& run_name);

// A file cbbg installs in share/cbbg/ beside the directory of this executable (bin/ when
// installed, apps/ in the build tree), or the path in the environment variable `override`.
std::filesystem::path shared_file(const char* override, const char* name);

// Runs the plotting script on DIR; returns its exit code.
int run_plot_script(const std::filesystem::path& directory, bool quiet);

// Renders the closed loop of preset `name` for `config` to `output` (.dot, .svg or .png).
void draw_diagram(const std::string& name, const config::Config& config,
                  const std::filesystem::path& output, const GraphvizOptions& options);

// The telemetry multiplexer of the closed loop named `name`, and the pose it records: left
// out of pictures by default, since the multiplexer reads every signal.
std::vector<std::string> telemetry_blocks(const std::string& name);

}  // namespace cbbg::app
