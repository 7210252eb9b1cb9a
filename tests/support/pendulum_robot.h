#pragma once
// A plant of the user's for the tests of every place a plant fits: the pitch as a linear
// inverted pendulum and one wheel angle for both wheels, theta'' = 24.5 theta - (tau_l +
// tau_r) / 2, phi'' = tau_l + tau_r; its own signals, in its own order: one wheel, no pose.
// Made with DisturbanceInput::kDeclared it takes a push from outside as the robots do: its
// input "disturbance" (force, pitch torque) adds the pitch torque to theta'' (the force it
// ignores). log() names the signals it logs into steps.csv.

#include <string>
#include <vector>

#include "cbbg/framework/block_context.h"
#include "cbbg/framework/context.h"
#include "cbbg/plant/plant_ports.h"
#include "cbbg/plant/robot_plant.h"

namespace cbbg::testing {

class PendulumRobot final : public plant::RobotPlant {
 public:
  explicit PendulumRobot(std::string name,
                         plant::DisturbanceInput disturbance = plant::DisturbanceInput::kNone)
      : RobotPlant(std::move(name)) {
    const InputPort& torque = declare_input_port("torque", plant::kTorqueSize);
    const InputPort* pushed = disturbance == plant::DisturbanceInput::kDeclared
                                  ? &declare_input_port("disturbance", plant::kDisturbanceSize)
                                  : nullptr;
    declare_continuous_state(Vector::Zero(4), [&torque, pushed](const BlockContext& context,
                                                                VectorRef d) {
      const auto x = context.continuous_state();  // theta, theta', phi, phi'
      const double tau = context.input(torque).sum();
      const double push = pushed == nullptr ? 0.0 : context.input(*pushed)[plant::kPushPitchTorque];
      d << x[1], 24.5 * x[0] - tau / 2.0 + push, x[3], tau;
    });
    declare_output_port("state", 4,
                        [](const BlockContext& context, VectorRef y) {
                          const auto x = context.continuous_state();
                          y << x[2], x[0], x[3], x[1];
                        },
                        {});
  }
  std::vector<std::string> signals() const override {
    return {"wheel", "pitch", "wheel_rate", "pitch_rate"};
  }
  std::vector<std::string> logged_signals() const override { return logged_; }
  void log(std::vector<std::string> names) { logged_ = std::move(names); }
  void reset(Context& context, double initial_pitch) const override {
    auto x = context.continuous_state(*this);
    x.setZero();
    x[0] = initial_pitch;
  }

 private:
  std::vector<std::string> logged_;
};

}  // namespace cbbg::testing
