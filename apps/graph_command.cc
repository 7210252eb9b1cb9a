// cbbg graph: the block diagram of a preset, or of a config's first arm.

#include <algorithm>
#include <iostream>

#include "cbbg/apps/commands.h"
#include "cbbg/apps/errors.h"
#include "cbbg/apps/figures.h"
#include "cbbg/diagrams/presets.h"
#include "cbbg/diagrams/validated_parameters.h"
#include "cbbg/experiments/experiments.h"
#include "cbbg/store/output_guard.h"

namespace cbbg::app {

int graph_command(const GraphOptions& options) {
  config::Config config;
  parameters::Parameters parameters;
  std::string diagram = options.diagram;
  try {
    if (!options.config_file.empty()) config.merge_file(options.config_file);
    for (const auto& assignment : options.sets) config.set(assignment);
    parameters = diagrams::validated_parameters(config);
    if (diagram.empty()) diagram = experiments::experiment_arms(parameters.run).front();
    const std::vector<std::string> names = diagrams::diagram_names();
    if (std::find(names.begin(), names.end(), diagram) == names.end()) {
      throw config::ConfigError("--diagram: unknown diagram '" + diagram + "'; the diagrams are " +
                                config::join(names));
    }
    if (options.max_depth && *options.max_depth < 0) {
      throw config::ConfigError("--depth must be 0 or more (the nesting levels to expand); got " +
                                std::to_string(*options.max_depth));
    }
    check_output_file(options.output, "-o");
    store::check_replaceable_file(options.output, "-o", kDiagramGeneratorTag);
  } catch (const config::ConfigError& error) {
    return report_error(kUserError, error.what());
  } catch (const std::exception& error) {
    return report_error(kMachineError, describe(error));
  }
  try {
    draw_diagram(
        diagram, parameters, options.output,
        GraphvizOptions{.max_depth = options.max_depth.value_or(-1),
                        .hidden_blocks = options.show_telemetry ? std::vector<std::string>{}
                                                                : telemetry_blocks(diagram)});
  } catch (const std::invalid_argument& error) {
    return report_error(kUserError, error.what());
  } catch (const std::exception& error) {
    return report_error(kMachineError, describe(error));
  }
  std::cout << "wrote " << options.output.string() << "\n";
  return 0;
}

}  // namespace cbbg::app
