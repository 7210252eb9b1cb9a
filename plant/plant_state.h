#pragma once
// What both plants share about their state vector (layout in plant_ports.h): the trial's
// initial state and the checks that keep a non-finite number from silently propagating.

#include "cbbg/framework/block.h"
#include "cbbg/framework/types.h"

namespace cbbg::plant {

// theta_b = initial_pitch (trial.theta0), everything else zero. A non-finite pitch throws
// std::invalid_argument naming trial.theta0.
// Throws naming trial.theta0 unless the initial pitch is finite.
void check_initial_pitch(double initial_pitch);
Vector initial_state_vector(double initial_pitch);

// For set_state: 10 finite values, else std::invalid_argument naming the block.
void check_state_argument(const Block& plant, const Vector& state);

// During a simulation, cbbg::SimulationError naming the block:
// "block 'robot/plant': torque input is not finite (tau_l = nan, tau_r = 0)".
void check_torque_finite(const Block& plant, const Eigen::Ref<const Eigen::VectorXd>& torque);
// "block 'robot/plant': disturbance input is not finite (force = nan, pitch torque = 0)".
void check_disturbance_finite(const Block& plant,
                              const Eigen::Ref<const Eigen::VectorXd>& disturbance);
// "block 'robot/plant': state is not finite at t = 1.25 (theta_b = inf, theta_b' = 0, ...)".
void check_state_finite(const Block& plant, const Eigen::Ref<const Eigen::VectorXd>& state,
                        double time);

}  // namespace cbbg::plant
