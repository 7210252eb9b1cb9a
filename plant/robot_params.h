#pragma once
// The two-wheeled robot's physical parameters (docs/model.md §1), one field per config key
// under `plant.` (docs/model.md §4), with the defaults of docs/model.md §1; body_roll_inertia and
// wheel_diametral_inertia are two keys this project adds (see below).

#include "cbbg/framework/parameters.h"

namespace cbbg::plant {

// The pitch a trial starts from by default (trial.theta0), rad.
inline constexpr double kDefaultInitialPitch = 0.1744;

// Config key plant.simbody_integrator: the error-controlled integrator that advances the
// Simbody plant between ticks.
enum class SimbodyIntegrator {
  kMerson,       // "merson": Runge-Kutta-Merson 4(5), the reference
  kRungeKutta3,  // "rk3": Runge-Kutta 3(2)
  kVerlet,       // "verlet": Simbody's error-controlled velocity Verlet
};

// Config key plant.simbody_model: how the Simbody plant enforces rolling without slip.
enum class SimbodyModel {
  kRollingBase,        // "rolling": in the base's mobilizer, no constraint (the fast one)
  kNoSlipConstraints,  // "constrained": wheels on their own joints, three NoSlip1D constraints
};

struct RobotParams {
  double wheel_mass = 1.0;             // m_l = m_r, kg
  double body_mass = 10.0;             // M, kg
  double wheel_radius = 0.15;          // R, m
  double track_width = 0.44;           // d, distance between the wheels, m
  double com_height = 0.4;             // L, axle midpoint to body centre of mass, m
  double wheel_inertia = 0.01125;      // J_w, wheel about its axle, kg m^2
  double body_pitch_inertia = 1.5417;  // J_y, body pitch about its centre of mass, kg m^2
  double body_yaw_inertia = 0.5893;    // J_z, body yaw about its centre of mass, kg m^2
  double gravity = 9.8;                // g, m/s^2
  double wheel_ground_friction = 0.1;  // mu_l = mu_r, viscous, N m / (rad/s)
  double axle_friction = 0.1;          // mu_w, wheel-axle viscous, N m / (rad/s)
  double torque_limit = 5.0;           // |tau_l|, |tau_r| saturate here, N m
  double accuracy = 1.0e-6;            // relative and absolute integrator tolerance
  SimbodyIntegrator simbody_integrator = SimbodyIntegrator::kMerson;
  SimbodyModel simbody_model = SimbodyModel::kRollingBase;

  // Two inertias the paper's equations leave out, which a rigid body cannot do without. The
  // paper's equations take the body's yaw inertia as J_z at every pitch, which needs a roll inertia
  // J_x = J_z; with J_y = 1.5417 > 2 J_z that breaks the triangle inequality every rigid
  // body obeys (J_y <= J_x + J_z), and Simbody rejects it. They also give the wheels no
  // inertia about a diameter. Both only act while the robot turns (yaw rate != 0), never in
  // the straight-line trials of the experiments. With body_roll_inertia = body_yaw_inertia
  // and wheel_diametral_inertia = 0 the inertia terms are the paper's (analytic plant only;
  // robot_dynamics.h lists the one other difference from the paper's equations).
  double body_roll_inertia = 1.5417;          // J_x, body roll about its centre of mass, kg m^2;
                                              // default J_y: a body symmetric about its long axis
  double wheel_diametral_inertia = 0.005625;  // I_d, wheel about a diameter, kg m^2; default
                                              // J_w / 2: a thin disc, as J_w = m R^2 / 2 is

  static constexpr const char* kSection = "plant";
  template <class Archive>
  void describe(Archive& a) {
    a.number("wheel_mass", wheel_mass, "m_l = m_r, kg", kPositive);
    a.number("body_mass", body_mass, "M, kg", kPositive);
    a.number("wheel_radius", wheel_radius, "R, m", kPositive);
    a.number("track_width", track_width, "d, distance between the wheels, m", kPositive);
    a.number("com_height", com_height, "L, axle midpoint to body centre of mass, m", kPositive);
    a.number("wheel_inertia", wheel_inertia, "J_w, wheel about its axle, kg m^2", kPositive);
    a.number("body_pitch_inertia", body_pitch_inertia,
             "J_y, body pitch about its centre of mass, kg m^2", kPositive);
    a.number("body_yaw_inertia", body_yaw_inertia, "J_z, body yaw inertia, kg m^2", kPositive);
    a.number("body_roll_inertia", body_roll_inertia,
             "J_x, body roll inertia, kg m^2 (matters only when turning)", kPositive);
    a.number("wheel_diametral_inertia", wheel_diametral_inertia,
             "wheel inertia about a diameter, kg m^2 (matters only when turning)", kNonNegative);
    a.number("gravity", gravity, "g, m/s^2", kNonNegative);
    a.number("wheel_ground_friction", wheel_ground_friction, "mu_l = mu_r, viscous, N m/(rad/s)",
             kNonNegative);
    a.number("axle_friction", axle_friction, "mu_w, wheel-axle viscous, N m/(rad/s)", kNonNegative);
    a.number("torque_limit", torque_limit, "motor torques saturate to +-this, N m", kPositive);
    a.number("accuracy", accuracy, "integrator error tolerance (relative and absolute)",
             interval(0.0, 1.0, kOpen, kOpen));
    a.choice("simbody_integrator", simbody_integrator,
             "merson (Runge-Kutta-Merson, the reference) | rk3 | verlet: the Simbody plant's",
             Choices<SimbodyIntegrator>{{"merson", SimbodyIntegrator::kMerson},
                                        {"rk3", SimbodyIntegrator::kRungeKutta3},
                                        {"verlet", SimbodyIntegrator::kVerlet}});
    a.choice("simbody_model", simbody_model,
             "rolling (no-slip built into the base's mobilizer) | constrained (three no-slip "
             "constraints, the reference): the Simbody plant's formulation",
             Choices<SimbodyModel>{{"rolling", SimbodyModel::kRollingBase},
                                   {"constrained", SimbodyModel::kNoSlipConstraints}});
  }
  // Throws std::invalid_argument naming the first offending key, e.g.
  // "plant.body_mass must be finite and > 0; got -1".
  void validate() const;
  // validate(), plus what a rigid-body (Simbody) model needs: each of the body's three
  // inertias at most the sum of the other two, and 2 I_d >= J_w for the wheel.
  void validate_rigid_bodies() const;
};

}  // namespace cbbg::plant
