#include "cbbg/framework/signal_log.h"

#include <filesystem>
#include <fstream>
#include <sstream>

#include <gtest/gtest.h>

#include "cbbg/framework/block_context.h"
#include "cbbg/framework/diagram_builder.h"
#include "cbbg/framework/primitives/constant_source.h"
#include "cbbg/framework/simulator.h"
#include "tests/framework/test_blocks.h"
#include "tests/support/scratch_directory.h"

namespace cbbg {
namespace {

std::string read_file(const std::filesystem::path& path) {
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

TEST(SignalLog, RecordsAtItsOwnPeriodAndWritesCsv) {
  DiagramBuilder builder("top");
  auto& counter = builder.emplace<testing::Counter>("counter", 0.1);
  auto& pair = builder.emplace<ConstantSource>("pair", Eigen::Vector2d(0.5, -1.25));
  auto diagram = builder.build();
  Simulator simulator(*diagram);
  SignalLog& count_log = simulator.add_log(counter.output_port("y"), 0.2);
  SignalLog& pair_log = simulator.add_log(pair.output_port("y"), 0.25, 0.1);
  simulator.advance_to(0.65);
  // Counter: the value the updates read at 0, 0.2, 0.4, 0.6.
  ASSERT_EQ(count_log.num_samples(), 4);
  EXPECT_EQ(count_log.values(), Eigen::RowVector4d(0.0, 2.0, 4.0, 6.0));
  std::ostringstream csv;
  count_log.write_csv(csv);
  // 3 x 0.2 is 0.6000000000000001, but the instant is the earliest of the simultaneous
  // event times (0.1 + 2 x 0.25 = 0.6), so every log of that instant records 0.6.
  EXPECT_EQ(csv.str(), "t,y\n0,0\n0.2,2\n0.4,4\n0.6,6\n");
  // Two elements get indexed names unless named otherwise; offsets shift the samples.
  pair_log.set_column_names({"first", "second"});
  std::ostringstream pair_csv;
  pair_log.write_csv(pair_csv);
  EXPECT_EQ(pair_csv.str(), "t,first,second\n0.1,0.5,-1.25\n0.35,0.5,-1.25\n0.6,0.5,-1.25\n");
}

TEST(SignalLog, StreamsTheSameBytesWithoutKeepingSamples) {
  DiagramBuilder builder("top");
  auto& decay = builder.emplace<testing::Exponential>("decay", -1.0, 1.0);
  auto diagram = builder.build();
  const testing::ScratchDirectory scratch;
  const auto path = scratch.path() / "steps.csv";

  Simulator in_memory(*diagram);
  SignalLog& kept = in_memory.add_log(decay.output_port("y"), 0.01);
  in_memory.advance_to(1.0);
  std::ostringstream expected;
  kept.write_csv(expected);

  {
    Simulator streaming(*diagram);
    SignalLog& streamed = streaming.add_log(decay.output_port("y"), 0.01);
    streamed.stream_to_csv(path);
    streaming.advance_to(1.0);
    EXPECT_EQ(streamed.num_samples(), 0);  // nothing kept in memory
  }                                        // the log's file closes with its simulator
  EXPECT_EQ(kept.num_samples(), 100);
  EXPECT_EQ(read_file(path), expected.str());
}

// Counts its initialisation updates in its state.
class InitialisationCounter final : public Block {
 public:
  InitialisationCounter() : Block("initialised") {
    declare_discrete_state("state", Vector::Zero(1), StateLifetime::kPersistent);
    declare_initialization_update([](BlockContext&, VectorRef next) {
      next[0] += 1.0;
      return EventStatus::succeeded();
    });
  }
};

TEST(SignalLog, ALogAddedMidRunRecordsFromThenOnWithoutRefiringUpdates) {
  DiagramBuilder builder("top");
  auto& counter = builder.emplace<testing::Counter>("counter", 0.1);
  auto& initialised = builder.add(std::make_unique<InitialisationCounter>());
  auto diagram = builder.build();
  Simulator simulator(*diagram);
  simulator.advance_to(0.25);  // instants 0, 0.1, 0.2
  SignalLog& log = simulator.add_log(counter.output_port("y"), 0.1);
  simulator.advance_to(0.45);  // instants 0.3, 0.4
  EXPECT_EQ(simulator.context().discrete_state(counter)[0], 5.0);
  EXPECT_EQ(simulator.context().discrete_state(initialised)[0], 1.0);  // not initialised again
  ASSERT_EQ(log.num_samples(), 2);
  EXPECT_DOUBLE_EQ(log.times()[0], 0.3);
  EXPECT_EQ(log.values(), Eigen::RowVector2d(3.0, 4.0));
}

TEST(SignalLog, RejectsBadPeriodsAndPortsOfOtherDiagrams) {
  DiagramBuilder builder("top");
  auto& counter = builder.emplace<testing::Counter>("counter", 0.1);
  auto diagram = builder.build();
  DiagramBuilder other_builder("other");
  auto& other = other_builder.emplace<testing::Counter>("counter", 0.1);
  auto other_diagram = other_builder.build();
  Simulator simulator(*diagram);
  try {
    simulator.add_log(counter.output_port("y"), 0.0);
    ADD_FAILURE();
  } catch (const std::invalid_argument& error) {
    EXPECT_STREQ(error.what(),
                 "log of 'top/counter.y': the period must be positive and finite; got 0.000000");
  }
  try {
    simulator.add_log(other.output_port("y"), 0.1);
    ADD_FAILURE();
  } catch (const std::invalid_argument& error) {
    EXPECT_STREQ(error.what(), "block 'other/counter' is not a leaf block of diagram 'top'");
  }
}

}  // namespace
}  // namespace cbbg
