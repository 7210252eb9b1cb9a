#include "cbbg/framework/control/lqr.h"

#include <cmath>
#include <complex>
#include <stdexcept>

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <Eigen/Dense>

#include "cbbg/framework/control/discretize.h"
#include "cbbg/framework/control/riccati.h"

namespace cbbg::control {
namespace {

using Eigen::MatrixXd;
using ::testing::HasSubstr;
using ::testing::ThrowsMessage;

MatrixXd double_integrator_a() { return (MatrixXd(2, 2) << 0, 1, 0, 0).finished(); }
MatrixXd double_integrator_b() { return (MatrixXd(2, 1) << 0, 1).finished(); }

TEST(Lqr, RegulatesTheDoubleIntegrator) {
  // Q = I, R = 1: S = [[sqrt(3), 1], [1, sqrt(3)]], K = B' S = (1, sqrt(3)); the closed loop
  // s^2 + sqrt(3) s + 1 has its poles at (-sqrt(3) +- i) / 2.
  const LqrResult lqr_result = lqr(double_integrator_a(), double_integrator_b(),
                                   MatrixXd::Identity(2, 2), MatrixXd::Identity(1, 1));
  EXPECT_NEAR(lqr_result.K(0, 0), 1.0, 1e-12);
  EXPECT_NEAR(lqr_result.K(0, 1), std::sqrt(3.0), 1e-12);
  EXPECT_NEAR(lqr_result.S(0, 0), std::sqrt(3.0), 1e-12);
  const Eigen::VectorXcd poles =
      (double_integrator_a() - double_integrator_b() * lqr_result.K).eigenvalues();
  for (const std::complex<double> pole : poles) {
    EXPECT_LT(pole.real(), 0.0);
    EXPECT_NEAR(pole.real(), -std::sqrt(3.0) / 2.0, 1e-9);
    EXPECT_NEAR(std::abs(pole.imag()), 0.5, 1e-9);
  }
}

TEST(Lqr, GainIsRInverseBTransposeSWithSeveralInputs) {
  MatrixXd A(3, 3);
  A << 0.5, 1, 0, -1, 0.2, 1, 0.3, 0, 1.5;  // unstable
  MatrixXd B(3, 2);
  B << 1, 0, 0, 1, 1, 1;
  MatrixXd R(2, 2);
  R << 2, 0.5, 0.5, 1;
  const MatrixXd Q = MatrixXd::Identity(3, 3);
  const LqrResult result = lqr(A, B, Q, R);
  EXPECT_LT((result.K - R.inverse() * B.transpose() * result.S).norm(), 1e-12);
  EXPECT_LT(continuous_riccati_residual(A, B, Q, R, result.S).norm(), 1e-10);
  EXPECT_LT((A - B * result.K).eigenvalues().real().maxCoeff(), 0.0);
}

TEST(DiscreteLqr, RegulatesAScalarSystemAsWorkedOutByHand) {
  // a = 2, b = q = r = 1: S = 2 + sqrt(5), K = a S / (1 + S) = 2 (2 + sqrt(5)) / (3 + sqrt(5)),
  // and the closed loop a - K = 2 / (3 + sqrt(5)).
  const MatrixXd one = MatrixXd::Ones(1, 1);
  const LqrResult result = discrete_lqr(2.0 * one, one, one, one);
  const double s = 2.0 + std::sqrt(5.0);
  EXPECT_NEAR(result.S(0, 0), s, 1e-12);
  EXPECT_NEAR(result.K(0, 0), 2.0 * s / (1.0 + s), 1e-12);
  EXPECT_NEAR(2.0 - result.K(0, 0), 2.0 / (3.0 + std::sqrt(5.0)), 1e-12);
}

TEST(DiscreteLqr, StabilisesTheSampledDoubleIntegrator) {
  const double h = 0.1;
  const StateSpace sampled = c2d(double_integrator_a(), double_integrator_b(), h);
  const MatrixXd Q = MatrixXd::Identity(2, 2);
  const MatrixXd R = MatrixXd::Identity(1, 1);
  const LqrResult result = discrete_lqr(sampled.A, sampled.B, Q, R);
  EXPECT_LT(discrete_riccati_residual(sampled.A, sampled.B, Q, R, result.S).norm(), 1e-10);
  const MatrixXd expected_k = (R + sampled.B.transpose() * result.S * sampled.B).inverse() *
                              sampled.B.transpose() * result.S * sampled.A;
  EXPECT_LT((result.K - expected_k).norm(), 1e-10);
  const Eigen::VectorXcd poles = (sampled.A - sampled.B * result.K).eigenvalues();
  for (const std::complex<double> pole : poles) EXPECT_LT(std::abs(pole), 1.0);
}

TEST(DiscreteLqr, ApproachesTheContinuousRegulatorAsThePeriodShrinks) {
  // Sampling fast with the weights scaled by the period (the sum approximating the integral),
  // the discrete cost-to-go and gain tend to the continuous ones, with an O(h) difference.
  const MatrixXd Q = MatrixXd::Identity(2, 2);
  const MatrixXd R = MatrixXd::Identity(1, 1);
  const LqrResult continuous = lqr(double_integrator_a(), double_integrator_b(), Q, R);
  const double h = 1e-3;
  const StateSpace sampled = c2d(double_integrator_a(), double_integrator_b(), h);
  const LqrResult discrete = discrete_lqr(sampled.A, sampled.B, h * Q, h * R);
  EXPECT_LT((discrete.S - continuous.S).norm(), 1e-2 * continuous.S.norm());
  EXPECT_LT((discrete.K - continuous.K).norm(), 1e-2 * continuous.K.norm());
}

TEST(Lqr, PassesOnTheRiccatiSolversErrors) {
  const MatrixXd one = MatrixXd::Ones(1, 1);
  EXPECT_THAT([&] { lqr(one, one, one, -one); },
              ThrowsMessage<std::invalid_argument>(
                  HasSubstr("continuous Riccati equation: R must be symmetric positive definite")));
  EXPECT_THAT([&] { discrete_lqr(one, MatrixXd::Zero(1, 1), one, one); },
              ThrowsMessage<std::invalid_argument>(
                  HasSubstr("discrete Riccati equation: no stabilising solution")));
}

}  // namespace
}  // namespace cbbg::control
