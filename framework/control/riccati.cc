#include "cbbg/framework/control/riccati.h"

#include <cmath>
#include <complex>
#include <cstdio>
#include <stdexcept>
#include <string>

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>
#include <Eigen/LU>

namespace cbbg::control {
namespace {

using Eigen::MatrixXd;

std::string size_text(const MatrixXd& M) {
  return std::to_string(M.rows()) + "x" + std::to_string(M.cols());
}

std::string short_number(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3g", value);
  return text;
}

// Checks the coefficients of either equation (`what` names it in messages) and returns the
// Cholesky factor of R.
Eigen::LLT<MatrixXd> check_coefficients(const char* what, const MatrixXd& A, const MatrixXd& B,
                                        const MatrixXd& Q, const MatrixXd& R) {
  const Eigen::Index n = A.rows();
  const Eigen::Index m = B.cols();
  if (n == 0 || m == 0 || A.cols() != n || B.rows() != n || Q.rows() != n || Q.cols() != n ||
      R.rows() != m || R.cols() != m) {
    throw std::invalid_argument(std::string(what) +
                                ": A must be n x n, B n x m, Q n x n and R m x m with n, m >= 1; "
                                "got A " +
                                size_text(A) + ", B " + size_text(B) + ", Q " + size_text(Q) +
                                ", R " + size_text(R));
  }
  if (!A.allFinite() || !B.allFinite() || !Q.allFinite() || !R.allFinite()) {
    throw std::invalid_argument(std::string(what) + ": A, B, Q and R must be finite");
  }
  if (!Q.isApprox(Q.transpose())) {
    throw std::invalid_argument(std::string(what) + ": Q must be symmetric");
  }
  Eigen::LLT<MatrixXd> r_factor(R);
  if (!R.isApprox(R.transpose()) || r_factor.info() != Eigen::Success) {
    throw std::invalid_argument(std::string(what) + ": R must be symmetric positive definite");
  }
  return r_factor;
}

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

// Solves the Stein (discrete Lyapunov) equation X = F' X F + M (F Schur stable) through its
// Kronecker form, (I - F' (x) F') vec(X) = vec(M).
MatrixXd solve_stein(const MatrixXd& F, const MatrixXd& M) {
  const Eigen::Index n = F.rows();
  MatrixXd kronecker = MatrixXd::Identity(n * n, n * n);
  const MatrixXd Ft = F.transpose();
  for (Eigen::Index i = 0; i < n; ++i) {
    for (Eigen::Index j = 0; j < n; ++j) {
      kronecker.block(i * n, j * n, n, n) -= Ft(i, j) * Ft;  // the (i, j) block of F' (x) F'
    }
  }
  const Eigen::VectorXd rhs = Eigen::Map<const Eigen::VectorXd>(M.data(), n * n);
  const Eigen::VectorXd x = kronecker.fullPivLu().solve(rhs);
  MatrixXd X = Eigen::Map<const MatrixXd>(x.data(), n, n);
  return (X + X.transpose()) / 2.0;
}

bool is_stable(const MatrixXd& F) { return (F.eigenvalues().real().array() < 0.0).all(); }

double spectral_radius(const MatrixXd& F) { return F.eigenvalues().cwiseAbs().maxCoeff(); }

// The discrete regulator's gain (R + B' X B)^-1 B' X A.
MatrixXd discrete_gain(const MatrixXd& A, const MatrixXd& B, const MatrixXd& R, const MatrixXd& X) {
  return (R + B.transpose() * X * B).ldlt().solve(B.transpose() * X * A);
}

}  // namespace

MatrixXd continuous_riccati_residual(const MatrixXd& A, const MatrixXd& B, const MatrixXd& Q,
                                     const MatrixXd& R, const MatrixXd& X) {
  return A.transpose() * X + X * A - X * B * R.llt().solve(B.transpose()) * X + Q;
}

MatrixXd discrete_riccati_residual(const MatrixXd& A, const MatrixXd& B, const MatrixXd& Q,
                                   const MatrixXd& R, const MatrixXd& X) {
  const MatrixXd XA = X * A;
  return A.transpose() * XA - X -
         XA.transpose() * B * (R + B.transpose() * X * B).ldlt().solve(B.transpose() * XA) + Q;
}

MatrixXd solve_continuous_riccati(const MatrixXd& A, const MatrixXd& B, const MatrixXd& Q,
                                  const MatrixXd& R) {
  constexpr const char* kWhat = "continuous Riccati equation";
  const Eigen::LLT<MatrixXd> r_factor = check_coefficients(kWhat, A, B, Q, R);
  const Eigen::Index n = A.rows();
  const MatrixXd G = B * r_factor.solve(B.transpose());  // B R^-1 B'

  // The n eigenvectors of the Hamiltonian with Re(lambda) < 0 span [I; X] (up to a change
  // of basis): X = V2 V1^-1.
  MatrixXd hamiltonian(2 * n, 2 * n);
  hamiltonian << A, -G, -Q, -A.transpose();
  const Eigen::ComplexEigenSolver<MatrixXd> eigen(hamiltonian);
  if (eigen.info() != Eigen::Success) {
    throw std::invalid_argument(std::string(kWhat) +
                                ": the Hamiltonian's eigenvalues did not converge");
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
        std::string(kWhat) +
        ": no stabilising solution (the Hamiltonian has eigenvalues on the imaginary axis: "
        "(A, B) not stabilisable or (A, Q) not detectable)");
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
  const double residual = continuous_riccati_residual(A, B, Q, R, X).norm();
  const double scale = 1.0 + Q.norm() + (A.transpose() * X).norm() + (X * G * X).norm();
  if (!X.allFinite() || !is_stable(A - G * X) || residual > 1e-8 * scale) {
    throw std::invalid_argument(std::string(kWhat) + ": no stabilising solution found (residual " +
                                short_number(residual) +
                                "): (A, B) not stabilisable or (A, Q) not detectable");
  }
  return X;
}

MatrixXd solve_discrete_riccati(const MatrixXd& A, const MatrixXd& B, const MatrixXd& Q,
                                const MatrixXd& R) {
  constexpr const char* kWhat = "discrete Riccati equation";
  const Eigen::LLT<MatrixXd> r_factor = check_coefficients(kWhat, A, B, Q, R);
  const Eigen::Index n = A.rows();
  const MatrixXd identity = MatrixXd::Identity(n, n);

  // Structured doubling: with G = B R^-1 B', the equation reads X = A' X (I + G X)^-1 A + Q,
  // and the iteration
  //   W = I + G_k H_k,  A_k+1 = A_k W^-1 A_k,  G_k+1 = G_k + A_k W^-1 G_k A_k',
  //   H_k+1 = H_k + A_k' H_k W^-1 A_k,
  // from (A, G, Q) gives in H_k the Riccati recursion's value after 2^k steps: H_k -> X
  // quadratically when the symplectic pencil has no eigenvalue on the unit circle.
  MatrixXd Ak = A;
  MatrixXd Gk = B * r_factor.solve(B.transpose());
  MatrixXd X = Q;
  for (int iteration = 0; iteration < 64; ++iteration) {
    const Eigen::PartialPivLU<MatrixXd> w(identity + Gk * X);
    const MatrixXd w_a = w.solve(Ak);  // W^-1 A_k
    MatrixXd next_g = Gk + Ak * w.solve(Gk) * Ak.transpose();
    MatrixXd next_x = X + Ak.transpose() * X * w_a;
    Ak = Ak * w_a;
    Gk = (next_g + next_g.transpose()) / 2.0;
    next_x = (next_x + next_x.transpose()) / 2.0;
    const double change = (next_x - X).norm();
    X = next_x;
    if (!X.allFinite() || !Gk.allFinite() || !Ak.allFinite()) break;
    if (change <= 1e-15 * (1.0 + X.norm())) break;
  }

  // Newton–Hewer: with K = (R + B' X B)^-1 B' X A, the solution solves the Stein equation
  // X+ = (A - B K)' X+ (A - B K) + Q + K' R K at the fixed point. Where X is large and the
  // equation ill-conditioned the steps end in rounding noise, so the iterate with the
  // smallest residual is kept.
  const auto residual_of = [&](const MatrixXd& candidate) {
    return discrete_riccati_residual(A, B, Q, R, candidate).norm();
  };
  double residual = X.allFinite() ? residual_of(X) : 0.0;
  MatrixXd best = X;
  for (int iteration = 0, stalled = 0; iteration < 20 && X.allFinite() && stalled < 3;
       ++iteration) {
    const MatrixXd K = discrete_gain(A, B, R, X);
    const MatrixXd closed_loop = A - B * K;
    if (spectral_radius(closed_loop) >= 1.0) break;
    const MatrixXd next = solve_stein(closed_loop, Q + K.transpose() * R * K);
    if (!next.allFinite()) break;
    const double change = (next - X).norm();
    X = next;
    const double next_residual = residual_of(X);
    if (next_residual < residual) {
      best = X;
      residual = next_residual;
      stalled = 0;
    } else {
      ++stalled;
    }
    if (change <= 1e-14 * (1.0 + X.norm())) break;
  }
  X = best;
  if (!X.allFinite()) {
    throw std::invalid_argument(
        std::string(kWhat) +
        ": no stabilising solution (the doubling iteration diverged): (A, B) not stabilisable "
        "or (A, Q) not detectable");
  }
  // The residual is the difference of terms as large as |A|^2 |X|, so its rounding error is.
  const double a_norm = A.norm();
  const double scale = 1.0 + Q.norm() + X.norm() * (1.0 + a_norm * a_norm);
  const double radius = spectral_radius(A - B * discrete_gain(A, B, R, X));
  if (!(radius < 1.0) || residual > 1e-8 * scale) {
    throw std::invalid_argument(std::string(kWhat) + ": no stabilising solution found (residual " +
                                short_number(residual) + ", closed-loop spectral radius " +
                                short_number(radius) +
                                "): (A, B) not stabilisable or (A, Q) not detectable");
  }
  return X;
}

}  // namespace cbbg::control
