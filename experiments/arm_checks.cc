#include "cbbg/experiments/arm_checks.h"

#include <stdexcept>
#include <string>
#include <vector>

#include "cbbg/blocks/weight_learner.h"
#include "cbbg/diagrams/arms.h"
#include "cbbg/experiments/protocols.h"

namespace cbbg::experiments {
namespace {

// The loop of arm `name`, its factory's refusal as the user's.
diagrams::ClosedLoop build_arm(const std::string& name, const config::Parameters& parameters) {
  try {
    return diagrams::named_arm(name).learner(parameters);
  } catch (const config::ConfigError&) {
    throw;
  } catch (const std::exception& error) {
    throw config::ConfigError("arm '" + name +
                              "' cannot be built from this config: " + error.what());
  }
}

void check_features(const std::string& name, const diagrams::ClosedLoop& loop) {
  if (!loop.learner.learns()) return;
  const int features = loop.learner.actor->num_features();
  if (features <= blocks::kMaxFeatures) return;
  std::vector<std::string> keys;
  for (const blocks::LayoutEntry& entry : loop.layout) keys.push_back(entry.key);
  throw config::ConfigError("arm '" + name + "' has " + std::to_string(features) +
                            " features per learner; a learner holds at most " +
                            std::to_string(blocks::kMaxFeatures) +
                            ", what a weights file stores: make its features smaller (its " +
                            "layout: " + (keys.empty() ? "none" : config::join(keys)) + ")");
}

}  // namespace

void check_arms_build(const config::Parameters& parameters) {
  for (const std::string& name : experiment_arms(parameters.run)) {
    check_features(name, build_arm(name, parameters));
  }
}

}  // namespace cbbg::experiments
