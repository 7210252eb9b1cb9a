#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "cbbg/framework/diagram_builder.h"
#include "cbbg/framework/primitives/constant_source.h"
#include "cbbg/framework/primitives/gain.h"
#include "cbbg/framework/primitives/multiplexer.h"
#include "cbbg/framework/primitives/selector.h"
#include "cbbg/framework/primitives/zero_order_hold.h"
#include "cbbg/framework/simulator.h"
#include "tests/framework/test_blocks.h"

namespace cbbg {
namespace {

TEST(Primitives, ConstantSourceAndGain) {
  DiagramBuilder builder("top");
  auto& source = builder.emplace<ConstantSource>("source", Eigen::Vector3d(1.0, -2.0, 0.5));
  auto& gain = builder.emplace<Gain>("gain", -4.0, 3);
  builder.connect(source, "y", gain, "u");
  auto diagram = builder.build();
  auto context = diagram->create_context();
  EXPECT_EQ(diagram->eval_output(*context, gain.output_port("y")),
            Eigen::Vector3d(-4.0, 8.0, -2.0));
  EXPECT_TRUE(gain.output_reads(0) == std::vector<int>{0});  // direct feedthrough
}

TEST(Primitives, MultiplexerConcatenatesInOrder) {
  DiagramBuilder builder("top");
  auto& a = builder.emplace<ConstantSource>("a", Eigen::Vector2d(1.0, 2.0));
  auto& b = builder.emplace<ConstantSource>("b", Vector::Constant(1, 3.0));
  auto& mux = builder.emplace<Multiplexer>(
      "mux", std::vector<Multiplexer::Input>{{"first", 2}, {"second", 1}, {"again", 2}});
  builder.connect(a, "y", mux, "first");
  builder.connect(b, "y", mux, "second");
  builder.connect(a, "y", mux, "again");
  auto diagram = builder.build();
  auto context = diagram->create_context();
  Vector expected(5);
  expected << 1.0, 2.0, 3.0, 1.0, 2.0;
  EXPECT_EQ(diagram->eval_output(*context, mux.output_port("y")), expected);
  EXPECT_EQ(mux.output_port("y").size(), 5);
  EXPECT_EQ(mux.output_reads(0), (std::vector<int>{0, 1, 2}));
}

TEST(Primitives, SelectorPicksTheElementsInTheOrderGiven) {
  DiagramBuilder builder("top");
  auto& source = builder.emplace<ConstantSource>("source", Eigen::Vector4d(1.0, 2.0, 3.0, 4.0));
  auto& selector = builder.emplace<Selector>("pick", 4, std::vector<int>{3, 0, 3});
  builder.connect(source, "y", selector, "u");
  auto diagram = builder.build();
  auto context = diagram->create_context();
  EXPECT_EQ(diagram->eval_output(*context, selector.output_port("y")),
            Eigen::Vector3d(4.0, 1.0, 4.0));
  EXPECT_EQ(selector.output_reads(0), std::vector<int>{0});  // direct feedthrough
}

TEST(Primitives, SelectorRefusesIndicesOutsideItsInput) {
  EXPECT_THAT(
      [] {
        Selector("pick", 4, {0, 4});
      },
      ::testing::ThrowsMessage<std::invalid_argument>(
          "selector 'pick': index 4 is outside its input of size 4"));
  EXPECT_THAT([] { Selector("pick", 4, {-1}); },
              ::testing::ThrowsMessage<std::invalid_argument>(
                  "selector 'pick': index -1 is outside its input of size 4"));
  EXPECT_THAT([] { Selector("pick", 4, {}); }, ::testing::ThrowsMessage<std::invalid_argument>(
                                                   "selector 'pick': select at least one element"));
}

TEST(Primitives, ZeroOrderHoldStartsFromItsInitialValueAndSamplesAtItsPeriod) {
  DiagramBuilder builder("top");
  auto& counter = builder.emplace<testing::Counter>("counter", 0.1);
  auto& hold = builder.emplace<ZeroOrderHold>("hold", Vector::Constant(1, -1.0), 0.3, 0.05);
  builder.connect(counter, "y", hold, "u");
  auto diagram = builder.build();
  Simulator simulator(*diagram);
  simulator.advance_to(0.04);
  EXPECT_EQ(simulator.context().discrete_state(hold)[0], -1.0);  // before its first sample
  simulator.advance_to(0.06);  // sampled at 0.05: the counter read 1 (updated at 0)
  EXPECT_EQ(simulator.context().discrete_state(hold)[0], 1.0);
  simulator.advance_to(0.36);  // sampled at 0.35: counter updated at 0, 0.1, 0.2, 0.3
  EXPECT_EQ(simulator.context().discrete_state(hold)[0], 4.0);
  EXPECT_TRUE(hold.output_reads(0).empty());  // no feedthrough: it breaks loops
}

TEST(Primitives, ZeroOrderHoldRejectsABadPeriod) {
  try {
    ZeroOrderHold hold("hold", 1, -0.01);
    ADD_FAILURE();
  } catch (const std::invalid_argument& error) {
    EXPECT_STREQ(error.what(),
                 "block 'hold': a periodic update needs a positive, finite period; got -0.010000");
  }
}

}  // namespace
}  // namespace cbbg
