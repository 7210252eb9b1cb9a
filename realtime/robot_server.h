#pragma once
// The robot's end of the link (wire.h), serving a SimulatedRobot in real time: `cbbg robot`.
// One controller at a time: a hello opens a session, each start a trial; every period the
// robot sends its measurement and applies the torque that answers it if it comes within
// the deadline, else holds the last (a deadline miss). Silence for timeout_periods, a stop
// from the controller, or a stop request here (SIGINT) ends the session at zero torque.

#include <functional>
#include <string>

#include "cbbg/realtime/link_figures.h"
#include "cbbg/realtime/simulated_robot.h"
#include "cbbg/realtime/udp_endpoint.h"
#include "cbbg/realtime/wire.h"

namespace cbbg::realtime {

struct ServeOptions {
  Address bind{"127.0.0.1", 5005};
  Key key;
  // The torque answering a measurement must arrive within this fraction of the period.
  double deadline = 0.5;
  // Lockstep: the robot waits for each torque (up to timeout_periods) instead of holding the
  // last, as a simulator in the loop does: a late torque is counted, and applied. A trial is
  // then the simulated one byte for byte however loaded the machine; its pace is not real.
  bool lockstep = false;
  int timeout_periods = 10;
  long long sessions = 0;  // sessions to serve before returning; 0: until a stop is asked
  std::string name = "cbbg robot";
  // Told a line once listening (with the port), and at each session's start and end.
  std::function<void(const std::string&)> report = [](const std::string&) {};
  // Told the address once bound (its port the system's pick when bind.port is 0).
  std::function<void(const Address&)> listening = [](const Address&) {};
};

// What the robot saw over its sessions: the link's figures from its side (latencies are its
// round trips), and its own overruns (periods whose step did not finish in time).
struct ServeFigures {
  LinkFigures link;
  long long sessions = 0;
  long long overruns = 0;
  std::string last_end;  // why the last session ended
};

// Serves `robot` on options.bind until options.sessions sessions ended or a stop is asked.
// Throws std::system_error when the address cannot be bound.
ServeFigures serve_robot(SimulatedRobot& robot, const ServeOptions& options);

}  // namespace cbbg::realtime
