#include "cbbg/framework/primitives/gain.h"

#include <cmath>
#include <stdexcept>
#include <string>

#include "cbbg/framework/block_context.h"
#include "cbbg/framework/number_text.h"
#include "cbbg/framework/primitives/argument_checks.h"

namespace cbbg {

Gain::Gain(std::string name, double gain, int size) : Block(std::move(name)), gain_(gain) {
  u_ = &declare_input_port("u", size);
  declare_output_port<&Gain::calc_y_scalar>("y", size, {u_}, "k u", OutputSources::kDiscreteState);
}

Gain::Gain(std::string name, Eigen::MatrixXd matrix)
    : Block(std::move(name)), matrix_(std::move(matrix)) {
  const std::string label = primitive_checks::label("Gain", this->name());
  if (matrix_.rows() < 1 || matrix_.cols() < 1) {
    throw std::invalid_argument(label + ": matrix is " + std::to_string(matrix_.rows()) + "x" +
                                std::to_string(matrix_.cols()) +
                                "; it needs at least one row and one column");
  }
  for (Eigen::Index j = 0; j < matrix_.cols(); ++j) {
    for (Eigen::Index i = 0; i < matrix_.rows(); ++i) {
      if (!std::isfinite(matrix_(i, j))) {
        throw std::invalid_argument(label + ": matrix element (" + std::to_string(i) + ", " +
                                    std::to_string(j) + ") is " + format_number(matrix_(i, j)) +
                                    "; every element must be finite");
      }
    }
  }
  u_ = &declare_input_port("u", static_cast<int>(matrix_.cols()));
  declare_output_port<&Gain::calc_y_matrix>("y", static_cast<int>(matrix_.rows()), {u_}, "K u",
                                            OutputSources::kDiscreteState);
}

void Gain::calc_y_scalar(const BlockContext& context, VectorRef y) const {
  y = gain_ * context.input(*u_);
}

void Gain::calc_y_matrix(const BlockContext& context, VectorRef y) const {
  y.noalias() = matrix_ * context.input(*u_);
}

}  // namespace cbbg
