#include "diagrams/params_from_config.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "framework/number_text.h"

namespace cbbg::diagrams {
namespace {

// A params struct's validate() names the key; the config layer reports it as a ConfigError.
template <typename Params>
Params validated(Params params) {
  try {
    params.validate();
  } catch (const std::invalid_argument& error) {
    throw config::ConfigError(error.what());
  }
  return params;
}

template <std::size_t N>
std::array<double, N> fixed_list(const std::vector<double>& values) {
  std::array<double, N> result{};
  std::copy_n(values.begin(), std::min(N, values.size()), result.begin());
  return result;
}

}  // namespace

plant::RobotParams robot_params(const config::Config& c) {
  plant::RobotParams p;
  p.wheel_mass = c.number("plant.wheel_mass");
  p.body_mass = c.number("plant.body_mass");
  p.wheel_radius = c.number("plant.wheel_radius");
  p.track_width = c.number("plant.track_width");
  p.com_height = c.number("plant.com_height");
  p.wheel_inertia = c.number("plant.wheel_inertia");
  p.body_pitch_inertia = c.number("plant.body_pitch_inertia");
  p.body_yaw_inertia = c.number("plant.body_yaw_inertia");
  p.body_roll_inertia = c.number("plant.body_roll_inertia");
  p.wheel_diametral_inertia = c.number("plant.wheel_diametral_inertia");
  p.gravity = c.number("plant.gravity");
  p.wheel_ground_friction = c.number("plant.wheel_ground_friction");
  p.axle_friction = c.number("plant.axle_friction");
  p.torque_limit = c.number("plant.torque_limit");
  p.accuracy = c.number("plant.accuracy");
  const std::string& integrator = c.text("plant.simbody_integrator");
  p.simbody_integrator = integrator == "rk3"      ? plant::SimbodyIntegrator::kRungeKutta3
                         : integrator == "verlet" ? plant::SimbodyIntegrator::kVerlet
                                                  : plant::SimbodyIntegrator::kMerson;
  p.simbody_model = c.text("plant.simbody_model") == "constrained"
                        ? plant::SimbodyModel::kNoSlipConstraints
                        : plant::SimbodyModel::kRollingBase;
  validated(p);
  if (c.text("plant.kind") == "simbody") {
    // A multibody model also needs inertias a rigid body can have.
    try {
      p.validate_rigid_bodies();
    } catch (const std::invalid_argument& error) {
      throw config::ConfigError(error.what());
    }
  }
  return p;
}

blocks::SensorsParams sensors_params(const config::Config& c) {
  blocks::SensorsParams p;
  p.noise_std = fixed_list<blocks::kMeasuredSize>(c.numbers("sensors.noise_std"));
  p.quantisation = fixed_list<blocks::kMeasuredSize>(c.numbers("sensors.quantisation"));
  return validated(p);
}

blocks::NormaliserParams normaliser_params(const config::Config& c) {
  blocks::NormaliserParams p;
  p.scale_theta = c.number("normaliser.scale_theta");
  p.scale_dtheta = c.number("normaliser.scale_dtheta");
  p.saturation = c.number("normaliser.saturation");
  return validated(p);
}

blocks::RbfParams rbf_params(const config::Config& c) {
  blocks::RbfParams p;
  p.centres = c.numbers("rbf.centres");
  p.width = c.number("rbf.width");
  return validated(p);
}

blocks::PdSupervisorParams pd_supervisor_params(const config::Config& c) {
  blocks::PdSupervisorParams p;
  p.k_theta = c.number("supervisor.k_theta");
  p.k_dtheta = c.number("supervisor.k_dtheta");
  p.k_phi = c.number("supervisor.k_phi");
  p.k_dphi = c.number("supervisor.k_dphi");
  return validated(p);
}

blocks::LqrSupervisorParams lqr_supervisor_params(const config::Config& c) {
  blocks::LqrSupervisorParams p;
  p.lqr_q = fixed_list<4>(c.numbers("supervisor.lqr_q"));
  p.lqr_r = c.number("supervisor.lqr_r");
  return validated(p);
}

blocks::CriticParams critic_params(const config::Config& c) {
  blocks::CriticParams p;
  p.beta = c.number("critic.beta");
  p.gamma = c.number("critic.gamma");
  p.lambda = c.number("critic.lambda");
  return validated(p);
}

blocks::ActorParams actor_params(const config::Config& c) {
  blocks::ActorParams p;
  p.alpha = c.number("actor.alpha");
  try {
    p.rule = blocks::parse_actor_rule(c.text("actor.rule"));
  } catch (const std::invalid_argument& error) {
    throw config::ConfigError(error.what());
  }
  return validated(p);
}

blocks::TropismParams tropism_params(const config::Config& c) {
  blocks::TropismParams p;
  p.k1 = c.number("tropism.k1");
  p.k2 = c.number("tropism.k2");
  return validated(p);
}

blocks::SamplerParams sampler_params(const config::Config& c) {
  blocks::SamplerParams p;
  p.k_b = c.number("sampler.k_b");
  return validated(p);
}

blocks::EntropyParams entropy_params(const config::Config& c) {
  blocks::EntropyParams p;
  p.k_b = c.number("sampler.k_b");
  return validated(p);
}

blocks::OmegaParams omega_params(const config::Config& c, blocks::OmegaMode mode) {
  blocks::OmegaParams p;
  p.n2 = c.number("omega.n2");
  p.n3 = c.number("omega.n3");
  p.mode = mode;
  return validated(p);
}

blocks::RewardParams reward_params(const config::Config& c) {
  blocks::RewardParams p;
  p.a1 = c.number("reward.a1");
  p.a2 = c.number("reward.a2");
  return validated(p);
}

blocks::FailureDetectorParams failure_params(const config::Config& c) {
  blocks::FailureDetectorParams p;
  p.failure_angle = c.number("trial.failure_angle");
  return validated(p);
}

void validate_all(const config::Config& c) {
  robot_params(c);
  sensors_params(c);
  normaliser_params(c);
  rbf_params(c);
  pd_supervisor_params(c);
  const blocks::LqrSupervisorParams lqr = lqr_supervisor_params(c);
  if (c.text("supervisor.kind") == "lqr") {
    // Weights without a stabilising gain show only when the gain is computed.
    try {
      blocks::LqrSupervisor("supervisor", robot_params(c), lqr);
    } catch (const std::invalid_argument& error) {
      throw config::ConfigError(error.what());
    }
  }
  critic_params(c);
  actor_params(c);
  tropism_params(c);
  sampler_params(c);
  entropy_params(c);
  omega_params(c, blocks::OmegaMode::kSchedule);
  reward_params(c);
  failure_params(c);
  check_trial_keys(c);
}

void check_trial_keys(const config::Config& c) {
  const double period = c.number("trial.period");
  const double duration = c.number("trial.duration");
  if (duration < period) {
    throw config::ConfigError("trial.duration (" + format_number(duration) +
                              " s) must be at least one trial.period (" + format_number(period) +
                              " s)");
  }
  const double failure = c.number("trial.failure_angle");
  auto inside = [failure](const std::string& key, double angle) {
    if (!(std::abs(angle) < failure)) {
      throw config::ConfigError(key + " (" + format_number(angle) +
                                " rad) must lie inside trial.failure_angle (" +
                                format_number(failure) + " rad): a trial from there fails at once");
    }
  };
  inside("trial.theta0", c.number("trial.theta0"));
  for (const char* key : {"evaluation.angles", "exp3.angles"}) {
    const std::vector<double>& angles = c.numbers(key);
    for (std::size_t i = 0; i < angles.size(); ++i) {
      inside(std::string(key) + "[" + std::to_string(i) + "]", angles[i]);
    }
  }
}

}  // namespace cbbg::diagrams
