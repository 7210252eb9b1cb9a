#include "cbbg/plant/robot_dynamics.h"

#include <cmath>
#include <random>

#include <gtest/gtest.h>
#include <Eigen/Geometry>

namespace cbbg::plant {
namespace {

RobotParams frictionless() {
  RobotParams p;
  p.wheel_ground_friction = 0.0;
  p.axle_friction = 0.0;
  return p;
}

TEST(RobotDynamics, MassMatrixHasTheHandComputedEntries) {
  const RobotParams p;
  // Upright: K = J_z + 2 I_d = 0.60055, rho^2 = (0.15 / 0.44)^2.
  const Eigen::Matrix3d upright = mass_matrix(p, 0.0);
  EXPECT_NEAR(upright(0, 0), 3.1417, 1e-12);
  EXPECT_NEAR(upright(0, 1), 0.3, 1e-12);
  EXPECT_NEAR(upright(0, 2), 0.3, 1e-12);
  EXPECT_NEAR(upright(1, 1), 0.15979532541322314, 1e-12);
  EXPECT_NEAR(upright(2, 2), 0.15979532541322314, 1e-12);
  EXPECT_NEAR(upright(1, 2), -0.01354532541322314, 1e-12);
  // Lying flat: the coupling vanishes and K gains M L^2 + J_x - J_z = 2.5524.
  const Eigen::Matrix3d flat = mass_matrix(p, M_PI / 2);
  EXPECT_NEAR(flat(0, 1), 0.0, 1e-12);
  EXPECT_NEAR(flat(1, 1), 0.456432722107438, 1e-12);
  EXPECT_NEAR(flat(1, 2), -0.31018272210743797, 1e-12);
  EXPECT_TRUE(flat.isApprox(flat.transpose(), 0.0));
}

TEST(RobotDynamics, EnergyAtRestIsTheBodysHeightTimesItsWeight) {
  const RobotParams p;
  EXPECT_NEAR(mechanical_energy(p, Coordinates(0.1744, 2.0, -1.0), Coordinates::Zero()),
              38.605368399993644, 1e-12);
  // Rolling straight at 1 rad/s with the body upright: (m22 + m33 + 2 m23) / 2 =
  // m_l R^2 + J_w + M R^2 / 2 = 0.0225 + 0.01125 + 0.1125.
  EXPECT_NEAR(mechanical_energy(p, Coordinates::Zero(), Coordinates(0.0, 1.0, 1.0)) - 39.2, 0.14625,
              1e-12);
}

TEST(RobotDynamics, TorquesPushTheWheelsForwardAndTheBodyBack) {
  const RobotParams p;
  const Coordinates a =
      accelerations(p, Coordinates::Zero(), Coordinates::Zero(), Torques(1.0, 1.0));
  EXPECT_LT(a[0], 0.0);
  EXPECT_GT(a[1], 0.0);
  EXPECT_DOUBLE_EQ(a[1], a[2]);
  EXPECT_EQ(yaw_rate(p, 1.0, 2.0), 0.15 / 0.44);
  EXPECT_EQ(forward_speed(p, 1.0, 2.0), 0.15 * 1.5);
  EXPECT_EQ(saturate_torque(Torques(7.0, -9.0), 5.0), Torques(5.0, -5.0));
  EXPECT_EQ(saturate_torque(Torques(4.0, -2.0), 5.0), Torques(4.0, -2.0));
}

// The generalised forces of a push from outside do the work of the force on the centre of
// mass's velocity along the heading and of the torque on the pitch rate, whatever the state.
TEST(RobotDynamics, APushFromOutsideDoesTheWorkOfItsForceAndTorque) {
  const RobotParams p;
  std::mt19937 random(7);
  std::uniform_real_distribution<double> any(-2.0, 2.0);
  for (int trial = 0; trial < 20; ++trial) {
    const double theta = any(random);
    const Coordinates q_dot(any(random), any(random), any(random));
    const double force = 10.0 * any(random);
    const double pitch_torque = any(random);
    const double com_speed =
        p.wheel_radius * (q_dot[1] + q_dot[2]) / 2.0 + p.com_height * std::cos(theta) * q_dot[0];
    EXPECT_NEAR(disturbance_forces(p, theta, force, pitch_torque).dot(q_dot),
                force * com_speed + pitch_torque * q_dot[0], 1e-12);
  }
  // Zero disturbance, the motors' accelerations; a pitch torque alone leans the body forward.
  const Coordinates q(0.1, 0.0, 0.0);
  const Coordinates q_dot(0.2, 1.0, 1.0);
  const Torques torque(1.0, 1.0);
  EXPECT_EQ(accelerations(p, q, q_dot, torque, disturbance_forces(p, q[0], 0.0, 0.0)),
            accelerations(p, q, q_dot, torque));
  EXPECT_GT(accelerations(p, q, q_dot, torque, disturbance_forces(p, q[0], 0.0, 1.0))[0],
            accelerations(p, q, q_dot, torque)[0]);
}

// An independent route to the equations: the kinetic energy written from 3-D kinematics in
// the robot's heading frame, as a function of the pitch and the velocities
// z = (theta_b', xi, eta, psi', phi_l', phi_r') (xi, eta: the axle's forward and sideways
// speeds), then Lagrange's equations in the coordinates (x, y, psi, theta_b, phi_l, phi_r)
// with the no-slip constraints (xi = R (phi_l' + phi_r') / 2, eta = 0,
// psi' = R (phi_r' - phi_l') / d) applied to the virtual displacements, not substituted
// into the energy.
using Velocities = Eigen::Matrix<double, 6, 1>;
enum { kThetaDot, kXi, kEta, kPsiDot, kPhiLDot, kPhiRDot };

double kinetic_energy(const RobotParams& p, double theta, const Velocities& z) {
  const Eigen::Vector3d up = Eigen::Vector3d::UnitZ();
  const Eigen::Vector3d axle_velocity(z[kXi], z[kEta], 0.0);
  const Eigen::Vector3d heading_spin = z[kPsiDot] * up;
  const Eigen::Matrix3d pitch = Eigen::AngleAxisd(theta, Eigen::Vector3d::UnitY()).matrix();
  // Body: mass centre at L along the body's up axis; angular velocity theta' y + psi' z.
  const Eigen::Vector3d centre = pitch * (p.com_height * up);
  const Eigen::Vector3d centre_rate =
      pitch * Eigen::Vector3d::UnitY().cross(p.com_height * up) * z[kThetaDot];
  const Eigen::Vector3d body_velocity = axle_velocity + heading_spin.cross(centre) + centre_rate;
  const Eigen::Vector3d body_spin = z[kThetaDot] * Eigen::Vector3d::UnitY() + heading_spin;
  const Eigen::Matrix3d body_inertia =
      pitch *
      Eigen::Vector3d(p.body_roll_inertia, p.body_pitch_inertia, p.body_yaw_inertia).asDiagonal() *
      pitch.transpose();
  double energy = 0.5 * p.body_mass * body_velocity.squaredNorm() +
                  0.5 * body_spin.dot(body_inertia * body_spin);
  // Wheels: centres at +-d/2 on the axle; each spins about the axle and turns with the heading.
  const Eigen::Matrix3d wheel_inertia =
      Eigen::Vector3d(p.wheel_diametral_inertia, p.wheel_inertia, p.wheel_diametral_inertia)
          .asDiagonal();
  for (const auto& [side, spin_rate] : {std::pair{1.0, z[kPhiLDot]}, {-1.0, z[kPhiRDot]}}) {
    const Eigen::Vector3d offset(0.0, side * p.track_width / 2.0, 0.0);
    const Eigen::Vector3d velocity = axle_velocity + heading_spin.cross(offset);
    const Eigen::Vector3d spin = spin_rate * Eigen::Vector3d::UnitY() + heading_spin;
    energy += 0.5 * p.wheel_mass * velocity.squaredNorm() + 0.5 * spin.dot(wheel_inertia * spin);
  }
  return energy;
}

// dT/dz_i: exact by a central difference of step 1, since T is quadratic in z.
double momentum(const RobotParams& p, double theta, const Velocities& z, int i) {
  const Velocities step = Velocities::Unit(i);
  return (kinetic_energy(p, theta, z + step) - kinetic_energy(p, theta, z - step)) / 2.0;
}

TEST(RobotDynamics, MatchesLagrangesEquationsWithTheRollingConstraints) {
  std::mt19937_64 generator(7);
  std::uniform_real_distribution<double> draw(-2.0, 2.0);
  RobotParams literal = frictionless();  // the paper's inertias, unphysical but fine for equations
  literal.body_roll_inertia = literal.body_yaw_inertia;
  literal.wheel_diametral_inertia = 0.0;
  for (const RobotParams& p : {frictionless(), literal}) {
    const double rho = p.wheel_radius / p.track_width;
    for (int trial = 0; trial < 20; ++trial) {
      const Coordinates q(draw(generator), draw(generator), draw(generator));
      const Coordinates q_dot(draw(generator), 3 * draw(generator), 3 * draw(generator));
      const Coordinates q_ddot(draw(generator), draw(generator), draw(generator));

      Velocities z;
      z << q_dot[0], p.wheel_radius * (q_dot[1] + q_dot[2]) / 2.0, 0.0, rho * (q_dot[2] - q_dot[1]),
          q_dot[1], q_dot[2];
      Velocities z_dot;
      z_dot << q_ddot[0], p.wheel_radius * (q_ddot[1] + q_ddot[2]) / 2.0, 0.0,
          rho * (q_ddot[2] - q_ddot[1]), q_ddot[1], q_ddot[2];
      // d/dt of each momentum along the motion, by a central difference in time.
      const double h = 1e-6;
      auto momentum_rate = [&](int i) {
        return (momentum(p, q[0] + h * q_dot[0], z + h * z_dot, i) -
                momentum(p, q[0] - h * q_dot[0], z - h * z_dot, i)) /
               (2.0 * h);
      };
      const double dT_dtheta =
          (kinetic_energy(p, q[0] + h, z) - kinetic_energy(p, q[0] - h, z)) / (2.0 * h);
      const double sideways = momentum(p, q[0], z, kEta);
      const double forward = momentum_rate(kXi) - z[kPsiDot] * sideways;  // x, y equations
      const double heading = momentum_rate(kPsiDot) + z[kXi] * sideways;  // psi equation

      Coordinates lagrange;
      lagrange[0] = momentum_rate(kThetaDot) - dT_dtheta -
                    p.body_mass * p.gravity * p.com_height * std::sin(q[0]);
      lagrange[1] = p.wheel_radius / 2.0 * forward - rho * heading + momentum_rate(kPhiLDot);
      lagrange[2] = p.wheel_radius / 2.0 * forward + rho * heading + momentum_rate(kPhiRDot);

      const Coordinates model = mass_matrix(p, q[0]) * q_ddot + bias_forces(p, q, q_dot);
      EXPECT_LT((model - lagrange).cwiseAbs().maxCoeff(), 1e-7)
          << "q = " << q.transpose() << ", q' = " << q_dot.transpose()
          << "\nmodel:    " << model.transpose() << "\nLagrange: " << lagrange.transpose();
    }
  }
}

TEST(RobotDynamics, FrictionIsViscousOnWheelsAgainstGroundAndAgainstTheBody) {
  const RobotParams p;  // mu_l = mu_r = mu_w = 0.1
  const Coordinates q = Coordinates::Zero();
  const Coordinates rest = bias_forces(p, q, Coordinates::Zero());
  // Upright, body still, wheels turning at 1 and 3 rad/s, no yaw coupling at theta_b = 0.
  const Coordinates n = bias_forces(p, q, Coordinates(0.0, 1.0, 3.0)) - rest;
  EXPECT_NEAR(n[0], -0.1 * (1.0 + 3.0), 1e-12);
  EXPECT_NEAR(n[1], (0.1 + 0.1) * 1.0, 1e-12);
  EXPECT_NEAR(n[2], (0.1 + 0.1) * 3.0, 1e-12);
}

}  // namespace
}  // namespace cbbg::plant
