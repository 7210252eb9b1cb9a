#include "cbbg/plant/plant_state.h"

#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>

#include "cbbg/framework/simulator.h"
#include "cbbg/plant/plant_ports.h"

#include "cbbg/framework/number_text.h"

namespace cbbg::plant {
namespace {

constexpr const char* kStateNames[kStateSize] = {
    "theta_b", "theta_b'", "phi_l", "phi_r", "phi_l'", "phi_r'", "x", "y", "yaw", "yaw rate"};

std::string list_state(const double* state, Eigen::Index size) {
  std::string values;
  for (Eigen::Index i = 0; i < kStateSize && i < size; ++i) {
    values += std::string(i == 0 ? "" : ", ") + kStateNames[i] + " = " + format_number(state[i]);
  }
  return values;
}

}  // namespace

void check_initial_pitch(double initial_pitch) {
  if (!std::isfinite(initial_pitch)) {
    throw std::invalid_argument("trial.theta0 must be finite; got " + format_number(initial_pitch));
  }
}

Vector initial_state_vector(double initial_pitch) {
  check_initial_pitch(initial_pitch);
  Vector state = Vector::Zero(kStateSize);
  state[kThetaB] = initial_pitch;
  return state;
}

void check_state_argument(const Block& plant, const Vector& state) {
  if (state.size() != kStateSize) {
    throw std::invalid_argument("block '" + plant.path() + "': set_state needs " +
                                std::to_string(kStateSize) + " values; got " +
                                std::to_string(state.size()));
  }
  if (!state.allFinite()) {
    throw std::invalid_argument("block '" + plant.path() +
                                "': set_state needs finite values; got " +
                                list_state(state.data(), state.size()));
  }
}

void check_torque_finite(const Block& plant, const Eigen::Ref<const Eigen::VectorXd>& torque) {
  if (torque.allFinite()) return;
  throw SimulationError("block '" + plant.path() + "': torque input is not finite (tau_l = " +
                        format_number(torque[kTauLeft]) +
                        ", tau_r = " + format_number(torque[kTauRight]) + ")");
}

void check_disturbance_finite(const Block& plant,
                              const Eigen::Ref<const Eigen::VectorXd>& disturbance) {
  if (disturbance.allFinite()) return;
  throw SimulationError("block '" + plant.path() + "': disturbance input is not finite (force = " +
                        format_number(disturbance[kPushForce]) +
                        ", pitch torque = " + format_number(disturbance[kPushPitchTorque]) + ")");
}

void check_state_finite(const Block& plant, const Eigen::Ref<const Eigen::VectorXd>& state,
                        double time) {
  if (state.allFinite()) return;
  throw SimulationError("block '" + plant.path() + "': state is not finite at t = " +
                        format_number(time) + " (" + list_state(state.data(), state.size()) + ")");
}

}  // namespace cbbg::plant
