#pragma once
// The controller's end of a link to a robot (wire.h): the session's handshake, a trial's
// start, and each tick's exchange (the torque answering a measurement, then the next
// measurement). A link that is lost, or asked to stop, sends a stop (zero torque at the
// robot) and throws SimulationStopped: the trial ends as stopped, no torque left applied.

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "cbbg/realtime/link_figures.h"
#include "cbbg/realtime/udp_endpoint.h"
#include "cbbg/realtime/wire.h"

namespace cbbg::realtime {

// Why the last link of this process was lost (no welcome, silence, or the robot's own stop);
// empty when none was. A stop request or the controller's own end loses none.
std::string link_failure();

struct LinkOptions {
  Address robot;                     // where the robot listens
  Address local{"127.0.0.1", 0};     // this end; port 0: one the system picks
  Key key;                           // shared with the robot; empty: none
  double period = 0.01;              // s, the robot's tick; the handshake checks it agrees
  int timeout_periods = 10;          // a robot silent for this many periods is lost
  double connect_timeout = 5.0;      // s the handshake waits for the robot's welcome
  std::string controller = "cbbg";   // the name the handshake gives the robot
  std::vector<std::string> signals;  // what each measurement must carry, in order
};

class RobotLink {
 public:
  explicit RobotLink(LinkOptions options);  // no datagram yet: the first trial opens the session
  ~RobotLink();                             // a session still open is stopped, zero torque
  RobotLink(const RobotLink&) = delete;
  RobotLink& operator=(const RobotLink&) = delete;

  // Opens the session when none is, asks the robot for a trial from `theta0` and returns its
  // first measurement's signals. A robot that does not welcome this controller throws
  // SimulationStopped, as a lost link does.
  const std::vector<double>& start_trial(double theta0);
  // Answers the last measurement with the wheel torques and returns the next measurement's
  // signals.
  const std::vector<double>& exchange(double tau_left, double tau_right);
  // A stop with `reason` (the robot holds zero torque), once; the session is over.
  void stop(const std::string& reason);

  // The figures since the last call (the trial's, called after each).
  LinkFigures take_figures();
  const std::string& robot_name() const { return robot_name_; }
  const LinkOptions& options() const { return options_; }

 private:
  void open_session();
  // The next datagram of this session from the robot, or none at `deadline`; refusals
  // counted. A stop from the robot, or a stop request here, throws.
  std::optional<Datagram> next_from_robot(Clock::time_point deadline);
  // Waits for the next measurement (the first of a trial when `first`) and applies the newest
  // queued; throws SimulationStopped after timeout_periods of silence.
  const std::vector<double>& await_measurement(bool first);
  // Whether `datagram` is a measurement to apply: well formed, newer than the last, of the
  // trial. Refusals counted.
  bool is_next_measurement(const Datagram& datagram, bool first);
  void apply(const Datagram& measurement, bool first);
  void send(Datagram datagram);
  [[noreturn]] void stop_and_throw(const std::string& reason);

  LinkOptions options_;
  std::unique_ptr<UdpEndpoint> endpoint_;
  sockaddr_in robot_{};
  std::uint32_t session_ = 0;
  bool open_ = false;
  std::string robot_name_;
  std::optional<std::uint32_t> last_sequence_;  // the last measurement applied
  std::uint64_t last_stamp_ = 0;
  double last_time_ = 0.0;
  std::vector<double> signals_;
  LinkFigures figures_;
};

}  // namespace cbbg::realtime
