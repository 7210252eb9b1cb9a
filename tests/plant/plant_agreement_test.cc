// The analytic plant and the Simbody plant are two routes to the same mechanics: they must
// give the same trajectory, both at accuracy 1e-8 (docs/model.md §1.4).

#include <cmath>
#include <optional>
#include <string>

#include <gtest/gtest.h>

#include "tests/plant/plant_rigs.h"

namespace cbbg::plant::testing {
namespace {

constexpr double kDuration = 3.0;
constexpr double kPitchTolerance = 1e-6;  // rad
constexpr double kTurningSigma = 3.0;     // N m, the random differential torque

RobotParams accurate_params() {
  RobotParams params;
  params.accuracy = 1e-8;
  return params;
}

// Runs both plants under `control` and returns the two state logs, one sample per tick.
struct Trajectories {
  Eigen::MatrixXd analytic;
  Eigen::MatrixXd simbody;
};

Trajectories run_both(Control control, SimbodyIntegrator integrator = SimbodyIntegrator::kMerson,
                      SimbodyModel model = SimbodyModel::kRollingBase,
                      const std::optional<Vector>& disturbance = std::nullopt) {
  RobotParams params = accurate_params();
  params.simbody_integrator = integrator;
  params.simbody_model = model;
  Trajectories result;
  for (const PlantKind kind : {PlantKind::kAnalytic, PlantKind::kSimbody}) {
    const Rig rig =
        make_rig(kind, params, kDefaultInitialPitch, control, kTurningSigma, disturbance);
    auto simulator = make_simulator(rig, params);
    const SignalLog& log = simulator->add_log(rig.state(), kPeriod);
    simulator->advance_to(kDuration + kPeriod / 2);
    (kind == PlantKind::kAnalytic ? result.analytic : result.simbody) = log.values();
  }
  return result;
}

double max_difference(const Trajectories& t, int row) {
  return (t.analytic.row(row) - t.simbody.row(row)).cwiseAbs().maxCoeff();
}

TEST(PlantAgreement, FallingFreelyFromTheTrialPitch) {
  const Trajectories t = run_both(Control::kFixedTorque);
  ASSERT_EQ(t.analytic.cols(), 301);
  ASSERT_EQ(t.simbody.cols(), 301);
  // It does fall: past horizontal within the 3 s, so the comparison covers large angles.
  EXPECT_GT(t.simbody.row(kThetaB).cwiseAbs().maxCoeff(), M_PI / 2);
  EXPECT_LT(max_difference(t, kThetaB), kPitchTolerance);
  EXPECT_LT(max_difference(t, kPhiLeft), 1e-5);
  EXPECT_LT(max_difference(t, kX), 1e-6);
}

TEST(PlantAgreement, UnderThePdLawWithAZeroOrderHold) {
  const Trajectories t = run_both(Control::kPd);
  EXPECT_LT(t.simbody.row(kThetaB).cwiseAbs().tail(100).maxCoeff(), 0.05);  // it balances
  EXPECT_LT(max_difference(t, kThetaB), kPitchTolerance);
  EXPECT_LT(max_difference(t, kPhiRight), 1e-5);
  EXPECT_LT(max_difference(t, kX), 1e-6);
}

TEST(PlantAgreement, EverySimbodyIntegratorAgreesUnderThePdLaw) {
  for (const SimbodyIntegrator integrator :
       {SimbodyIntegrator::kRungeKutta3, SimbodyIntegrator::kVerlet}) {
    const Trajectories t = run_both(Control::kPd, integrator);
    EXPECT_LT(max_difference(t, kThetaB), kPitchTolerance)
        << "integrator " << static_cast<int>(integrator);
    EXPECT_LT(max_difference(t, kX), 1e-6) << "integrator " << static_cast<int>(integrator);
  }
}

// The test that needs the sideways-momentum terms of robot_dynamics.h: without them the
// pitch differs by about 6e-5 rad here, the wheel angles by 7e-3 rad.
TEST(PlantAgreement, UnderRandomDifferentialTorquesThatMakeItTurn) {
  const Trajectories t = run_both(Control::kTurningPd);
  // It turns: a yaw rate of order 1 rad/s and a heading far from zero.
  EXPECT_GT(t.simbody.row(kYawRate).cwiseAbs().maxCoeff(), 0.5);
  EXPECT_GT(t.simbody.row(kYaw).cwiseAbs().maxCoeff(), 0.3);
  EXPECT_LT(max_difference(t, kThetaB), kPitchTolerance);
  for (const int row : {kPhiLeft, kPhiRight, kX, kY, kYaw, kYawRate}) {
    EXPECT_LT(max_difference(t, row), 1e-5) << "state element " << row;
  }
}

// The reference formulation, wheels on their own joints held by no-slip constraints, agrees
// as closely as the default one, turning included.
TEST(PlantAgreement, TheConstrainedFormulationAgreesWhileTurning) {
  const Trajectories t =
      run_both(Control::kTurningPd, SimbodyIntegrator::kMerson, SimbodyModel::kNoSlipConstraints);
  EXPECT_GT(t.simbody.row(kYaw).cwiseAbs().maxCoeff(), 0.3);
  EXPECT_LT(max_difference(t, kThetaB), kPitchTolerance);
  for (const int row : {kPhiLeft, kPhiRight, kX, kY, kYaw, kYawRate}) {
    EXPECT_LT(max_difference(t, row), 1e-5) << "state element " << row;
  }
}

// A push from outside (a force at the centre of mass, a torque on the body) reaches the
// analytic plant as generalised forces worked out by hand and the Simbody plant as a force
// and a torque on the body: both formulations agree with the hand-worked ones.
TEST(PlantAgreement, UnderAForceAtTheCentreOfMassAndATorqueOnTheBody) {
  const Trajectories unpushed = run_both(Control::kPd);
  Vector disturbance(2);
  for (const Eigen::Vector2d& push :
       {Eigen::Vector2d(15.0, 0.0), Eigen::Vector2d(0.0, 1.5), Eigen::Vector2d(-10.0, 0.8)}) {
    disturbance << push[0], push[1];
    for (const SimbodyModel model :
         {SimbodyModel::kRollingBase, SimbodyModel::kNoSlipConstraints}) {
      const Trajectories t = run_both(Control::kPd, SimbodyIntegrator::kMerson, model, disturbance);
      const std::string what = "push (" + std::to_string(push[0]) + ", " + std::to_string(push[1]) +
                               "), model " + std::to_string(static_cast<int>(model));
      // The push moves the robot: far more than the plants differ.
      EXPECT_GT((t.simbody.row(kX) - unpushed.simbody.row(kX)).cwiseAbs().maxCoeff(), 0.05) << what;
      EXPECT_LT(max_difference(t, kThetaB), kPitchTolerance) << what;
      for (const int row : {kPhiLeft, kPhiRight, kX}) {
        EXPECT_LT(max_difference(t, row), 1e-5) << what << ", state element " << row;
      }
    }
  }
}

}  // namespace
}  // namespace cbbg::plant::testing
