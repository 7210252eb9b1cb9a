#pragma once
// What the protocols keep of a learning block: one weight per feature, as the critic learns
// w (V = w . phi) and the actor theta (a_A = theta . phi). blocks::Critic and blocks::Actor
// implement it, and so may a user's own critic or actor: a closed loop finds its learners by
// this interface (diagrams::LearnerBlocks), and weights files, results, evaluations and
// resume read and write them through it.

#include "cbbg/framework/block.h"
#include "cbbg/framework/context.h"
#include "cbbg/framework/types.h"

namespace cbbg::blocks {

// The most features a learner may have: what a weights file and a task record store (each
// weight a line), checked before a run starts (experiments/arm_checks.h).
inline constexpr int kMaxFeatures = 1000000;

class WeightLearner {
 public:
  enum class Role { kCritic, kActor };

  virtual ~WeightLearner() = default;
  // Which of the two learners of an actor-critic it is.
  virtual Role learner_role() const = 0;
  // The block itself (its path names it in messages).
  virtual const Block& learner_block() const = 0;
  // The size of its weights: one per feature.
  virtual int num_features() const = 0;
  // Its learnt weights in `context`, a part of its persistent discrete state.
  virtual ConstVectorView weights(const Context& context) const = 0;
  virtual VectorView mutable_weights(Context& context) const = 0;
};

}  // namespace cbbg::blocks
