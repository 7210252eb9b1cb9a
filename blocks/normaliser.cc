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
  const InputPort& measured = declare_input_port("measured", kMeasuredSize, "measured signals");
  declare_output_port(
      "x", params_.size(),
      [this, &measured](const BlockContext& context, VectorRef x) {
        const auto y = context.input(measured);
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
      },
      {&measured}, "normalised (theta_b, theta_b'[, phi][, phi']), saturated to the grid");
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
