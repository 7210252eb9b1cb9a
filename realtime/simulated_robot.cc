#include "cbbg/realtime/simulated_robot.h"

#include <stdexcept>

#include "cbbg/framework/diagram_builder.h"

namespace cbbg::realtime {

SimulatedRobot::SimulatedRobot(std::shared_ptr<plant::RobotPlant> plant, double period,
                               double accuracy)
    : period_(period) {
  names_ = plant->signals();
  if (names_ != plant::two_wheeler_signals()) {
    throw std::invalid_argument("the plant '" + plant->name() +
                                "' does not measure the two-wheeler's signals, which the wire "
                                "carries (docs/realtime.md)");
  }
  DiagramBuilder builder("robot");
  plant_ = &builder.add(std::move(plant));
  builder.export_input(plant_->torque_input());
  builder.export_output(plant_->state_output());
  if (const InputPort* pushed = plant_->disturbance_input()) builder.export_input(*pushed);
  diagram_ = builder.build();
  auto context = diagram_->create_context();
  for (int input = 1; input < diagram_->num_input_ports(); ++input) {
    context->fix_input(diagram_->input_port(input),
                       Vector::Zero(diagram_->input_port(input).size()));
  }
  simulator_ = std::make_unique<Simulator>(*diagram_, std::move(context),
                                           SimulatorOptions{.accuracy = accuracy});
}

void SimulatedRobot::reset(double theta0) {
  Context& context = simulator_->context();
  context.reset_trial_state();
  plant_->reset(context, theta0);
  context.set_time(0.0);
  context.fix_input(diagram_->input_port(0), Vector::Zero(plant::kTorqueSize));
  simulator_->initialize();
  ticks_ = 0;
}

void SimulatedRobot::step(double tau_left, double tau_right) {
  Vector torque(plant::kTorqueSize);
  torque << tau_left, tau_right;
  simulator_->context().fix_input(diagram_->input_port(0), torque);
  ++ticks_;
  // The instant as the closed loop's clock counts it, k periods: no drift from summing.
  simulator_->advance_to(static_cast<double>(ticks_) * period_);
}

std::vector<double> SimulatedRobot::signals() const {
  const Vector y = diagram_->eval_output(simulator_->context(), plant_->state_output());
  return {y.data(), y.data() + y.size()};
}

}  // namespace cbbg::realtime
