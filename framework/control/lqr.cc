#include "cbbg/framework/control/lqr.h"

#include <Eigen/Cholesky>

#include "cbbg/framework/control/riccati.h"

namespace cbbg::control {

// K by an LDL' solve: with one input it is (B' S) / r, entry by entry, exactly.
LqrResult lqr(const Eigen::MatrixXd& A, const Eigen::MatrixXd& B, const Eigen::MatrixXd& Q,
              const Eigen::MatrixXd& R) {
  LqrResult result;
  result.S = solve_continuous_riccati(A, B, Q, R);
  result.K = R.ldlt().solve(B.transpose() * result.S);
  return result;
}

LqrResult discrete_lqr(const Eigen::MatrixXd& A, const Eigen::MatrixXd& B, const Eigen::MatrixXd& Q,
                       const Eigen::MatrixXd& R) {
  LqrResult result;
  result.S = solve_discrete_riccati(A, B, Q, R);
  const Eigen::MatrixXd BtS = B.transpose() * result.S;
  result.K = (R + BtS * B).ldlt().solve(BtS * A);
  return result;
}

}  // namespace cbbg::control
