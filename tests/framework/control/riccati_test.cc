#include "cbbg/framework/control/riccati.h"

#include <array>
#include <cmath>
#include <initializer_list>
#include <limits>
#include <stdexcept>

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <Eigen/Dense>

namespace cbbg::control {
namespace {

using Eigen::MatrixXd;
using ::testing::HasSubstr;
using ::testing::StartsWith;
using ::testing::ThrowsMessage;

MatrixXd scalar(double value) { return MatrixXd::Constant(1, 1, value); }

MatrixXd matrix(int rows, int cols, std::initializer_list<double> values) {
  MatrixXd M(rows, cols);
  auto value = values.begin();
  for (int i = 0; i < rows; ++i) {
    for (int j = 0; j < cols; ++j) M(i, j) = *value++;
  }
  return M;
}

// The scalar continuous equation 2 a x - b^2 x^2 / r + q = 0 has the roots
// x = r (a +- sqrt(a^2 + b^2 q / r)) / b^2; the stabilising one (a - b^2 x / r < 0) takes +.
double scalar_care(double a, double b, double q, double r) {
  return r * (a + std::sqrt(a * a + b * b * q / r)) / (b * b);
}

// The scalar discrete equation a^2 x - x - a^2 b^2 x^2 / (r + b^2 x) + q = 0, multiplied out
// by (r + b^2 x), is b^2 x^2 + (r (1 - a^2) - q b^2) x - q r = 0; the stabilising root is
// the non-negative one.
double scalar_dare(double a, double b, double q, double r) {
  const double c = r * (1.0 - a * a) - q * b * b;
  return (-c + std::sqrt(c * c + 4.0 * b * b * q * r)) / (2.0 * b * b);
}

TEST(ContinuousRiccati, SolvesScalarEquationsAsWorkedOutByHand) {
  // a = 1, b = 1, q = 3, r = 1: 2x - x^2 + 3 = 0, roots 3 and -1; a - x = -2 < 0 for x = 3.
  EXPECT_NEAR(solve_continuous_riccati(scalar(1), scalar(1), scalar(3), scalar(1))(0, 0), 3.0,
              1e-12);
  for (const auto& [a, b, q, r] : {std::array{-2.0, 3.0, 5.0, 2.0}, std::array{0.0, 1.0, 1.0, 1.0},
                                   std::array{4.0, 0.5, 0.0, 3.0}}) {
    const MatrixXd X = solve_continuous_riccati(scalar(a), scalar(b), scalar(q), scalar(r));
    EXPECT_NEAR(X(0, 0), scalar_care(a, b, q, r), 1e-12 * (1.0 + X(0, 0)))
        << "a " << a << " b " << b << " q " << q << " r " << r;
    EXPECT_LT(continuous_riccati_residual(scalar(a), scalar(b), scalar(q), scalar(r), X).norm(),
              1e-10);
  }
}

TEST(ContinuousRiccati, SolvesTheDoubleIntegrator) {
  // x'' = u, Q = I, R = 1, worked by hand: S = [[sqrt(3), 1], [1, sqrt(3)]] (the (1,1) entry
  // of the equation gives s12 = 1, the (2,2) one s22 = sqrt(3), the (1,2) one s11 = s12 s22).
  const MatrixXd A = matrix(2, 2, {0, 1, 0, 0});
  const MatrixXd B = matrix(2, 1, {0, 1});
  const MatrixXd Q = MatrixXd::Identity(2, 2);
  const MatrixXd R = scalar(1);
  const MatrixXd X = solve_continuous_riccati(A, B, Q, R);
  EXPECT_LT((X - matrix(2, 2, {std::sqrt(3.0), 1, 1, std::sqrt(3.0)})).norm(), 1e-12);
  EXPECT_LT(continuous_riccati_residual(A, B, Q, R, X).norm(), 1e-10);
}

// CAREX, the benchmark collection of P. Benner, A. J. Laub, V. Mehrmann, "A collection of
// benchmark examples for the numerical solution of algebraic Riccati equations I:
// continuous-time case", TU Chemnitz-Zwickau, report SPC 95_22 (1995), examples 1 and 2 of
// its MATLAB generator carex.m, both with exact solutions.
TEST(ContinuousRiccati, SolvesCarexBenchmarksWithExactSolutions) {
  {  // Example 1: a double integrator, Q = diag(1, 2): X = [[2, 1], [1, 2]].
    const MatrixXd A = matrix(2, 2, {0, 1, 0, 0});
    const MatrixXd B = matrix(2, 1, {0, 1});
    const MatrixXd Q = matrix(2, 2, {1, 0, 0, 2});
    const MatrixXd X = solve_continuous_riccati(A, B, Q, scalar(1));
    EXPECT_LT((X - matrix(2, 2, {2, 1, 1, 2})).norm(), 1e-12);
    EXPECT_LT(continuous_riccati_residual(A, B, Q, scalar(1), X).norm(), 1e-10);
  }
  {  // Example 2: X = (1 + sqrt(2)) [[9, 6], [6, 4]].
    const MatrixXd A = matrix(2, 2, {4, 3, -4.5, -3.5});
    const MatrixXd B = matrix(2, 1, {1, -1});
    const MatrixXd Q = matrix(2, 2, {9, 6, 6, 4});
    const MatrixXd X = solve_continuous_riccati(A, B, Q, scalar(1));
    EXPECT_LT((X - (1.0 + std::sqrt(2.0)) * Q).norm(), 1e-11);
    EXPECT_LT(continuous_riccati_residual(A, B, Q, scalar(1), X).norm(), 1e-10);
  }
}

TEST(DiscreteRiccati, SolvesScalarEquationsInClosedForm) {
  // a = 2, b = 1, q = 1, r = 1: x^2 - 4x - 1 = 0, x = 2 + sqrt(5); the closed loop
  // a - b k = 2 / (1 + x) = 2 / (3 + sqrt(5)) ~ 0.38 is inside the unit circle.
  EXPECT_NEAR(solve_discrete_riccati(scalar(2), scalar(1), scalar(1), scalar(1))(0, 0),
              2.0 + std::sqrt(5.0), 1e-12);
  for (const auto& [a, b, q, r] : {std::array{0.5, 2.0, 3.0, 0.7}, std::array{-1.5, 0.3, 2.0, 5.0},
                                   std::array{0.0, 1.0, 4.0, 1.0}, std::array{1.0, 1.0, 1.0, 1.0},
                                   std::array{0.9, 1.0, 0.0, 1.0}}) {
    const MatrixXd X = solve_discrete_riccati(scalar(a), scalar(b), scalar(q), scalar(r));
    EXPECT_NEAR(X(0, 0), scalar_dare(a, b, q, r), 1e-12 * (1.0 + X(0, 0)))
        << "a " << a << " b " << b << " q " << q << " r " << r;
    EXPECT_LT(discrete_riccati_residual(scalar(a), scalar(b), scalar(q), scalar(r), X).norm(),
              1e-10);
  }
}

// DAREX, the benchmark collection of P. Benner, A. J. Laub, V. Mehrmann, "A collection of
// benchmark examples for the numerical solution of algebraic Riccati equations II:
// discrete-time case", TU Chemnitz-Zwickau, report SPC 95_23 (1995): examples 1, 5 and 15
// of its MATLAB generator darex.m, with exact solutions.
TEST(DiscreteRiccati, SolvesDarexBenchmarksWithExactSolutions) {
  {  // Example 1: X = (1 + sqrt(5)) / 2 [[9, 6], [6, 4]].
    const MatrixXd A = matrix(2, 2, {4, 3, -4.5, -3.5});
    const MatrixXd B = matrix(2, 1, {1, -1});
    const MatrixXd Q = matrix(2, 2, {9, 6, 6, 4});
    const MatrixXd X = solve_discrete_riccati(A, B, Q, scalar(1));
    EXPECT_LT((X - (1.0 + std::sqrt(5.0)) / 2.0 * Q).norm(), 1e-11);
    EXPECT_LT(discrete_riccati_residual(A, B, Q, scalar(1), X).norm(), 1e-10);
  }
  {  // Example 5: a singular A (a two-step delay); X = [[1, 2], [2, 2 + sqrt(5)]].
    const MatrixXd A = matrix(2, 2, {0, 1, 0, 0});
    const MatrixXd B = matrix(2, 1, {0, 1});
    const MatrixXd Q = matrix(2, 2, {1, 2, 2, 4});
    const MatrixXd X = solve_discrete_riccati(A, B, Q, scalar(1));
    EXPECT_LT((X - matrix(2, 2, {1, 2, 2, 2 + std::sqrt(5.0)})).norm(), 1e-12);
    EXPECT_LT(discrete_riccati_residual(A, B, Q, scalar(1), X).norm(), 1e-10);
  }
  {  // Example 15 with n = 6: a shift register, Q = I, R = 1; X = diag(1, ..., n).
    const int n = 6;
    MatrixXd A = MatrixXd::Zero(n, n);
    A.diagonal(1).setOnes();
    MatrixXd B = MatrixXd::Zero(n, 1);
    B(n - 1, 0) = 1.0;
    const MatrixXd Q = MatrixXd::Identity(n, n);
    const MatrixXd X = solve_discrete_riccati(A, B, Q, scalar(1));
    const Eigen::VectorXd expected = Eigen::VectorXd::LinSpaced(n, 1.0, n);
    EXPECT_LT((X - MatrixXd(expected.asDiagonal())).norm(), 1e-12);
    EXPECT_LT(discrete_riccati_residual(A, B, Q, scalar(1), X).norm(), 1e-10);
  }
}

TEST(DiscreteRiccati, SolvesAMultiInputSystemWithAStabilisingSolution) {
  // No closed form: the solution must be symmetric, positive definite, satisfy the equation
  // and stabilise (DAREX example 2's data, R and Q from the same example).
  const MatrixXd A = matrix(2, 2, {0.9512, 0, 0, 0.9048});
  const MatrixXd B = matrix(2, 2, {4.877, 4.877, -1.1895, 3.569});
  const MatrixXd R = matrix(2, 2, {1.0 / 3.0, 0, 0, 3});
  const MatrixXd Q = matrix(2, 2, {0.005, 0, 0, 0.02});
  const MatrixXd X = solve_discrete_riccati(A, B, Q, R);
  EXPECT_LT((X - X.transpose()).norm(), 1e-15);
  EXPECT_GT(X.selfadjointView<Eigen::Lower>().eigenvalues().minCoeff(), 0.0);
  EXPECT_LT(discrete_riccati_residual(A, B, Q, R, X).norm(), 1e-10);
  const MatrixXd K = (R + B.transpose() * X * B).ldlt().solve(B.transpose() * X * A);
  EXPECT_LT((A - B * K).eigenvalues().cwiseAbs().maxCoeff(), 1.0);
}

TEST(Riccati, RejectsBadSizes) {
  const MatrixXd A = MatrixXd::Identity(2, 2);
  const MatrixXd B = MatrixXd::Ones(3, 1);
  EXPECT_THAT([&] { solve_continuous_riccati(A, B, A, scalar(1)); },
              ThrowsMessage<std::invalid_argument>(
                  HasSubstr("continuous Riccati equation: A must be n x n, B n x m, Q n x n and "
                            "R m x m with n, m >= 1; got A 2x2, B 3x1, Q 2x2, R 1x1")));
  EXPECT_THAT([&] { solve_discrete_riccati(A, MatrixXd::Ones(2, 1), A, A); },
              ThrowsMessage<std::invalid_argument>(
                  HasSubstr("discrete Riccati equation: A must be n x n, B n x m, Q n x n and "
                            "R m x m with n, m >= 1; got A 2x2, B 2x1, Q 2x2, R 2x2")));
}

TEST(Riccati, RejectsANonSymmetricQ) {
  const MatrixXd A = MatrixXd::Identity(2, 2);
  const MatrixXd B = MatrixXd::Ones(2, 1);
  const MatrixXd Q = matrix(2, 2, {1, 1, 0, 1});
  EXPECT_THAT([&] { solve_continuous_riccati(A, B, Q, scalar(1)); },
              ThrowsMessage<std::invalid_argument>(
                  HasSubstr("continuous Riccati equation: Q must be symmetric")));
  EXPECT_THAT([&] { solve_discrete_riccati(A, B, Q, scalar(1)); },
              ThrowsMessage<std::invalid_argument>(
                  HasSubstr("discrete Riccati equation: Q must be symmetric")));
}

TEST(Riccati, RejectsAnRThatIsNotPositiveDefinite) {
  const MatrixXd A = MatrixXd::Identity(2, 2);
  const MatrixXd B = MatrixXd::Identity(2, 2);
  for (const MatrixXd& R :
       {MatrixXd(matrix(2, 2, {1, 0, 0, 0})), MatrixXd(matrix(2, 2, {1, 2, 2, 1})),
        MatrixXd(matrix(2, 2, {1, 0.5, 0, 1}))}) {
    EXPECT_THAT([&] { solve_continuous_riccati(A, B, A, R); },
                ThrowsMessage<std::invalid_argument>(HasSubstr(
                    "continuous Riccati equation: R must be symmetric positive definite")));
    EXPECT_THAT([&] { solve_discrete_riccati(A, B, A, R); },
                ThrowsMessage<std::invalid_argument>(
                    HasSubstr("discrete Riccati equation: R must be symmetric positive definite")));
  }
}

TEST(Riccati, RejectsNonFiniteCoefficients) {
  const MatrixXd A = scalar(std::numeric_limits<double>::quiet_NaN());
  EXPECT_THAT([&] { solve_continuous_riccati(A, scalar(1), scalar(1), scalar(1)); },
              ThrowsMessage<std::invalid_argument>(
                  HasSubstr("continuous Riccati equation: A, B, Q and R must be finite")));
  EXPECT_THAT([&] { solve_discrete_riccati(scalar(1), A, scalar(1), scalar(1)); },
              ThrowsMessage<std::invalid_argument>(
                  HasSubstr("discrete Riccati equation: A, B, Q and R must be finite")));
}

TEST(Riccati, RejectsSystemsWithoutAStabilisingSolution) {
  // An unstable mode the input cannot reach: continuous (eigenvalue 1) and discrete (2).
  const MatrixXd B = matrix(2, 1, {0, 1});
  const MatrixXd Q = MatrixXd::Identity(2, 2);
  EXPECT_THAT(
      [&] {
        solve_continuous_riccati(matrix(2, 2, {1, 0, 0, -1}), B, Q, scalar(1));
      },
      ThrowsMessage<std::invalid_argument>(
          StartsWith("continuous Riccati equation: no stabilising solution")));
  EXPECT_THAT(
      [&] {
        solve_discrete_riccati(matrix(2, 2, {2, 0, 0, 0.5}), B, Q, scalar(1));
      },
      ThrowsMessage<std::invalid_argument>(
          StartsWith("discrete Riccati equation: no stabilising solution")));
  // A mode on the unit circle that Q does not see: x+ = x + u with q = 0 gives X = 0 and
  // the closed loop a - b k = 1, not stable.
  EXPECT_THAT([&] { solve_discrete_riccati(scalar(1), scalar(1), scalar(0), scalar(1)); },
              ThrowsMessage<std::invalid_argument>(
                  StartsWith("discrete Riccati equation: no stabilising solution")));
}

}  // namespace
}  // namespace cbbg::control
