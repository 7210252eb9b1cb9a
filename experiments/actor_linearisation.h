#pragma once
// What a learnt actor does near rest, and what that makes of the robot: the slopes of its
// action with respect to each measured input at the origin, and the modes of the robot
// linearised upright (plant_kinds.h's linearisation) closed by those slopes through the
// sampled, held action. A mode outside the unit circle is a drift or a fall the actor does
// not correct; one that leans on the wheels' rate is a drift in speed.

#include <array>
#include <complex>
#include <vector>

#include <Eigen/Core>

#include "cbbg/diagrams/closed_loop.h"
#include "cbbg/experiments/learnt_weights.h"
#include "cbbg/parameters/parameters.h"

namespace cbbg::experiments {

// The linearisation's state, x = (theta_b, phi, theta_b', phi'), phi the wheels' mean angle.
inline constexpr std::array<const char*, 4> kLinearisedStates{"theta_b", "phi", "theta_b'", "phi'"};

struct ClosedLoopMode {
  std::complex<double> z;  // eigenvalue of Ad + Bd K, per period
  std::complex<double> s;  // ln(z) / period, 1/s: > 0 real part grows
  int leans_on = 0;        // the state (kLinearisedStates) its eigenvector is largest in
};

struct ActorLinearisation {
  // da/dx at x = 0, N m per rad (per rad/s), by central differences.
  Eigen::Vector4d slopes = Eigen::Vector4d::Zero();
  // Ad + Bd K's eigenvalues (the robot held for trial.period, u = a = K x), largest |z| first.
  std::vector<ClosedLoopMode> modes;
};

// Builds the learnt actor `policy` on the analytic two-wheeler with the run's parameters (no
// sensor noise), loads `weights`, reads its action at the origin perturbed in each state, and
// closes plant.kind's linearisation with the slopes. Throws std::invalid_argument when the
// kind offers no linearisation or the weights do not fit the policy.
ActorLinearisation linearise_actor(const parameters::Parameters& parameters,
                                   const diagrams::ClosedLoopFactory& policy,
                                   const LearntWeights& weights);

}  // namespace cbbg::experiments
