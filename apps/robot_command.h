#pragma once
// cbbg robot: a simulated robot (plant.kind's, any kind with the two-wheeler's signals)
// served over UDP in real time (realtime/robot_server.h), for `cbbg drive` to be tried
// without hardware. Prints a line when listening, and one per session with its figures.

#include <filesystem>
#include <string>
#include <vector>

namespace cbbg::app {

struct RobotOptions {
  std::filesystem::path config_file;    // --config: plant.*, trial.period of the robot
  std::vector<std::string> sets;        // --set overrides
  std::string bind = "127.0.0.1:5005";  // --bind HOST:PORT (port 0: any, printed)
  std::filesystem::path key_file;       // --key-file; empty: no key
  double deadline = 0.5;                // --deadline: of a period, in (0, 1]
  bool lockstep = false;                // --lockstep: wait for each torque (ServeOptions)
  long long timeout_periods = 10;       // --timeout-periods
  long long sessions = 0;               // --sessions; 0: until SIGINT
};

// Returns 0 after its sessions or a stop (SIGINT, SIGTERM), 2 for bad input, 1 when the
// address cannot be bound.
int robot_command(const RobotOptions& options);

}  // namespace cbbg::app
