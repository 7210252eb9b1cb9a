#include "cbbg/framework/primitives/linear_system.h"

#include <cmath>
#include <limits>
#include <stdexcept>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "cbbg/framework/diagram_builder.h"
#include "cbbg/framework/primitives/gain.h"
#include "cbbg/framework/primitives/step_source.h"
#include "cbbg/framework/simulator.h"

namespace cbbg {
namespace {

using ::testing::HasSubstr;
using ::testing::ThrowsMessage;

// The simulator's default accuracy is 1e-6 per step (relative and absolute); over a few
// seconds of smooth, decaying dynamics the global error stays well below this.
constexpr double kTolerance = 1e-5;

Eigen::MatrixXd matrix(int rows, int cols, std::initializer_list<double> values) {
  Eigen::MatrixXd m(rows, cols);
  auto it = values.begin();
  for (int i = 0; i < rows; ++i) {
    for (int j = 0; j < cols; ++j) m(i, j) = *it++;
  }
  return m;
}

TEST(LinearSystem, PortsAndFeedthroughOnlyWithANonzeroD) {
  const Eigen::MatrixXd A = Eigen::Matrix3d::Identity() * -1.0;
  const Eigen::MatrixXd B = Eigen::MatrixXd::Ones(3, 2);
  const Eigen::MatrixXd C = Eigen::MatrixXd::Ones(4, 3);
  const LinearSystem strict("strict", A, B, C, Eigen::MatrixXd::Zero(4, 2));
  ASSERT_EQ(strict.num_input_ports(), 1);
  ASSERT_EQ(strict.num_output_ports(), 1);
  EXPECT_EQ(strict.input_port("u").size(), 2);
  EXPECT_EQ(strict.output_port("y").size(), 4);
  EXPECT_TRUE(strict.output_reads(0).empty());  // D = 0: y reads the state alone
  EXPECT_FALSE(strict.has_direct_feedthrough());
  EXPECT_EQ(strict.initial_continuous_state(), Vector::Zero(3));

  Eigen::MatrixXd D = Eigen::MatrixXd::Zero(4, 2);
  D(3, 1) = 1e-300;  // any nonzero element feeds u through
  const LinearSystem proper("proper", A, B, C, D, Eigen::Vector3d(1.0, 2.0, 3.0));
  EXPECT_EQ(proper.output_reads(0), std::vector<int>{0});
  EXPECT_TRUE(proper.has_direct_feedthrough());
  EXPECT_EQ(proper.initial_continuous_state(), Eigen::Vector3d(1.0, 2.0, 3.0));
}

TEST(LinearSystem, StepResponseMatchesTheExponentialSolution) {
  // Two decoupled modes read together, plus feedthrough: with u = 1 from t = 0 and x(0) = x0,
  // x1 = 1 + (x0_1 - 1) e^{-t}, x2 = 2/3 + (x0_2 - 2/3) e^{-3t}, y = x1 + x2 + 0.5 u.
  DiagramBuilder builder("top");
  auto& step = builder.emplace<StepSource>("step", 0.0, 1.0, 0.0);
  auto& system = builder.emplace<LinearSystem>("system", matrix(2, 2, {-1.0, 0.0, 0.0, -3.0}),
                                               matrix(2, 1, {1.0, 2.0}), matrix(1, 2, {1.0, 1.0}),
                                               matrix(1, 1, {0.5}), Eigen::Vector2d(0.5, -1.0));
  builder.connect(step, "y", system, "u");
  auto diagram = builder.build();
  Simulator simulator(*diagram);
  for (const double t : {0.1, 0.5, 1.0, 2.0, 4.0}) {
    simulator.advance_to(t);
    const double x1 = 1.0 + (0.5 - 1.0) * std::exp(-t);
    const double x2 = 2.0 / 3.0 + (-1.0 - 2.0 / 3.0) * std::exp(-3.0 * t);
    const auto x = simulator.context().continuous_state(system);
    EXPECT_NEAR(x[0], x1, kTolerance) << "t = " << t;
    EXPECT_NEAR(x[1], x2, kTolerance) << "t = " << t;
    EXPECT_NEAR(diagram->eval_output(simulator.context(), system.output_port("y"))[0],
                x1 + x2 + 0.5, kTolerance)
        << "t = " << t;
  }
}

TEST(LinearSystem, FreeOscillatorFollowsCosineAndSine) {
  // x1' = x2, x2' = -w^2 x1 from (1, 0): x1 = cos(w t), x2 = -w sin(w t); y = (x1, x2).
  const double w = 2.0;
  DiagramBuilder builder("top");
  auto& zero = builder.emplace<StepSource>("zero", 0.0, 0.0, 0.0);
  auto& oscillator = builder.emplace<LinearSystem>(
      "oscillator", matrix(2, 2, {0.0, 1.0, -w * w, 0.0}), matrix(2, 1, {0.0, 1.0}),
      Eigen::MatrixXd::Identity(2, 2), Eigen::MatrixXd::Zero(2, 1), Eigen::Vector2d(1.0, 0.0));
  builder.connect(zero, "y", oscillator, "u");
  auto diagram = builder.build();
  Simulator simulator(*diagram);
  for (const double t : {0.3, 1.0, 2.5}) {
    simulator.advance_to(t);
    const auto y = diagram->eval_output(simulator.context(), oscillator.output_port("y"));
    EXPECT_NEAR(y[0], std::cos(w * t), kTolerance) << "t = " << t;
    EXPECT_NEAR(y[1], -w * std::sin(w * t), kTolerance) << "t = " << t;
  }
}

TEST(LinearSystem, ClosesAFeedbackLoopOnlyWithoutFeedthrough) {
  // x' = -x + u, y = x, u = -2 y: x' = -3 x, x = x0 e^{-3t}.
  DiagramBuilder builder("top");
  auto& plant = builder.emplace<LinearSystem>("plant", matrix(1, 1, {-1.0}), matrix(1, 1, {1.0}),
                                              matrix(1, 1, {1.0}), matrix(1, 1, {0.0}),
                                              Vector::Constant(1, 2.0));
  auto& feedback = builder.emplace<Gain>("feedback", -2.0, 1);
  builder.connect(plant, "y", feedback, "u");
  builder.connect(feedback, "y", plant, "u");
  auto diagram = builder.build();
  Simulator simulator(*diagram);
  simulator.advance_to(1.0);
  EXPECT_NEAR(simulator.context().continuous_state(plant)[0], 2.0 * std::exp(-3.0), kTolerance);

  DiagramBuilder looped("top");
  auto& proper = looped.emplace<LinearSystem>("plant", matrix(1, 1, {-1.0}), matrix(1, 1, {1.0}),
                                              matrix(1, 1, {1.0}), matrix(1, 1, {0.5}));
  auto& gain = looped.emplace<Gain>("feedback", -2.0, 1);
  looped.connect(proper, "y", gain, "u");
  looped.connect(gain, "y", proper, "u");
  EXPECT_THAT([&] { looped.build(); },
              ThrowsMessage<std::invalid_argument>(HasSubstr("algebraic loop")));
}

TEST(LinearSystem, RefusesMatricesThatDoNotFit) {
  const Eigen::MatrixXd A = Eigen::MatrixXd::Identity(2, 2);
  const Eigen::MatrixXd B = Eigen::MatrixXd::Ones(2, 1);
  const Eigen::MatrixXd C = Eigen::MatrixXd::Ones(1, 2);
  const Eigen::MatrixXd D = Eigen::MatrixXd::Zero(1, 1);
  EXPECT_THAT([&] { LinearSystem("sys", Eigen::MatrixXd::Ones(2, 3), B, C, D); },
              ThrowsMessage<std::invalid_argument>(
                  "LinearSystem 'sys': A is 2x3; it must be square, n x n with n >= 1"));
  EXPECT_THAT([&] { LinearSystem("sys", Eigen::MatrixXd(0, 0), B, C, D); },
              ThrowsMessage<std::invalid_argument>(
                  "LinearSystem 'sys': A is 0x0; it must be square, n x n with n >= 1"));
  EXPECT_THAT([&] { LinearSystem("sys", A, Eigen::MatrixXd::Ones(3, 1), C, D); },
              ThrowsMessage<std::invalid_argument>(
                  "LinearSystem 'sys': B is 3x1; it must have n = 2 rows (A is 2x2)"));
  EXPECT_THAT([&] { LinearSystem("sys", A, Eigen::MatrixXd(2, 0), C, D); },
              ThrowsMessage<std::invalid_argument>(
                  "LinearSystem 'sys': B is 2x0; it must have m >= 1 columns (the input size)"));
  EXPECT_THAT([&] { LinearSystem("sys", A, B, Eigen::MatrixXd::Ones(1, 3), D); },
              ThrowsMessage<std::invalid_argument>(
                  "LinearSystem 'sys': C is 1x3; it must have n = 2 columns (A is 2x2)"));
  EXPECT_THAT([&] { LinearSystem("sys", A, B, Eigen::MatrixXd(0, 2), D); },
              ThrowsMessage<std::invalid_argument>(
                  "LinearSystem 'sys': C is 0x2; it must have p >= 1 rows (the output size)"));
  EXPECT_THAT([&] { LinearSystem("sys", A, B, C, Eigen::MatrixXd::Zero(1, 2)); },
              ThrowsMessage<std::invalid_argument>(
                  "LinearSystem 'sys': D is 1x2; it must be p x m = 1x1 (C's rows by B's "
                  "columns)"));
  EXPECT_THAT([&] { LinearSystem("sys", A, B, C, D, Vector::Zero(3)); },
              ThrowsMessage<std::invalid_argument>(
                  "LinearSystem 'sys': the initial state has size 3; it must have size n = 2 "
                  "(A is 2x2)"));
  Eigen::MatrixXd bad_a = A;
  bad_a(1, 0) = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THAT([&] { LinearSystem("sys", bad_a, B, C, D); },
              ThrowsMessage<std::invalid_argument>(
                  "LinearSystem 'sys': A(1, 0) is nan; every element must be finite"));
  EXPECT_THAT(
      [&] {
        LinearSystem("sys", A, B, C, D,
                     Eigen::Vector2d(0.0, std::numeric_limits<double>::infinity()));
      },
      ThrowsMessage<std::invalid_argument>(
          "LinearSystem 'sys': initial state inf at element 1 must be finite"));
}

}  // namespace
}  // namespace cbbg
