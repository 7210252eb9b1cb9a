#pragma once
// Fills each block's params struct from the config tree and validates it, so every range a
// block owns is checked (with the block's own message naming the key) before a run starts.

#include "blocks/actor.h"
#include "blocks/boltzmann_sampler.h"
#include "blocks/critic.h"
#include "blocks/entropy.h"
#include "blocks/failure_detector.h"
#include "blocks/lqr_supervisor.h"
#include "blocks/normaliser.h"
#include "blocks/omega_schedule.h"
#include "blocks/pd_supervisor.h"
#include "blocks/rbf_features.h"
#include "blocks/reward.h"
#include "blocks/sensors.h"
#include "blocks/tropism.h"
#include "config/config.h"
#include "plant/robot_params.h"

namespace cbbg::diagrams {

plant::RobotParams robot_params(const config::Config& config);
blocks::SensorsParams sensors_params(const config::Config& config);
blocks::NormaliserParams normaliser_params(const config::Config& config);
blocks::RbfParams rbf_params(const config::Config& config);
blocks::PdSupervisorParams pd_supervisor_params(const config::Config& config);
blocks::LqrSupervisorParams lqr_supervisor_params(const config::Config& config);
blocks::CriticParams critic_params(const config::Config& config);
blocks::ActorParams actor_params(const config::Config& config);
blocks::TropismParams tropism_params(const config::Config& config);
blocks::SamplerParams sampler_params(const config::Config& config);
blocks::EntropyParams entropy_params(const config::Config& config);
blocks::OmegaParams omega_params(const config::Config& config, blocks::OmegaMode mode);
blocks::RewardParams reward_params(const config::Config& config);
blocks::FailureDetectorParams failure_params(const config::Config& config);

// Builds and validates every params struct above, and check_trial_keys: the whole config's
// ranges at once. Throws config::ConfigError with the block's message.
void validate_all(const config::Config& config);

// The rules across keys: trial.duration >= trial.period; trial.theta0 and every
// evaluation.angles entry strictly inside trial.failure_angle. Throws config::ConfigError
// naming both keys and their values.
void check_trial_keys(const config::Config& config);

}  // namespace cbbg::diagrams
