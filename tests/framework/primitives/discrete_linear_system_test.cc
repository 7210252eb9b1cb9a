#include "cbbg/framework/primitives/discrete_linear_system.h"

#include <stdexcept>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "cbbg/framework/diagram_builder.h"
#include "cbbg/framework/primitives/gain.h"
#include "cbbg/framework/primitives/ramp_source.h"
#include "cbbg/framework/simulator.h"

namespace cbbg {
namespace {

using ::testing::HasSubstr;
using ::testing::ThrowsMessage;

// x_{k+1} = [1 0.1; 0 0.9] x_k + [0; 0.1] u_k, y = [1 0] x + d u.
Eigen::MatrixXd a_matrix() { return (Eigen::MatrixXd(2, 2) << 1.0, 0.1, 0.0, 0.9).finished(); }
Eigen::MatrixXd b_matrix() { return (Eigen::MatrixXd(2, 1) << 0.0, 0.1).finished(); }
Eigen::MatrixXd c_matrix() { return (Eigen::MatrixXd(1, 2) << 1.0, 0.0).finished(); }
Eigen::MatrixXd d_matrix(double d) { return Eigen::MatrixXd::Constant(1, 1, d); }

TEST(DiscreteLinearSystem, PortsStateAndFeedthroughOnlyWithANonzeroD) {
  const DiscreteLinearSystem strict("strict", a_matrix(), b_matrix(), c_matrix(), d_matrix(0.0),
                                    Eigen::Vector2d(1.0, -1.0), 0.1);
  ASSERT_EQ(strict.num_input_ports(), 1);
  ASSERT_EQ(strict.num_output_ports(), 1);
  EXPECT_EQ(strict.input_port("u").size(), 1);
  EXPECT_EQ(strict.output_port("y").size(), 1);
  EXPECT_TRUE(strict.output_reads(0).empty());
  EXPECT_EQ(strict.discrete_state_part("x").size, 2);
  EXPECT_EQ(strict.discrete_state_part("x").lifetime, StateLifetime::kPerTrial);
  EXPECT_EQ(strict.initial_discrete_state(), Eigen::Vector2d(1.0, -1.0));
  ASSERT_EQ(strict.periodic_updates().size(), 1U);
  EXPECT_EQ(strict.periodic_updates()[0].period, 0.1);
  EXPECT_FALSE(strict.has_continuous_state());

  const DiscreteLinearSystem proper("proper", a_matrix(), b_matrix(), c_matrix(), d_matrix(2.0),
                                    Eigen::Vector2d(1.0, -1.0), 0.1, 0.05);
  EXPECT_EQ(proper.output_reads(0), std::vector<int>{0});
  EXPECT_EQ(proper.periodic_updates()[0].offset, 0.05);
}

TEST(DiscreteLinearSystem, FollowsTheRecurrenceWorkedByHand) {
  // u(t) = t, sampled at t_k = 0.1 k, so u_k = 0.1 k. From x_0 = (1, -1):
  //   x_1 = (1 - 0.1,          -0.9 + 0)      = (0.9,  -0.9)
  //   x_2 = (0.9 - 0.09,       -0.81 + 0.01)  = (0.81, -0.8)
  //   x_3 = (0.81 - 0.08,      -0.72 + 0.02)  = (0.73, -0.7)
  // and y = x_1 + 2 u (D = 2) reads the input of the moment.
  DiagramBuilder builder("top");
  auto& ramp = builder.emplace<RampSource>("ramp", 1.0, 0.0);
  auto& system = builder.emplace<DiscreteLinearSystem>(
      "system", a_matrix(), b_matrix(), c_matrix(), d_matrix(2.0), Eigen::Vector2d(1.0, -1.0), 0.1);
  builder.connect(ramp, "y", system, "u");
  auto diagram = builder.build();
  Simulator simulator(*diagram);
  const Eigen::Vector2d expected[] = {{1.0, -1.0}, {0.9, -0.9}, {0.81, -0.8}, {0.73, -0.7}};
  EXPECT_EQ(simulator.context().discrete_state(system), expected[0]);  // before any update
  for (int k = 1; k < 4; ++k) {
    // After the updates at 0, ..., 0.1 (k - 1): x_k, held until 0.1 k.
    simulator.advance_to(0.1 * (k - 1) + 0.05);
    const auto x = simulator.context().discrete_state(system);
    EXPECT_NEAR(x[0], expected[k][0], 1e-12) << "k = " << k;
    EXPECT_NEAR(x[1], expected[k][1], 1e-12) << "k = " << k;
    const double t = simulator.context().time();
    EXPECT_NEAR(diagram->eval_output(simulator.context(), system.output_port("y"))[0],
                expected[k][0] + 2.0 * t, 1e-12)
        << "k = " << k;
  }

  // Further on, the same recurrence run here.
  simulator.advance_to(5.05);
  Eigen::Vector2d x(1.0, -1.0);
  for (int k = 0; k <= 50; ++k) x = a_matrix() * x + b_matrix() * (0.1 * k);
  EXPECT_NEAR(simulator.context().discrete_state(system)[0], x[0], 1e-9);
  EXPECT_NEAR(simulator.context().discrete_state(system)[1], x[1], 1e-9);

  // Per trial: a new trial starts again from x_0.
  simulator.context().reset_trial_state();
  EXPECT_EQ(simulator.context().discrete_state(system), Eigen::Vector2d(1.0, -1.0));
}

TEST(DiscreteLinearSystem, ClosesAFeedbackLoopOnlyWithoutFeedthrough) {
  // x_{k+1} = 0.5 x_k + u_k, y = x, u = -0.25 y: x_{k+1} = 0.25 x_k.
  const auto scalar = [](double v) { return Eigen::MatrixXd::Constant(1, 1, v); };
  DiagramBuilder builder("top");
  auto& system = builder.emplace<DiscreteLinearSystem>(
      "system", scalar(0.5), scalar(1.0), scalar(1.0), scalar(0.0), Vector::Constant(1, 8.0), 1.0);
  auto& feedback = builder.emplace<Gain>("feedback", -0.25, 1);
  builder.connect(system, "y", feedback, "u");
  builder.connect(feedback, "y", system, "u");
  auto diagram = builder.build();
  Simulator simulator(*diagram);
  simulator.advance_to(2.5);  // updates at 0, 1, 2
  EXPECT_EQ(simulator.context().discrete_state(system)[0], 8.0 * 0.25 * 0.25 * 0.25);

  DiagramBuilder looped("top");
  auto& proper = looped.emplace<DiscreteLinearSystem>(
      "system", scalar(0.5), scalar(1.0), scalar(1.0), scalar(1.0), Vector::Constant(1, 8.0), 1.0);
  auto& gain = looped.emplace<Gain>("feedback", -0.25, 1);
  looped.connect(proper, "y", gain, "u");
  looped.connect(gain, "y", proper, "u");
  EXPECT_THAT([&] { looped.build(); },
              ThrowsMessage<std::invalid_argument>(HasSubstr("algebraic loop")));
}

TEST(DiscreteLinearSystem, RefusesBadArguments) {
  EXPECT_THAT(
      [] {
        DiscreteLinearSystem("sys", a_matrix(), b_matrix(), c_matrix(), d_matrix(0.0),
                             Vector::Zero(2), 0.0);
      },
      ThrowsMessage<std::invalid_argument>(
          "DiscreteLinearSystem 'sys': period 0 must be positive and finite"));
  EXPECT_THAT(
      [] {
        DiscreteLinearSystem("sys", a_matrix(), b_matrix(), c_matrix(), d_matrix(0.0),
                             Vector::Zero(2), 0.1, -1.0);
      },
      ThrowsMessage<std::invalid_argument>(
          "DiscreteLinearSystem 'sys': offset -1 must be finite and >= 0"));
  EXPECT_THAT(
      [] {
        DiscreteLinearSystem("sys", a_matrix(), b_matrix(), c_matrix(), Eigen::MatrixXd(2, 1),
                             Vector::Zero(2), 0.1);
      },
      ThrowsMessage<std::invalid_argument>(
          "DiscreteLinearSystem 'sys': D is 2x1; it must be p x m = 1x1 (C's rows by B's "
          "columns)"));
  EXPECT_THAT(
      [] {
        DiscreteLinearSystem("sys", a_matrix(), b_matrix(), c_matrix(), d_matrix(0.0),
                             Vector::Zero(1), 0.1);
      },
      ThrowsMessage<std::invalid_argument>(
          "DiscreteLinearSystem 'sys': the initial state has size 1; it must have size n = 2 "
          "(A is 2x2)"));
}

}  // namespace
}  // namespace cbbg
