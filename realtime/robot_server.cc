// The robot's loop. Its clock is the master: measurement k leaves at T0 + k period whatever
// the controller does; a torque is applied only if it answers the measurement just sent.

#include "cbbg/realtime/robot_server.h"

#include <array>
#include <cmath>
#include <optional>
#include <thread>

#include "cbbg/framework/number_text.h"
#include "cbbg/realtime/stop_request.h"

namespace cbbg::realtime {
namespace {

// How long a robot waits for a session's first start, and for a hello between checks of
// the stop request.
constexpr double kStartTimeout = 10.0;  // s
constexpr double kIdlePoll = 0.2;       // s

class Session {
 public:
  // `welcome`: what answers the controller's hello, sent again if it says hello again.
  Session(SimulatedRobot& robot, UdpEndpoint& endpoint, const ServeOptions& options,
          const sockaddr_in& peer, const Datagram& welcome)
      : robot_(robot),
        endpoint_(endpoint),
        options_(options),
        peer_(peer),
        id_(welcome.session),
        welcome_(welcome) {}

  // Until a stop (either side's), or the link's silence. Returns the session's figures.
  ServeFigures run() {
    send(welcome_);
    std::optional<Datagram> start = await(Clock::now() + to_duration(kStartTimeout), std::nullopt);
    while (start) start = trial(start->values[0]);
    send({DatagramKind::kStop, id_, 0, 0.0, now_ns(), {}, end_reason_});
    figures_.last_end = end_reason_;
    return figures_;
  }

 private:
  // A trial from theta0 until the next start (returned) or the session's end (none).
  std::optional<Datagram> trial(double theta0) {
    if (!robot_does([&] { robot_.reset(theta0); }, "it cannot start there")) return std::nullopt;
    torque_ = {0.0, 0.0};
    round_trip_ = kNoTorqueAsked;
    silent_ = 0;
    const Clock::time_point t0 = Clock::now();
    for (long long k = 0;; ++k) {
      std::optional<Datagram> start = tick(t0 + k * to_duration(robot_.period()), k);
      if (start || ended_) return start;
      ++figures_.link.ticks;
      if (!robot_does([&] { robot_.step(torque_[0], torque_[1]); }, "its simulation failed")) {
        return std::nullopt;
      }
    }
  }

  // Tick k, due at `due`: the measurement sent, then the torque that answers it taken, or
  // the last one held (a deadline miss; in lockstep, waited for and taken late). Returns a
  // start that came instead.
  std::optional<Datagram> tick(Clock::time_point due, long long k) {
    const double period = robot_.period();
    if (Clock::now() > due + to_duration(options_.deadline * period)) ++figures_.overruns;
    std::this_thread::sleep_until(due);
    std::vector<double> values = robot_.signals();
    values.push_back(round_trip_);
    const std::uint64_t stamp = now_ns();
    send({DatagramKind::kMeasurement,
          id_,
          ++sequence_,
          static_cast<double>(k) * period,
          stamp,
          values,
          {}});
    const Clock::time_point deadline = due + to_duration(options_.deadline * period);
    const Clock::time_point silent_too_long =
        due + to_duration(static_cast<double>(options_.timeout_periods) * period);
    std::optional<Datagram> answer =
        await(options_.lockstep ? silent_too_long : deadline, sequence_);
    if (answer && answer->kind != DatagramKind::kTorque) return answer;
    if (answer) {
      if (Clock::now() > deadline) ++figures_.link.deadline_misses;  // only in lockstep
      torque_ = {answer->values[0], answer->values[1]};
      round_trip_ = static_cast<double>(now_ns() - stamp) * 1e-9;
      figures_.link.latencies.push_back(round_trip_);
      silent_ = 0;
    } else if (!ended_) {
      round_trip_ = kMissedDeadline;
      ++figures_.link.deadline_misses;
      silent_ = options_.lockstep ? options_.timeout_periods : silent_ + 1;
      if (silent_ >= options_.timeout_periods) {
        end("no torque for " + std::to_string(silent_) + " periods");
      }
    }
    return std::nullopt;
  }

  // Runs `work` on the robot; a failure (a pitch it cannot start at, a simulation that
  // fails) ends the session with `what` and the reason, instead of ending the server.
  template <typename Work>
  bool robot_does(Work work, const char* what) {
    try {
      work();
      return true;
    } catch (const std::exception& error) {
      end(std::string(what) + ": " + error.what());
      return false;
    }
  }

  // The next datagram of the session before `deadline`: a torque answering `sequence` (when
  // set), a start, or none (the deadline, or the session's end: ended_ set).
  std::optional<Datagram> await(Clock::time_point deadline, std::optional<std::uint32_t> sequence) {
    while (!ended_) {
      if (stop_requested()) {
        end(std::string("the robot was stopped by ") + stop_signal_name());
        break;
      }
      auto received = endpoint_.receive_until(deadline);
      if (!received) {
        if (stop_requested()) continue;
        return std::nullopt;
      }
      std::optional<Datagram> datagram = accepted(*received);
      if (!datagram) continue;
      if (datagram->kind == DatagramKind::kStop) {
        end("the controller stopped: " + datagram->text);
      } else if (datagram->kind == DatagramKind::kStart && datagram->values.size() == 1) {
        return datagram;
      } else if (datagram->kind == DatagramKind::kTorque && sequence &&
                 datagram->sequence == *sequence && datagram->values.size() == 2) {
        return datagram;
      } else if (datagram->kind == DatagramKind::kTorque) {
        figures_.link.refuse(Refusal::kOutOfSequence);  // late, or for no measurement
      } else if (datagram->kind == DatagramKind::kHello) {
        send(welcome_);  // the controller missed the welcome
      } else {
        figures_.link.refuse(Refusal::kMalformed);  // a kind a controller does not send
      }
    }
    return std::nullopt;
  }

  // The datagram, when it is well formed and this session's.
  std::optional<Datagram> accepted(const UdpEndpoint::Received& received) {
    Decoded decoded = decode(received.bytes.data(), received.bytes.size(), options_.key);
    if (!decoded.datagram) {
      figures_.link.refuse(decoded.refusal);
    } else if (!same_peer(received.from, peer_)) {
      figures_.link.refuse(Refusal::kOtherSource);
    } else if (decoded.datagram->session != id_) {
      figures_.link.refuse(Refusal::kOtherSession);
    } else {
      return std::move(decoded.datagram);
    }
    return std::nullopt;
  }

  // The session's end: zero torque at once, whatever comes.
  void end(std::string reason) {
    ended_ = true;
    end_reason_ = std::move(reason);
    torque_ = {0.0, 0.0};
  }

  void send(const Datagram& datagram) { endpoint_.send(encode(datagram, options_.key), peer_); }

  SimulatedRobot& robot_;
  UdpEndpoint& endpoint_;
  const ServeOptions& options_;
  sockaddr_in peer_;
  std::uint32_t id_;
  Datagram welcome_;
  ServeFigures figures_;
  std::uint32_t sequence_ = 0;
  std::array<double, 2> torque_{0.0, 0.0};
  double round_trip_ = kNoTorqueAsked;  // of the last torque, for the next measurement
  int silent_ = 0;                      // periods since the last torque
  bool ended_ = false;
  std::string end_reason_ = "no start came";
};

}  // namespace

ServeFigures serve_robot(SimulatedRobot& robot, const ServeOptions& options) {
  UdpEndpoint endpoint(options.bind);
  options.listening(Address{options.bind.host, endpoint.port()});
  options.report("serving on " + options.bind.host + ":" + std::to_string(endpoint.port()) +
                 ", a tick every " + format_number(robot.period()) + " s");
  ServeFigures figures;
  const std::string welcome = options.name + "\n" + joined_names(robot.signal_names());
  while (!stop_requested() && (options.sessions == 0 || figures.sessions < options.sessions)) {
    auto received = endpoint.receive_until(Clock::now() + to_duration(kIdlePoll));
    if (!received) continue;
    Decoded decoded = decode(received->bytes.data(), received->bytes.size(), options.key);
    if (!decoded.datagram || decoded.datagram->kind != DatagramKind::kHello) {
      figures.link.refuse(decoded.datagram ? Refusal::kOtherSession : decoded.refusal);
      continue;
    }
    const Datagram& hello = *decoded.datagram;
    if (hello.values.size() != 1 || hello.values[0] != robot.period()) {
      endpoint.send(encode({DatagramKind::kStop,
                            hello.session,
                            0,
                            0.0,
                            now_ns(),
                            {},
                            "this robot ticks every " + format_number(robot.period()) + " s"},
                           options.key),
                    received->from);
      continue;
    }
    options.report("session with '" + hello.text + "'");
    const Datagram welcoming{DatagramKind::kWelcome, hello.session, 0, 0.0, now_ns(),
                             {robot.period()},       welcome};
    const ServeFigures session = Session(robot, endpoint, options, received->from, welcoming).run();
    figures.link.add(session.link);
    figures.overruns += session.overruns;
    figures.last_end = session.last_end;
    ++figures.sessions;
    options.report("session over (" + session.last_end + "): " + session.link.line() + ", " +
                   std::to_string(session.overruns) + " overruns");
  }
  return figures;
}

}  // namespace cbbg::realtime
