#include "cbbg/apps/learnt_policy.h"

#include <algorithm>
#include <vector>

#include "cbbg/diagrams/arms.h"
#include "cbbg/diagrams/plant_kinds.h"
#include "cbbg/diagrams/presets.h"

namespace cbbg::app {

config::Config weights_config(const experiments::LearntWeights& weights,
                              const std::filesystem::path& config_file,
                              const std::vector<std::string>& sets) {
  config::Config config;
  const std::vector<diagrams::PlantKind>& kinds = diagrams::plant_kinds();
  const std::string& kind = weights.provenance.plant;
  if (std::any_of(kinds.begin(), kinds.end(),
                  [&kind](const diagrams::PlantKind& known) { return known.name == kind; })) {
    config.set("plant.kind=" + kind);
  }
  if (!config_file.empty()) config.merge_file(config_file);
  for (const auto& assignment : sets) config.set(assignment);
  return config;
}

diagrams::ClosedLoopFactory policy_of(const std::string& arm,
                                      const diagrams::ClosedLoopOptions& loop) {
  const std::vector<std::string> arms = diagrams::arm_names();
  if (std::find(arms.begin(), arms.end(), arm) != arms.end()) {
    diagrams::Arm named = diagrams::named_arm(arm, loop);
    if (named.policy) return named.policy;
  }
  return diagrams::closed_loop_factory(diagrams::kLearntActor,
                                       diagrams::preset(diagrams::kLearntActor).options, loop);
}

}  // namespace cbbg::app
