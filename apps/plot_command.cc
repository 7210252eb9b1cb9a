// cbbg plot DIR, and the figures `cbbg run` draws at its end.

#include <cstdlib>
#include <iostream>
#include <string>

#include <spdlog/spdlog.h>
#include <sys/wait.h>

#include "apps/commands.h"
#include "apps/figures.h"
#include "diagrams/controller_diagram.h"
#include "diagrams/experiments.h"
#include "framework/graphviz.h"

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

int run_plot_script(const std::filesystem::path& directory, bool quiet) {
  // Quiet: the script's "wrote ..." lines would name the staging directory; errors still show.
  const std::string command = std::string(kPython) + " " + quoted(CBBG_PLOT_SCRIPT) + " " +
                              quoted(directory.string()) + (quiet ? " > /dev/null" : "");
  const int status = std::system(command.c_str());
  if (status == -1 || !WIFEXITED(status)) return 1;
  return WEXITSTATUS(status);
}

bool draw_figures(const std::filesystem::path& directory, const config::Config& config,
                  bool quiet) {
  bool complete = run_plot_script(directory, quiet) == 0;
  if (!complete) spdlog::warn("the plots could not be drawn (see the message above)");
  std::filesystem::create_directories(directory / "figures");
  const std::string arm = diagrams::experiment_arms(config).front();
  try {
    const auto controller = diagrams::build_controller_diagram(arm, config);
    render_dot(to_dot(*controller.diagram), directory / "figures" / "diagram.svg");
  } catch (const std::runtime_error& error) {
    spdlog::warn("diagram.svg: {}", error.what());
    complete = false;
  }
  return complete;
}

int plot_command(const std::filesystem::path& directory) {
  if (!std::filesystem::is_directory(directory)) {
    std::cerr << "cbbg: error: '" << directory.string() << "' is not a results directory\n";
    return 2;
  }
  config::Config config;
  try {
    config.merge_file(directory / "config.yaml");
  } catch (const config::ConfigError& error) {
    std::cerr << "cbbg: error: " << error.what() << "\n";
    return 2;
  }
  return draw_figures(directory, config, /*quiet=*/false) ? 0 : 1;
}

}  // namespace cbbg::app
