#pragma once
// The figures of a results directory: the plots (plot_results.py, matplotlib) and the block
// diagram of its first arm.

#include <filesystem>
#include <string>
#include <vector>

#include "cbbg/framework/graphviz.h"
#include "cbbg/parameters/parameters.h"

namespace cbbg::app {

struct FigureOptions {
  bool quiet = false;    // hide the script's list of files written
  bool replays = true;   // the replay pages too (write_run_replays)
  std::string run_name;  // the replays' title; empty: the directory's name
};

// The figures cbbg itself writes into DIR/figures (the plots are the script's).
inline constexpr const char* kDiagramFigure = "diagram.svg";
inline std::string replay_figure(const std::string& arm) { return "replay_" + arm + ".html"; }

// Draws DIR/figures/, listing each file in its manifest (store/output_guard.h), never over a
// file of the user's. A missing Python/matplotlib, Graphviz or replay page is reported as a
// warning: the data files stand on their own. Returns 0 when every figure was made, 1 when
// one could not be, 2 when the plotting script refused a name a user's file holds.
int draw_figures(const std::filesystem::path& directory, const parameters::Parameters& parameters,
                 const FigureOptions& options);

// The arms whose trials DIR holds (its trials.csv; else the parameters' run's).
std::vector<std::string> run_arms(const std::filesystem::path& directory,
                                  const parameters::RunParams& run);
// What draw_figures writes itself for those arms.
std::vector<std::string> own_figure_names(const std::vector<std::string>& arms,
                                          const FigureOptions& options);

// DIR/figures/replay_<arm>.html per arm of the run: its first seed's first trial, first
// successful trial and last trial. Warns and returns false when they cannot be written.
bool write_run_replays(const std::filesystem::path& directory,
                       const parameters::Parameters& parameters, const std::string& run_name);

// A file cbbg installs in share/cbbg/: the path in the environment variable `override`, else
// share/cbbg/ beside the directory of this executable (bin/ when installed, apps/ in the build
// tree) when it is there, else the share directory the command line was given (run_cli).
std::filesystem::path shared_file(const char* override, const char* name);
void set_share_directory(const std::filesystem::path& share);

// Runs the plotting script on DIR; returns its exit code.
int run_plot_script(const std::filesystem::path& directory, bool quiet);

// Renders the closed loop of preset `name` for `parameters` to `output` (.dot, .svg or .png).
void draw_diagram(const std::string& name, const parameters::Parameters& parameters,
                  const std::filesystem::path& output, const GraphvizOptions& options);

// The telemetry multiplexer of the closed loop named `name`, and the pose it records: left
// out of pictures by default, since the multiplexer reads every signal.
std::vector<std::string> telemetry_blocks(const std::string& name);

}  // namespace cbbg::app
