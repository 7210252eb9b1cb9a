#pragma once
// The figures of a results directory: the plots (plot_results.py, matplotlib) and the block
// diagram of its first arm.

#include <filesystem>
#include <string>
#include <vector>

#include "config/config.h"
#include "framework/graphviz.h"

namespace cbbg::app {

// Draws DIR/figures/. A missing Python/matplotlib or Graphviz is reported as a warning: the
// data files stand on their own. Returns false when a figure could not be made.
// Quiet hides the script's list of files written.
bool draw_figures(const std::filesystem::path& directory, const config::Config& config, bool quiet);

// Runs the plotting script on DIR; returns its exit code.
int run_plot_script(const std::filesystem::path& directory, bool quiet);

// Renders the closed loop of preset `name` for `config` to `output` (.dot, .svg or .png).
void draw_diagram(const std::string& name, const config::Config& config,
                  const std::filesystem::path& output, const GraphvizOptions& options);

// The telemetry multiplexer of the closed loop named `name`, and the pose it records: left
// out of pictures by default, since the multiplexer reads every signal.
std::vector<std::string> telemetry_blocks(const std::string& name);

}  // namespace cbbg::app
