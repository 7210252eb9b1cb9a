#include "cbbg/framework/diagram_builder.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "cbbg/framework/primitives/constant_source.h"
#include "cbbg/framework/primitives/gain.h"
#include "cbbg/framework/primitives/zero_order_hold.h"
#include "tests/framework/test_blocks.h"
#include "tests/support/error_of.h"

namespace cbbg {
namespace {

using ::testing::HasSubstr;

using testing::error_of;

// A subsystem that builds itself and keeps typed accessors (DiagramBuilder(Diagram&)).
class Amplifier final : public Diagram {
 public:
  explicit Amplifier(double gain) : Diagram("amplifier") {
    DiagramBuilder builder(*this);
    auto& stage = builder.emplace<Gain>("stage", gain, 1);
    stage_ = &stage;
    input_ = &builder.export_input(stage.input_port("u"), "in");
    output_ = &builder.export_output(stage.output_port("y"), "out");
    builder.build_into();
  }
  const InputPort& in() const { return *input_; }
  const OutputPort& out() const { return *output_; }
  const Gain& stage() const { return *stage_; }

 private:
  const InputPort* input_;
  const OutputPort* output_;
  const Gain* stage_;
};

TEST(DiagramBuilder, BuildsIntoASubclassThatKeepsTypedAccessors) {
  DiagramBuilder builder("top");
  auto& source = builder.emplace<ConstantSource>("source", Vector::Constant(1, 2.0));
  auto& amplifier = builder.add(std::make_unique<Amplifier>(3.0));
  builder.connect(source.output_port("y"), amplifier.in());
  const auto top = builder.build();
  EXPECT_EQ(&amplifier.in(), &amplifier.input_port("in"));
  EXPECT_EQ(amplifier.stage().path(), "top/amplifier/stage");
  auto context = top->create_context();
  EXPECT_EQ(top->eval_output(*context, amplifier.out())[0], 6.0);
}

TEST(DiagramBuilder, BuildIntoAndBuildAreNotInterchangeable) {
  DiagramBuilder own("own");
  EXPECT_EQ(error_of<std::logic_error>([&] { own.build_into(); }),
            "DiagramBuilder: this builder makes its own diagram; call build()");
  Amplifier built(1.0);
  EXPECT_EQ(error_of<std::logic_error>([&] { DiagramBuilder again(built); }),
            "DiagramBuilder: diagram 'amplifier' is already built; a builder builds into an empty "
            "diagram");
}

TEST(DiagramBuilder, ConnectRejectsSizeMismatchNamingBothPortsAndSizes) {
  DiagramBuilder builder("top");
  auto& source = builder.emplace<ConstantSource>("source", Vector::Zero(2));
  auto& gain = builder.emplace<Gain>("gain", 2.0, 3);
  EXPECT_EQ(error_of([&] { builder.connect(source.output_port("y"), gain.input_port("u")); }),
            "connect: size mismatch: output 'top/source.y' has size 2 but input 'top/gain.u' "
            "has size 3");
}

TEST(DiagramBuilder, BuildRejectsAnInputNeitherConnectedExportedNorFixed) {
  DiagramBuilder builder("top");
  builder.emplace<Gain>("gain", 2.0, 3);
  EXPECT_EQ(error_of([&] { builder.build(); }),
            "build: diagram 'top': input 'top/gain.u' (size 3) is neither connected, exported "
            "nor fixed");
}

TEST(DiagramBuilder, BuildListsEveryOpenInput) {
  DiagramBuilder builder("top");
  builder.emplace<testing::Adder>("sum", 1);
  EXPECT_EQ(error_of([&] { builder.build(); }),
            "build: diagram 'top': input 'top/sum.a' (size 1) is neither connected, exported "
            "nor fixed; input 'top/sum.b' (size 1) is neither connected, exported nor fixed");
}

TEST(DiagramBuilder, BuildRejectsAnAlgebraicLoopListingItPortByPort) {
  DiagramBuilder builder("top");
  auto& first = builder.emplace<Gain>("first", 2.0, 1);
  auto& second = builder.emplace<Gain>("second", 3.0, 1);
  builder.connect(first, "y", second, "u");
  builder.connect(second, "y", first, "u");
  EXPECT_EQ(error_of([&] { builder.build(); }),
            "build: diagram 'top': algebraic loop (outputs that read each other through direct "
            "feedthrough): top/first.y -> top/second.u -> top/second.y -> top/first.u -> "
            "top/first.y");
}

TEST(DiagramBuilder, AHoldInTheLoopBreaksIt) {
  DiagramBuilder builder("top");
  auto& gain = builder.emplace<Gain>("gain", 2.0, 1);
  auto& hold = builder.emplace<ZeroOrderHold>("hold", 1, 0.1);
  builder.connect(gain, "y", hold, "u");
  builder.connect(hold, "y", gain, "u");
  EXPECT_NO_THROW(builder.build());
}

TEST(DiagramBuilder, FindsAnAlgebraicLoopThroughANestedDiagram) {
  DiagramBuilder inner_builder("inner");
  auto& inner_gain = inner_builder.emplace<Gain>("gain", 2.0, 1);
  inner_builder.export_input(inner_gain.input_port("u"));
  inner_builder.export_output(inner_gain.output_port("y"));
  DiagramBuilder builder("top");
  auto& inner = builder.add(inner_builder.build());
  auto& outer_gain = builder.emplace<Gain>("gain", 3.0, 1);
  builder.connect(inner, "y", outer_gain, "u");
  builder.connect(outer_gain, "y", inner, "u");
  EXPECT_EQ(error_of([&] { builder.build(); }),
            "build: diagram 'top': algebraic loop (outputs that read each other through direct "
            "feedthrough): top/inner/gain.y -> top/gain.u -> top/gain.y -> top/inner/gain.u -> "
            "top/inner/gain.y");
}

TEST(DiagramBuilder, RejectsDuplicateBlockNames) {
  DiagramBuilder builder("top");
  builder.emplace<Gain>("gain", 2.0, 1);
  EXPECT_EQ(error_of([&] { builder.emplace<Gain>("gain", 3.0, 1); }),
            "diagram 'top': a block named 'gain' already exists; names must be unique");
}

TEST(DiagramBuilder, ABlockBelongsToOneDiagram) {
  auto shared = std::make_shared<Gain>("gain", 2.0, 1);
  DiagramBuilder first("first");
  first.add(shared);
  DiagramBuilder second("second");
  EXPECT_EQ(error_of([&] { second.add(shared); }),
            "diagram 'second': block 'first/gain' is in a diagram already; a block belongs to one "
            "diagram");
}

TEST(DiagramBuilder, ASharedBlockOutlivesItsDiagramWhileItsOtherOwnerHoldsIt) {
  auto shared = std::make_shared<Gain>("gain", 2.0, 1);
  {
    DiagramBuilder builder("top");
    Gain& added = builder.add(shared);
    EXPECT_EQ(&added, shared.get());
    builder.export_input(added.input_port("u"));
    builder.export_output(added.output_port("y"));
    const std::unique_ptr<Diagram> diagram = builder.build();
    EXPECT_EQ(shared.use_count(), 2);
  }
  EXPECT_EQ(shared.use_count(), 1);
  EXPECT_EQ(shared->name(), "gain");
  // Its diagram gone, it belongs to none (no dangling parent) and may join another.
  EXPECT_EQ(shared->parent(), nullptr);
  EXPECT_EQ(shared->path(), "gain");
  DiagramBuilder next("next");
  EXPECT_EQ(&next.add(shared), shared.get());
  EXPECT_EQ(shared->path(), "next/gain");
}

TEST(DiagramBuilder, RejectsConnectingABlockOfAnotherDiagram) {
  DiagramBuilder builder("top");
  DiagramBuilder other("other");
  auto& gain = builder.emplace<Gain>("gain", 2.0, 1);
  auto& stranger = other.emplace<ConstantSource>("source", Vector::Zero(1));
  EXPECT_EQ(error_of([&] { builder.connect(stranger.output_port("y"), gain.input_port("u")); }),
            "connect: block 'other/source' is not in diagram 'top'; add it to this builder first");
}

TEST(DiagramBuilder, RejectsASecondSourceForOneInput) {
  DiagramBuilder builder("top");
  auto& a = builder.emplace<ConstantSource>("a", Vector::Zero(1));
  auto& b = builder.emplace<ConstantSource>("b", Vector::Zero(1));
  auto& gain = builder.emplace<Gain>("gain", 2.0, 1);
  builder.connect(a, "y", gain, "u");
  EXPECT_EQ(error_of([&] { builder.connect(b, "y", gain, "u"); }),
            "connect: input 'top/gain.u' is already connected from 'top/a.y'");
  EXPECT_EQ(error_of([&] { builder.fix_input(gain.input_port("u"), Vector::Zero(1)); }),
            "fix_input: input 'top/gain.u' is already connected from 'top/a.y'");
}

TEST(DiagramBuilder, UnknownPortNamesListTheBlocksPorts) {
  DiagramBuilder builder("top");
  auto& sum = builder.emplace<testing::Adder>("sum", 1);
  EXPECT_EQ(error_of([&] { sum.input_port("c"); }),
            "block 'top/sum' has no input port 'c'; its input ports are: a, b");
  EXPECT_EQ(error_of([&] { sum.output_port("z"); }),
            "block 'top/sum' has no output port 'z'; its output ports are: y");
}

TEST(DiagramBuilder, RejectsFixedValuesOfTheWrongSize) {
  DiagramBuilder builder("top");
  auto& gain = builder.emplace<Gain>("gain", 2.0, 2);
  EXPECT_EQ(error_of([&] { builder.fix_input(gain.input_port("u"), Vector::Zero(3)); }),
            "fix_input: input 'top/gain.u' has size 2, got a value of size 3");
}

TEST(DiagramBuilder, IsSpentAfterBuild) {
  DiagramBuilder builder("top");
  builder.emplace<ConstantSource>("source", Vector::Zero(1));
  builder.build();
  EXPECT_EQ(error_of<std::logic_error>([&] { builder.build(); }),
            "this DiagramBuilder has already built its diagram");
}

TEST(DiagramBuilder, EvaluatesAChainAddedInReverseOrderInOnePass) {
  DiagramBuilder builder("top");
  auto& last = builder.emplace<Gain>("last", 5.0, 1);
  auto& middle = builder.emplace<Gain>("middle", 3.0, 1);
  auto& source = builder.emplace<ConstantSource>("source", Vector::Constant(1, 2.0));
  builder.connect(middle, "y", last, "u");
  builder.connect(source, "y", middle, "u");
  auto diagram = builder.build();
  auto context = diagram->create_context();
  EXPECT_EQ(diagram->eval_output(*context, last.output_port("y"))[0], 30.0);
}

TEST(DiagramBuilder, FixedInputsFeedTheirPort) {
  DiagramBuilder builder("top");
  auto& gain = builder.emplace<Gain>("gain", 2.0, 2);
  builder.fix_input(gain.input_port("u"), Eigen::Vector2d(1.0, -4.0));
  auto diagram = builder.build();
  auto context = diagram->create_context();
  EXPECT_EQ(diagram->eval_output(*context, gain.output_port("y")), Eigen::Vector2d(2.0, -8.0));
}

TEST(DiagramBuilder, NestedDiagramsRouteSignalsThroughExportedPorts) {
  // inner: u -> gain(2) -> gain(3) -> y, exported; the exported input fans out to a second
  // gain whose output is exported as "direct".
  DiagramBuilder inner_builder("inner");
  auto& double_it = inner_builder.emplace<Gain>("double_it", 2.0, 1);
  auto& triple_it = inner_builder.emplace<Gain>("triple_it", 3.0, 1);
  auto& negate = inner_builder.emplace<Gain>("negate", -1.0, 1);
  inner_builder.connect(double_it, "y", triple_it, "u");
  inner_builder.export_input(double_it.input_port("u"), "u");
  inner_builder.export_input(negate.input_port("u"), "u");
  inner_builder.export_output(triple_it.output_port("y"), "y");
  inner_builder.export_output(negate.output_port("y"), "direct");

  DiagramBuilder builder("top");
  auto& source = builder.emplace<ConstantSource>("source", Vector::Constant(1, 1.5));
  auto& inner = builder.add(inner_builder.build());
  auto& sum = builder.emplace<testing::Adder>("sum", 1);
  builder.connect(source, "y", inner, "u");
  builder.connect(inner, "y", sum, "a");
  builder.connect(inner, "direct", sum, "b");
  auto diagram = builder.build();
  auto context = diagram->create_context();
  EXPECT_EQ(diagram->eval_output(*context, sum.output_port("y"))[0], 1.5 * 6.0 - 1.5);
  EXPECT_EQ(context->signal(inner.output_port("y"))[0], 9.0);
  EXPECT_EQ(inner.path(), "top/inner");
  EXPECT_EQ(double_it.path(), "top/inner/double_it");
  EXPECT_EQ(diagram->leaves().size(), 5u);
}

TEST(DiagramBuilder, ExportingOneNameWithTwoSizesIsAnError) {
  DiagramBuilder builder("top");
  auto& one = builder.emplace<Gain>("one", 1.0, 1);
  auto& two = builder.emplace<Gain>("two", 1.0, 2);
  builder.export_input(one.input_port("u"), "u");
  EXPECT_EQ(error_of([&] { builder.export_input(two.input_port("u"), "u"); }),
            "export_input: size mismatch: diagram input 'top.u' has size 1 but input 'top/two.u' "
            "has size 2");
}

TEST(DiagramBuilder, RejectsTwoExportedOutputsOfOneName) {
  DiagramBuilder builder("top");
  auto& a = builder.emplace<ConstantSource>("a", Vector::Zero(1));
  auto& b = builder.emplace<ConstantSource>("b", Vector::Zero(1));
  builder.export_output(a.output_port("y"));
  EXPECT_EQ(error_of([&] { builder.export_output(b.output_port("y")); }),
            "export_output: diagram 'top' already has an output port 'y'");
}

TEST(DiagramBuilder, RejectsContinuousCouplingTheSimulatorCannotIntegrate) {
  // A self-integrating block whose input follows another block's continuous state through
  // direct feedthrough would see that input frozen over each interval.
  DiagramBuilder builder("top");
  auto& ramp_rate = builder.emplace<ConstantSource>("rate", Vector::Ones(1));
  auto& ramp = builder.emplace<testing::Integrator>("ramp");
  auto& gain = builder.emplace<Gain>("gain", 1.0, 1);
  auto& self = builder.emplace<testing::SelfIntegrator>("self");
  builder.connect(ramp_rate, "y", ramp, "u");
  builder.connect(ramp, "y", gain, "u");
  builder.connect(gain, "y", self, "u");
  EXPECT_EQ(error_of([&] { builder.build(); }),
            "build: diagram 'top': block 'top/self' integrates its own continuous state, so its "
            "inputs must hold still between events, but input 'top/self.u' depends through "
            "direct feedthrough on the continuous state of 'top/ramp'; sample it through a "
            "discrete block (a zero-order hold)");
}

TEST(DiagramBuilder, RejectsInvalidNames) {
  EXPECT_EQ(error_of([] { Gain("bad/name", 1.0, 1); }),
            "block: invalid block name 'bad/name': use letters, digits and '_' only");
  EXPECT_EQ(error_of([] { Gain("gain", 1.0, 0); }),
            "block 'gain': port 'u' has size 0; a port has at least 1 element");
}

}  // namespace
}  // namespace cbbg
