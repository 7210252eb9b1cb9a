#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <stdexcept>
#include <vector>

#include "cbbg/framework/block_harness.h"
#include "cbbg/framework/diagram_builder.h"
#include "cbbg/framework/primitives/constant_source.h"
#include "cbbg/framework/primitives/demultiplexer.h"
#include "cbbg/framework/primitives/multiplexer.h"

namespace cbbg {
namespace {

using ::testing::ThrowsMessage;

const std::vector<Demultiplexer::Output> kCuts{{"a", 2}, {"b", 1}, {"c", 3}};

TEST(Demultiplexer, HasOneInputOfTheSumOfTheSizesAndAnOutputPerCutReadingIt) {
  const Demultiplexer demux("split", kCuts);
  ASSERT_EQ(demux.num_input_ports(), 1);
  EXPECT_EQ(demux.input_port("u").size(), 6);
  ASSERT_EQ(demux.num_output_ports(), 3);
  EXPECT_EQ(demux.output_port_names(), "a, b, c");
  EXPECT_EQ(demux.output_port("a").size(), 2);
  EXPECT_EQ(demux.output_port("b").size(), 1);
  EXPECT_EQ(demux.output_port("c").size(), 3);
  for (int i = 0; i < 3; ++i) EXPECT_EQ(demux.output_reads(i), std::vector<int>{0});
}

TEST(Demultiplexer, CutsItsInputInOrder) {
  testing::BlockHarness<Demultiplexer> harness("split", kCuts);
  Vector u(6);
  u << 1.0, 2.0, 3.0, 4.0, 5.0, 6.0;
  harness.set_input("u", u);
  EXPECT_EQ(harness.output("a"), Eigen::Vector2d(1.0, 2.0));
  EXPECT_EQ(harness.output("b"), Vector::Constant(1, 3.0));
  EXPECT_EQ(harness.output("c"), Eigen::Vector3d(4.0, 5.0, 6.0));
}

TEST(Demultiplexer, UndoesAMultiplexerOfTheSameSizes) {
  Vector u(6);
  u << -1.0, 0.5, 7.0, 2.0, -3.0, 0.25;
  DiagramBuilder builder("top");
  auto& source = builder.emplace<ConstantSource>("source", u);
  auto& demux = builder.emplace<Demultiplexer>("split", kCuts);
  auto& mux = builder.emplace<Multiplexer>(
      "join", std::vector<Multiplexer::Input>{{"a", 2}, {"b", 1}, {"c", 3}});
  builder.connect(source, "y", demux, "u");
  for (const char* name : {"a", "b", "c"}) builder.connect(demux, name, mux, name);
  auto diagram = builder.build();
  auto context = diagram->create_context();
  EXPECT_EQ(diagram->eval_output(*context, mux.output_port("y")), u);
}

TEST(Demultiplexer, RefusesNoOutputsAndAnEmptyCut) {
  EXPECT_THAT(
      [] { Demultiplexer("split", {}); },
      ThrowsMessage<std::invalid_argument>("Demultiplexer 'split': no outputs; give at least one"));
  EXPECT_THAT(
      [] {
        Demultiplexer("split", {{"a", 2}, {"b", 0}});
      },
      ThrowsMessage<std::invalid_argument>(
          "Demultiplexer 'split': output 'b' has size 0; a size is at least 1"));
}

}  // namespace
}  // namespace cbbg
