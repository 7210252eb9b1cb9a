#include "cbbg/diagrams/configured_blocks.h"

#include <stdexcept>

#include "cbbg/blocks/actor.h"
#include "cbbg/blocks/boltzmann_sampler.h"
#include "cbbg/blocks/critic.h"
#include "cbbg/blocks/entropy.h"
#include "cbbg/blocks/failure_detector.h"
#include "cbbg/blocks/gaussian_exploration.h"
#include "cbbg/blocks/lqr_supervisor.h"
#include "cbbg/blocks/mixer.h"
#include "cbbg/blocks/normaliser.h"
#include "cbbg/blocks/ou_exploration.h"
#include "cbbg/blocks/pd_supervisor.h"
#include "cbbg/blocks/quadratic_reward.h"
#include "cbbg/blocks/rbf_features.h"
#include "cbbg/blocks/reward.h"
#include "cbbg/blocks/sensors.h"
#include "cbbg/blocks/tropism.h"
#include "cbbg/diagrams/plant_kinds.h"

namespace cbbg::diagrams {

std::shared_ptr<Block> configured_supervisor(const SlotRequest& request) {
  const parameters::Parameters& p = request.parameters;
  if (p.supervisor.kind == "lqr") {
    return std::make_shared<blocks::LqrSupervisor>(request.name, planar_linearization(p),
                                                   p.supervisor.lqr);
  }
  return std::make_shared<blocks::PdSupervisor>(request.name, p.supervisor.pd);
}

std::shared_ptr<Block> configured_normaliser(const SlotRequest& request) {
  return std::make_shared<blocks::Normaliser>(request.name, request.parameters.normaliser);
}

std::shared_ptr<Block> configured_features(const SlotRequest& request) {
  const parameters::Parameters& p = request.parameters;
  return std::make_shared<blocks::RbfFeatures>(request.name, p.rbf, p.normaliser.size());
}

std::shared_ptr<Block> configured_critic(const SlotRequest& request) {
  const parameters::Parameters& p = request.parameters;
  blocks::CriticParams params = p.critic;
  params.frozen = !request.learns;
  return std::make_shared<blocks::Critic>(request.name, request.num_features, params,
                                          p.trial.period);
}

std::shared_ptr<Block> configured_actor(const SlotRequest& request) {
  blocks::ActorParams params = request.parameters.actor;
  params.frozen = !request.learns;
  return std::make_shared<blocks::Actor>(request.name, request.num_features, params,
                                         request.parameters.trial.period);
}

std::shared_ptr<Block> configured_exploration(const SlotRequest& request) {
  const parameters::Parameters& p = request.parameters;
  switch (p.exploration.kind) {
    case blocks::ExplorationKind::kGaussian:
      return std::make_shared<blocks::GaussianExploration>(request.name, p.exploration,
                                                           p.trial.period);
    case blocks::ExplorationKind::kOu:
      return std::make_shared<blocks::OuExploration>(request.name, p.exploration, p.trial.period);
    case blocks::ExplorationKind::kBoltzmann:
      break;
  }
  return std::make_shared<blocks::BoltzmannSampler>(request.name, p.sampler, p.trial.period);
}

std::shared_ptr<Block> configured_tropism(const SlotRequest& request) {
  return std::make_shared<blocks::Tropism>(request.name, request.parameters.tropism);
}

std::shared_ptr<Block> configured_entropy(const SlotRequest& request) {
  return std::make_shared<blocks::Entropy>(request.name,
                                           blocks::EntropyParams{request.parameters.sampler.k_b});
}

std::shared_ptr<Block> configured_mixer(const SlotRequest& request) {
  return std::make_shared<blocks::Mixer>(request.name);
}

std::shared_ptr<Block> configured_sensors(const SlotRequest& request) {
  const parameters::Parameters& p = request.parameters;
  return std::make_shared<blocks::Sensors>(request.name, p.sensors, p.trial.period,
                                           *request.signals, request.plant_state_size);
}

std::shared_ptr<Block> configured_failure(const SlotRequest& request) {
  const parameters::Parameters& p = request.parameters;
  return std::make_shared<blocks::FailureDetector>(
      request.name, blocks::FailureDetectorParams{p.trial.failure_angle}, p.trial.period);
}

std::shared_ptr<Block> configured_reward(const SlotRequest& request) {
  const parameters::Parameters& p = request.parameters;
  if (p.reward.kind == blocks::RewardKind::kQuadratic) {
    return std::make_shared<blocks::QuadraticReward>(request.name, p.reward, p.trial.period);
  }
  return std::make_shared<blocks::Reward>(request.name, p.reward, p.trial.period);
}

std::shared_ptr<Block> fill_slot(const char* slot, const BlockFactory& user,
                                 std::shared_ptr<Block> (*configured)(const SlotRequest&),
                                 const SlotRequest& request) {
  std::shared_ptr<Block> block = user ? user(request) : configured(request);
  if (!block) {
    throw std::invalid_argument(std::string("the factory of the ") + slot + " slot returned null");
  }
  return block;
}

}  // namespace cbbg::diagrams
