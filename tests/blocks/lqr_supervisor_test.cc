#include "cbbg/blocks/lqr_supervisor.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <Eigen/Eigenvalues>

#include "cbbg/blocks/measured_signals.h"
#include "cbbg/blocks/sensors.h"
#include "cbbg/framework/block_context.h"
#include "cbbg/framework/block_harness.h"
#include "cbbg/framework/control/riccati.h"
#include "cbbg/framework/diagram_builder.h"
#include "cbbg/framework/primitives/zero_order_hold.h"
#include "cbbg/framework/signal_log.h"
#include "cbbg/framework/simulator.h"
#include "cbbg/plant/analytic_plant.h"
#include "cbbg/plant/linearization.h"
#include "cbbg/plant/plant_ports.h"

namespace cbbg::blocks {
namespace {

using ::cbbg::control::continuous_riccati_residual;
using ::cbbg::control::solve_continuous_riccati;
using ::testing::HasSubstr;
using ::testing::StrEq;
using ::testing::ThrowsMessage;

constexpr double kPeriod = 0.01;

TEST(Riccati, SolvesAScalarEquationAsWorkedOutByHand) {
  // a = 1, b = 1, q = 3, r = 1: 2x - x^2 + 3 = 0, whose stabilising root is x = 3 (a - b^2
  // x / r = -2 < 0); the other root, -1, is not.
  const Eigen::MatrixXd X = solve_continuous_riccati(
      Eigen::MatrixXd::Constant(1, 1, 1.0), Eigen::MatrixXd::Constant(1, 1, 1.0),
      Eigen::MatrixXd::Constant(1, 1, 3.0), Eigen::MatrixXd::Constant(1, 1, 1.0));
  EXPECT_NEAR(X(0, 0), 3.0, 1e-12);
}

TEST(Riccati, SolvesTheDoubleIntegratorAsWorkedOutByHand) {
  // x'' = u, Q = I, R = 1: X = [[sqrt(3), 1], [1, sqrt(3)]], K = (1, sqrt(3)).
  Eigen::MatrixXd A(2, 2);
  A << 0, 1, 0, 0;
  Eigen::MatrixXd B(2, 1);
  B << 0, 1;
  const Eigen::MatrixXd X = solve_continuous_riccati(A, B, Eigen::MatrixXd::Identity(2, 2),
                                                     Eigen::MatrixXd::Identity(1, 1));
  EXPECT_NEAR(X(0, 0), std::sqrt(3.0), 1e-12);
  EXPECT_NEAR(X(0, 1), 1.0, 1e-12);
  EXPECT_NEAR(X(1, 0), 1.0, 1e-12);
  EXPECT_NEAR(X(1, 1), std::sqrt(3.0), 1e-12);
}

TEST(Riccati, RejectsAnUnstabilisableSystem) {
  // An unstable mode the input cannot reach.
  Eigen::MatrixXd A(2, 2);
  A << 1, 0, 0, -1;
  Eigen::MatrixXd B(2, 1);
  B << 0, 1;
  EXPECT_THAT(
      [&] {
        solve_continuous_riccati(A, B, Eigen::MatrixXd::Identity(2, 2),
                                 Eigen::MatrixXd::Identity(1, 1));
      },
      ThrowsMessage<std::invalid_argument>(HasSubstr("no stabilising solution")));
}

TEST(LqrSupervisor, SolvesTheRiccatiEquationOfTheLinearisedRobot) {
  const plant::RobotParams robot;
  const LqrSupervisorParams params;
  const plant::LinearModel model = plant::linearize_planar_upright(robot);
  const Eigen::Vector4d q(params.lqr_q.data());
  const Eigen::MatrixXd Q = q.asDiagonal();
  const Eigen::MatrixXd R = Eigen::MatrixXd::Constant(1, 1, params.lqr_r);
  const Eigen::MatrixXd X = solve_continuous_riccati(model.A, model.B, Q, R);
  EXPECT_LT(continuous_riccati_residual(model.A, model.B, Q, R, X).norm(), 1e-9 * X.norm());
  EXPECT_LT((X - X.transpose()).norm(), 1e-12 * X.norm());
  EXPECT_GT(X.selfadjointView<Eigen::Lower>().eigenvalues().minCoeff(), 0.0);

  const LqrSupervisor supervisor("supervisor", robot, params);
  const Eigen::RowVector4d expected = (model.B.transpose() * X / params.lqr_r).row(0);
  EXPECT_LT((supervisor.gain() - expected).norm(), 1e-9 * expected.norm());
}

TEST(LqrSupervisor, GainIsBitIdenticalToTheRiccatiFormulaItReplaced) {
  // The gain comes from control::lqr; before, it was (B' X / r) with X from the Riccati
  // solver. Both must give the same bits, so runs with the LQR supervisor are unchanged.
  const plant::RobotParams robot;
  const plant::LinearModel model = plant::linearize_planar_upright(robot);
  const std::array<std::array<double, 4>, 3> weights{
      {{100.0, 1.0, 1.0, 1.0}, {10.0, 0.5, 2.0, 0.1}, {1000.0, 3.0, 0.25, 7.0}}};
  for (const auto& q : weights) {
    for (const double r : {1.0, 0.3, 7.0, 1e-3}) {
      LqrSupervisorParams params;
      params.lqr_q = q;
      params.lqr_r = r;
      const Eigen::MatrixXd Q = Eigen::Vector4d(q.data()).asDiagonal();
      const Eigen::MatrixXd R = Eigen::MatrixXd::Constant(1, 1, r);
      const Eigen::MatrixXd X = solve_continuous_riccati(model.A, model.B, Q, R);
      const Eigen::RowVector4d previous = (model.B.transpose() * X / r).row(0);
      const LqrSupervisor supervisor("supervisor", model, params);
      for (int i = 0; i < 4; ++i) {
        EXPECT_EQ(supervisor.gain()[i], previous[i]) << "q[0] = " << q[0] << ", r = " << r;
      }
    }
  }
}

TEST(LqrSupervisor, ClosedLoopOfTheLinearisedRobotIsStable) {
  const plant::RobotParams robot;
  const plant::LinearModel model = plant::linearize_planar_upright(robot);
  // Upright is unstable on its own: one pitch pole in the right half-plane.
  EXPECT_GT(model.A.eigenvalues().real().maxCoeff(), 0.0);
  const LqrSupervisor supervisor("supervisor", robot, LqrSupervisorParams{});
  const Eigen::MatrixXd closed_loop = model.A - model.B * supervisor.gain();
  const Eigen::VectorXcd poles = closed_loop.eigenvalues();
  for (Eigen::Index i = 0; i < poles.size(); ++i) {
    EXPECT_LT(poles[i].real(), 0.0) << "pole " << poles[i];
  }
}

TEST(LqrSupervisor, ActionIsMinusGainTimesTheState) {
  testing::BlockHarness<LqrSupervisor> harness("supervisor", plant::RobotParams{},
                                               LqrSupervisorParams{});
  const Eigen::RowVector4d k = harness.block().gain();
  Vector y(kMeasuredSize);
  y << 0.1, -0.2, 1.0, 3.0, 0.5, -1.5;  // phi = 2, phi' = -0.5
  harness.set_input("measured", y);
  EXPECT_NEAR(harness.scalar_output("action"),
              -(k[0] * 0.1 + k[1] * 2.0 + k[2] * -0.2 + k[3] * -0.5), 1e-12);
  // Leaning forward, the wheels must drive forward (tau > 0) to get under the body.
  y << 0.1, 0.0, 0.0, 0.0, 0.0, 0.0;
  harness.set_input("measured", y);
  EXPECT_GT(harness.scalar_output("action"), 0.0);
}

// Drives both wheels with one command: (a) -> (a, a).
class BothWheels final : public Block {
 public:
  explicit BothWheels(std::string name) : Block(std::move(name)) {
    const InputPort& action = declare_input_port("action", 1);
    declare_output_port("torque", plant::kTorqueSize,
                        [&action](const BlockContext& context, VectorRef torque) {
                          torque.setConstant(context.input(action)[0]);
                        },
                        {&action});
  }
};

TEST(LqrSupervisor, BalancesTheAnalyticPlantFromTheTrialStart) {
  const plant::RobotParams robot;
  DiagramBuilder builder("lqr_loop");
  const auto& robot_plant = builder.emplace<plant::AnalyticPlant>("plant", robot, 0.1744);
  const auto& sensors = builder.emplace<Sensors>("sensors", SensorsParams{}, kPeriod);
  const auto& supervisor =
      builder.emplace<LqrSupervisor>("supervisor", robot, LqrSupervisorParams{});
  const auto& wheels = builder.emplace<BothWheels>("wheels");
  const auto& hold = builder.emplace<ZeroOrderHold>("hold", plant::kTorqueSize, kPeriod);
  builder.connect(robot_plant, "state", sensors, "plant_state");
  builder.connect(sensors, "measured", supervisor, "measured");
  builder.connect(supervisor, "action", wheels, "action");
  builder.connect(wheels, "torque", hold, "u");
  builder.connect(hold, "y", robot_plant, "torque");
  const auto diagram = builder.build();
  Simulator simulator(*diagram);
  SignalLog& log = simulator.add_log(robot_plant.output_port("state"), kPeriod);
  simulator.advance_to(20.0);

  double largest_pitch = 0.0;
  double last_second_pitch = 0.0;
  for (int k = 0; k < log.num_samples(); ++k) {
    const double pitch = std::abs(log.sample(k)[plant::kThetaB]);
    largest_pitch = std::max(largest_pitch, pitch);
    if (log.times()[static_cast<size_t>(k)] >= 19.0) {
      last_second_pitch = std::max(last_second_pitch, pitch);
    }
  }
  EXPECT_LT(largest_pitch, 0.5236);    // never fails
  EXPECT_LT(last_second_pitch, 1e-3);  // and settles upright
  const auto state = log.sample(log.num_samples() - 1);
  EXPECT_LT(std::abs(state[plant::kThetaBDot]), 1e-2);
  EXPECT_LT(std::abs(state[plant::kPhiLeftDot]), 1e-2);
}

TEST(LqrSupervisor, RejectsInvalidWeights) {
  LqrSupervisorParams negative;
  negative.lqr_q[2] = -1.0;
  EXPECT_THAT([&] { LqrSupervisor("supervisor", plant::RobotParams{}, negative); },
              ThrowsMessage<std::invalid_argument>(
                  StrEq("supervisor.lqr_q[2] must be finite and >= 0; got -1")));
  LqrSupervisorParams zero_r;
  zero_r.lqr_r = 0.0;
  EXPECT_THAT([&] { LqrSupervisor("supervisor", plant::RobotParams{}, zero_r); },
              ThrowsMessage<std::invalid_argument>(
                  StrEq("supervisor.lqr_r must be finite and > 0; got 0")));
  LqrSupervisorParams blind_to_wheels;
  blind_to_wheels.lqr_q = {100.0, 0.0, 1.0, 1.0};
  EXPECT_THAT([&] { LqrSupervisor("supervisor", plant::RobotParams{}, blind_to_wheels); },
              ThrowsMessage<std::invalid_argument>(
                  HasSubstr("supervisor.lqr_q = [100, 0, 1, 1] with supervisor.lqr_r = 1 give "
                            "no stabilising LQR gain for this robot")));
  LqrSupervisorParams nan_q;
  nan_q.lqr_q[0] = NAN;
  EXPECT_THAT([&] { LqrSupervisor("supervisor", plant::RobotParams{}, nan_q); },
              ThrowsMessage<std::invalid_argument>(
                  StrEq("supervisor.lqr_q[0] must be finite and >= 0; got nan")));
}

}  // namespace
}  // namespace cbbg::blocks
