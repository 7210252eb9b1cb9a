#include "cbbg/framework/primitives/pid_controller.h"

#include <limits>
#include <stdexcept>
#include <vector>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "cbbg/framework/diagram_builder.h"
#include "cbbg/framework/primitives/gain.h"
#include "cbbg/framework/primitives/step_source.h"
#include "cbbg/framework/simulator.h"

namespace cbbg {
namespace {

using ::testing::ThrowsMessage;

TEST(PidController, PortsStateAndNoFeedthrough) {
  const PidController pid("pid", {.kp = 1.0, .ki = 0.5, .kd = 0.1, .u_min = -2.0, .u_max = 3.0},
                          0.01, 2);
  ASSERT_EQ(pid.num_input_ports(), 1);
  ASSERT_EQ(pid.num_output_ports(), 1);
  EXPECT_EQ(pid.input_port("e").size(), 2);
  EXPECT_EQ(pid.output_port("u").size(), 2);
  EXPECT_TRUE(pid.output_reads(0).empty());  // u is held state: the PID closes loops
  for (const char* part : {"integral", "previous_error", "command"}) {
    EXPECT_EQ(pid.discrete_state_part(part).size, 2) << part;
    EXPECT_EQ(pid.discrete_state_part(part).lifetime, StateLifetime::kPerTrial) << part;
  }
  EXPECT_EQ(pid.discrete_state_part("started").lifetime, StateLifetime::kPerTrial);
  ASSERT_EQ(pid.periodic_updates().size(), 1U);
  EXPECT_EQ(pid.periodic_updates()[0].period, 0.01);

  // Before the first sample u is sat(0).
  const PidController shifted("shifted", {.kp = 1.0, .u_min = 0.5, .u_max = 1.0}, 0.01);
  EXPECT_EQ(shifted.discrete_state_part("command").of(shifted.initial_discrete_state())[0], 0.5);

  // Closes a loop with a block that feeds through.
  DiagramBuilder builder("top");
  auto& controller = builder.emplace<PidController>("pid", PidController::Params{.kp = 1.0}, 0.1);
  auto& plant = builder.emplace<Gain>("plant", -1.0, 1);
  builder.connect(controller, "u", plant, "u");
  builder.connect(plant, "y", controller, "e");
  EXPECT_NO_THROW(builder.build());
}

TEST(PidController, FollowsTheSequenceWorkedByHand) {
  // h = 0.5, kp = 1, ki = 2, kd = 0.25, u in [-1, 1.5]; e = 1 up to t = 1.5, -0.5 from t = 2.
  //  k  t    e     D    I_k    v = e + 2 I + D/4   u      I_{k+1}
  //  0  0    1     0    0      1                   1      0.5     (D_0 = 0: no kick)
  //  1  0.5  1     0    0.5    2                   1.5    0.5     (v > u_max, e > 0: held)
  //  2  1    1     0    0.5    2                   1.5    0.5
  //  3  1.5  1     0    0.5    2                   1.5    0.5
  //  4  2   -0.5  -3    0.5   -0.25               -0.25   0.25    (unwound at once)
  //  5  2.5 -0.5   0    0.25   0                   0      0
  //  6  3   -0.5   0    0     -0.5                -0.5   -0.25
  //  7  3.5 -0.5   0   -0.25  -1                  -1     -0.5     (v = u_min: integrates)
  //  8  4   -0.5   0   -0.5   -1.5                -1     -0.5     (v < u_min, e < 0: held)
  //  9  4.5 -0.5   0   -0.5   -1.5                -1     -0.5
  // Without anti-windup I would reach 2 by k = 4 and u would stay at 1.5 there.
  DiagramBuilder builder("top");
  auto& error = builder.emplace<StepSource>("error", 1.0, -0.5, 1.75);
  auto& pid = builder.emplace<PidController>(
      "pid", PidController::Params{.kp = 1.0, .ki = 2.0, .kd = 0.25, .u_min = -1.0, .u_max = 1.5},
      0.5);
  builder.connect(error, "y", pid, "e");
  auto diagram = builder.build();
  const std::vector<double> expected_u = {1.0, 1.5, 1.5, 1.5, -0.25, 0.0, -0.5, -1.0, -1.0, -1.0};
  const std::vector<double> expected_integral = {0.5, 0.5,   0.5,  0.5,  0.25,
                                                 0.0, -0.25, -0.5, -0.5, -0.5};
  const StatePart& integral = pid.discrete_state_part("integral");
  const StatePart& previous = pid.discrete_state_part("previous_error");

  Simulator simulator(*diagram);
  for (int run = 0; run < 2; ++run) {  // the second, a new trial, repeats the first
    for (std::size_t k = 0; k < expected_u.size(); ++k) {
      simulator.advance_to(0.5 * static_cast<double>(k) + 0.25);  // u_k is held here
      Context& context = simulator.context();
      EXPECT_EQ(diagram->eval_output(context, pid.output_port("u"))[0], expected_u[k])
          << "run " << run << ", k = " << k;
      EXPECT_EQ(integral.of(context.discrete_state(pid))[0], expected_integral[k])
          << "run " << run << ", k = " << k;
      EXPECT_EQ(previous.of(context.discrete_state(pid))[0], k < 4 ? 1.0 : -0.5);
    }
    simulator.context().reset_trial_state();
    EXPECT_EQ(simulator.context().discrete_state(pid), pid.initial_discrete_state());
    simulator.initialize();
  }
}

TEST(PidController, WorksElementwise) {
  // Two independent loops of one block; no limits: u_k = kp e_k + ki I_k + kd D_k.
  DiagramBuilder builder("top");
  auto& error = builder.emplace<StepSource>("error", Eigen::Vector2d(2.0, -4.0),
                                            Eigen::Vector2d(0.0, 1.0), 0.5);
  auto& pid = builder.emplace<PidController>(
      "pid", PidController::Params{.kp = 0.5, .ki = 1.0, .kd = 0.125}, 0.25, 2);
  builder.connect(error, "y", pid, "e");
  auto diagram = builder.build();
  Simulator simulator(*diagram);
  // k = 0 (t = 0): u = 0.5 e = (1, -2); I_1 = 0.25 e = (0.5, -1).
  simulator.advance_to(0.1);
  EXPECT_EQ(diagram->eval_output(simulator.context(), pid.output_port("u")),
            Eigen::Vector2d(1.0, -2.0));
  // k = 1 (t = 0.25): u = 0.5 e + I_1 = (1.5, -3); I_2 = (1, -2).
  simulator.advance_to(0.3);
  EXPECT_EQ(diagram->eval_output(simulator.context(), pid.output_port("u")),
            Eigen::Vector2d(1.5, -3.0));
  // k = 2 (t = 0.5): e = (0, 1), D = (-8, 20): u = (0 + 1 - 1, 0.5 - 2 + 2.5) = (0, 1).
  simulator.advance_to(0.6);
  EXPECT_EQ(diagram->eval_output(simulator.context(), pid.output_port("u")),
            Eigen::Vector2d(0.0, 1.0));
}

TEST(PidController, RefusesBadArguments) {
  const auto nan = std::numeric_limits<double>::quiet_NaN();
  const auto inf = std::numeric_limits<double>::infinity();
  EXPECT_THAT(
      [] { PidController("pid", {.kp = -1.0}, 0.1); },
      ThrowsMessage<std::invalid_argument>("PidController 'pid': kp -1 must be finite and >= 0"));
  EXPECT_THAT(
      [&] { PidController("pid", {.ki = nan}, 0.1); },
      ThrowsMessage<std::invalid_argument>("PidController 'pid': ki nan must be finite and >= 0"));
  EXPECT_THAT(
      [&] { PidController("pid", {.kd = inf}, 0.1); },
      ThrowsMessage<std::invalid_argument>("PidController 'pid': kd inf must be finite and >= 0"));
  EXPECT_THAT([] { PidController("pid", {.u_min = 2.0, .u_max = 1.0}, 0.1); },
              ThrowsMessage<std::invalid_argument>(
                  "PidController 'pid': u_min 2 is above u_max 1; u_min must be <= u_max"));
  EXPECT_THAT([&] { PidController("pid", {.u_min = inf}, 0.1); },
              ThrowsMessage<std::invalid_argument>(
                  "PidController 'pid': u_min inf must be a number below inf (-inf for no "
                  "lower limit)"));
  EXPECT_THAT([&] { PidController("pid", {.u_max = nan}, 0.1); },
              ThrowsMessage<std::invalid_argument>(
                  "PidController 'pid': u_max nan must be a number above -inf (inf for no "
                  "upper limit)"));
  EXPECT_THAT([] { PidController("pid", {}, 0.0); },
              ThrowsMessage<std::invalid_argument>(
                  "PidController 'pid': period 0 must be positive and finite"));
  EXPECT_THAT(
      [] { PidController("pid", {}, 0.1, 0); },
      ThrowsMessage<std::invalid_argument>("PidController 'pid': size 0 must be at least 1"));
}

}  // namespace
}  // namespace cbbg
