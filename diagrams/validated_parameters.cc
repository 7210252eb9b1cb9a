#include "cbbg/diagrams/validated_parameters.h"

#include <stdexcept>

#include "cbbg/blocks/failure_detector.h"
#include "cbbg/blocks/lqr_supervisor.h"
#include "cbbg/diagrams/plant_kinds.h"

namespace cbbg::diagrams {
namespace {

// What the blocks check of their own params, beyond the ranges every value was read with.
void check_blocks(const config::Parameters& p) {
  if (p.plant.kind == "simbody") {
    p.plant.robot.validate_rigid_bodies();  // a multibody model needs a rigid body's inertias
  } else {
    p.plant.robot.validate();
  }
  p.sensors.validate();
  p.normaliser.validate();
  p.rbf.validate();
  p.supervisor.pd.validate();
  p.supervisor.lqr.validate();
  // Weights without a stabilising gain show only when the gain is computed.
  if (p.supervisor.kind == "lqr") {
    blocks::LqrSupervisor("supervisor", planar_linearization(p), p.supervisor.lqr);
  }
  p.critic.validate();
  p.actor.validate();
  p.tropism.validate();
  p.sampler.validate();
  p.omega.validate();
  p.reward.validate();
  p.push.validate();
  blocks::FailureDetectorParams{p.trial.failure_angle}.validate();
}

// The blocks' invariants and the rules across sections, as the config's errors.
void check_invariants(const config::Parameters& parameters) {
  try {
    check_blocks(parameters);
  } catch (const std::invalid_argument& error) {
    throw config::ConfigError(error.what());
  }
  parameters.check_across_sections();
}

}  // namespace

config::Parameters validated_parameters(const config::Config& config) {
  // Each value was checked against its declaration as it arrived in the config.
  const config::Parameters parameters = config::read_parameters(config);
  check_invariants(parameters);
  return parameters;
}

namespace {

config::Config with_settings(const config::Parameters& parameters, const std::string& entry,
                             const std::string& source) {
  config::Config config;
  config::write_parameters(parameters, config);
  for (const auto& [key, value] : config::split_settings(entry)) {
    config.set(key + "=" + value, source);
  }
  return config;
}

}  // namespace

config::Parameters validated_with_settings(const config::Parameters& parameters,
                                           const std::string& entry, const std::string& source) {
  return validated_parameters(with_settings(parameters, entry, source));
}

bool settings_change(const config::Parameters& parameters, const std::string& entry) {
  config::Config config;
  config::write_parameters(parameters, config);
  return !(with_settings(parameters, entry, "settings") == config);
}

void validate_parameters(const config::Parameters& parameters) {
  try {
    check_declared(parameters, "");
  } catch (const std::invalid_argument& error) {
    throw config::ConfigError(error.what());
  }
  check_invariants(parameters);
}

}  // namespace cbbg::diagrams
