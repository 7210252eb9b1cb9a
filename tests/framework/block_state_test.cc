// Named parts of a block's discrete state: their layout, their lifetimes, the reset of a new
// trial and the carrying on of learning into another diagram.

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "cbbg/framework/block_context.h"
#include "cbbg/framework/block_harness.h"
#include "cbbg/framework/diagram_builder.h"
#include "tests/support/error_of.h"

namespace cbbg {
namespace {

using testing::error_of;

// A learner-like block: weights that persist, a trace that lives one trial.
class Learner final : public Block {
 public:
  explicit Learner(std::string name, int weights = 2) : Block(std::move(name)) {
    weights_ = declare_discrete_state("weights", Vector::Constant(weights, 1.0),
                                      StateLifetime::kPersistent);
    trace_ = declare_discrete_state("trace", Vector::Constant(1, -1.0), StateLifetime::kPerTrial);
    declare_periodic_update(0.1, 0.0, [this](BlockContext& context, VectorRef next) {
      weights_.of(next).array() += 1.0;
      trace_.of(next)[0] = context.time();
      return EventStatus::succeeded();
    });
  }
  void declare_again(const std::string& name) {
    declare_discrete_state(name, Vector::Zero(1), StateLifetime::kPersistent);
  }

  StatePart weights_;
  StatePart trace_;
};

std::unique_ptr<Diagram> one_learner(const std::string& root, int weights = 2) {
  DiagramBuilder builder(root);
  builder.emplace<Learner>("learner", weights);
  return builder.build();
}

const Block& learner_of(const Diagram& diagram) { return diagram.block("learner"); }

TEST(StateParts, LieBackToBackInDeclarationOrder) {
  const Learner learner("learner", 3);
  ASSERT_EQ(learner.discrete_state_parts().size(), 2u);
  EXPECT_EQ(learner.weights_.offset, 0);
  EXPECT_EQ(learner.weights_.size, 3);
  EXPECT_EQ(learner.trace_.offset, 3);
  EXPECT_EQ(learner.initial_discrete_state(), (Vector(4) << 1.0, 1.0, 1.0, -1.0).finished());
  EXPECT_EQ(learner.discrete_state_part("trace").lifetime, StateLifetime::kPerTrial);
}

TEST(StateParts, UnknownOrRepeatedNamesAreRefusedByName) {
  Learner learner("learner");
  EXPECT_EQ(error_of([&] { learner.discrete_state_part("z"); }),
            "block 'learner' has no state part 'z'; it has: weights, trace");
  EXPECT_EQ(error_of([&] { learner.declare_again("trace"); }),
            "block 'learner' already has a state part 'trace'");
}

TEST(StateParts, ANewTrialResetsPerTrialPartsOnly) {
  const auto diagram = one_learner("top");
  auto context = diagram->create_context(1);
  auto state = context->discrete_state(learner_of(*diagram));
  state << 5.0, 6.0, 7.0;
  context->set_time(3.0);
  context->reset_trial_state();
  EXPECT_EQ(context->discrete_state(learner_of(*diagram)),
            (Vector(3) << 5.0, 6.0, -1.0).finished());
  EXPECT_EQ(context->time(), 0.0);
}

TEST(StateParts, ContinueFromCarriesPersistentPartsAndStreamsOfMatchingBlocks) {
  const auto first = one_learner("first_arm");
  const auto second = one_learner("second_arm");
  const auto other_layout = one_learner("third_arm", 5);
  auto from = first->create_context(1);
  from->discrete_state(learner_of(*first)) << 5.0, 6.0, 7.0;
  from->random_generator(learner_of(*first)).discard(10);
  auto to = second->create_context(2);
  to->continue_from(*from);
  EXPECT_EQ(to->discrete_state(learner_of(*second)), (Vector(3) << 5.0, 6.0, -1.0).finished());
  EXPECT_EQ(to->random_generator(learner_of(*second)), from->random_generator(learner_of(*first)));
  // Another state layout under the same path: nothing is carried.
  auto unrelated = other_layout->create_context(2);
  unrelated->continue_from(*from);
  EXPECT_EQ(unrelated->discrete_state(learner_of(*other_layout)),
            learner_of(*other_layout).initial_discrete_state());
}

// The installed harness of a block's unit tests: one block alone, its state read by part.
TEST(BlockHarness, RunsOneBlockAloneAndReadsItsStateByPart) {
  testing::BlockHarness<Learner> harness("learner", 3);
  EXPECT_EQ(harness.state_part("weights"), Vector::Constant(3, 1.0));
  harness.tick();  // the event instant at t = 0: one update
  EXPECT_EQ(harness.state_part("weights"), Vector::Constant(3, 2.0));
  EXPECT_EQ(harness.state_part("trace"), Vector::Zero(1));
  EXPECT_THAT([&] { harness.state_part("bias"); },
              ::testing::ThrowsMessage<std::invalid_argument>(
                  "block 'harness/learner' has no state part 'bias'; it has: weights, trace"));
}

}  // namespace
}  // namespace cbbg
