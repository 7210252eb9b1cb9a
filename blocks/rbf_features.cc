#include "cbbg/blocks/rbf_features.h"

#include <cmath>
#include <stdexcept>

#include "cbbg/blocks/parameter_checks.h"
#include "cbbg/framework/block_context.h"

namespace cbbg::blocks {

void RbfParams::validate() const {
  check_declared(*this, kSection);
  if (centres.empty()) {
    throw std::invalid_argument("rbf.centres must list at least one centre; got none");
  }
  for (size_t i = 0; i < centres.size(); ++i) {
    const std::string key = "rbf.centres[" + std::to_string(i) + "]";
    if (i > 0 && centres[i] <= centres[i - 1]) {
      throw_invalid_parameter(
          key, "must be greater than the centre before it (" + format_number(centres[i - 1]) + ")",
          centres[i]);
    }
  }
}

RbfFeatures::RbfFeatures(std::string name, const RbfParams& params)
    : Block(std::move(name)), params_(params) {
  params_.validate();
  inverse_two_width_squared_ = 1.0 / (2.0 * params_.width * params_.width);
  const InputPort& x = declare_input_port("x", 2, "normalised (theta_b, theta_b')");
  declare_output_port(
      "features", num_features(),
      [this, &x](const BlockContext& context, VectorRef features) {
        const auto point = context.input(x);
        const int m = static_cast<int>(params_.centres.size());
        for (int i = 0; i < m; ++i) {
          const double d0 = point[0] - params_.centres[static_cast<size_t>(i)];
          for (int j = 0; j < m; ++j) {
            const double d1 = point[1] - params_.centres[static_cast<size_t>(j)];
            features[i * m + j] = std::exp(-(d0 * d0 + d1 * d1) * inverse_two_width_squared_);
          }
        }
      },
      {&x}, "Gaussian features on the centres x centres grid");
}

int RbfFeatures::num_features() const {
  const int m = static_cast<int>(params_.centres.size());
  return m * m;
}

FeatureLayout RbfFeatures::layout() const { return declared_layout(params_); }

std::string RbfFeatures::layout_note() const {
  return "Weight k belongs to the unit at (rbf.centres[k / m], rbf.centres[k % m]), m = " +
         std::to_string(params_.centres.size()) + ".";
}

}  // namespace cbbg::blocks
