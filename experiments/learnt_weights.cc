#include "cbbg/experiments/learnt_weights.h"

#include <stdexcept>
#include <string>
#include <utility>

#include "cbbg/config/config.h"
#include "cbbg/diagrams/plant_kinds.h"

namespace cbbg::experiments {

namespace {

// "weights (49), trace (49)": the parts a learner declares, as records::parts_text shows
// learnt ones.
std::string parts_text(const std::vector<StatePart>& parts) {
  std::string text;
  for (const StatePart& part : parts) {
    text += (text.empty() ? "" : ", ") + part.name + " (" + std::to_string(part.size) + ")";
  }
  return text.empty() ? "nothing" : text;
}

// What `learner` learns in `context`, part by part.
LearntState learnt_state(const blocks::Learner& learner, const Context& context) {
  LearntState state;
  for (const StatePart& part : learner.learnt_parts()) {
    state.parts.push_back({part.name, learner.learnt(context, part)});
  }
  return state;
}

// Empty when `state` holds exactly the parts `learner` learns, by name and size, in its
// order; else the line that says how they differ, starting with `what`.
std::string parts_difference(const LearntState& state, const blocks::Learner& learner,
                             const std::string& what) {
  const std::vector<StatePart> parts = learner.learnt_parts();
  bool same = parts.size() == state.parts.size();
  for (std::size_t k = 0; same && k < parts.size(); ++k) {
    same = parts[k].name == state.parts[k].name &&
           parts[k].size == static_cast<int>(state.parts[k].values.size());
  }
  if (same) return {};
  const char* role = blocks::role_name(learner.learner_role());
  return what + " holds " + role + " parts " + records::parts_text(state) + "; the " + role + " '" +
         learner.learner_block().path() + "' learns " + parts_text(parts);
}

}  // namespace

LearntWeights learnt_weights(const diagrams::ClosedLoop& loop, const Context& context,
                             const WeightsProvenance& provenance) {
  if (loop.learner.actor == nullptr) {
    throw std::invalid_argument("diagram '" + loop.diagram->name() +
                                "' has no actor: it learns no weights");
  }
  LearntWeights weights;
  weights.layout = loop.layout;
  weights.layout_notes = loop.layout_notes;
  weights.features = loop.learner.actor->num_features();
  weights.actor = learnt_state(*loop.learner.actor, context);
  // A critic that is no blocks::Learner (a user's that keeps nothing) leaves no parts.
  if (loop.learner.critic != nullptr) {
    weights.critic = learnt_state(*loop.learner.critic, context);
  }
  weights.provenance = provenance;
  return weights;
}

void check_weights_fit(const LearntWeights& weights, const std::string& plant_kind,
                       const diagrams::ClosedLoop& loop, const std::string& what) {
  const std::string& learnt_on = weights.provenance.plant;
  if (!diagrams::same_robot(learnt_on, plant_kind)) {
    throw config::ConfigError(what + " was made on plant kind '" + learnt_on +
                              "' and cannot be loaded onto plant kind '" + plant_kind +
                              "' (plant.kind): another robot");
  }
  check_layout_fit(weights, loop.layout, what);
  for (const blocks::Learner* learner : {loop.learner.actor, loop.learner.critic}) {
    if (learner == nullptr) continue;
    const std::string difference =
        parts_difference(weights.of(learner->learner_role()), *learner, what);
    if (!difference.empty()) throw config::ConfigError(difference);
  }
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
  for (const blocks::Learner* learner : {loop.learner.actor, loop.learner.critic}) {
    if (learner == nullptr) continue;
    const LearntState& state = weights.of(learner->learner_role());
    const std::string difference = parts_difference(state, *learner, "the weights");
    if (!difference.empty()) throw std::invalid_argument(difference);
    const std::vector<StatePart> parts = learner->learnt_parts();
    for (std::size_t k = 0; k < parts.size(); ++k) {
      learner->mutable_learnt(context, parts[k]) = state.parts[k].values;
    }
  }
}

namespace {

std::string file_name(const std::filesystem::path& path) {
  return "weights file '" + path.string() + "'";
}

}  // namespace

void check_weights(const LearntWeights& weights, const std::string& plant_kind,
                   const diagrams::ClosedLoop& loop, const std::filesystem::path& source) {
  check_weights_fit(weights, plant_kind, loop, file_name(source));
}

void check_layout(const LearntWeights& weights, const blocks::FeatureLayout& layout,
                  const std::filesystem::path& source) {
  check_layout_fit(weights, layout, file_name(source));
}

}  // namespace cbbg::experiments
