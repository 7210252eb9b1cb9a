#include "cbbg/blocks/rbf_features.h"

#include <array>
#include <cmath>
#include <sstream>
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

RbfFeatures::RbfFeatures(std::string name, const RbfParams& params, int dimensions)
    : Block(std::move(name)), params_(params), dimensions_(dimensions) {
  params_.validate();
  if (dimensions < 1 || dimensions > kMaxDimensions) {
    throw std::invalid_argument(
        "RbfFeatures '" + this->name() + "': dimensions must be from 1 to " +
        std::to_string(kMaxDimensions) + "; got " + std::to_string(dimensions));
  }
  inverse_two_width_squared_ = 1.0 / (2.0 * params_.width * params_.width);
  x_ = &declare_input_port("x", dimensions, "normalised inputs, grid units");
  declare_output_port<&RbfFeatures::calc_features>(
      "features", num_features(), {x_}, "Gaussian features on the grid of centres per axis");
}

void RbfFeatures::calc_features(const BlockContext& context, VectorRef features) const {
  const auto point = context.input(*x_);
  if (params_.units == RbfUnits::kPerAxis) {
    per_axis_features(point, features);
    return;
  }
  if (dimensions_ != 2) {
    grid_features(point, features);
    return;
  }
  const int m = static_cast<int>(params_.centres.size());
  for (int i = 0; i < m; ++i) {
    const double d0 = point[0] - params_.centres[static_cast<size_t>(i)];
    for (int j = 0; j < m; ++j) {
      const double d1 = point[1] - params_.centres[static_cast<size_t>(j)];
      features[i * m + j] = std::exp(-(d0 * d0 + d1 * d1) * inverse_two_width_squared_);
    }
  }
}

void RbfFeatures::grid_features(const ConstVectorView& point, VectorRef features) const {
  const std::vector<double>& c = params_.centres;
  const int m = static_cast<int>(c.size());
  const int d = dimensions_;
  std::array<int, kMaxDimensions> digit{};
  // partial[a]: the squared distance over the axes up to a, for the current digits.
  std::array<double, kMaxDimensions> partial{};
  auto refresh_from = [&](int axis) {
    for (int a = axis; a < d; ++a) {
      const double delta = point[a] - c[static_cast<size_t>(digit[static_cast<size_t>(a)])];
      partial[static_cast<size_t>(a)] =
          (a == 0 ? 0.0 : partial[static_cast<size_t>(a - 1)]) + delta * delta;
    }
  };
  refresh_from(0);
  const int units = num_features();
  for (int k = 0; k < units; ++k) {
    features[k] = std::exp(-partial[static_cast<size_t>(d - 1)] * inverse_two_width_squared_);
    int axis = d - 1;  // the last axis turns fastest; a full turn carries to the one before
    while (axis >= 0 && ++digit[static_cast<size_t>(axis)] == m) {
      digit[static_cast<size_t>(axis)] = 0;
      --axis;
    }
    if (axis >= 0) refresh_from(axis);
  }
}

void RbfFeatures::per_axis_features(const ConstVectorView& point, VectorRef features) const {
  const int m = static_cast<int>(params_.centres.size());
  for (int a = 0; a < dimensions_; ++a) {
    for (int i = 0; i < m; ++i) {
      const double delta = point[a] - params_.centres[static_cast<size_t>(i)];
      features[a * m + i] = std::exp(-delta * delta * inverse_two_width_squared_);
    }
  }
}

codegen::CCalculation RbfFeatures::c_calculation(int, const Context&) const {
  codegen::CCalculation c;
  c.constants = {{"centres", params_.centres, true},
                 codegen::c_number("inverse_two_width_squared", inverse_two_width_squared_)};
  if (params_.units == RbfUnits::kPerAxis) {
    c.body = per_axis_c_body();
    return c;
  }
  const std::size_t m = params_.centres.size();
  // One loop per axis, the first the outermost: the unit index runs as k = sum k_a m^(d-1-a).
  // Each axis adds its squared distance to the sum of the axes before it, as the C++ does.
  std::ostringstream body;
  body << "  int k = 0;\n";
  for (int a = 0; a < dimensions_; ++a) {
    const std::string indent(static_cast<std::size_t>(2 * a + 2), ' ');
    body << indent << "for (int i" << a << " = 0; i" << a << " < " << m << "; ++i" << a << ") {\n";
    body << indent << "  const real d" << a << " = in0[" << a << "] - $centres[i" << a << "];\n";
    body << indent << "  const real p" << a << " = ";
    if (a > 0) body << "p" << a - 1 << " + ";
    body << "d" << a << " * d" << a << ";\n";
  }
  body << std::string(static_cast<std::size_t>(2 * dimensions_ + 2), ' ')
       << "out[k++] = CBBG_EXP(-p" << dimensions_ - 1 << " * $inverse_two_width_squared);\n";
  for (int a = dimensions_ - 1; a >= 0; --a) {
    body << std::string(static_cast<std::size_t>(2 * a + 2), ' ') << "}\n";
  }
  c.body = body.str();
  return c;
}

// The same products in the same order as per_axis_features.
std::string RbfFeatures::per_axis_c_body() const {
  const std::size_t m = params_.centres.size();
  std::ostringstream body;
  body << "  for (int a = 0; a < " << dimensions_ << "; ++a) {\n"
       << "    for (int i = 0; i < " << m << "; ++i) {\n"
       << "      const real delta = in0[a] - $centres[i];\n"
       << "      out[a * " << m
       << " + i] = CBBG_EXP(-delta * delta * $inverse_two_width_squared);\n"
       << "    }\n"
       << "  }\n";
  return body.str();
}

int RbfFeatures::num_features() const {
  const int m = static_cast<int>(params_.centres.size());
  if (params_.units == RbfUnits::kPerAxis) return dimensions_ * m;
  int units = 1;
  for (int a = 0; a < dimensions_; ++a) units *= m;
  return units;
}

FeatureLayout RbfFeatures::layout() const {
  FeatureLayout layout = declared_layout(params_);
  // A word is no layout entry: per_axis says itself, and the grid's layout stays as it was.
  if (params_.units == RbfUnits::kPerAxis) layout.push_back({"rbf.per_axis", {1.0}});
  return layout;
}

std::string RbfFeatures::layout_note() const {
  if (params_.units == RbfUnits::kPerAxis) {
    return "Weight k belongs to the unit at rbf.centres[k % m] on axis k / m alone (of " +
           std::to_string(dimensions_) + "), m = " + std::to_string(params_.centres.size()) + ".";
  }
  if (dimensions_ != 2) {
    return "Weight k belongs to the unit whose digits in base m = " +
           std::to_string(params_.centres.size()) + " index rbf.centres on each of the " +
           std::to_string(dimensions_) + " axes, the first axis the most significant.";
  }
  return "Weight k belongs to the unit at (rbf.centres[k / m], rbf.centres[k % m]), m = " +
         std::to_string(params_.centres.size()) + ".";
}

}  // namespace cbbg::blocks
