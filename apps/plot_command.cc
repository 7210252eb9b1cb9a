// cbbg plot DIR, and the figures `cbbg run` draws at its end.

#include <algorithm>
#include <cstdlib>
#include <iostream>
#include <string>

#include <spdlog/spdlog.h>
#include <sys/wait.h>

#include "cbbg/apps/commands.h"
#include "cbbg/apps/errors.h"
#include "cbbg/apps/figures.h"
#include "cbbg/diagrams/presets.h"
#include "cbbg/experiments/experiments.h"
#include "cbbg/replay/trial_log.h"
#include "cbbg/store/output_guard.h"

namespace cbbg::app {
namespace {

// Debian's matplotlib belongs to /usr/bin/python3; the python3 first on PATH may lack it.
constexpr const char* kPython = "/usr/bin/python3";

std::string quoted(const std::string& text) {
  std::string result = "'";
  for (const char c : text) result += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return result + "'";
}

// A sweep's merged results: its figures are the plotting script's alone.
bool is_sweep(const std::filesystem::path& directory) {
  std::error_code error;
  return std::filesystem::exists(directory / "sweep.csv", error);
}

}  // namespace

namespace {
std::filesystem::path& share_directory() {
  static std::filesystem::path share;
  return share;
}
}  // namespace

void set_share_directory(const std::filesystem::path& share) { share_directory() = share; }

std::filesystem::path shared_file(const char* override, const char* name) {
  if (const char* chosen = std::getenv(override); chosen != nullptr && *chosen) return chosen;
  std::error_code error;
  const std::filesystem::path self = std::filesystem::read_symlink("/proc/self/exe", error);
  const std::filesystem::path beside = self.parent_path().parent_path() / "share" / "cbbg" / name;
  if (share_directory().empty() || std::filesystem::exists(beside, error)) return beside;
  return share_directory() / name;
}

int run_plot_script(const std::filesystem::path& directory, bool quiet) {
  const std::filesystem::path script = shared_file("CBBG_PLOT_SCRIPT", "plot_results.py");
  if (!std::filesystem::is_regular_file(script)) {
    spdlog::warn("the plotting script '{}' is missing (set CBBG_PLOT_SCRIPT)", script.string());
    return 1;
  }
  // Quiet: the script's "wrote ..." lines would name the staging directory; errors still show.
  const std::string command = std::string(kPython) + " " + quoted(script.string()) + " " +
                              quoted(directory.string()) + (quiet ? " > /dev/null" : "");
  const int status = std::system(command.c_str());
  if (status == -1 || !WIFEXITED(status)) return 1;
  return WEXITSTATUS(status);
}

std::vector<std::string> run_arms(const std::filesystem::path& directory,
                                  const parameters::RunParams& run) {
  // trials.csv names the arms that ran, a user's own too; config.yaml may not know them.
  std::vector<std::string> arms;
  try {
    for (const replay::TrialEntry& entry : replay::read_trial_entries(directory / "trials.csv")) {
      if (std::find(arms.begin(), arms.end(), entry.arm) == arms.end()) arms.push_back(entry.arm);
    }
  } catch (const replay::InputError&) {
    arms.clear();
  }
  return arms.empty() ? experiments::experiment_arms(run) : arms;
}

std::vector<std::string> own_figure_names(const std::vector<std::string>& arms,
                                          const FigureOptions& options) {
  std::vector<std::string> names{kDiagramFigure};
  if (options.replays) {
    for (const std::string& arm : arms) names.push_back(replay_figure(arm));
  }
  return names;
}

int draw_figures(const std::filesystem::path& directory, const parameters::Parameters& parameters,
                 const FigureOptions& options) {
  const int plotted = run_plot_script(directory, options.quiet);
  if (plotted == kUserError) return kUserError;  // a figure's name is taken by a user's file
  bool complete = plotted == 0;
  if (!complete) spdlog::warn("the plots could not be drawn (see the message above)");
  if (is_sweep(directory)) return complete ? 0 : kMachineError;  // the script's figures alone
  std::filesystem::create_directories(directory / "figures");
  const std::vector<std::string> arms = run_arms(directory, parameters.run);
  const std::vector<std::string> presets = diagrams::arm_names();
  if (std::find(presets.begin(), presets.end(), arms.front()) == presets.end()) {
    spdlog::info(
        "no diagram.svg: arm '{}' is not a preset nor registered (draw it with "
        "cbbg::to_dot, or register it: diagrams/arms.h)",
        arms.front());
  } else {
    try {
      store::Manifest manifest(directory / "figures");
      manifest.check_writable({kDiagramFigure}, "the diagram");
      manifest.add({kDiagramFigure});
      draw_diagram(arms.front(), parameters, directory / "figures" / kDiagramFigure,
                   GraphvizOptions{.hidden_blocks = telemetry_blocks(arms.front())});
    } catch (const std::runtime_error& error) {
      spdlog::warn("{}: {}", kDiagramFigure, error.what());
      complete = false;
    }
  }
  if (options.replays) {
    complete = write_run_replays(directory, parameters, options.run_name) && complete;
  }
  return complete ? 0 : kMachineError;
}

void draw_diagram(const std::string& name, const parameters::Parameters& parameters,
                  const std::filesystem::path& output, const GraphvizOptions& options) {
  const diagrams::ClosedLoop loop = name == diagrams::kLearntActor
                                        ? diagrams::build_preset(name, parameters)
                                        : diagrams::named_arm(name).learner(parameters);
  render_dot(to_dot(*loop.diagram, options), output);
}

std::vector<std::string> telemetry_blocks(const std::string& name) {
  return {name + "/telemetry", name + "/pose", name + "/pose_x", name + "/pose_y",
          name + "/pose_yaw"};
}

int plot_command(const std::filesystem::path& directory) {
  config::Config config;
  parameters::Parameters parameters;
  try {
    std::error_code error;
    if (!std::filesystem::is_regular_file(directory / "config.yaml", error)) {
      throw config::ConfigError("'" + directory.string() +
                                "' is not a results directory (it has no config.yaml)");
    }
    config.merge_file(directory / "config.yaml");
    parameters = parameters::read_parameters(config);
    check_output_directory(directory / "figures", "cbbg plot");
    if (!is_sweep(directory)) {
      store::Manifest(directory / "figures")
          .check_writable(own_figure_names(run_arms(directory, parameters.run), {}), "cbbg plot");
    }
    store::remove_temporaries(directory, store::Leftovers::kStale);  // a killed plot's staging
  } catch (const config::ConfigError& error) {
    return report_error(kUserError, error.what());
  } catch (const std::exception& error) {
    return report_error(kMachineError, describe(error));
  }
  return draw_figures(directory, parameters, {});
}

}  // namespace cbbg::app
