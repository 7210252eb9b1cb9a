#include "cbbg/blocks/riccati.h"

#include <cmath>
#include <complex>
#include <stdexcept>
#include <string>

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>
#include <Eigen/LU>

namespace cbbg::blocks {
namespace {

using Eigen::MatrixXd;

// Solves the Lyapunov equation F' X + X F = -M (F stable) through its Kronecker form,
// (I (x) F' + F' (x) I) vec(X) = -vec(M); fine for the few states of a regulator.
MatrixXd solve_lyapunov(const MatrixXd& F, const MatrixXd& M) {
  const Eigen::Index n = F.rows();
  MatrixXd kronecker = MatrixXd::Zero(n * n, n * n);
  const MatrixXd Ft = F.transpose();
  for (Eigen::Index i = 0; i < n; ++i) {
    kronecker.block(i * n, i * n, n, n) += Ft;  // I (x) F'
    for (Eigen::Index j = 0; j < n; ++j) {
      kronecker.block(i * n, j * n, n, n).diagonal().array() += Ft(i, j);  // F' (x) I
    }
  }
  const Eigen::VectorXd rhs = -Eigen::Map<const Eigen::VectorXd>(M.data(), n * n);
  const Eigen::VectorXd x = kronecker.fullPivLu().solve(rhs);
  MatrixXd X = Eigen::Map<const MatrixXd>(x.data(), n, n);
  return (X + X.transpose()) / 2.0;
}

bool is_stable(const MatrixXd& F) { return (F.eigenvalues().real().array() < 0.0).all(); }

}  // namespace

MatrixXd riccati_residual(const MatrixXd& A, const MatrixXd& B, const MatrixXd& Q,
                          const MatrixXd& R, const MatrixXd& X) {
  return A.transpose() * X + X * A - X * B * R.llt().solve(B.transpose()) * X + Q;
}

MatrixXd solve_continuous_riccati(const MatrixXd& A, const MatrixXd& B, const MatrixXd& Q,
                                  const MatrixXd& R) {
  const Eigen::Index n = A.rows();
  const Eigen::Index m = B.cols();
  if (A.cols() != n || B.rows() != n || Q.rows() != n || Q.cols() != n || R.rows() != m ||
      R.cols() != m) {
    throw std::invalid_argument("Riccati equation: A must be n x n, B n x m, Q n x n, R m x m");
  }
  if (!Q.isApprox(Q.transpose())) {
    throw std::invalid_argument("Riccati equation: Q must be symmetric");
  }
  const Eigen::LLT<MatrixXd> r_factor(R);
  if (!R.isApprox(R.transpose()) || r_factor.info() != Eigen::Success) {
    throw std::invalid_argument("Riccati equation: R must be symmetric positive definite");
  }
  const MatrixXd G = B * r_factor.solve(B.transpose());  // B R^-1 B'

  // The n eigenvectors of the Hamiltonian with Re(lambda) < 0 span [I; X] (up to a change
  // of basis): X = V2 V1^-1.
  MatrixXd hamiltonian(2 * n, 2 * n);
  hamiltonian << A, -G, -Q, -A.transpose();
  const Eigen::ComplexEigenSolver<MatrixXd> eigen(hamiltonian);
  if (eigen.info() != Eigen::Success) {
    throw std::invalid_argument("Riccati equation: the Hamiltonian's eigenvalues did not converge");
  }
  Eigen::MatrixXcd stable(2 * n, n);
  Eigen::Index count = 0;
  for (Eigen::Index i = 0; i < 2 * n; ++i) {
    if (eigen.eigenvalues()[i].real() < 0.0 && count < n) {
      stable.col(count++) = eigen.eigenvectors().col(i);
    }
  }
  if (count != n) {
    throw std::invalid_argument(
        "Riccati equation: no stabilising solution (the Hamiltonian has eigenvalues on the "
        "imaginary axis: (A, B) not stabilisable or (A, Q) not detectable)");
  }
  const Eigen::MatrixXcd V1 = stable.topRows(n);
  const Eigen::MatrixXcd V2 = stable.bottomRows(n);
  MatrixXd X = (V1.transpose().partialPivLu().solve(V2.transpose())).transpose().real();
  X = (X + X.transpose()) / 2.0;

  // Newton–Kleinman: X solves (A - G X)' X+ + X+ (A - G X) = -(Q + X G X) at the fixed point.
  for (int iteration = 0; iteration < 20; ++iteration) {
    const MatrixXd closed_loop = A - G * X;
    if (!is_stable(closed_loop)) break;
    const MatrixXd next = solve_lyapunov(closed_loop, Q + X * G * X);
    const double change = (next - X).norm();
    X = next;
    if (change <= 1e-14 * (1.0 + X.norm())) break;
  }
  const double residual = riccati_residual(A, B, Q, R, X).norm();
  const double scale = 1.0 + Q.norm() + (A.transpose() * X).norm() + (X * G * X).norm();
  if (!X.allFinite() || !is_stable(A - G * X) || residual > 1e-8 * scale) {
    throw std::invalid_argument("Riccati equation: no stabilising solution found (residual " +
                                std::to_string(residual) +
                                "): (A, B) not stabilisable or (A, Q) not detectable");
  }
  return X;
}

}  // namespace cbbg::blocks
