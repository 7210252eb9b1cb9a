#include "cbbg/diagrams/validated_parameters.h"

#include <cmath>
#include <stdexcept>
#include <string>

#include "cbbg/blocks/failure_detector.h"
#include "cbbg/blocks/learner.h"
#include "cbbg/blocks/lqr_supervisor.h"
#include "cbbg/config/declared_keys.h"
#include "cbbg/diagrams/plant_kinds.h"
#include "cbbg/framework/number_text.h"

namespace cbbg::diagrams {
namespace {

// The RBF grid's units, centres^inputs, before a grid too large to store is built at all.
void check_rbf_grid(const parameters::Parameters& p) {
  const double units = std::pow(static_cast<double>(p.rbf.centres.size()), p.normaliser.size());
  if (units <= blocks::kMaxFeatures) return;
  throw config::ConfigError(
      "rbf.centres (" + std::to_string(p.rbf.centres.size()) +
      " of them) over normaliser.inputs (" + std::to_string(p.normaliser.size()) +
      " inputs) make " + format_number(units) + " features per learner; a learner holds at most " +
      std::to_string(blocks::kMaxFeatures) +
      ", what a weights file stores: use fewer rbf.centres or normaliser.inputs");
}

// What the blocks check of their own params, beyond the ranges every value was read with.
void check_blocks(const parameters::Parameters& p) {
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
  p.exploration.validate();
  p.omega.validate();
  p.reward.validate();
  p.push.validate();
  blocks::FailureDetectorParams{p.trial.failure_angle}.validate();
}

// The blocks' invariants and the rules across sections, as the config's errors.
void check_invariants(const parameters::Parameters& parameters) {
  try {
    check_blocks(parameters);
  } catch (const std::invalid_argument& error) {
    throw config::ConfigError(error.what());
  }
  parameters.check_across_sections();
  check_rbf_grid(parameters);
  config::check_own_sections(parameters.own);
}

}  // namespace

parameters::Parameters validated_parameters(const config::Config& config) {
  // Each value was checked against its declaration as it arrived in the config.
  const parameters::Parameters parameters = parameters::read_parameters(config);
  check_invariants(parameters);
  return parameters;
}

namespace {

config::Config with_settings(const parameters::Parameters& parameters, const std::string& entry,
                             const std::string& source) {
  config::Config config;
  parameters::write_parameters(parameters, config);
  for (const auto& [key, value] : config::split_settings(entry)) {
    config.set(key + "=" + value, source);
  }
  return config;
}

}  // namespace

parameters::Parameters validated_with_settings(const parameters::Parameters& parameters,
                                               const std::string& entry,
                                               const std::string& source) {
  return validated_parameters(with_settings(parameters, entry, source));
}

bool settings_change(const parameters::Parameters& parameters, const std::string& entry) {
  config::Config config;
  parameters::write_parameters(parameters, config);
  return !(with_settings(parameters, entry, "settings") == config);
}

void validate_parameters(const parameters::Parameters& parameters) {
  try {
    check_declared(parameters, "");
  } catch (const std::invalid_argument& error) {
    throw config::ConfigError(error.what());
  }
  check_invariants(parameters);
}

}  // namespace cbbg::diagrams
