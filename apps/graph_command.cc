// cbbg graph: the block diagram of a named diagram, or of a config's first arm.

#include <iostream>

#include "apps/commands.h"
#include "diagrams/controller_diagram.h"
#include "diagrams/experiments.h"
#include "diagrams/params_from_config.h"
#include "framework/graphviz.h"

namespace cbbg::app {

int graph_command(const GraphOptions& options) {
  config::Config config;
  std::string diagram = options.diagram;
  try {
    if (!options.config_file.empty()) config.merge_file(options.config_file);
    for (const auto& assignment : options.sets) config.set(assignment);
    if (!diagram.empty()) config.set("experiment=" + diagram, "--diagram " + diagram);
    diagrams::validate_all(config);
    if (diagram.empty()) {
      diagram = diagrams::experiment_arms(config).front();
    }
    if (diagram == "exp1" || diagram == "exp2") {
      throw config::ConfigError("--diagram " + diagram +
                                ": an experiment, not a diagram; the diagrams are cbbg, "
                                "cbbg_weighted, bg_only, cb_only, pd_only");
    }
  } catch (const config::ConfigError& error) {
    std::cerr << "cbbg: error: " << error.what() << "\n";
    return 2;
  }
  try {
    const auto controller = diagrams::build_controller_diagram(diagram, config);
    render_dot(to_dot(*controller.diagram, GraphvizOptions{.max_depth = options.max_depth}),
               options.output);
  } catch (const std::invalid_argument& error) {
    std::cerr << "cbbg: error: " << error.what() << "\n";
    return 2;
  } catch (const std::exception& error) {
    std::cerr << "cbbg: error: " << error.what() << "\n";
    return 1;
  }
  std::cout << "wrote " << options.output.string() << "\n";
  return 0;
}

}  // namespace cbbg::app
