#include "cbbg/framework/primitives/linear_system.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <utility>
#include <vector>

#include "cbbg/framework/block_context.h"
#include "cbbg/framework/number_text.h"
#include "cbbg/framework/primitives/argument_checks.h"

namespace cbbg {
namespace {

std::string shape(const Eigen::MatrixXd& matrix) {
  return std::to_string(matrix.rows()) + "x" + std::to_string(matrix.cols());
}

void check_finite_matrix(const std::string& label, const char* what,
                         const Eigen::MatrixXd& matrix) {
  for (Eigen::Index j = 0; j < matrix.cols(); ++j) {
    for (Eigen::Index i = 0; i < matrix.rows(); ++i) {
      if (!std::isfinite(matrix(i, j))) {
        throw std::invalid_argument(label + ": " + what + "(" + std::to_string(i) + ", " +
                                    std::to_string(j) + ") is " + format_number(matrix(i, j)) +
                                    "; every element must be finite");
      }
    }
  }
}

}  // namespace

void check_state_space(const std::string& label, const Eigen::MatrixXd& A, const Eigen::MatrixXd& B,
                       const Eigen::MatrixXd& C, const Eigen::MatrixXd& D,
                       const Vector& initial_state) {
  const auto n = A.rows();
  if (n < 1 || A.cols() != n) {
    throw std::invalid_argument(label + ": A is " + shape(A) +
                                "; it must be square, n x n with n >= 1");
  }
  const std::string a_is = " (A is " + shape(A) + ")";
  if (B.rows() != n) {
    throw std::invalid_argument(label + ": B is " + shape(B) +
                                "; it must have n = " + std::to_string(n) + " rows" + a_is);
  }
  if (B.cols() < 1) {
    throw std::invalid_argument(label + ": B is " + shape(B) +
                                "; it must have m >= 1 columns (the input size)");
  }
  if (C.cols() != n) {
    throw std::invalid_argument(label + ": C is " + shape(C) +
                                "; it must have n = " + std::to_string(n) + " columns" + a_is);
  }
  if (C.rows() < 1) {
    throw std::invalid_argument(label + ": C is " + shape(C) +
                                "; it must have p >= 1 rows (the output size)");
  }
  if (D.rows() != C.rows() || D.cols() != B.cols()) {
    throw std::invalid_argument(label + ": D is " + shape(D) +
                                "; it must be p x m = " + std::to_string(C.rows()) + "x" +
                                std::to_string(B.cols()) + " (C's rows by B's columns)");
  }
  if (initial_state.size() != n) {
    throw std::invalid_argument(label + ": the initial state has size " +
                                std::to_string(initial_state.size()) +
                                "; it must have size n = " + std::to_string(n) + a_is);
  }
  check_finite_matrix(label, "A", A);
  check_finite_matrix(label, "B", B);
  check_finite_matrix(label, "C", C);
  check_finite_matrix(label, "D", D);
  primitive_checks::check_finite(label, "initial state", initial_state);
}

LinearSystem::LinearSystem(std::string name, const Eigen::MatrixXd& A, const Eigen::MatrixXd& B,
                           const Eigen::MatrixXd& C, const Eigen::MatrixXd& D)
    : LinearSystem(std::move(name), A, B, C, D, Vector::Zero(std::max<Eigen::Index>(A.rows(), 0))) {
}

LinearSystem::LinearSystem(std::string name, const Eigen::MatrixXd& A, const Eigen::MatrixXd& B,
                           const Eigen::MatrixXd& C, const Eigen::MatrixXd& D,
                           const Vector& initial_state)
    : Block(std::move(name)), A_(A), B_(B), C_(C), D_(D), feedthrough_(false) {
  check_state_space(primitive_checks::label("LinearSystem", this->name()), A_, B_, C_, D_,
                    initial_state);
  feedthrough_ = (D_.array() != 0.0).any();
  u_ = &declare_input_port("u", static_cast<int>(B_.cols()), "the input");
  declare_continuous_state<&LinearSystem::calc_derivatives>(initial_state);
  std::vector<const InputPort*> reads;
  if (feedthrough_) reads.push_back(u_);
  declare_output_port<&LinearSystem::calc_y>("y", static_cast<int>(C_.rows()), std::move(reads),
                                             "C x + D u");
}

void LinearSystem::calc_derivatives(const BlockContext& context, VectorRef derivatives) const {
  derivatives.noalias() = A_ * context.continuous_state();
  derivatives.noalias() += B_ * context.input(*u_);
}

void LinearSystem::calc_y(const BlockContext& context, VectorRef y) const {
  y.noalias() = C_ * context.continuous_state();
  if (feedthrough_) y.noalias() += D_ * context.input(*u_);
}

}  // namespace cbbg
