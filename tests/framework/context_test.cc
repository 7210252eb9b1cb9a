#include "cbbg/framework/context.h"

#include <gtest/gtest.h>

#include "cbbg/framework/block_context.h"
#include "cbbg/framework/diagram_builder.h"
#include "cbbg/framework/primitives/constant_source.h"
#include "cbbg/framework/simulator.h"
#include "tests/framework/test_blocks.h"

namespace cbbg {
namespace {

// Draws one standard normal into its state at each update; has a "scale" parameter.
class Noise final : public Block {
 public:
  explicit Noise(std::string name) : Block(std::move(name)) {
    scale_ = declare_parameter("scale", Vector::Ones(1));
    declare_discrete_state("state", Vector::Zero(1), StateLifetime::kPersistent);
    declare_output_port("y", 1,
                        [this](const BlockContext& context, VectorRef y) {
                          y = context.parameter(scale_)[0] * context.discrete_state();
                        },
                        {});
    declare_periodic_update(0.01, 0.0, [](BlockContext& context, VectorRef next) {
      next[0] = draw_standard_normal(context.random_generator());
      return EventStatus::succeeded();
    });
  }

 private:
  int scale_ = 0;
};

struct NoiseDiagram {
  std::unique_ptr<Diagram> diagram;
  const Noise* first;
  const Noise* second;
};

NoiseDiagram make_noise_diagram() {
  DiagramBuilder builder("top");
  auto& first = builder.emplace<Noise>("first");
  auto& second = builder.emplace<Noise>("second");
  return {builder.build(), &first, &second};
}

std::string error_of(const std::function<void()>& action) {
  try {
    action();
  } catch (const std::exception& error) {
    return error.what();
  }
  return "no exception";
}

TEST(Context, HoldsEachBlocksInitialStateInContiguousStorage) {
  DiagramBuilder builder("top");
  auto& a = builder.emplace<testing::Exponential>("a", -1.0, 3.0);
  auto& counter = builder.emplace<testing::Counter>("counter", 0.1);
  auto& b = builder.emplace<testing::Exponential>("b", -1.0, 5.0);
  auto diagram = builder.build();
  auto context = diagram->create_context();
  EXPECT_EQ(context->continuous_states(), Eigen::Vector2d(3.0, 5.0));
  EXPECT_EQ(context->continuous_state(b)[0], 5.0);
  EXPECT_EQ(context->continuous_state(a)[0], 3.0);
  EXPECT_EQ(context->discrete_states().size(), 1);
  EXPECT_EQ(context->discrete_state(counter)[0], 0.0);
}

TEST(Context, ACloneIsIndependentAndContinuesIdentically) {
  auto [diagram, first, second] = make_noise_diagram();
  Simulator simulator(*diagram, SimulatorOptions{}, 7);
  simulator.advance_to(0.5);
  Simulator copy(*diagram, simulator.context().clone());
  simulator.advance_to(1.0);
  copy.initialize();
  copy.advance_to(1.0);
  EXPECT_EQ(copy.context().discrete_states(), simulator.context().discrete_states());
  copy.context().discrete_state(*first)[0] = 42.0;
  EXPECT_NE(simulator.context().discrete_state(*first)[0], 42.0);
}

TEST(Context, GeneratorsComeFromTheRootSeedAndTheBlockPath) {
  auto [diagram, first, second] = make_noise_diagram();
  auto seven = diagram->create_context(7);
  auto seven_again = diagram->create_context(7);
  auto eight = diagram->create_context(8);
  const auto draw = [](Context& context, const Block& block) {
    return context.random_generator(block)();
  };
  EXPECT_EQ(draw(*seven, *first), draw(*seven_again, *first));
  EXPECT_NE(draw(*seven, *second), draw(*seven, *first));
  EXPECT_NE(draw(*eight, *first), draw(*seven_again, *first));
  // The path below the root: the root's own name does not enter.
  RandomGenerator expected(derive_seed(7, "first"));
  EXPECT_EQ(diagram->create_context(7)->random_generator(*first)(), expected());
}

TEST(Context, DiagramsThatDifferOnlyInTheirRootsNameShareTheirStreams) {
  // Two arms of a comparison: the same blocks under roots of other names.
  DiagramBuilder builder("other_arm");
  auto& first = builder.emplace<Noise>("first");
  const auto other = builder.build();
  auto [diagram, original_first, second] = make_noise_diagram();
  EXPECT_EQ(other->create_context(3)->random_generator(first),
            diagram->create_context(3)->random_generator(*original_first));
}

TEST(Context, ReseedingRepeatsTheDraws) {
  auto [diagram, first, second] = make_noise_diagram();
  auto context = diagram->create_context(3);
  const auto a = context->random_generator(*second)();
  context->reseed(3);
  EXPECT_EQ(context->random_generator(*second)(), a);
}

TEST(Context, KnowsWhetherABlockHasDrawnSinceTheSeed) {
  auto [diagram, first, second] = make_noise_diagram();
  auto context = diagram->create_context(3);
  EXPECT_TRUE(context->generators_at_seed());
  context->random_generator (*second)();
  EXPECT_FALSE(context->generators_at_seed());
  context->reseed(4);
  EXPECT_TRUE(context->generators_at_seed());
  // A block that draws in its update: two ticks of a simulation move its generator.
  Simulator simulator(*diagram, SimulatorOptions{}, 5);
  EXPECT_TRUE(simulator.context().generators_at_seed());
  simulator.advance_to(0.02);
  EXPECT_FALSE(simulator.context().generators_at_seed());
}

TEST(Context, ParametersChangePerContext) {
  auto [diagram, first, second] = make_noise_diagram();
  Simulator simulator(*diagram, SimulatorOptions{}, 1);
  simulator.advance_to(0.005);
  auto other = simulator.context().clone();
  other->set_parameter(*first, "scale", Vector::Constant(1, 10.0));
  const double base = diagram->eval_output(simulator.context(), first->output_port("y"))[0];
  EXPECT_EQ(diagram->eval_output(*other, first->output_port("y"))[0], 10.0 * base);
  EXPECT_EQ(simulator.context().parameter(*first, "scale")[0], 1.0);
  EXPECT_EQ(error_of([&] { other->set_parameter(*first, "scale", Vector::Zero(2)); }),
            "parameter 'scale' of block 'top/first' has size 1, got a value of size 2");
  EXPECT_EQ(error_of([&] { other->set_parameter(*first, "gain", Vector::Zero(1)); }),
            "block 'top/first' has no parameter 'gain'; its parameters are: scale");
}

// A trial in another diagram as the protocol set it up: the parameters of the leaves of the same
// path come along, except those of the block named as the diagram's own.
TEST(Context, CopiesTheParametersOfAnotherDiagramsLeavesOfTheSamePath) {
  const NoiseDiagram from = make_noise_diagram();
  const NoiseDiagram to = make_noise_diagram();
  auto source = from.diagram->create_context(1);
  source->set_parameter(*from.first, "scale", Vector::Constant(1, 3.0));
  source->set_parameter(*from.second, "scale", Vector::Constant(1, 4.0));
  auto target = to.diagram->create_context(1);
  target->copy_parameters_from(*source, to.second);
  EXPECT_EQ(target->parameter(*to.first, "scale")[0], 3.0);
  EXPECT_EQ(target->parameter(*to.second, "scale")[0], 1.0);
  target->copy_parameters_from(*source);
  EXPECT_EQ(target->parameter(*to.second, "scale")[0], 4.0);
  EXPECT_EQ(target->discrete_states(), source->discrete_states());  // only the parameters

  DiagramBuilder builder("top");
  builder.emplace<ConstantSource>("first", Vector::Constant(1, 5.0));
  const auto unrelated = builder.build();
  auto other = unrelated->create_context(1);
  const Vector before = other->parameters();
  other->copy_parameters_from(*source);  // no leaf of the same path and parameters
  EXPECT_EQ(other->parameters(), before);
}

TEST(Context, ResetRestoresTheDeclaredInitialStateOnly) {
  DiagramBuilder builder("top");
  auto& counter = builder.emplace<testing::Counter>("counter", 0.1);
  auto& decay = builder.emplace<testing::Exponential>("decay", -1.0, 2.0);
  auto diagram = builder.build();
  Simulator simulator(*diagram);
  simulator.advance_to(1.0);
  simulator.context().reset_state(counter);
  EXPECT_EQ(simulator.context().discrete_state(counter)[0], 0.0);
  EXPECT_LT(simulator.context().continuous_state(decay)[0], 1.0);
  simulator.context().reset_all_state();
  EXPECT_EQ(simulator.context().continuous_state(decay)[0], 2.0);
  EXPECT_EQ(simulator.context().time(), 0.0);
}

TEST(Context, RejectsBlocksOutsideItsDiagram) {
  auto [diagram, first, second] = make_noise_diagram();
  auto [other_diagram, other_first, other_second] = make_noise_diagram();
  auto context = diagram->create_context();
  EXPECT_EQ(error_of([&] { context->discrete_state(*other_first); }),
            "block 'top/first' is not a leaf block of diagram 'top'");
  EXPECT_EQ(error_of([&] { context->assign_from(*other_diagram->create_context()); }),
            "assign_from: the source context belongs to another diagram than this one ('top')");
}

}  // namespace
}  // namespace cbbg
