// cbbg drive: the flags checked in their own words, then `cbbg run` of the protocol realtime
// with the controller's arm, one seed, plant.kind remote.

#include "cbbg/apps/drive_command.h"

#include <cmath>
#include <stdexcept>

#include "cbbg/apps/commands.h"
#include "cbbg/apps/errors.h"
#include "cbbg/config/config.h"
#include "cbbg/experiments/realtime_params.h"
#include "cbbg/experiments/run_names.h"
#include "cbbg/framework/number_text.h"
#include "cbbg/realtime/robot_link.h"
#include "cbbg/realtime/stop_request.h"
#include "cbbg/realtime/udp_endpoint.h"

namespace cbbg::app {
namespace {

// The run `options` asks for; throws config::ConfigError naming the flag at fault.
RunOptions drive_run(const DriveOptions& options) {
  try {
    experiments::check_arm_names({options.controller});
  } catch (const config::ConfigError& error) {
    throw config::ConfigError("--controller: " + std::string(error.what()));
  }
  RunOptions run;
  run.experiment = experiments::kRealtimeProtocol;
  run.config_file = options.config_file;
  run.sets = options.sets;
  run.seeds = "1";
  run.jobs = 1;
  run.out = options.out;
  run.load_weights = options.weights_file;
  run.replace = options.replace;
  run.figures = options.figures;
  const auto address = [](const std::string& text, const char* flag) {
    try {
      return realtime::parse_address(text, flag);
    } catch (const std::invalid_argument& error) {
      throw config::ConfigError(error.what());
    }
  };
  run.sets.push_back("arms=[" + options.controller + "]");
  run.sets.push_back("plant.kind=remote");
  if (options.robot) {
    const realtime::Address robot = address(*options.robot, "--robot");
    run.sets.push_back("remote.host=" + robot.host);
    run.sets.push_back("remote.port=" + std::to_string(robot.port));
  }
  if (options.bind) {
    const realtime::Address bind = address(*options.bind, "--bind");
    run.sets.push_back("remote.bind_host=" + bind.host);
    run.sets.push_back("remote.bind_port=" + std::to_string(bind.port));
  }
  if (!options.key_file.empty()) {
    try {
      realtime::read_key_file(options.key_file.string(), "--key-file");
    } catch (const std::invalid_argument& error) {
      throw config::ConfigError(error.what());
    }
    run.sets.push_back("remote.key_file=" + options.key_file.string());
  }
  if (options.policy) run.sets.push_back("realtime.loop=policy");
  if (options.duration) {
    if (!std::isfinite(*options.duration) || *options.duration <= 0.0) {
      throw config::ConfigError("--duration must be a finite number > 0 (s); got " +
                                format_number(*options.duration));
    }
    run.sets.push_back("trial.duration=" + format_number(*options.duration));
  }
  if (options.trials) {
    if (*options.trials < 1) {
      throw config::ConfigError("--trials must be at least 1; got " +
                                std::to_string(*options.trials));
    }
    run.sets.push_back("realtime.trials=" + std::to_string(*options.trials));
  }
  return run;
}

}  // namespace

int drive_command(const DriveOptions& options) {
  RunOptions run;
  try {
    run = drive_run(options);
  } catch (const config::ConfigError& error) {
    return report_error(kUserError, error.what());
  }
  realtime::install_stop_handlers();
  const int code = run_command(run);
  if (const std::string lost = realtime::link_failure(); code == 0 && !lost.empty()) {
    return report_error(kMachineError,
                        lost + "; the trials until then are in " + options.out.string());
  }
  return code;
}

}  // namespace cbbg::app
