// Both ends of the real-time link over the loopback address, in one process: a trial against
// a served robot is the simulated trial tick for tick; a silent peer is lost at zero torque;
// what a third party sends is refused and never applied.

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <atomic>
#include <cstring>
#include <fstream>
#include <future>
#include <thread>

#include "cbbg/config/config.h"
#include "cbbg/diagrams/arms.h"
#include "cbbg/diagrams/plant_kinds.h"
#include "cbbg/diagrams/validated_parameters.h"
#include "cbbg/experiments/trial_runner.h"
#include "cbbg/framework/simulator.h"
#include "cbbg/plant/plant_signals.h"
#include "cbbg/realtime/remote_plant.h"
#include "cbbg/realtime/robot_link.h"
#include "cbbg/realtime/robot_server.h"

namespace cbbg::realtime {
namespace {

// A generous period and deadline: the tests check what the link does, not this machine's
// timing, which a loaded test run may stretch.
constexpr double kPeriod = 0.02;

parameters::Parameters parameters_with(const std::vector<std::string>& sets) {
  config::Config config;
  config.set("trial.period=" + std::to_string(kPeriod));
  for (const std::string& set : sets) config.set(set);
  return diagrams::validated_parameters(config);
}

// `cbbg robot` in a thread: the analytic two-wheeler on a port the system picks.
class ServedRobot {
 public:
  ServedRobot() : ServedRobot(served_defaults()) {}
  explicit ServedRobot(ServeOptions options) : ServedRobot(std::move(options), analytic_robot()) {}
  ServedRobot(ServeOptions options, SimulatedRobot robot) : robot_(std::move(robot)) {
    options.bind = Address{"127.0.0.1", 0};
    options.sessions = 1;
    options.deadline = 1.0;
    std::promise<Address> bound;
    auto address = bound.get_future();
    options.listening = [&bound](const Address& at) { bound.set_value(at); };
    served_ =
        std::async(std::launch::async, [this, options] { return serve_robot(robot_, options); });
    address_ = address.get();
  }
  const Address& address() const { return address_; }
  ServeFigures figures() { return served_.get(); }
  // In lockstep: a trial is the simulated one however loaded the machine running the test.
  static ServeOptions served_defaults() {
    ServeOptions options;
    options.lockstep = true;
    return options;
  }

 private:
  static SimulatedRobot analytic_robot() {
    const parameters::Parameters p = parameters_with({"plant.kind=analytic"});
    return SimulatedRobot(diagrams::plant_kind("analytic").make("plant", p), p.trial.period,
                          p.plant.robot.accuracy);
  }

  SimulatedRobot robot_;
  std::future<ServeFigures> served_;
  Address address_;
};

LinkOptions link_to(const Address& robot, int timeout_periods = 10) {
  LinkOptions link;
  link.robot = robot;
  link.period = kPeriod;
  link.timeout_periods = timeout_periods;
  link.connect_timeout = 5.0;
  link.controller = "link_test";
  link.signals = plant::two_wheeler_signals();
  return link;
}

// The pd_only arm's trial of `seconds` from 0.1744 rad: its telemetry, tick by tick.
Eigen::MatrixXd pd_trial(const parameters::Parameters& p, double seconds,
                         experiments::TrialStatus expected = experiments::TrialStatus::kSuccess) {
  const diagrams::ClosedLoop loop = diagrams::named_arm("pd_only").learner(p);
  experiments::TrialRunner runner(loop, 1, p.trial.period);
  EXPECT_EQ(runner.run_trial(0.1744, seconds).status, expected);
  return runner.telemetry().values();
}

// Bit for bit, NaN (a signal the arm has not: pd_only's value) included.
bool same_bits(const Eigen::MatrixXd& a, const Eigen::MatrixXd& b) {
  return a.rows() == b.rows() && a.cols() == b.cols() &&
         std::memcmp(a.data(), b.data(), sizeof(double) * static_cast<std::size_t>(a.size())) == 0;
}

TEST(RealtimeLink, ATrialAgainstAServedRobotIsTheSimulatedTrialTickForTick) {
  ServedRobot served;
  const auto simulated = pd_trial(parameters_with({"plant.kind=analytic"}), 1.0);
  const auto remote =
      pd_trial(parameters_with(
                   {"plant.kind=remote", "remote.port=" + std::to_string(served.address().port)}),
               1.0);
  const ServeFigures figures = served.figures();
  EXPECT_EQ(figures.sessions, 1);
  EXPECT_EQ(figures.link.refused_total(), 0);
  ASSERT_EQ(remote.cols(), simulated.cols());  // the whole trial: 1 s
  EXPECT_TRUE(same_bits(remote, simulated));
}

// A robot of the test's own: it welcomes, measures once, then answers only what it is asked.
class SilentRobot {
 public:
  SilentRobot() : endpoint_(Address{"127.0.0.1", 0}) {}
  Address address() const { return {"127.0.0.1", endpoint_.port()}; }
  // The next datagram from the controller, decoded.
  Datagram next() {
    auto received = endpoint_.receive_until(Clock::now() + std::chrono::seconds(5));
    EXPECT_TRUE(received.has_value());
    if (!received) return {};
    from_ = received->from;
    Decoded decoded = decode(received->bytes.data(), received->bytes.size(), "");
    EXPECT_TRUE(decoded.datagram.has_value());
    return decoded.datagram.value_or(Datagram{});
  }
  void send(const Datagram& datagram) { endpoint_.send(encode(datagram, ""), from_); }
  void welcome_and_measure_once() {
    const Datagram hello = next();
    EXPECT_EQ(hello.kind, DatagramKind::kHello);
    EXPECT_EQ(hello.text, "link_test");
    const std::string names = joined_names(plant::two_wheeler_signals());
    send({DatagramKind::kWelcome, hello.session, 0, 0.0, 0, {kPeriod}, "silent\n" + names});
    const Datagram start = next();
    EXPECT_EQ(start.kind, DatagramKind::kStart);
    std::vector<double> values(plant::two_wheeler_signals().size(), 0.0);
    values.push_back(kNoTorqueAsked);
    send({DatagramKind::kMeasurement, hello.session, 7, 0.0, 99, values, {}});
  }

 private:
  UdpEndpoint endpoint_;
  sockaddr_in from_{};
};

TEST(RealtimeLink, ARobotSilentForTheTimeoutIsLostAtZeroTorque) {
  SilentRobot robot;
  RobotLink link(link_to(robot.address(), 3));
  std::thread silent([&robot] { robot.welcome_and_measure_once(); });
  link.start_trial(0.1);
  silent.join();
  try {
    link.exchange(1.5, 1.5);
    FAIL() << "a silent robot was not lost";
  } catch (const SimulationStopped& stopped) {
    EXPECT_EQ(std::string(stopped.what()),
              "the robot at " + robot.address().text() +
                  " sent nothing for 3 periods: stopped at zero torque");
  }
  EXPECT_EQ(link_failure(),
            "the robot at " + robot.address().text() + " sent nothing for 3 periods");
  const Datagram asked = robot.next();
  EXPECT_EQ(asked.kind, DatagramKind::kTorque);
  EXPECT_EQ(asked.values, (std::vector<double>{1.5, 1.5}));
  EXPECT_EQ(asked.sequence, 7u);  // answering the measurement
  const Datagram stop = robot.next();
  EXPECT_EQ(stop.kind, DatagramKind::kStop);
  EXPECT_EQ(stop.text, "the robot at " + robot.address().text() + " sent nothing for 3 periods");
}

TEST(RealtimeLink, AControllerSilentForTheTimeoutIsStoppedByTheRobot) {
  ServeOptions options;  // in real time: a torque not there by the deadline is missed
  options.timeout_periods = 3;
  ServedRobot served(options);
  RobotLink link(link_to(served.address()));
  link.start_trial(0.1);
  std::this_thread::sleep_for(std::chrono::duration<double>(6 * kPeriod));
  try {
    link.exchange(0.0, 0.0);
    FAIL() << "the robot went on without torques";
  } catch (const SimulationStopped& stopped) {
    EXPECT_EQ(std::string(stopped.what()), "the robot at " + served.address().text() +
                                               " stopped the session: no torque for 3 periods");
  }
  EXPECT_EQ(served.figures().link.deadline_misses, 3);
}

TEST(RealtimeLink, ARobotOfAnotherPeriodOrOtherSignalsRefusesTheSession) {
  ServedRobot served;
  LinkOptions other_period = link_to(served.address());
  other_period.period = 0.01;
  other_period.connect_timeout = 1.0;
  try {
    RobotLink(other_period).start_trial(0.1);
    FAIL() << "a session of another period opened";
  } catch (const SimulationStopped& refused) {
    EXPECT_EQ(std::string(refused.what()), "the robot at " + served.address().text() +
                                               " stopped the session: this robot ticks every "
                                               "0.02 s");
  }
  LinkOptions other_signals = link_to(served.address());
  other_signals.signals = {"theta_b", "dtheta_b"};
  try {
    RobotLink(other_signals).start_trial(0.1);
    FAIL() << "a session of other signals opened";
  } catch (const SimulationStopped& refused) {
    EXPECT_EQ(std::string(refused.what()),
              "the robot at " + served.address().text() +
                  " serves the signals 'pitch,pitch_rate,wheel_left,wheel_right,"
                  "wheel_left_rate,wheel_right_rate,x,y,yaw,yaw_rate'; the loop reads "
                  "'theta_b,dtheta_b'");
  }
}

// A user's robot that stands still and cannot start beyond 1 rad.
class StillRobot final : public plant::RobotPlant {
 public:
  StillRobot() : RobotPlant("still") {
    declare_input_port("torque", plant::kTorqueSize);
    declare_continuous_state(
        Vector::Zero(plant::kStateSize),
        [](const BlockContext&, VectorRef derivatives) { derivatives.setZero(); });
    declare_output_port(
        "state", plant::kStateSize,
        [](const BlockContext& context, VectorRef y) { y = context.continuous_state(); }, {});
  }
  void reset(Context& context, double initial_pitch) const override {
    if (std::abs(initial_pitch) > 1.0) throw std::invalid_argument("beyond 1 rad");
    context.continuous_state(*this).setZero();
    context.continuous_state(*this)[plant::kThetaB] = initial_pitch;
  }
};

TEST(RealtimeLink, APitchTheRobotCannotStartAtEndsTheSessionNotTheRobot) {
  ServedRobot served(ServedRobot::served_defaults(),
                     SimulatedRobot(std::make_shared<StillRobot>(), kPeriod, 1e-6));
  try {
    RobotLink(link_to(served.address())).start_trial(3.0);
    FAIL() << "a trial started upside down";
  } catch (const SimulationStopped& refused) {
    EXPECT_THAT(std::string(refused.what()),
                ::testing::StartsWith("the robot at " + served.address().text() +
                                      " stopped the session: it cannot start there: beyond 1 "
                                      "rad"));
  }
  const ServeFigures figures = served.figures();  // the server returned: it did not fail
  EXPECT_EQ(figures.sessions, 1);
  EXPECT_EQ(figures.last_end, "it cannot start there: beyond 1 rad");
}

TEST(RealtimeLink, NoRobotThereIsAOneLineErrorAfterTheConnectTimeout) {
  UdpEndpoint nobody(Address{"127.0.0.1", 0});  // a port that never answers
  LinkOptions options = link_to({"127.0.0.1", nobody.port()});
  options.connect_timeout = 0.5;
  try {
    RobotLink(options).start_trial(0.1);
    FAIL() << "a session opened with nobody";
  } catch (const SimulationStopped& error) {
    EXPECT_EQ(std::string(error.what()),
              "no robot welcomed this controller at 127.0.0.1:" + std::to_string(nobody.port()) +
                  " within 0.5 s (is `cbbg robot` serving there, with the same key?)");
  }
}

// A third party on the loopback address sends to both ends during a trial: rubbish, datagrams
// signed with another key, and well-formed ones of its own. Each end refuses them by reason,
// and the trial is the simulated one still.
TEST(RealtimeLink, WhatAThirdPartySendsIsRefusedAndNeverApplied) {
  ServeOptions options = ServedRobot::served_defaults();
  options.key = "shared key";
  ServedRobot served(options);
  // A port for the controller the forger can aim at: free once the probe is gone.
  const std::uint16_t controller_port = [] {
    return UdpEndpoint(Address{"127.0.0.1", 0}).port();
  }();
  std::atomic<bool> running{true};
  std::thread forger([&] {
    UdpEndpoint third(Address{"127.0.0.1", 0});
    const Datagram shove{DatagramKind::kTorque, 1, 1, 0.0, 0, {1000.0, 1000.0}, {}};
    while (running) {
      for (const sockaddr_in to :
           {to_sockaddr(served.address()), to_sockaddr({"127.0.0.1", controller_port})}) {
        third.send({1, 2, 3}, to);
        third.send(encode(shove, "a guess"), to);
        third.send(encode(shove, "shared key"), to);
      }
      std::this_thread::sleep_for(std::chrono::milliseconds(5));
    }
  });
  const auto simulated = pd_trial(parameters_with({"plant.kind=analytic"}), 1.0);
  const std::string key_file = testing::TempDir() + "/cbbg_link_key";
  std::ofstream(key_file) << "shared key\n";
  config::Config keyed;
  keyed.set("trial.period=" + std::to_string(kPeriod));
  for (const std::string& set : std::vector<std::string>{
           "plant.kind=remote", "remote.port=" + std::to_string(served.address().port),
           "remote.bind_port=" + std::to_string(controller_port), "remote.key_file=" + key_file}) {
    keyed.set(set);
  }
  const parameters::Parameters p = diagrams::validated_parameters(keyed);
  const diagrams::ClosedLoop loop = diagrams::named_arm("pd_only").learner(p);
  experiments::TrialRunner runner(loop, 1, p.trial.period);
  EXPECT_EQ(runner.run_trial(0.1744, 1.0).status, experiments::TrialStatus::kSuccess);
  RobotLink& link = dynamic_cast<const RemotePlant&>(*loop.plant).link();
  const LinkFigures controller = link.take_figures();
  link.stop("the test is over");
  running = false;
  forger.join();
  const ServeFigures robot = served.figures();
  EXPECT_TRUE(same_bits(runner.telemetry().values(), simulated));
  for (const LinkFigures* end : {&controller, &robot.link}) {
    EXPECT_GT(end->refused[static_cast<std::size_t>(Refusal::kMalformed)], 0);
    EXPECT_GT(end->refused[static_cast<std::size_t>(Refusal::kForged)], 0);
    EXPECT_GT(end->refused[static_cast<std::size_t>(Refusal::kOtherSource)], 0);
  }
}

}  // namespace
}  // namespace cbbg::realtime
