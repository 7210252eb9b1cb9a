#pragma once
// mujoco.*: the MuJoCo plant's section (plant.kind: mujoco). A model file (MJCF or URDF) says
// the robot; these keys say what the file cannot: which of its elements the loop reads and
// drives, and how the run integrates it. No MuJoCo header here: the section is known to every
// build, with or without MuJoCo.

#include <string>
#include <vector>

#include "cbbg/framework/parameters.h"

namespace cbbg::plant {

// mujoco.integrator: MuJoCo's, or the model file's own.
enum class MujocoIntegrator { kModel, kEuler, kRungeKutta4, kImplicit };

struct MujocoParams {
  // The model file; empty: the paper's two-wheeler, written from plant.* (two_wheeler_mjcf.h).
  std::string model{};
  double timestep = 0.0;  // s; 0: the model file's own
  MujocoIntegrator integrator = MujocoIntegrator::kModel;
  // The actuators the torque input drives: two take tau_l and tau_r, one takes their sum. A
  // hinge or slide joint may stand for an actuator (a URDF file has none): it takes the torque
  // between its body and the parent.
  std::vector<std::string> actuators{"left_motor", "right_motor"};
  // The 1-dof joint a trial starts at trial.theta0 (every other joint at the model's qpos0).
  std::string pitch_joint = "pitch";
  // The body pushes act on (at its centre of mass) and evaluation's body changes change.
  std::string body = "body";
  double wheel_radius = 0.0;  // m, for the trials' forward speed; 0: not stated
  // What evaluation.body_mass_scale and evaluation.com_height_scale set on a model file: the
  // body's mass and inertia, and its centre of mass's offset from the body's frame, times these.
  double body_mass_scale = 1.0;
  double com_height_scale = 1.0;

  template <class Archive>
  void describe(Archive& a) {
    a.file("model", model,
           "an MJCF or URDF file; empty: the two-wheeler of plant.* (MJCF written by the plant)");
    a.number("timestep", timestep, "MuJoCo's step, s; 0: the model's (the two-wheeler's: 0.005)",
             interval(0.0, 0.01));
    a.choice("integrator", integrator, "model (the file's own) | euler | rk4 | implicit",
             Choices<MujocoIntegrator>{{"model", MujocoIntegrator::kModel},
                                       {"euler", MujocoIntegrator::kEuler},
                                       {"rk4", MujocoIntegrator::kRungeKutta4},
                                       {"implicit", MujocoIntegrator::kImplicit}});
    a.names("actuators", actuators,
            "the model's actuators (or 1-dof joints) the wheel torques drive: two (tau_l, tau_r) "
            "or one (their sum)",
            {});
    a.text("pitch_joint", pitch_joint, "the model's 1-dof joint set to trial.theta0 at a reset",
           {});
    a.text("body", body, "the model's body that push.* pushes and evaluation.* changes", {});
    a.number("wheel_radius", wheel_radius, "m, turns wheel angles into distance; 0: not stated",
             kNonNegative);
    a.number("body_mass_scale", body_mass_scale,
             "the body's mass and inertias times this (set by evaluation.body_mass_scale)",
             kPositive);
    a.number("com_height_scale", com_height_scale,
             "the body's centre-of-mass offset times this (set by evaluation.com_height_scale)",
             kPositive);
  }
};

}  // namespace cbbg::plant
