#include "cbbg/plant/analytic_plant.h"

#include <cmath>
#include <optional>
#include <stdexcept>

#include "cbbg/framework/block_context.h"
#include "cbbg/plant/plant_ports.h"
#include "cbbg/plant/plant_state.h"
#include "cbbg/plant/robot_dynamics.h"

namespace cbbg::plant {
namespace {

// Layout of the continuous state.
enum ContinuousIndex : int {
  kQ = 0,     // theta_b, phi_l, phi_r
  kQDot = 3,  // their rates
  kPose = 6,  // x, y, yaw
  kContinuousSize = 9
};

using Output = Eigen::Matrix<double, kStateSize, 1>;

// x: the continuous state, a view of any size type.
template <typename State>
Output to_output(const RobotParams& params, const State& x) {
  Output y;
  y[kThetaB] = x[kQ];
  y[kThetaBDot] = x[kQDot];
  y[kPhiLeft] = x[kQ + 1];
  y[kPhiRight] = x[kQ + 2];
  y[kPhiLeftDot] = x[kQDot + 1];
  y[kPhiRightDot] = x[kQDot + 2];
  y[kX] = x[kPose];
  y[kY] = x[kPose + 1];
  y[kYaw] = x[kPose + 2];
  y[kYawRate] = yaw_rate(params, x[kQDot + 1], x[kQDot + 2]);
  return y;
}

Vector to_continuous(const Vector& y) {
  Vector x(kContinuousSize);
  x << y[kThetaB], y[kPhiLeft], y[kPhiRight], y[kThetaBDot], y[kPhiLeftDot], y[kPhiRightDot], y[kX],
      y[kY], y[kYaw];
  return x;
}

}  // namespace

// The generalised forces of the input "disturbance" (zero when the plant has none or it is zero).
std::optional<Coordinates> external_forces(const RobotPlant& plant, const RobotParams& params,
                                           const BlockContext& context,
                                           const InputPort* disturbance, double theta_b) {
  if (disturbance == nullptr) return std::nullopt;
  const ConstVectorView d = context.input(*disturbance);
  if (d[kPushForce] == 0.0 && d[kPushPitchTorque] == 0.0) return std::nullopt;
  check_disturbance_finite(plant, d);
  return disturbance_forces(params, theta_b, d[kPushForce], d[kPushPitchTorque]);
}

AnalyticPlant::AnalyticPlant(std::string name, const RobotParams& params, double initial_pitch,
                             DisturbanceInput disturbance)
    : RobotPlant(std::move(name)), params_(params) {
  params_.validate();
  torque_ = &declare_input_port("torque", kTorqueSize,
                                "tau_l, tau_r: motor torques body -> wheel, N m (saturated here)");
  disturbance_ = declare_disturbance_input(disturbance);
  declare_output_port<&AnalyticPlant::calc_state>(
      "state", kStateSize, {},
      "theta_b, theta_b', phi_l, phi_r, phi_l', phi_r', x, y, yaw, yaw rate");
  declare_continuous_state<&AnalyticPlant::calc_derivatives>(
      to_continuous(initial_state_vector(initial_pitch)));
}

void AnalyticPlant::calc_state(const BlockContext& context, VectorRef y) const {
  y = to_output(params_, context.continuous_state<kContinuousSize>());
}

void AnalyticPlant::calc_derivatives(const BlockContext& context, VectorRef x_dot) const {
  // Fixed-size views: Eigen unrolls the reads and the finiteness test below.
  const auto tau = context.input<kTorqueSize>(*torque_);
  // One inline test at every stage; the call that names the culprit only when it fails
  // (a sum of finite torques is finite unless they are huge, which the call then clears).
  if (!std::isfinite(tau[kTauLeft] + tau[kTauRight])) check_torque_finite(*this, tau);
  const auto x = context.continuous_state<kContinuousSize>();
  if (!x.allFinite()) {
    const Output y = to_output(params_, x);
    check_state_finite(*this, ConstVectorView(y.data(), kStateSize), context.time());
  }
  const Coordinates q = x.segment<3>(kQ);
  const Coordinates q_dot = x.segment<3>(kQDot);
  const Torques applied =
      saturate_torque(Torques(tau[kTauLeft], tau[kTauRight]), params_.torque_limit);
  const double v = forward_speed(params_, q_dot[1], q_dot[2]);
  const double yaw = x[kPose + 2];
  x_dot.segment<3>(kQ) = q_dot;
  const std::optional<Coordinates> external =
      external_forces(*this, params_, context, disturbance_, q[0]);
  x_dot.segment<3>(kQDot) = external ? accelerations(params_, q, q_dot, applied, *external)
                                     : accelerations(params_, q, q_dot, applied);
  x_dot[kPose] = v * std::cos(yaw);
  x_dot[kPose + 1] = v * std::sin(yaw);
  x_dot[kPose + 2] = yaw_rate(params_, q_dot[1], q_dot[2]);
}

void AnalyticPlant::reset(Context& context, double initial_pitch) const {
  check_initial_pitch(initial_pitch);
  // Written in place: a reset between trials allocates nothing.
  VectorView x = context.continuous_state(*this);
  x.setZero();
  x[kQ] = initial_pitch;  // theta_b leads the coordinates
}

void AnalyticPlant::set_state(Context& context, const Vector& state) const {
  check_state_argument(*this, state);
  context.continuous_state(*this) = to_continuous(state);
}

}  // namespace cbbg::plant
