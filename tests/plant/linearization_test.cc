#include "cbbg/plant/linearization.h"

#include <cmath>
#include <stdexcept>

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <Eigen/Dense>
#include <Eigen/Eigenvalues>

namespace cbbg::plant {
namespace {

// The model about upright worked out by hand: at theta_b = 0 and rest, sin ~ theta_b, every
// term quadratic in the rates vanishes, and what is left is
//   M0 q'' + D q' + G q = E T,
// M0 the mass matrix at theta_b = 0, D the friction matrix, G = diag(-M g L, 0, 0).
struct HandModel {
  Eigen::Matrix3d mass;
  Eigen::Matrix3d friction;
  Eigen::Matrix3d stiffness;
  Eigen::Matrix<double, 3, 2> input;
};

HandModel hand_model(const RobotParams& p) {
  const double rho2 = std::pow(p.wheel_radius / p.track_width, 2);
  const double r2 = p.wheel_radius * p.wheel_radius;
  const double yaw = p.body_yaw_inertia + 2.0 * p.wheel_diametral_inertia;
  const double ml = p.body_mass * p.com_height;
  const double wheel = p.wheel_mass * r2 + p.wheel_inertia + p.body_mass * r2 / 4 + rho2 * yaw;
  const double cross = p.body_mass * r2 / 4 - rho2 * yaw;
  const double mu_w = p.axle_friction;
  const double mu_g = p.wheel_ground_friction;
  HandModel m;
  m.mass << ml * p.com_height + p.body_pitch_inertia, ml * p.wheel_radius / 2,
      ml * p.wheel_radius / 2,  //
      ml * p.wheel_radius / 2, wheel, cross, ml * p.wheel_radius / 2, cross, wheel;
  m.friction << 2 * mu_w, -mu_w, -mu_w, -mu_w, mu_g + mu_w, 0, -mu_w, 0, mu_g + mu_w;
  m.stiffness << -ml * p.gravity, 0, 0, 0, 0, 0, 0, 0, 0;
  m.input << -1, -1, 1, 0, 0, 1;
  return m;
}

int count_unstable(const Eigen::MatrixXd& a) {
  const Eigen::VectorXcd poles = a.eigenvalues();
  int unstable = 0;
  for (const auto& pole : poles) unstable += pole.real() > 1e-9 ? 1 : 0;
  return unstable;
}

double largest_real_pole(const Eigen::MatrixXd& a) {
  const Eigen::VectorXcd poles = a.eigenvalues();
  double largest = -INFINITY;
  for (const auto& pole : poles) largest = std::max(largest, pole.real());
  return largest;
}

RobotParams frictionless() {
  RobotParams p;
  p.wheel_ground_friction = 0.0;
  p.axle_friction = 0.0;
  return p;
}

TEST(Linearization, MatchesTheHandDerivedModelAboutUpright) {
  for (const RobotParams& p : {RobotParams{}, frictionless()}) {
    const HandModel hand = hand_model(p);
    const Eigen::Matrix3d inverse = hand.mass.inverse();
    Eigen::MatrixXd a = Eigen::MatrixXd::Zero(6, 6);
    a.topRightCorner<3, 3>().setIdentity();
    a.bottomLeftCorner<3, 3>() = -inverse * hand.stiffness;
    a.bottomRightCorner<3, 3>() = -inverse * hand.friction;
    Eigen::MatrixXd b = Eigen::MatrixXd::Zero(6, 2);
    b.bottomRows<3>() = inverse * hand.input;

    const LinearModel model = linearize_upright(p);
    ASSERT_EQ(model.A.rows(), 6);
    ASSERT_EQ(model.A.cols(), 6);
    ASSERT_EQ(model.B.rows(), 6);
    ASSERT_EQ(model.B.cols(), 2);
    EXPECT_LT((model.A - a).cwiseAbs().maxCoeff(), 1e-8) << model.A << "\n\n" << a;
    EXPECT_LT((model.B - b).cwiseAbs().maxCoeff(), 1e-8) << model.B << "\n\n" << b;
  }
}

TEST(Linearization, HasExactlyOneUnstablePitchPole) {
  for (const RobotParams& p : {RobotParams{}, frictionless()}) {
    const LinearModel model = linearize_upright(p);
    EXPECT_EQ(count_unstable(model.A), 1);
    // Its eigenvector is a fall: the pitch moves, both wheels alike.
    Eigen::EigenSolver<Eigen::MatrixXd> solver(model.A);
    for (int i = 0; i < 6; ++i) {
      if (solver.eigenvalues()[i].real() <= 1e-9) continue;
      EXPECT_NEAR(solver.eigenvalues()[i].imag(), 0.0, 1e-12);
      const Eigen::VectorXd mode = solver.eigenvectors().col(i).real();
      EXPECT_GT(std::abs(mode[0]), 0.01 * mode.norm()) << mode.transpose();
      EXPECT_NEAR(mode[1], mode[2], 1e-9) << "a fall turns neither way";
    }
  }
  // Frictionless, the pole is sqrt(M g L m_pp / det M_p) of the planar model
  // M_p = [[M L^2 + J_y, M L R], [M L R, (2 m + M) R^2 + 2 J_w]] = [[3.1417, 0.6],
  // [0.6, 0.2925]]: sqrt(39.2 * 0.2925 / 0.55894725) = 4.529...
  const double expected = std::sqrt(39.2 * 0.2925 / (3.1417 * 0.2925 - 0.36));
  EXPECT_NEAR(largest_real_pole(linearize_upright(frictionless()).A), expected, 1e-7);
  EXPECT_NEAR(largest_real_pole(linearize_planar_upright(frictionless()).A), expected, 1e-7);
}

TEST(Linearization, PlanarModelIsTheHandDerivedStraightLineModel) {
  // phi_l = phi_r = phi: M_p = T' M0 T, D_p = T' D T, E_p = T' E (1, 1)' with
  // T = [[1, 0], [0, 1], [0, 1]].
  for (const RobotParams& p : {RobotParams{}, frictionless()}) {
    const HandModel hand = hand_model(p);
    Eigen::Matrix<double, 3, 2> t;
    t << 1, 0, 0, 1, 0, 1;
    const Eigen::Matrix2d mass = t.transpose() * hand.mass * t;
    const Eigen::Matrix2d friction = t.transpose() * hand.friction * t;
    const Eigen::Matrix2d stiffness = t.transpose() * hand.stiffness * t;
    const Eigen::Vector2d input = t.transpose() * hand.input * Eigen::Vector2d::Ones();
    EXPECT_NEAR(input[0], -2.0, 0.0);
    EXPECT_NEAR(mass(1, 1), (2 * p.wheel_mass + p.body_mass) * 0.0225 + 2 * p.wheel_inertia, 1e-12);
    Eigen::MatrixXd a = Eigen::MatrixXd::Zero(4, 4);
    a.topRightCorner<2, 2>().setIdentity();
    a.bottomLeftCorner<2, 2>() = -mass.inverse() * stiffness;
    a.bottomRightCorner<2, 2>() = -mass.inverse() * friction;
    Eigen::MatrixXd b = Eigen::MatrixXd::Zero(4, 1);
    b.bottomRows<2>() = mass.inverse() * input;

    const LinearModel model = linearize_planar_upright(p);
    ASSERT_EQ(model.A.rows(), 4);
    ASSERT_EQ(model.A.cols(), 4);
    ASSERT_EQ(model.B.rows(), 4);
    ASSERT_EQ(model.B.cols(), 1);
    EXPECT_LT((model.A - a).cwiseAbs().maxCoeff(), 1e-8) << model.A << "\n\n" << a;
    EXPECT_LT((model.B - b).cwiseAbs().maxCoeff(), 1e-8) << model.B << "\n\n" << b;
    EXPECT_EQ(count_unstable(model.A), 1);
  }
}

TEST(Linearization, FollowsTheParameters) {
  RobotParams heavy = frictionless();
  heavy.body_mass = 20.0;
  EXPECT_GT(largest_real_pole(linearize_upright(heavy).A),
            largest_real_pole(linearize_upright(frictionless()).A));
}

TEST(Linearization, RejectsInvalidParameters) {
  RobotParams p;
  p.com_height = -0.4;
  EXPECT_THAT([&] { linearize_upright(p); },
              ::testing::ThrowsMessage<std::invalid_argument>(
                  "plant.com_height must be finite and > 0; got -0.4"));
  EXPECT_THAT([&] { linearize_planar_upright(p); },
              ::testing::ThrowsMessage<std::invalid_argument>(
                  "plant.com_height must be finite and > 0; got -0.4"));
}

}  // namespace
}  // namespace cbbg::plant
