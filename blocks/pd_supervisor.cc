#include "cbbg/blocks/pd_supervisor.h"

#include "cbbg/blocks/measured_signals.h"
#include "cbbg/blocks/parameter_checks.h"
#include "cbbg/framework/block_context.h"

namespace cbbg::blocks {

void PdSupervisorParams::validate() const { check_declared(*this, kSection); }

PdSupervisor::PdSupervisor(std::string name, const PdSupervisorParams& params)
    : Block(std::move(name)), params_(params) {
  params_.validate();
  measured_ = &declare_input_port("measured", kMeasuredSize, "measured signals");
  declare_output_port<&PdSupervisor::calc_action>("action", 1, {measured_},
                                                  "a_S, the supervisor's torque");
}

void PdSupervisor::calc_action(const BlockContext& context, VectorRef action) const {
  const auto y = context.input(*measured_);
  action[0] = params_.k_theta * y[kMeasuredThetaB] + params_.k_dtheta * y[kMeasuredThetaBDot] +
              params_.k_phi * (y[kMeasuredPhiLeft] + y[kMeasuredPhiRight]) / 2.0 +
              params_.k_dphi * (y[kMeasuredPhiLeftDot] + y[kMeasuredPhiRightDot]) / 2.0;
}

codegen::CCalculation PdSupervisor::c_calculation(int, const Context&) const {
  using codegen::c_number;
  codegen::CCalculation c;
  c.constants = {c_number("k_theta", params_.k_theta), c_number("k_dtheta", params_.k_dtheta),
                 c_number("k_phi", params_.k_phi), c_number("k_dphi", params_.k_dphi)};
  c.body =
      "  out[0] = $k_theta * in0[0] + $k_dtheta * in0[1] + $k_phi * (in0[2] + in0[3]) / "
      "(real)2 +\n           $k_dphi * (in0[4] + in0[5]) / (real)2;\n";
  return c;
}

}  // namespace cbbg::blocks
