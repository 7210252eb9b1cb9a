#pragma once
// The figures of a results directory: the plots (scripts/plot_results.py, matplotlib) and
// the block diagram of each arm.

#include <filesystem>

#include "config/config.h"

namespace cbbg::app {

// Draws DIR/figures/. A missing Python/matplotlib or Graphviz is reported as a warning: the
// data files stand on their own. Returns false when a figure could not be made.
// Quiet hides the script's list of files written.
bool draw_figures(const std::filesystem::path& directory, const config::Config& config, bool quiet);

// Runs the plotting script on DIR; returns its exit code.
int run_plot_script(const std::filesystem::path& directory, bool quiet);

}  // namespace cbbg::app
