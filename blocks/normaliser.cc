#include "cbbg/blocks/normaliser.h"

#include <algorithm>

#include "cbbg/blocks/measured_signals.h"
#include "cbbg/blocks/parameter_checks.h"
#include "cbbg/framework/block_context.h"

namespace cbbg::blocks {

void NormaliserParams::validate() const { check_declared(*this, kSection); }

Normaliser::Normaliser(std::string name, const NormaliserParams& params)
    : Block(std::move(name)), params_(params) {
  params_.validate();
  const InputPort& measured = declare_input_port("measured", kMeasuredSize, "measured signals");
  declare_output_port(
      "x", 2,
      [this, &measured](const BlockContext& context, VectorRef x) {
        const auto y = context.input(measured);
        const double limit = params_.saturation;
        x[0] = std::clamp(y[kMeasuredThetaB] / params_.scale_theta, -limit, limit);
        x[1] = std::clamp(y[kMeasuredThetaBDot] / params_.scale_dtheta, -limit, limit);
      },
      {&measured}, "normalised (theta_b, theta_b'), saturated to the grid");
}

FeatureLayout Normaliser::layout() const { return declared_layout(params_); }

}  // namespace cbbg::blocks
