// Both plants as blocks: the same ports, torque saturation inside the plant, cheap resets,
// contexts that clone and run apart, and errors that name the plant.

#include <cmath>
#include <limits>
#include <stdexcept>
#include <thread>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "cbbg/framework/primitives/constant_source.h"
#include "tests/plant/plant_rigs.h"

namespace cbbg::plant::testing {
namespace {

using Eigen::Vector2d;
using ::testing::HasSubstr;
using ::testing::StartsWith;

class PlantBlock : public ::testing::TestWithParam<PlantKind> {
 protected:
  PlantKind kind() const { return GetParam(); }
};

// Runs a rig with a fixed torque for `duration` and returns the logged states.
Eigen::MatrixXd run_fixed_torque(PlantKind kind, const RobotParams& p, const Vector& torque,
                                 double duration = 1.0) {
  const Rig rig = make_rig(kind, p, kDefaultInitialPitch, Control::kFixedTorque);
  auto simulator = make_simulator(rig, p, torque);
  const SignalLog& log = simulator->add_log(rig.state(), kPeriod);
  simulator->advance_to(duration);
  return log.values();
}

TEST_P(PlantBlock, HasTheSharedPorts) {
  const RobotParams p;
  const Rig rig = make_rig(kind(), p, kDefaultInitialPitch, Control::kFixedTorque);
  ASSERT_EQ(rig.plant->num_input_ports(), 1);
  ASSERT_EQ(rig.plant->num_output_ports(), 1);
  EXPECT_EQ(rig.plant->input_port("torque").size(), kTorqueSize);
  EXPECT_EQ(rig.plant->output_port("state").size(), kStateSize);
  EXPECT_TRUE(rig.plant->output_reads(0).empty()) << "the state output reads only state";
  EXPECT_EQ(rig.plant->path(), "robot/plant");
}

TEST_P(PlantBlock, StartsAtTheInitialPitchWithEverythingElseZero) {
  const RobotParams p;
  const Rig rig = make_rig(kind(), p, 0.25, Control::kFixedTorque);
  auto context = rig.diagram->create_context();
  Vector expected = Vector::Zero(kStateSize);
  expected[kThetaB] = 0.25;
  EXPECT_EQ(Vector(rig.diagram->eval_output(*context, rig.state())), expected);
}

TEST_P(PlantBlock, SaturatesTheTorqueToTheLimitInsideThePlant) {
  const RobotParams p;
  const Eigen::MatrixXd at_limit = run_fixed_torque(kind(), p, Vector::Constant(2, 5.0));
  const Eigen::MatrixXd beyond = run_fixed_torque(kind(), p, Vector::Constant(2, 100.0));
  const Eigen::MatrixXd below = run_fixed_torque(kind(), p, Vector::Constant(2, 4.0));
  EXPECT_EQ(beyond, at_limit);
  EXPECT_GT((below - at_limit).cwiseAbs().maxCoeff(), 1e-3);
  // Each torque on its own, and the limit is a parameter.
  RobotParams low = p;
  low.torque_limit = 2.0;
  EXPECT_EQ(run_fixed_torque(kind(), low, Vector2d(-9.0, 7.0)),
            run_fixed_torque(kind(), p, Vector2d(-2.0, 2.0)));
}

TEST_P(PlantBlock, UnequalTorquesTurnTheRobotLeftWhenTheRightWheelDrivesHarder) {
  const RobotParams p;
  const Eigen::MatrixXd y = run_fixed_torque(kind(), p, Vector2d(0.0, 1.0), 0.5);
  const auto last = y.col(y.cols() - 1);
  EXPECT_GT(last[kPhiRightDot], last[kPhiLeftDot]);
  EXPECT_GT(last[kYawRate], 0.0);  // counter-clockwise seen from above
  EXPECT_GT(last[kYaw], 0.0);
  EXPECT_NEAR(last[kYawRate],
              p.wheel_radius * (last[kPhiRightDot] - last[kPhiLeftDot]) / p.track_width, 1e-9);
}

// The Simbody plant restarts its integrator on a reset, so a trial repeats bit for bit. The
// analytic plant is integrated by the Simulator, whose integrator keeps the step size it
// last used across initialize(): the repeat agrees to within the integrator's accuracy.
void expect_same_trial(PlantKind kind, const Eigen::MatrixXd& a, const Eigen::MatrixXd& b) {
  ASSERT_EQ(a.cols(), b.cols());
  if (kind == PlantKind::kSimbody) {
    EXPECT_EQ(a, b);
  } else {
    EXPECT_LT((a - b).cwiseAbs().maxCoeff(), 1e-6);
  }
}

TEST_P(PlantBlock, ResetRestartsATrialAsAFreshContextWould) {
  const RobotParams p;
  const Rig rig = make_rig(kind(), p, kDefaultInitialPitch, Control::kFixedTorque);
  auto simulator = make_simulator(rig, p, Vector::Constant(2, 1.0));
  SignalLog& log = simulator->add_log(rig.state(), kPeriod);
  simulator->advance_to(1.0);
  const Eigen::MatrixXd first = log.values();

  // Same pitch: the same trial again, bit for bit.
  log.clear();
  simulator->context().set_time(0.0);
  rig.reset(simulator->context(), kDefaultInitialPitch);
  simulator->initialize();
  simulator->advance_to(1.0);
  expect_same_trial(kind(), log.values(), first);

  // Another pitch: as a plant built with that pitch.
  log.clear();
  simulator->context().set_time(0.0);
  rig.reset(simulator->context(), -0.1);
  simulator->initialize();
  simulator->advance_to(1.0);
  const Rig fresh = make_rig(kind(), p, -0.1, Control::kFixedTorque);
  auto fresh_simulator = make_simulator(fresh, p, Vector::Constant(2, 1.0));
  const SignalLog& fresh_log = fresh_simulator->add_log(fresh.state(), kPeriod);
  fresh_simulator->advance_to(1.0);
  expect_same_trial(kind(), log.values(), fresh_log.values());

  // Context::reset_all_state returns to the constructor's pitch; the plant notices too.
  log.clear();
  simulator->context().reset_all_state();
  simulator->initialize();
  simulator->advance_to(1.0);
  expect_same_trial(kind(), log.values(), first);
}

TEST_P(PlantBlock, ClonedContextsRunApartAndAgree) {
  const RobotParams p;
  const Rig rig = make_rig(kind(), p, kDefaultInitialPitch, Control::kPd);
  Simulator original(*rig.diagram, SimulatorOptions{p.accuracy});
  original.advance_to(0.5);
  Simulator copy(*rig.diagram, original.context().clone(), SimulatorOptions{p.accuracy});
  original.advance_to(1.5);
  copy.advance_to(1.5);
  const Vector a = original.context().continuous_state(*rig.plant);
  const Vector b = copy.context().continuous_state(*rig.plant);
  // The copy's integrator restarts (its step size history is not copied): the same
  // trajectory within the integrator's accuracy, not bit for bit.
  EXPECT_LT((a - b).cwiseAbs().maxCoeff(), 1e-5);
  EXPECT_GT(std::abs(a[kThetaB] - kDefaultInitialPitch), 0.05) << "the robot moved";
}

TEST_P(PlantBlock, ContextsOfOneDiagramRunInParallelThreads) {
  const RobotParams p;
  const Rig rig = make_rig(kind(), p, kDefaultInitialPitch, Control::kTurningPd);
  auto run = [&](std::uint64_t seed, Vector* final_state) {
    Simulator simulator(*rig.diagram, SimulatorOptions{p.accuracy}, seed);
    simulator.advance_to(2.0);
    *final_state = simulator.context().continuous_state(*rig.plant);
  };
  Vector serial_a, serial_b, parallel_a, parallel_b;
  run(1, &serial_a);
  run(2, &serial_b);
  std::thread first(run, 1, &parallel_a);
  std::thread second(run, 2, &parallel_b);
  first.join();
  second.join();
  EXPECT_EQ(parallel_a, serial_a);
  EXPECT_EQ(parallel_b, serial_b);
  EXPECT_NE(serial_a, serial_b);
}

// A diagram whose torque comes from a constant source (a root input cannot hold NaN: the
// simulator reads NaN there as "not set").
std::unique_ptr<Diagram> constant_torque_diagram(PlantKind kind, const Vector& torque) {
  DiagramBuilder builder("robot");
  auto& source = builder.emplace<ConstantSource>("torque", torque);
  Block* plant = nullptr;
  if (kind == PlantKind::kAnalytic) {
    plant = &builder.emplace<AnalyticPlant>("plant", RobotParams{});
  } else {
    plant = &builder.emplace<SimbodyPlant>("plant", RobotParams{});
  }
  builder.connect(source, "y", *plant, "torque");
  return builder.build();
}

std::string simulation_error(Simulator& simulator, double end_time) {
  try {
    simulator.advance_to(end_time);
  } catch (const SimulationError& error) {
    return error.what();
  }
  return "";
}

TEST_P(PlantBlock, NonFiniteTorqueIsAnErrorNamingThePlant) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  {
    const auto diagram = constant_torque_diagram(kind(), Vector2d(nan, 0.0));
    Simulator simulator(*diagram);
    EXPECT_EQ(simulation_error(simulator, 0.1),
              "block 'robot/plant': torque input is not finite (tau_l = nan, tau_r = 0)");
  }
  {
    const auto diagram = constant_torque_diagram(kind(), Vector2d(1.5, -inf));
    Simulator simulator(*diagram);
    EXPECT_EQ(simulation_error(simulator, 0.1),
              "block 'robot/plant': torque input is not finite (tau_l = 1.5, tau_r = -inf)");
  }
}

TEST_P(PlantBlock, NonFiniteStateIsAnErrorNamingThePlant) {
  const RobotParams p;
  const Rig rig = make_rig(kind(), p, kDefaultInitialPitch, Control::kFixedTorque);
  auto simulator = make_simulator(rig, p);
  simulator->advance_to(0.5);
  simulator->context().continuous_state(*rig.plant)[0] = std::numeric_limits<double>::infinity();
  EXPECT_THAT(simulation_error(*simulator, 1.0),
              StartsWith("block 'robot/plant': state is not finite at t = 0.5 (theta_b = inf, "
                         "theta_b' = "));
}

TEST_P(PlantBlock, StateThatOverflowsIsAnErrorNamingThePlant) {
  // Gravity of 1e300 m/s^2 accelerates the fall beyond any double within a step.
  RobotParams p;
  p.gravity = 1e300;
  const Rig rig = make_rig(kind(), p, kDefaultInitialPitch, Control::kFixedTorque);
  auto simulator = make_simulator(rig, p);
  EXPECT_THAT(simulation_error(*simulator, 1.0), StartsWith("block 'robot/plant': "));
}

TEST_P(PlantBlock, RejectsInvalidParametersAndPitches) {
  RobotParams bad;
  bad.body_mass = -1.0;
  const double nan = std::numeric_limits<double>::quiet_NaN();
  auto make = [this](const RobotParams& params, double pitch) {
    DiagramBuilder builder("robot");
    if (kind() == PlantKind::kAnalytic) {
      builder.emplace<AnalyticPlant>("plant", params, pitch);
    } else {
      builder.emplace<SimbodyPlant>("plant", params, pitch);
    }
  };
  EXPECT_THAT([&] { make(bad, 0.1); }, ::testing::ThrowsMessage<std::invalid_argument>(
                                           "plant.body_mass must be finite and > 0; got -1"));
  EXPECT_THAT([&] { make(RobotParams{}, nan); }, ::testing::ThrowsMessage<std::invalid_argument>(
                                                     "trial.theta0 must be finite; got nan"));

  const RobotParams p;
  const Rig rig = make_rig(kind(), p, kDefaultInitialPitch, Control::kFixedTorque);
  auto context = rig.diagram->create_context();
  EXPECT_THAT([&] { rig.reset(*context, nan); }, ::testing::ThrowsMessage<std::invalid_argument>(
                                                     "trial.theta0 must be finite; got nan"));
  EXPECT_THAT([&] { rig.set_state(*context, Vector::Zero(3)); },
              ::testing::ThrowsMessage<std::invalid_argument>(
                  "block 'robot/plant': set_state needs 10 values; got 3"));
  Vector infinite = Vector::Zero(kStateSize);
  infinite[kY] = INFINITY;
  EXPECT_THAT([&] { rig.set_state(*context, infinite); },
              ::testing::ThrowsMessage<std::invalid_argument>(HasSubstr(
                  "block 'robot/plant': set_state needs finite values; got theta_b = 0, ")));
}

TEST_P(PlantBlock, DrawsTheTwoWheelerOfItsOwnParameters) {
  RobotParams p;
  p.wheel_radius = 0.2;
  p.track_width = 0.5;
  p.com_height = 0.3;
  const Rig rig = make_rig(kind(), p, kDefaultInitialPitch, Control::kFixedTorque);
  const PlantDrawing drawing = dynamic_cast<const RobotPlant&>(*rig.plant).drawing();
  EXPECT_EQ(drawing, two_wheeler_drawing(p));
  EXPECT_EQ(drawing.wheel_radius, 0.2);
  EXPECT_EQ(drawing.track_width, 0.5);
  EXPECT_EQ(drawing.com_height, 0.3);
  EXPECT_EQ(drawing.body_length, 0.6);
  EXPECT_EQ(drawing.body_width, 0.35);
  EXPECT_EQ(drawing.cart_length, 0.0);  // no cart: the body pitches about the axle
}

INSTANTIATE_TEST_SUITE_P(BothPlants, PlantBlock,
                         ::testing::Values(PlantKind::kAnalytic, PlantKind::kSimbody),
                         [](const auto& parameter) { return plant_name(parameter.param); });

// A plant that states no drawing is drawn as the two-wheeler of the default robot.
class Silent final : public RobotPlant {
 public:
  Silent() : RobotPlant("silent") {}
  void reset(Context&, double) const override {}
};

TEST(PlantDrawing, TheDefaultIsTheDefaultTwoWheelers) {
  EXPECT_EQ(Silent().drawing(), two_wheeler_drawing(RobotParams{}));
  const PlantDrawing drawing;
  EXPECT_EQ(drawing.wheel_radius, RobotParams{}.wheel_radius);
  EXPECT_EQ(drawing.com_height, RobotParams{}.com_height);
  EXPECT_EQ(drawing.body_length, 2.0 * RobotParams{}.com_height);
}

TEST(SimbodyPlant, RejectsInertiasNoRigidBodyHas) {
  RobotParams literal;  // the paper's equations read literally: yaw inertia J_z at every pitch
  literal.body_roll_inertia = literal.body_yaw_inertia;
  EXPECT_THAT([&] { SimbodyPlant("plant", literal); },
              ::testing::ThrowsMessage<std::invalid_argument>(
                  HasSubstr("must each be at most the sum of the other two")));
  EXPECT_NO_THROW(AnalyticPlant("plant", literal));
}

}  // namespace
}  // namespace cbbg::plant::testing
