#include "cbbg/records/learnt_state.h"

#include <stdexcept>
#include <string>
#include <utility>

namespace cbbg::records {
namespace {

bool same_values(const Vector& a, const Vector& b) {
  return a.size() == b.size() && (a.size() == 0 || (a.array() == b.array()).all());
}

}  // namespace

std::string parts_text(const LearntState& state) {
  std::string text;
  for (const LearntPart& part : state.parts) {
    text +=
        (text.empty() ? "" : ", ") + part.name + " (" + std::to_string(part.values.size()) + ")";
  }
  return text.empty() ? "nothing" : text;
}

const Vector* LearntState::find(std::string_view name) const {
  for (const LearntPart& part : parts) {
    if (part.name == name) return &part.values;
  }
  return nullptr;
}

LearntState LearntState::of_weights(Vector weights) {
  return LearntState{{{"weights", std::move(weights)}}};
}

Vector& LearntState::weights(const char* role) {
  return const_cast<Vector&>(std::as_const(*this).weights(role));
}

const Vector& LearntState::weights(const char* role) const {
  if (const Vector* found = find("weights")) return *found;
  throw std::invalid_argument(std::string("the ") + role + " learnt no part 'weights'; it learnt " +
                              parts_text(*this));
}

bool LearntState::is_weights_only(int features) const {
  return parts.size() == 1 && parts[0].name == "weights" && parts[0].values.size() == features;
}

bool LearntState::all_finite() const {
  for (const LearntPart& part : parts) {
    if (!part.values.allFinite()) return false;
  }
  return true;
}

bool LearntState::operator==(const LearntState& other) const {
  if (parts.size() != other.parts.size()) return false;
  for (std::size_t k = 0; k < parts.size(); ++k) {
    if (parts[k].name != other.parts[k].name ||
        !same_values(parts[k].values, other.parts[k].values)) {
      return false;
    }
  }
  return true;
}

const LearntState& LearntWeights::of(blocks::Learner::Role role) const {
  return role == blocks::Learner::Role::kCritic ? critic : actor;
}

bool LearntWeights::operator==(const LearntWeights& other) const {
  return layout == other.layout && features == other.features && actor == other.actor &&
         critic == other.critic && provenance == other.provenance;
}

}  // namespace cbbg::records
