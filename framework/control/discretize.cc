#include "cbbg/framework/control/discretize.h"

#include <cmath>
#include <stdexcept>
#include <string>

#include <unsupported/Eigen/MatrixFunctions>

#include "cbbg/framework/number_text.h"

namespace cbbg::control {
namespace {

std::string size_text(const Eigen::MatrixXd& M) {
  return std::to_string(M.rows()) + "x" + std::to_string(M.cols());
}

}  // namespace

StateSpace c2d(const StateSpace& continuous, double h) {
  if (!std::isfinite(h) || h <= 0.0) {
    throw std::invalid_argument("c2d: the period must be positive and finite; got " +
                                format_number(h));
  }
  if (continuous.time_period != 0.0) {
    throw std::invalid_argument("c2d: the system is already discrete (time_period " +
                                format_number(continuous.time_period) + ")");
  }
  const Eigen::MatrixXd& A = continuous.A;
  const Eigen::MatrixXd& B = continuous.B;
  const Eigen::Index n = A.rows();
  const Eigen::Index m = B.cols();
  const bool no_outputs = continuous.C.size() == 0 && continuous.D.size() == 0;
  const Eigen::Index p = no_outputs ? 0 : continuous.C.rows();
  if (A.cols() != n || B.rows() != n ||
      (!no_outputs &&
       (continuous.C.cols() != n || continuous.D.rows() != p || continuous.D.cols() != m))) {
    throw std::invalid_argument("c2d: A must be n x n, B n x m, C p x n and D p x m; got A " +
                                size_text(A) + ", B " + size_text(B) + ", C " +
                                size_text(continuous.C) + ", D " + size_text(continuous.D));
  }
  if (!A.allFinite() || !B.allFinite() || !continuous.C.allFinite() || !continuous.D.allFinite()) {
    throw std::invalid_argument("c2d: A, B, C and D must be finite");
  }

  Eigen::MatrixXd augmented = Eigen::MatrixXd::Zero(n + m, n + m);
  augmented.topLeftCorner(n, n) = A * h;
  augmented.topRightCorner(n, m) = B * h;
  // (Eigen's matrix exponential: scaling and squaring of a Padé approximant.)
  const Eigen::MatrixXd exponential = n == 0 ? augmented : Eigen::MatrixXd(augmented.exp());

  StateSpace discrete;
  discrete.A = exponential.topLeftCorner(n, n);
  discrete.B = exponential.topRightCorner(n, m);
  discrete.C = no_outputs ? Eigen::MatrixXd(0, n) : continuous.C;
  discrete.D = no_outputs ? Eigen::MatrixXd(0, m) : continuous.D;
  discrete.time_period = h;
  return discrete;
}

StateSpace c2d(const Eigen::MatrixXd& A, const Eigen::MatrixXd& B, double h) {
  return c2d(StateSpace{A, B, Eigen::MatrixXd(0, A.rows()), Eigen::MatrixXd(0, B.cols()), 0.0}, h);
}

}  // namespace cbbg::control
