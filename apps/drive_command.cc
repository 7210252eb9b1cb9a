// cbbg drive: the flags checked in their own words, then `cbbg run` of the protocol realtime
// with the controller's arm, one seed, plant.kind remote.

#include "cbbg/apps/drive_command.h"

#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "cbbg/apps/commands.h"
#include "cbbg/apps/errors.h"
#include "cbbg/config/config.h"
#include "cbbg/experiments/realtime_params.h"
#include "cbbg/experiments/run_names.h"
#include "cbbg/framework/number_text.h"
#include "cbbg/realtime/robot_link.h"
#include "cbbg/realtime/stop_request.h"
#include "cbbg/realtime/udp_endpoint.h"
#include "cbbg/realtime/wire.h"

namespace cbbg::app {
namespace {

// The link's flags as remote.* settings: --robot, --bind, --key-file (read now, so that a
// missing one is named by its flag). Throws std::invalid_argument naming the flag.
void add_link_sets(const DriveOptions& options, std::vector<std::string>& sets) {
  if (options.robot) {
    const realtime::Address robot = realtime::parse_address(*options.robot, "--robot");
    sets.push_back("remote.host=" + robot.host);
    sets.push_back("remote.port=" + std::to_string(robot.port));
  }
  if (options.bind) {
    const realtime::Address bind = realtime::parse_address(*options.bind, "--bind");
    sets.push_back("remote.bind_host=" + bind.host);
    sets.push_back("remote.bind_port=" + std::to_string(bind.port));
  }
  if (!options.key_file.empty()) {
    realtime::read_key_file(options.key_file.string(), "--key-file");
    sets.push_back("remote.key_file=" + options.key_file.string());
  }
}

// --duration and --trials as trial.duration and realtime.trials. Throws config::ConfigError.
void add_length_sets(const DriveOptions& options, std::vector<std::string>& sets) {
  if (options.duration) {
    if (!std::isfinite(*options.duration) || *options.duration <= 0.0) {
      throw config::ConfigError("--duration must be a finite number > 0 (s); got " +
                                format_number(*options.duration));
    }
    sets.push_back("trial.duration=" + format_number(*options.duration));
  }
  if (options.trials) {
    if (*options.trials < 1) {
      throw config::ConfigError("--trials must be at least 1; got " +
                                std::to_string(*options.trials));
    }
    sets.push_back("realtime.trials=" + std::to_string(*options.trials));
  }
}

// The run `options` asks for: the protocol realtime, the controller's arm, one seed, the
// flags as settings after the user's. Throws config::ConfigError or std::invalid_argument
// naming the flag at fault.
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
  run.seeds.emplace("1");  // (an assignment from the literal trips a false -Wrestrict in GCC 12)
  run.jobs = 1;
  run.out = options.out;
  run.load_weights = options.weights_file;
  run.replace = options.replace;
  run.figures = options.figures;
  run.sets.push_back("arms=[" + options.controller + "]");
  run.sets.push_back("plant.kind=remote");
  if (options.policy) run.sets.push_back("realtime.loop=policy");
  add_link_sets(options, run.sets);
  add_length_sets(options, run.sets);
  return run;
}

}  // namespace

int drive_command(const DriveOptions& options) {
  RunOptions run;
  try {
    run = drive_run(options);
  } catch (const config::ConfigError& error) {
    return report_error(kUserError, error.what());
  } catch (const std::invalid_argument& error) {
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
