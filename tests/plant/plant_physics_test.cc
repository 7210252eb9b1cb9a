// Physics both plants must obey: energy conservation, the upright equilibrium, balance under
// the PD law of docs/model.md §2.4, and parameters acting the way mechanics says.

#include <cmath>

#include <gtest/gtest.h>

#include "cbbg/plant/robot_dynamics.h"
#include "tests/plant/plant_rigs.h"

namespace cbbg::plant::testing {
namespace {

constexpr double kFailureAngle = 0.5236;  // trial.failure_angle, rad

class PlantPhysics : public ::testing::TestWithParam<PlantKind> {};

RobotParams frictionless() {
  RobotParams p;
  p.wheel_ground_friction = 0.0;
  p.axle_friction = 0.0;
  return p;
}

double energy_of(const RobotParams& p, const ConstVectorView& y) {
  return mechanical_energy(p, Coordinates(y[kThetaB], y[kPhiLeft], y[kPhiRight]),
                           Coordinates(y[kThetaBDot], y[kPhiLeftDot], y[kPhiRightDot]));
}

// Largest |E(t) - E(0)| / |E(0)| over 10 s with friction and torque off, at accuracy 1e-6,
// sampled every tick; for the Simbody plant also Simbody's own energy, every 0.5 s.
double energy_drift(PlantKind kind, const Vector& initial_state) {
  const RobotParams p = frictionless();
  const Rig rig = make_rig(kind, p, 0.0, Control::kFixedTorque);
  auto simulator = make_simulator(rig, p);
  rig.set_state(simulator->context(), initial_state);
  const SignalLog& log = simulator->add_log(rig.state(), kPeriod);
  const double initial = energy_of(p, ConstVectorView(initial_state.data(), kStateSize));
  double drift = 0.0;
  for (int half_seconds = 1; half_seconds <= 20; ++half_seconds) {
    simulator->advance_to(0.5 * half_seconds);
    if (kind == PlantKind::kSimbody) {
      const double own =
          static_cast<const SimbodyPlant&>(*rig.plant).multibody_energy(simulator->context());
      drift = std::max(drift, std::abs(own - initial) / std::abs(initial));
    }
  }
  EXPECT_EQ(log.num_samples(), 1000);
  for (int k = 0; k < log.num_samples(); ++k) {
    drift = std::max(drift, std::abs(energy_of(p, log.sample(k)) - initial) / std::abs(initial));
  }
  return drift;
}

TEST_P(PlantPhysics, ConservesEnergyWithoutFrictionOrTorqueGoingStraight) {
  Vector state = Vector::Zero(kStateSize);
  state[kThetaB] = kDefaultInitialPitch;  // it falls and swings right round
  EXPECT_LT(energy_drift(GetParam(), state), 1e-5);
}

TEST_P(PlantPhysics, ConservesEnergyWithoutFrictionOrTorqueWhileTurning) {
  Vector state = Vector::Zero(kStateSize);
  state[kThetaB] = kDefaultInitialPitch;
  state[kThetaBDot] = 0.5;
  state[kPhiLeftDot] = -2.0;  // unequal wheel speeds: it turns at 1.7 rad/s
  state[kPhiRightDot] = 3.0;
  EXPECT_LT(energy_drift(GetParam(), state), 1e-5);
}

TEST_P(PlantPhysics, UprightAtRestStaysUpright) {
  const RobotParams p;
  const Rig rig = make_rig(GetParam(), p, 0.0, Control::kFixedTorque);
  auto simulator = make_simulator(rig, p);
  const SignalLog& log = simulator->add_log(rig.state(), kPeriod);
  simulator->advance_to(10.0);
  ASSERT_EQ(log.num_samples(), 1000);
  EXPECT_EQ(log.values().cwiseAbs().maxCoeff(), 0.0);
}

TEST_P(PlantPhysics, PdLawWithTheTorqueLimitBalancesForTwentySeconds) {
  const RobotParams p;
  const Rig rig = make_rig(GetParam(), p, kDefaultInitialPitch, Control::kPd);
  auto simulator = make_simulator(rig, p);
  const SignalLog& log = simulator->add_log(rig.state(), kPeriod);
  simulator->advance_to(20.0 + kPeriod / 2);
  ASSERT_EQ(log.num_samples(), 2001);
  const Eigen::MatrixXd y = log.values();
  EXPECT_LT(y.row(kThetaB).cwiseAbs().maxCoeff(), kFailureAngle);
  EXPECT_LT(std::abs(y(kThetaB, 2000)), 1e-3);  // settled upright
  EXPECT_LT(std::abs(y(kThetaBDot, 2000)), 1e-3);
}

// Falls: the first tick at which |theta_b| exceeds the failure angle, or infinity.
double falling_time(PlantKind kind, const RobotParams& p, Control control, double duration,
                    double sample_period = kPeriod) {
  const Rig rig = make_rig(kind, p, kDefaultInitialPitch, control);
  auto simulator = make_simulator(rig, p);
  const SignalLog& log = simulator->add_log(rig.state(), sample_period);
  simulator->advance_to(duration);
  for (int k = 0; k < log.num_samples(); ++k) {
    if (std::abs(log.sample(k)[kThetaB]) > kFailureAngle) return log.times()[k];
  }
  return INFINITY;
}

TEST_P(PlantPhysics, PdLawWithItsSignFlippedMakesItFall) {
  const RobotParams p;
  EXPECT_LT(falling_time(GetParam(), p, Control::kPdFlipped, 20.0), 1.0);
  EXPECT_EQ(falling_time(GetParam(), p, Control::kPd, 20.0), INFINITY);
}

// The unstable pole of the frictionless straight-line model, worked out by hand:
// M_p = [[M L^2 + J_y, M L R], [M L R, (2 m + M) R^2 + 2 J_w]], pole^2 = M g L m_pp / det M_p.
double hand_unstable_pole(const RobotParams& p) {
  const double m11 = p.body_mass * p.com_height * p.com_height + p.body_pitch_inertia;
  const double m12 = p.body_mass * p.com_height * p.wheel_radius;
  const double m22 =
      (2 * p.wheel_mass + p.body_mass) * p.wheel_radius * p.wheel_radius + 2 * p.wheel_inertia;
  return std::sqrt(p.body_mass * p.gravity * p.com_height * m22 / (m11 * m22 - m12 * m12));
}

TEST_P(PlantPhysics, HeavierBodyOrLongerLegChangesTheFallingTimeAsMechanicsSays) {
  const RobotParams base = frictionless();
  RobotParams heavy = base;
  heavy.body_mass = 20.0;
  RobotParams tall = base;
  tall.com_height = 0.8;  // J_y about the centre of mass unchanged
  // Mechanics: the fall grows as exp(pole t). A heavier body (same inertia about its centre)
  // is relatively more point-like: pole 4.53 -> 6.33 /s. A longer L lets the wheels roll
  // back under the body less effectively: 4.53 -> 5.10 /s. Both fall sooner.
  ASSERT_GT(hand_unstable_pole(heavy), hand_unstable_pole(base) * 1.3);
  ASSERT_GT(hand_unstable_pole(tall), hand_unstable_pole(base) * 1.1);

  const double sample = 0.001;
  const double base_time = falling_time(GetParam(), base, Control::kFixedTorque, 2.0, sample);
  const double heavy_time = falling_time(GetParam(), heavy, Control::kFixedTorque, 2.0, sample);
  const double tall_time = falling_time(GetParam(), tall, Control::kFixedTorque, 2.0, sample);
  ASSERT_LT(base_time, 2.0);
  EXPECT_LT(heavy_time, base_time);
  EXPECT_LT(tall_time, base_time);
  // And by about the ratio of the poles (the fall is nearly exponential up to 0.52 rad).
  EXPECT_NEAR(base_time / heavy_time, hand_unstable_pole(heavy) / hand_unstable_pole(base), 0.1);
  EXPECT_NEAR(base_time / tall_time, hand_unstable_pole(tall) / hand_unstable_pole(base), 0.1);
}

INSTANTIATE_TEST_SUITE_P(BothPlants, PlantPhysics,
                         ::testing::Values(PlantKind::kAnalytic, PlantKind::kSimbody),
                         [](const auto& parameter) { return plant_name(parameter.param); });

}  // namespace
}  // namespace cbbg::plant::testing
