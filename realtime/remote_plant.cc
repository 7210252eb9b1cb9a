#include "cbbg/realtime/remote_plant.h"

#include <cmath>
#include <string>

#include "cbbg/framework/number_text.h"
#include "cbbg/framework/simulator.h"
#include "cbbg/plant/plant_state.h"

namespace cbbg::realtime {

RemotePlant::RemotePlant(std::string name, LinkOptions link, const plant::RobotParams& robot)
    : RobotPlant(std::move(name)),
      link_(std::make_unique<RobotLink>(std::move(link))),
      robot_(robot) {
  const int size = static_cast<int>(link_->options().signals.size());
  torque_ =
      &declare_input_port("torque", plant::kTorqueSize, "tau_l, tau_r: sent to the robot, N m");
  declare_output_port<&RemotePlant::calc_state>("state", size, {}, "the robot's last measurement");
  declare_self_integrated_state<&RemotePlant::advance>(Vector::Zero(size));
}

void RemotePlant::calc_state(const BlockContext& context, VectorRef y) const {
  y = context.continuous_state();
}

void RemotePlant::advance(BlockContext& context, double end_time) const {
  const double start = context.time();
  const double period = link_->options().period;
  if (std::abs(end_time - start - period) > 1e-9 * std::max(1.0, std::abs(end_time))) {
    throw SimulationError("block '" + path() + "': a robot steps whole periods of " +
                          format_number(period) +
                          " s; an event splits the one from t = " + format_number(start) +
                          " (push.start and push.duration must be " + "multiples of trial.period)");
  }
  const ConstVectorView tau = context.input(*torque_);
  if (!tau.allFinite()) {
    link_->stop("the controller's torque is not finite");
    plant::check_torque_finite(*this, tau);  // throws, naming the block
  }
  const std::vector<double>& measured =
      link_->exchange(tau[plant::kTauLeft], tau[plant::kTauRight]);
  context.mutable_continuous_state() = Eigen::Map<const Vector>(measured.data(), measured.size());
}

void RemotePlant::reset(Context& context, double initial_pitch) const {
  const std::vector<double>& measured = link_->start_trial(initial_pitch);
  context.continuous_state(*this) = Eigen::Map<const Vector>(measured.data(), measured.size());
}

}  // namespace cbbg::realtime
