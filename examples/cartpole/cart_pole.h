#pragma once
// A plant of the user's own: a pole on a cart, the cart driven through its wheels' torque, as
// a plant kind (plant.kind: cartpole) with its own parameters (cartpole.*). The motor turns
// the wheels against the pole, as the two-wheeler's turn them against its body.

#include <algorithm>
#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include <cbbg/config/declared_keys.h>
#include <cbbg/diagrams/plant_kinds.h>
#include <cbbg/framework/block_context.h>
#include <cbbg/plant/robot_plant.h>

namespace cartpole {

// cartpole.*: declared once, here; they become config keys like the built-in ones.
struct CartPoleParams {
  double cart_mass = 2.0;     // kg, wheels included
  double pole_mass = 1.0;     // kg, at the pole's tip
  double pole_length = 0.5;   // m, pivot to the mass
  double wheel_radius = 0.1;  // m
  double torque_limit = 5.0;  // N m per wheel (the motors saturate)
  double gravity = 9.81;      // m/s^2

  template <class Archive>
  void describe(Archive& a) {
    a.number("cart_mass", cart_mass, "cart mass with its wheels, kg", cbbg::kPositive);
    a.number("pole_mass", pole_mass, "mass at the pole's tip, kg", cbbg::kPositive);
    a.number("pole_length", pole_length, "pivot to the pole's mass, m", cbbg::kPositive);
    a.number("wheel_radius", wheel_radius, "wheel radius, m", cbbg::kPositive);
    a.number("torque_limit", torque_limit, "motor torque limit per wheel, N m", cbbg::kPositive);
    a.number("gravity", gravity, "gravitational acceleration, m/s^2", cbbg::kPositive);
  }
};

inline CartPoleParams cart_pole_params(const cbbg::parameters::Parameters& parameters) {
  return cbbg::config::read_section<CartPoleParams>(parameters.own, "cartpole");
}

/// CartPole: pole angle theta (> 0 leans forward), wheel angle phi (cart at x = R phi).
///
/// | port   | dir | size | meaning                                                  |
/// |--------|-----|------|----------------------------------------------------------|
/// | torque | in  | 2    | the wheels' motor torques, each clamped to the limit     |
/// | state  | out | 5    | pitch, pitch_rate, wheel, wheel_rate, x (no y, no yaw)   |
///
/// With tau their sum, F = tau / R on the cart and -tau on the pole:
///   (M + m) x'' + m l cos(theta) theta'' = F + m l sin(theta) theta'^2
///   m l cos(theta) x'' + m l^2 theta''   = m g l sin(theta) - tau
class CartPole final : public cbbg::plant::RobotPlant {
 public:
  CartPole(std::string name, const CartPoleParams& p) : RobotPlant(std::move(name)), p_(p) {
    torque_ = &declare_input_port("torque", 2);
    declare_continuous_state<&CartPole::calc_derivatives>(
        cbbg::Vector::Zero(4));  // theta, phi, theta', phi'
    declare_output_port<&CartPole::calc_state>("state", 5, {});
  }

  std::vector<std::string> signals() const override {
    return {"pitch", "pitch_rate", "wheel", "wheel_rate", "x"};
  }
  double wheel_radius() const override { return p_.wheel_radius; }
  // The replay draws a cart on its wheels and the pole from the cart's top.
  cbbg::plant::PlantDrawing drawing() const override {
    cbbg::plant::PlantDrawing drawing;
    drawing.wheel_radius = p_.wheel_radius;
    drawing.track_width = 0.3;
    drawing.cart_length = 0.4;
    drawing.cart_height = 0.12;
    drawing.body_length = p_.pole_length;
    drawing.body_thickness = 0.02;
    drawing.body_width = 0.02;
    drawing.com_height = p_.pole_length;  // the pole's mass sits at its tip
    return drawing;
  }

  void reset(cbbg::Context& context, double initial_pitch) const override {
    auto s = context.continuous_state(*this);
    s.setZero();
    s[0] = initial_pitch;
  }

 private:
  // The equations of motion above, each wheel's torque clamped to the limit.
  void calc_derivatives(const cbbg::BlockContext& context, cbbg::VectorRef d) const {
    const auto u = context.input(*torque_);
    const double tau = std::clamp(u[0], -p_.torque_limit, p_.torque_limit) +
                       std::clamp(u[1], -p_.torque_limit, p_.torque_limit);
    const auto s = context.continuous_state();
    const double sin = std::sin(s[0]), cos = std::cos(s[0]);
    const double ml = p_.pole_mass * p_.pole_length;
    const double cart = tau / p_.wheel_radius + ml * sin * s[2] * s[2];
    const double pole = ml * p_.gravity * sin - tau;
    const double det = (p_.cart_mass + p_.pole_mass) * ml * p_.pole_length - ml * ml * cos * cos;
    const double x_dd = (cart * ml * p_.pole_length - ml * cos * pole) / det;
    const double theta_dd = ((p_.cart_mass + p_.pole_mass) * pole - ml * cos * cart) / det;
    d << s[2], s[3], theta_dd, x_dd / p_.wheel_radius;
  }
  // "state": pitch, pitch_rate, wheel, wheel_rate, x from the continuous state.
  void calc_state(const cbbg::BlockContext& context, cbbg::VectorRef y) const {
    const auto s = context.continuous_state();
    y << s[0], s[2], s[1], s[3], p_.wheel_radius * s[1];
  }

  CartPoleParams p_;
  const cbbg::InputPort* torque_;
};

// Linearised upright at rest, both wheels driven alike: x = (theta, phi, theta', phi'), u the
// torque on each wheel (tau = 2u), what an LQR supervisor designs from.
inline cbbg::plant::LinearModel linearize(const CartPoleParams& p) {
  const double M = p.cart_mass, m = p.pole_mass, l = p.pole_length, R = p.wheel_radius;
  cbbg::plant::LinearModel model{Eigen::MatrixXd::Zero(4, 4), Eigen::MatrixXd::Zero(4, 1)};
  model.A(0, 2) = model.A(1, 3) = 1.0;
  model.A(2, 0) = (M + m) * p.gravity / (M * l);
  model.A(3, 0) = -m * p.gravity / (M * R);
  model.B(2, 0) = -2.0 * ((M + m) / (M * m * l * l) + 1.0 / (M * l * R));
  model.B(3, 0) = 2.0 * (1.0 / R + 1.0 / l) / (M * R);
  return model;
}

// plant.kind: cartpole. An evaluation's body mass scale reaches the pole's mass; the CoM
// height scale is refused (the example keeps the pole's length as its own key to sweep).
inline void register_cart_pole() {
  cbbg::config::register_section<CartPoleParams>("cartpole");
  cbbg::diagrams::register_plant_kind(
      {.name = "cartpole",
       .description = "a pole on a wheeled cart (cartpole.*)",
       .make = [](const std::string& name, const cbbg::parameters::Parameters& p)
           -> std::unique_ptr<cbbg::plant::RobotPlant> {
         return std::make_unique<CartPole>(name, cart_pole_params(p));
       },
       .change =
           [](cbbg::parameters::Parameters& p, cbbg::diagrams::RobotChange change, double factor) {
             if (change != cbbg::diagrams::RobotChange::kBodyMass) return false;
             std::get<double>(p.own.values.at("cartpole.pole_mass")) *= factor;
             return true;
           },
       .linearize =
           [](const cbbg::parameters::Parameters& p) { return linearize(cart_pole_params(p)); }});
}

}  // namespace cartpole
