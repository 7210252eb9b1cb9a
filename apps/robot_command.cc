// cbbg robot: plant.kind's plant from the config, served until its sessions end or a stop.

#include "cbbg/apps/robot_command.h"

#include <cmath>
#include <cstdio>
#include <memory>
#include <stdexcept>
#include <system_error>

#include "cbbg/apps/errors.h"
#include "cbbg/config/config.h"
#include "cbbg/diagrams/plant_kinds.h"
#include "cbbg/diagrams/validated_parameters.h"
#include "cbbg/framework/number_text.h"
#include "cbbg/realtime/robot_server.h"
#include "cbbg/realtime/stop_request.h"

namespace cbbg::app {
namespace {

realtime::ServeOptions serve_options(const RobotOptions& options) {
  realtime::ServeOptions serve;
  serve.bind = realtime::parse_address(options.bind, "--bind");
  if (!options.key_file.empty()) {
    serve.key = realtime::read_key_file(options.key_file.string(), "--key-file");
  }
  if (!(options.deadline > 0.0 && options.deadline <= 1.0)) {
    throw std::invalid_argument("--deadline must be a fraction of the period in (0, 1]; got " +
                                format_number(options.deadline));
  }
  if (options.timeout_periods < 1 || options.timeout_periods > 1000) {
    throw std::invalid_argument("--timeout-periods must be from 1 to 1000; got " +
                                std::to_string(options.timeout_periods));
  }
  if (options.sessions < 0) {
    throw std::invalid_argument("--sessions must be 0 (until stopped) or more; got " +
                                std::to_string(options.sessions));
  }
  serve.deadline = options.deadline;
  serve.lockstep = options.lockstep;
  serve.timeout_periods = static_cast<int>(options.timeout_periods);
  serve.sessions = options.sessions;
  serve.report = [](const std::string& line) {
    std::printf("cbbg robot: %s\n", line.c_str());
    std::fflush(stdout);
  };
  return serve;
}

}  // namespace

int robot_command(const RobotOptions& options) {
  realtime::ServeOptions serve;
  std::unique_ptr<realtime::SimulatedRobot> robot;
  try {
    config::Config config;
    if (!options.config_file.empty()) config.merge_file(options.config_file);
    for (const auto& assignment : options.sets) config.set(assignment);
    const parameters::Parameters p = diagrams::validated_parameters(config);
    if (p.plant.kind == "remote") {
      throw config::ConfigError(
          "cbbg robot serves a simulated plant; plant.kind remote is cbbg drive's side");
    }
    serve = serve_options(options);
    serve.name = "cbbg robot (" + p.plant.kind + ")";
    robot = std::make_unique<realtime::SimulatedRobot>(
        diagrams::plant_kind(p.plant.kind).make("plant", p), p.trial.period,
        p.plant.robot.accuracy);
  } catch (const config::ConfigError& error) {
    return report_error(kUserError, error.what());
  } catch (const std::invalid_argument& error) {
    return report_error(kUserError, error.what());
  }
  realtime::install_stop_handlers();
  try {
    realtime::serve_robot(*robot, serve);
  } catch (const std::exception& error) {
    return report_error(kMachineError, describe(error));
  }
  if (realtime::stop_requested()) {
    std::printf("cbbg robot: stopped by %s, motors at zero\n", realtime::stop_signal_name());
  }
  return 0;
}

}  // namespace cbbg::app
