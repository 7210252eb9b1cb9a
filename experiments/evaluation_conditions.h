#pragma once
// The conditions a learnt policy (or a controller that learns nothing) is evaluated under:
// the training parameters with the evaluation.* perturbations applied, so an evaluation can ask
// how what was learnt copes with a robot it was not trained on.
//
//   evaluation.body_mass_scale   the two-wheeler's plant.body_mass and the body's three
//                                inertias times it (a denser body of the same shape); a
//                                user's plant kind says what it scales (plant_kinds.h)
//   evaluation.com_height_scale  plant.com_height times it (the load moved; the body's
//                                inertias about its own centre of mass kept), or the kind's
//   evaluation.noise_std         Gaussian noise of this std added, in quadrature, to
//                                sensors.noise_std's pitch and pitch rate
//   evaluation.push_torque,      when any is non-zero, push.* becomes this push (through
//   evaluation.push_force,       the motors; from outside, at the centre of mass; from
//   evaluation.push_pitch_torque outside, on the body) from evaluation.push_start for
//                                evaluation.push_duration
//
// At their defaults (1, 1, 0, 0, 0, 0) the evaluation parameters equal the training ones. A plant
// parameter read by a controller at build time (supervisor.kind = lqr designs its gains
// from plant.*) sees the perturbed value: the PD supervisor has fixed gains.

#include <string>

#include "cbbg/diagrams/closed_loop.h"
#include "cbbg/parameters/parameters.h"

namespace cbbg::experiments {

// `training` with its evaluation.* perturbations applied, the robot's through plant.kind's
// kind. Throws config::ConfigError naming the evaluation key when a scaled value is not a
// finite number > 0, or the kind has no parameter the key changes.
parameters::Parameters evaluation_parameters(const parameters::Parameters& training);

// Before any work: the robot and the push the evaluation.* keys make of `training` are valid
// (a scale of 1e308 makes an infinite mass). Throws config::ConfigError naming the evaluation
// key and the value it makes.
void check_evaluation_conditions(const parameters::Parameters& training);

// Whether `evaluation` changes the robot: a body mass or CoM height scale other than 1 (the
// noise and the push reach any plant, through the sensors and the wheels).
bool changes_robot(const parameters::EvaluationParams& evaluation);

// Throws config::ConfigError when `evaluation` changes the robot and `loop`'s plant is the
// arm's own (ClosedLoopOptions::plant), not plant.kind's, which applies the change.
void check_plant_takes_conditions(const parameters::EvaluationParams& evaluation,
                                  const diagrams::ClosedLoop& loop);

// Whether `evaluation` pushes from outside (evaluation.push_force, evaluation.push_pitch_torque),
// which needs a plant with the input "disturbance".
bool pushes_from_outside(const parameters::EvaluationParams& evaluation);

// Before any training: throws config::ConfigError naming the key when `training`'s evaluation
// pushes from outside and the plant the arm `loop` builds would have no input "disturbance".
void check_plant_takes_push(const parameters::Parameters& training,
                            const diagrams::ClosedLoopFactory& loop);

// The perturbations of `evaluation` in words ("body mass x1.3, pitch noise 0.02"), or "" at
// their defaults.
std::string describe_conditions(const parameters::EvaluationParams& evaluation);

}  // namespace cbbg::experiments
