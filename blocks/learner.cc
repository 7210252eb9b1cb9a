#include "cbbg/blocks/learner.h"

#include <stdexcept>
#include <string>

namespace cbbg::blocks {

std::vector<StatePart> Learner::learnt_parts() const {
  std::vector<StatePart> parts;
  for (const StatePart& part : learner_block().discrete_state_parts()) {
    if (part.lifetime == StateLifetime::kPersistent) parts.push_back(part);
  }
  return parts;
}

ConstVectorView Learner::learnt(const Context& context, const StatePart& part) const {
  return ConstVectorView(context.discrete_state(learner_block()).data() + part.offset, part.size);
}

VectorView Learner::mutable_learnt(Context& context, const StatePart& part) const {
  return VectorView(context.discrete_state(learner_block()).data() + part.offset, part.size);
}

ConstVectorView Learner::learnt(const Context& context, std::string_view part) const {
  return learnt(context, learnt_part(part));
}

VectorView Learner::mutable_learnt(Context& context, std::string_view part) const {
  return mutable_learnt(context, learnt_part(part));
}

StatePart Learner::learnt_part(std::string_view name) const {
  std::string known;
  for (const StatePart& part : learnt_parts()) {
    if (part.name == name) return part;
    known += (known.empty() ? "" : ", ") + part.name;
  }
  throw std::invalid_argument("block '" + learner_block().path() + "' learns no part '" +
                              std::string(name) +
                              "'; it learns: " + (known.empty() ? "nothing" : known));
}

const char* role_name(Learner::Role role) {
  return role == Learner::Role::kCritic ? "critic" : "actor";
}

bool is_part_name(std::string_view name) {
  return !name.empty() && name.find_first_not_of(
                              "abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUV"
                              "WXYZ0123456789_") == std::string_view::npos;
}

}  // namespace cbbg::blocks
