#include "cbbg/blocks/lqr_supervisor.h"

#include <stdexcept>
#include <string>

#include "cbbg/blocks/measured_signals.h"
#include "cbbg/blocks/parameter_checks.h"
#include "cbbg/framework/block_context.h"
#include "cbbg/framework/control/lqr.h"
#include "cbbg/plant/linearization.h"

namespace cbbg::blocks {

void LqrSupervisorParams::validate() const { check_declared(*this, kSection); }

LqrSupervisor::LqrSupervisor(std::string name, const plant::RobotParams& robot,
                             const LqrSupervisorParams& params)
    : LqrSupervisor(std::move(name), plant::linearize_planar_upright(robot), params) {}

LqrSupervisor::LqrSupervisor(std::string name, const plant::LinearModel& model,
                             const LqrSupervisorParams& params)
    : Block(std::move(name)) {
  params.validate();
  if (model.A.rows() != 4 || model.A.cols() != 4 || model.B.rows() != 4 || model.B.cols() != 1) {
    throw std::invalid_argument(
        "block '" + this->name() +
        "': the plant's linearisation must have 4 states (theta_b, phi, "
        "theta_b', phi') and 1 input; it has A " +
        std::to_string(model.A.rows()) + "x" + std::to_string(model.A.cols()) + ", B " +
        std::to_string(model.B.rows()) + "x" + std::to_string(model.B.cols()));
  }
  const Eigen::Vector4d q(params.lqr_q[0], params.lqr_q[1], params.lqr_q[2], params.lqr_q[3]);
  const Eigen::MatrixXd Q = q.asDiagonal();
  const Eigen::MatrixXd R = Eigen::MatrixXd::Constant(1, 1, params.lqr_r);
  try {
    gain_ = control::lqr(model.A, model.B, Q, R).K.row(0);
  } catch (const std::invalid_argument& error) {
    throw std::invalid_argument(
        "supervisor.lqr_q = [" + format_number(q[0]) + ", " + format_number(q[1]) + ", " +
        format_number(q[2]) + ", " + format_number(q[3]) +
        "] with supervisor.lqr_r = " + format_number(params.lqr_r) +
        " give no stabilising LQR gain for this robot (a zero weight can leave a mode out of "
        "the cost): " +
        error.what());
  }

  measured_ = &declare_input_port("measured", kMeasuredSize, "measured signals");
  declare_output_port<&LqrSupervisor::calc_action>("action", 1, {measured_},
                                                   "a_S = -K x, the LQR torque");
}

void LqrSupervisor::calc_action(const BlockContext& context, VectorRef action) const {
  const auto y = context.input(*measured_);
  const Eigen::Vector4d x(y[kMeasuredThetaB], (y[kMeasuredPhiLeft] + y[kMeasuredPhiRight]) / 2.0,
                          y[kMeasuredThetaBDot],
                          (y[kMeasuredPhiLeftDot] + y[kMeasuredPhiRightDot]) / 2.0);
  action[0] = -gain_.dot(x);
}

codegen::CCalculation LqrSupervisor::c_calculation(int, const Context&) const {
  codegen::CCalculation c;
  c.constants = {{"gain", {gain_[0], gain_[1], gain_[2], gain_[3]}, true}};
  // x as the C++ forms it, then -K x summed in the order of Eigen's fixed-size dot.
  c.body =
      "  real x[4], kx;\n  x[0] = in0[0];\n  x[1] = (in0[2] + in0[3]) / (real)2;\n"
      "  x[2] = in0[1];\n  x[3] = (in0[4] + in0[5]) / (real)2;\n" +
      codegen::c_dot("kx", "$gain", "x", 4) + "  out[0] = -kx;\n";
  return c;
}

}  // namespace cbbg::blocks
