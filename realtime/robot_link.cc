// The controller's end of the link: every wait bounded by the period, every datagram checked
// (wire.h's decode, then source, session and sequence) before anything in it is applied.

#include "cbbg/realtime/robot_link.h"

#include <cmath>
#include <mutex>
#include <random>
#include <stdexcept>

#include "cbbg/framework/number_text.h"
#include "cbbg/framework/simulator.h"
#include "cbbg/realtime/stop_request.h"

namespace cbbg::realtime {
namespace {

// How often the hello is sent again while no welcome came: a datagram may be lost.
constexpr double kHelloRetry = 0.2;  // s

std::mutex failure_mutex;
std::string failure;  // guarded by failure_mutex

// Records `reason` as the process's last link failure and returns it.
std::string lose(std::string reason) {
  const std::lock_guard lock(failure_mutex);
  failure = reason;
  return reason;
}

}  // namespace

std::string link_failure() {
  const std::lock_guard lock(failure_mutex);
  return failure;
}

RobotLink::RobotLink(LinkOptions options) : options_(std::move(options)) {}

RobotLink::~RobotLink() {
  if (open_) stop("the controller ended");
}

void RobotLink::send(Datagram datagram) {
  datagram.session = session_;
  endpoint_->send(encode(datagram, options_.key), robot_);
}

std::optional<Datagram> RobotLink::next_from_robot(Clock::time_point deadline) {
  while (true) {
    if (stop_requested()) stop_and_throw(std::string("stopped by ") + stop_signal_name());
    auto received = endpoint_->receive_until(deadline);
    if (!received) {
      if (stop_requested()) continue;
      return std::nullopt;
    }
    Decoded decoded = decode(received->bytes.data(), received->bytes.size(), options_.key);
    if (!decoded.datagram) {
      figures_.refuse(decoded.refusal);
    } else if (!same_peer(received->from, robot_)) {
      figures_.refuse(Refusal::kOtherSource);
    } else if (decoded.datagram->session != session_) {
      figures_.refuse(Refusal::kOtherSession);
    } else if (decoded.datagram->kind == DatagramKind::kStop) {
      open_ = false;
      throw SimulationStopped(lose("the robot at " + options_.robot.text() +
                                   " stopped the session: " + decoded.datagram->text));
    } else {
      return std::move(decoded.datagram);
    }
  }
}

void RobotLink::open_session() {
  if (!endpoint_) endpoint_ = std::make_unique<UdpEndpoint>(options_.local);
  robot_ = to_sockaddr(options_.robot);
  session_ = std::random_device{}() | 1u;  // never 0: a zeroed datagram names no session
  const Clock::time_point give_up = Clock::now() + to_duration(options_.connect_timeout);
  while (Clock::now() < give_up) {
    send({DatagramKind::kHello, 0, 0, 0.0, now_ns(), {options_.period}, options_.controller});
    const Clock::time_point retry = std::min(give_up, Clock::now() + to_duration(kHelloRetry));
    const std::optional<Datagram> answer = next_from_robot(retry);
    if (!answer || answer->kind != DatagramKind::kWelcome) continue;
    const std::size_t newline = std::min(answer->text.find('\n'), answer->text.size());
    const std::string served = answer->text.substr(std::min(newline + 1, answer->text.size()));
    open_ = true;
    if (served != joined_names(options_.signals)) {
      const std::string reason = "the robot at " + options_.robot.text() + " serves the signals '" +
                                 served + "'; the loop reads '" + joined_names(options_.signals) +
                                 "'";
      stop(reason.substr(0, kMaxTextBytes));
      throw SimulationStopped(lose(reason));
    }
    robot_name_ = answer->text.substr(0, newline);
    return;
  }
  throw SimulationStopped(lose("no robot welcomed this controller at " + options_.robot.text() +
                               " within " + format_number(options_.connect_timeout) +
                               " s (is `cbbg robot` serving there, with the same key?)"));
}

const std::vector<double>& RobotLink::start_trial(double theta0) {
  if (!open_) open_session();
  send({DatagramKind::kStart, 0, 0, 0.0, now_ns(), {theta0}, {}});
  return await_measurement(true);
}

const std::vector<double>& RobotLink::exchange(double tau_left, double tau_right) {
  send({DatagramKind::kTorque,
        0,
        *last_sequence_,
        last_time_,
        last_stamp_,
        {tau_left, tau_right},
        {}});
  return await_measurement(false);
}

const std::vector<double>& RobotLink::await_measurement(bool first) {
  const double silence = options_.timeout_periods * options_.period;
  const Clock::time_point lost = Clock::now() + to_duration(silence);
  std::optional<Datagram> newest;
  // Waits for one measurement, then takes what else is queued without waiting: a controller
  // that fell behind answers the newest, never a backlog of old ones.
  for (Clock::time_point until = lost;; until = Clock::now()) {
    std::optional<Datagram> datagram = next_from_robot(until);
    if (!datagram) {
      if (newest) break;
      stop_and_throw(lose("the robot at " + options_.robot.text() + " sent nothing for " +
                          std::to_string(options_.timeout_periods) + " periods"));
    }
    if (!is_next_measurement(*datagram, first)) continue;
    if (newest) ++figures_.lost;  // passed over for this newer one
    newest = std::move(datagram);
  }
  apply(*newest, first);
  return signals_;
}

bool RobotLink::is_next_measurement(const Datagram& datagram, bool first) {
  if (datagram.kind != DatagramKind::kMeasurement ||
      datagram.values.size() != options_.signals.size() + 1) {
    figures_.refuse(Refusal::kMalformed);
    return false;
  }
  if (last_sequence_ && datagram.sequence <= *last_sequence_) {
    figures_.refuse(Refusal::kOutOfSequence);
    return false;
  }
  // The robot ticks on between trials: its last measurements before the start are no
  // trial's, and are passed over.
  return !(first && datagram.time != 0.0);
}

void RobotLink::apply(const Datagram& measurement, bool first) {
  const std::size_t n = options_.signals.size();
  if (last_sequence_ && !first) figures_.lost += measurement.sequence - *last_sequence_ - 1;
  const double round_trip = measurement.values[n];
  if (round_trip == kMissedDeadline) ++figures_.deadline_misses;
  if (round_trip >= 0.0) figures_.latencies.push_back(round_trip);
  ++figures_.ticks;
  last_sequence_ = measurement.sequence;
  last_stamp_ = measurement.stamp;
  last_time_ = measurement.time;
  signals_.assign(measurement.values.begin(), measurement.values.begin() + static_cast<long>(n));
}

void RobotLink::stop(const std::string& reason) {
  if (!open_) return;
  open_ = false;
  // A stop is zero torque at the robot; a robot that misses it stops for the silence.
  send({DatagramKind::kStop, 0, 0, 0.0, now_ns(), {}, reason.substr(0, kMaxTextBytes)});
}

void RobotLink::stop_and_throw(const std::string& reason) {
  stop(reason);
  throw SimulationStopped(reason + ": stopped at zero torque");
}

LinkFigures RobotLink::take_figures() { return std::exchange(figures_, LinkFigures{}); }

}  // namespace cbbg::realtime
