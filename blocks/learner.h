#pragma once
// What the protocols keep of a learning block: the parts of its discrete state it learns,
// by name and size (a critic's weights w, an actor's theta, and whatever else a user's
// learner carries across trials: traces, a second weight vector, a step-size estimate), and
// its role. blocks::Critic and blocks::Actor implement it, and so may a user's own critic or
// actor: a closed loop finds its learners by this interface (diagrams::LearnerBlocks), and
// weights files, task records, resume, exp2's carry-over, evaluations and Python read and
// write what it declares.

#include <string_view>
#include <vector>

#include "cbbg/framework/block.h"
#include "cbbg/framework/context.h"
#include "cbbg/framework/types.h"

namespace cbbg::blocks {

// The most numbers one learnt part may hold (and the most features a learner may read): what
// a weights file and a task record store (each number a line), checked before a run starts
// (experiments/arm_checks.h).
inline constexpr int kMaxFeatures = 1000000;

class Learner {
 public:
  enum class Role { kCritic, kActor };

  virtual ~Learner() = default;
  // Which of the two learners of an actor-critic it is.
  virtual Role learner_role() const = 0;
  // The block itself (its path names it in messages; its discrete state holds the parts).
  virtual const Block& learner_block() const = 0;
  // The size of the features it reads (its input "features").
  virtual int num_features() const = 0;
  // The parts of its discrete state that it learns and a weights file keeps, in the order
  // the file lists them; each must be a part learner_block() declared. The default: every
  // part it declared StateLifetime::kPersistent (the library's critic and actor: "weights").
  virtual std::vector<StatePart> learnt_parts() const;

  // One learnt part in `context` (a view into the block's discrete state), given or by name
  // (std::invalid_argument naming the block and its learnt parts for another name).
  ConstVectorView learnt(const Context& context, const StatePart& part) const;
  VectorView mutable_learnt(Context& context, const StatePart& part) const;
  ConstVectorView learnt(const Context& context, std::string_view part) const;
  VectorView mutable_learnt(Context& context, std::string_view part) const;

 private:
  StatePart learnt_part(std::string_view name) const;
};

// "critic" or "actor": the role's word in files and messages.
const char* role_name(Learner::Role role);

// Whether `name` may name a learnt part in a file: letters, digits and '_'.
bool is_part_name(std::string_view name);

}  // namespace cbbg::blocks
