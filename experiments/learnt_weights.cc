#include "cbbg/experiments/learnt_weights.h"

#include <stdexcept>
#include <string>

#include "cbbg/config/config.h"
#include "cbbg/diagrams/plant_kinds.h"

namespace cbbg::experiments {

int LearntWeights::num_features() const { return static_cast<int>(actor.size()); }

bool LearntWeights::operator==(const LearntWeights& other) const {
  auto same = [](const Vector& a, const Vector& b) {
    return a.size() == b.size() && (a.size() == 0 || (a.array() == b.array()).all());
  };
  return layout == other.layout && same(actor, other.actor) && same(critic, other.critic) &&
         provenance == other.provenance;
}

LearntWeights learnt_weights(const diagrams::ClosedLoop& loop, const Context& context,
                             const WeightsProvenance& provenance) {
  if (loop.learner.actor == nullptr || loop.learner.critic == nullptr) {
    throw std::invalid_argument("diagram '" + loop.diagram->name() +
                                "' has no critic and actor: it learns no weights");
  }
  LearntWeights weights;
  weights.layout = loop.layout;
  weights.layout_notes = loop.layout_notes;
  weights.actor = loop.learner.actor->weights(context);
  weights.critic = loop.learner.critic->weights(context);
  weights.provenance = provenance;
  return weights;
}

void check_weights_fit(const LearntWeights& weights, const std::string& plant_kind,
                       const blocks::FeatureLayout& layout, const std::string& what) {
  const std::string& learnt_on = weights.provenance.plant;
  if (!diagrams::same_robot(learnt_on, plant_kind)) {
    throw config::ConfigError(what + " was made on plant kind '" + learnt_on +
                              "' and cannot be loaded onto plant kind '" + plant_kind +
                              "' (plant.kind): another robot");
  }
  check_layout_fit(weights, layout, what);
}

void check_layout_fit(const LearntWeights& weights, const blocks::FeatureLayout& layout,
                      const std::string& what) {
  const blocks::LayoutDifference difference = blocks::first_difference(weights.layout, layout);
  if (difference.empty()) return;
  throw config::ConfigError(what + " was made for " + difference.first + "; this diagram has " +
                            difference.second);
}

void load_learnt_weights(const diagrams::ClosedLoop& loop, Context& context,
                         const LearntWeights& weights) {
  if (loop.learner.actor == nullptr) {
    throw std::invalid_argument("diagram '" + loop.diagram->name() +
                                "' has no actor to load weights into");
  }
  if (const blocks::LayoutDifference difference =
          blocks::first_difference(weights.layout, loop.layout);
      !difference.empty()) {
    throw std::invalid_argument("the weights were made for " + difference.first + "; diagram '" +
                                loop.diagram->name() + "' has " + difference.second);
  }
  auto check = [&loop](const char* name, Eigen::Index size, int features) {
    if (size != features) {
      throw std::invalid_argument("the weights have " + std::to_string(size) + " " + name +
                                  " weights; diagram '" + loop.diagram->name() + "' has " +
                                  std::to_string(features) + " features");
    }
  };
  check("actor", weights.actor.size(), loop.learner.actor->num_features());
  if (loop.learner.critic != nullptr) {
    check("critic", weights.critic.size(), loop.learner.critic->num_features());
  }
  loop.learner.actor->mutable_weights(context) = weights.actor;
  if (loop.learner.critic != nullptr)
    loop.learner.critic->mutable_weights(context) = weights.critic;
}

}  // namespace cbbg::experiments
