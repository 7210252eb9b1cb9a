#include "cbbg/blocks/normaliser.h"

#include <algorithm>

#include "cbbg/blocks/measured_signals.h"
#include "cbbg/blocks/parameter_checks.h"
#include "cbbg/framework/block_context.h"

namespace cbbg::blocks {

void NormaliserParams::validate() const { check_declared(*this, kSection); }

int NormaliserParams::size() const {
  return 2 + (sees_wheel_angle() ? 1 : 0) + (sees_wheel_rate() ? 1 : 0);
}

Normaliser::Normaliser(std::string name, const NormaliserParams& params)
    : Block(std::move(name)), params_(params) {
  params_.validate();
  measured_ = &declare_input_port("measured", kMeasuredSize, "measured signals");
  declare_output_port<&Normaliser::calc_x>(
      "x", params_.size(), {measured_},
      "normalised (theta_b, theta_b'[, phi][, phi']), saturated to the grid");
}

void Normaliser::calc_x(const BlockContext& context, VectorRef x) const {
  const auto y = context.input(*measured_);
  const double limit = params_.saturation;
  x[0] = std::clamp(y[kMeasuredThetaB] / params_.scale_theta, -limit, limit);
  x[1] = std::clamp(y[kMeasuredThetaBDot] / params_.scale_dtheta, -limit, limit);
  int next = 2;
  if (params_.sees_wheel_angle()) {
    const double phi = (y[kMeasuredPhiLeft] + y[kMeasuredPhiRight]) / 2.0;
    x[next++] = std::clamp(phi / params_.scale_phi, -limit, limit);
  }
  if (params_.sees_wheel_rate()) {
    const double phi_dot = (y[kMeasuredPhiLeftDot] + y[kMeasuredPhiRightDot]) / 2.0;
    x[next] = std::clamp(phi_dot / params_.scale_dphi, -limit, limit);
  }
}

codegen::CCalculation Normaliser::c_calculation(int, const Context&) const {
  using codegen::c_number;
  codegen::CCalculation c;
  c.constants = {c_number("limit", params_.saturation),
                 c_number("scale_theta", params_.scale_theta),
                 c_number("scale_dtheta", params_.scale_dtheta)};
  // Each value saturated as std::clamp does, from the same quotient.
  const auto saturated = [](int index, const std::string& quotient) {
    return "  v = " + quotient + ";\n  out[" + std::to_string(index) +
           "] = " + codegen::c_clamp("v", "-$limit", "$limit") + ";\n";
  };
  c.body = "  real v;\n" + saturated(0, "in0[0] / $scale_theta") +
           saturated(1, "in0[1] / $scale_dtheta");
  int next = 2;
  if (params_.sees_wheel_angle()) {
    c.constants.push_back(c_number("scale_phi", params_.scale_phi));
    c.body += saturated(next++, "((in0[2] + in0[3]) / (real)2) / $scale_phi");
  }
  if (params_.sees_wheel_rate()) {
    c.constants.push_back(c_number("scale_dphi", params_.scale_dphi));
    c.body += saturated(next, "((in0[4] + in0[5]) / (real)2) / $scale_dphi");
  }
  return c;
}

FeatureLayout Normaliser::layout() const {
  FeatureLayout layout = declared_layout(params_);
  // The scale of an input it does not see gives the weights no meaning: left out.
  std::erase_if(layout, [this](const LayoutEntry& entry) {
    return (entry.key == "normaliser.scale_phi" && !params_.sees_wheel_angle()) ||
           (entry.key == "normaliser.scale_dphi" && !params_.sees_wheel_rate());
  });
  return layout;
}

}  // namespace cbbg::blocks
