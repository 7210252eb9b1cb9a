// cbbg plot DIR, and the figures `cbbg run` draws at its end.

#include <cstdlib>
#include <iostream>
#include <string>

#include <spdlog/spdlog.h>
#include <sys/wait.h>

#include "apps/commands.h"
#include "apps/errors.h"
#include "apps/figures.h"
#include "diagrams/presets.h"
#include "experiments/experiments.h"

namespace cbbg::app {
namespace {

// Debian's matplotlib belongs to /usr/bin/python3; the python3 first on PATH may lack it.
constexpr const char* kPython = "/usr/bin/python3";

std::string quoted(const std::string& text) {
  std::string result = "'";
  for (const char c : text) result += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return result + "'";
}

}  // namespace

std::filesystem::path shared_file(const char* override, const char* name) {
  if (const char* chosen = std::getenv(override); chosen != nullptr && *chosen) return chosen;
  std::error_code error;
  const std::filesystem::path self = std::filesystem::read_symlink("/proc/self/exe", error);
  return self.parent_path().parent_path() / "share" / "cbbg" / name;
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

bool draw_figures(const std::filesystem::path& directory, const config::Config& config,
                  const FigureOptions& options) {
  bool complete = run_plot_script(directory, options.quiet) == 0;
  if (!complete) spdlog::warn("the plots could not be drawn (see the message above)");
  std::filesystem::create_directories(directory / "figures");
  const std::string arm = experiments::experiment_arms(config).front();
  try {
    draw_diagram(arm, config, directory / "figures" / "diagram.svg",
                 GraphvizOptions{.hidden_blocks = telemetry_blocks(arm)});
  } catch (const std::runtime_error& error) {
    spdlog::warn("diagram.svg: {}", error.what());
    complete = false;
  }
  if (options.replays) {
    complete = write_run_replays(directory, config, options.run_name) && complete;
  }
  return complete;
}

void draw_diagram(const std::string& name, const config::Config& config,
                  const std::filesystem::path& output, const GraphvizOptions& options) {
  const diagrams::ClosedLoop loop = diagrams::build_preset(name, config);
  render_dot(to_dot(*loop.diagram, options), output);
}

std::vector<std::string> telemetry_blocks(const std::string& name) {
  return {name + "/telemetry", name + "/pose"};
}

int plot_command(const std::filesystem::path& directory) {
  config::Config config;
  try {
    std::error_code error;
    if (!std::filesystem::is_regular_file(directory / "config.yaml", error)) {
      throw config::ConfigError("'" + directory.string() +
                                "' is not a results directory (it has no config.yaml)");
    }
    config.merge_file(directory / "config.yaml");
    check_output_directory(directory / "figures", "cbbg plot");
  } catch (const config::ConfigError& error) {
    return report_error(kUserError, error.what());
  } catch (const std::exception& error) {
    return report_error(kMachineError, describe(error));
  }
  return draw_figures(directory, config, {}) ? 0 : 1;
}

}  // namespace cbbg::app
