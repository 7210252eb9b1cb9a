#include "cbbg/framework/control/discretize.h"

#include <cmath>
#include <limits>
#include <stdexcept>

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <Eigen/Dense>

namespace cbbg::control {
namespace {

using Eigen::MatrixXd;
using ::testing::HasSubstr;
using ::testing::ThrowsMessage;

TEST(C2d, SamplesTheDoubleIntegratorExactly) {
  // x'' = u: e^(A h) = I + A h (A^2 = 0), so Ad = [[1, h], [0, 1]] and
  // Bd = integral of [s; 1] ds = [h^2 / 2; h].
  MatrixXd A(2, 2);
  A << 0, 1, 0, 0;
  MatrixXd B(2, 1);
  B << 0, 1;
  for (const double h : {0.01, 0.1, 1.0, 3.0}) {
    const StateSpace sampled = c2d(A, B, h);
    MatrixXd Ad(2, 2);
    Ad << 1, h, 0, 1;
    MatrixXd Bd(2, 1);
    Bd << h * h / 2.0, h;
    EXPECT_LT((sampled.A - Ad).norm(), 1e-14 * (1.0 + h)) << "h = " << h;
    EXPECT_LT((sampled.B - Bd).norm(), 1e-14 * (1.0 + h * h)) << "h = " << h;
    EXPECT_EQ(sampled.time_period, h);
    EXPECT_TRUE(sampled.is_discrete());
    EXPECT_EQ(sampled.C.rows(), 0);
    EXPECT_EQ(sampled.C.cols(), 2);
    EXPECT_EQ(sampled.D.rows(), 0);
    EXPECT_EQ(sampled.D.cols(), 1);
  }
}

TEST(C2d, SamplesAFirstOrderLagAsItsExponentialDecay) {
  // tau x' = -x + u, y = 2 x: over a period with u held, x decays by e^(-h / tau) towards u,
  // so Ad = e^(-h / tau), Bd = 1 - e^(-h / tau); C and D are kept.
  const double tau = 0.35;
  const StateSpace lag{MatrixXd::Constant(1, 1, -1.0 / tau), MatrixXd::Constant(1, 1, 1.0 / tau),
                       MatrixXd::Constant(1, 1, 2.0), MatrixXd::Zero(1, 1), 0.0};
  for (const double h : {1e-3, 0.05, 0.35, 2.0}) {
    const StateSpace sampled = c2d(lag, h);
    EXPECT_NEAR(sampled.A(0, 0), std::exp(-h / tau), 1e-15);
    EXPECT_NEAR(sampled.B(0, 0), 1.0 - std::exp(-h / tau), 1e-15);
    EXPECT_EQ(sampled.C, lag.C);
    EXPECT_EQ(sampled.D, lag.D);
    EXPECT_EQ(sampled.time_period, h);
  }
}

TEST(C2d, SamplesAHarmonicOscillatorAsARotation) {
  // x' = w [[0, 1], [-1, 0]] x + [0; 1] u: Ad rotates by w h, and
  // Bd = [(1 - cos w h) / w; sin(w h) / w].
  const double w = 3.0;
  const double h = 0.2;
  MatrixXd A(2, 2);
  A << 0, w, -w, 0;
  MatrixXd B(2, 1);
  B << 0, 1;
  const StateSpace sampled = c2d(A, B, h);
  MatrixXd Ad(2, 2);
  Ad << std::cos(w * h), std::sin(w * h), -std::sin(w * h), std::cos(w * h);
  MatrixXd Bd(2, 1);
  Bd << (1.0 - std::cos(w * h)) / w, std::sin(w * h) / w;
  EXPECT_LT((sampled.A - Ad).norm(), 1e-14);
  EXPECT_LT((sampled.B - Bd).norm(), 1e-14);
}

TEST(C2d, RejectsABadPeriodADiscreteSystemAndBadSizes) {
  const MatrixXd A = MatrixXd::Identity(2, 2);
  const MatrixXd B = MatrixXd::Ones(2, 1);
  for (const double h : {0.0, -0.1, std::numeric_limits<double>::infinity()}) {
    EXPECT_THAT([&] { c2d(A, B, h); }, ThrowsMessage<std::invalid_argument>(HasSubstr(
                                           "c2d: the period must be positive and finite; got")));
  }
  EXPECT_THAT(
      [&] {
        c2d(StateSpace{A, B, {}, {}, 0.1}, 0.1);
      },
      ThrowsMessage<std::invalid_argument>(
          HasSubstr("c2d: the system is already discrete (time_period 0.1)")));
  EXPECT_THAT([&] { c2d(A, MatrixXd::Ones(3, 1), 0.1); },
              ThrowsMessage<std::invalid_argument>(
                  HasSubstr("c2d: A must be n x n, B n x m, C p x n and D p x m; got A 2x2, "
                            "B 3x1, C 0x2, D 0x1")));
  EXPECT_THAT(
      [&] {
        c2d(StateSpace{A, B, MatrixXd::Ones(1, 2), MatrixXd::Ones(2, 1), 0.0}, 0.1);
      },
      ThrowsMessage<std::invalid_argument>(HasSubstr("got A 2x2, B 2x1, C 1x2, D 2x1")));
  MatrixXd not_finite = A;
  not_finite(0, 1) = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THAT([&] { c2d(not_finite, B, 0.1); },
              ThrowsMessage<std::invalid_argument>(HasSubstr("c2d: A, B, C and D must be finite")));
}

}  // namespace
}  // namespace cbbg::control
