#include "cbbg/framework/primitives/csv_sink.h"

#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "cbbg/framework/diagram_builder.h"
#include "cbbg/framework/primitives/constant_source.h"
#include "cbbg/framework/primitives/ramp_source.h"
#include "cbbg/framework/simulator.h"
#include "tests/support/scratch_directory.h"

namespace cbbg {
namespace {

using ::testing::ThrowsMessage;

std::string read_file(const std::filesystem::path& path) {
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

void write_file(const std::filesystem::path& path, const std::string& text) {
  std::ofstream(path) << text;
}

// A ramp (y = 2 t) and a constant pair into a sink every 0.25 s from 0.5 s.
struct SinkDiagram {
  std::unique_ptr<Diagram> diagram;
  CsvSink* sink;

  SinkDiagram(const std::filesystem::path& path, std::vector<std::string> pair_columns) {
    DiagramBuilder builder("top");
    auto& ramp = builder.emplace<RampSource>("ramp", 2.0, 0.0);
    auto& pair = builder.emplace<ConstantSource>("pair", Eigen::Vector2d(0.5, -1.25));
    sink = &builder.emplace<CsvSink>(
        "sink", path,
        std::vector<CsvSink::Input>{{"ramp", 1}, {"pair", 2, std::move(pair_columns)}}, 0.25, 0.5);
    builder.connect(ramp, "y", *sink, "ramp");
    builder.connect(pair, "y", *sink, "pair");
    diagram = builder.build();
  }
};

TEST(CsvSink, PortsAndColumns) {
  const testing::ScratchDirectory scratch;
  const CsvSink sink("sink", scratch.path() / "out.csv",
                     {{"position", 3}, {"speed", 1}, {"named", 2, {"left", "right"}}}, 0.1);
  ASSERT_EQ(sink.num_input_ports(), 3);
  EXPECT_EQ(sink.num_output_ports(), 0);
  EXPECT_EQ(sink.input_port("position").size(), 3);
  EXPECT_EQ(sink.input_port("speed").size(), 1);
  EXPECT_EQ(sink.input_port("named").size(), 2);
  EXPECT_EQ(sink.column_names(),
            (std::vector<std::string>{"position[0]", "position[1]", "position[2]", "speed", "left",
                                      "right"}));
  EXPECT_EQ(sink.file_path(), scratch.path() / "out.csv");
  // Nothing is written before a simulation starts.
  EXPECT_FALSE(std::filesystem::exists(scratch.path() / "out.csv"));
}

TEST(CsvSink, WritesTheTagTheHeaderAndARowPerSample) {
  const testing::ScratchDirectory scratch;
  const auto path = scratch.path() / "signals.csv";
  SinkDiagram setup(path, {"a", "b"});
  Simulator simulator(*setup.diagram);
  simulator.advance_to(1.1);  // samples at 0.5, 0.75, 1
  setup.sink->flush();
  EXPECT_EQ(read_file(path),
            "# written by cbbg CsvSink\n"
            "t,ramp,a,b\n"
            "0.5,1,0.5,-1.25\n"
            "0.75,1.5,0.5,-1.25\n"
            "1,2,0.5,-1.25\n");
  EXPECT_EQ(setup.sink->num_rows(), 3);

  // A later run of the same diagram appends its rows; t starts again.
  Simulator second(*setup.diagram);
  second.advance_to(0.6);
  setup.sink->flush();
  EXPECT_THAT(read_file(path), ::testing::EndsWith("1,2,0.5,-1.25\n0.5,1,0.5,-1.25\n"));
}

TEST(CsvSink, ReplacesAFileItWroteAndNamesColumnsAfterThePorts) {
  const testing::ScratchDirectory scratch;
  const auto path = scratch.path() / "signals.csv";
  {
    SinkDiagram first(path, {"a", "b"});
    Simulator simulator(*first.diagram);
    simulator.advance_to(2.0);
  }  // the block closes the file
  SinkDiagram again(path, {});
  Simulator simulator(*again.diagram);
  simulator.advance_to(0.6);
  again.sink->flush();
  EXPECT_EQ(read_file(path),
            "# written by cbbg CsvSink\n"
            "t,ramp,pair[0],pair[1]\n"
            "0.5,1,0.5,-1.25\n");
}

TEST(CsvSink, RefusesAFileItDidNotWrite) {
  const testing::ScratchDirectory scratch;
  const auto path = scratch.path() / "mine.csv";
  write_file(path, "t,x\n0,1\n");
  EXPECT_THAT([&] { SinkDiagram setup(path, {}); },
              ThrowsMessage<std::invalid_argument>(
                  "CsvSink 'sink': '" + path.string() +
                  "' exists and cbbg did not write it; cbbg never replaces a file of yours: "
                  "give a new path"));
  EXPECT_EQ(read_file(path), "t,x\n0,1\n");
}

TEST(CsvSink, RefusesAFileThatAppearedBeforeTheRun) {
  const testing::ScratchDirectory scratch;
  const auto path = scratch.path() / "late.csv";
  SinkDiagram setup(path, {});
  write_file(path, "the user's\n");
  Simulator simulator(*setup.diagram);
  EXPECT_THAT([&] { simulator.advance_to(1.0); },
              ThrowsMessage<std::invalid_argument>(
                  "CsvSink 'sink': '" + path.string() +
                  "' exists and cbbg did not write it; cbbg never replaces a file of yours: "
                  "give a new path"));
  EXPECT_EQ(read_file(path), "the user's\n");
}

TEST(CsvSink, RefusesPathsThatCannotBeItsFile) {
  const testing::ScratchDirectory scratch;
  EXPECT_THAT(
      [&] {
        CsvSink("sink", scratch.path(), {{"u", 1}}, 0.1);
      },
      ThrowsMessage<std::invalid_argument>("CsvSink 'sink': cannot write '" +
                                           scratch.path().string() +
                                           "': it is a directory; give a regular file's path"));
  const auto nowhere = scratch.path() / "missing" / "out.csv";
  EXPECT_THAT(
      [&] {
        CsvSink("sink", nowhere, {{"u", 1}}, 0.1);
      },
      ThrowsMessage<std::invalid_argument>("CsvSink 'sink': cannot write '" + nowhere.string() +
                                           "': its directory does not exist"));
  EXPECT_THAT(
      [&] {
        CsvSink("sink", "", {{"u", 1}}, 0.1);
      },
      ThrowsMessage<std::invalid_argument>(
          "CsvSink 'sink': the path is empty; give a file's path"));
}

TEST(CsvSink, RefusesBadInputsAndPeriods) {
  const testing::ScratchDirectory scratch;
  const auto path = scratch.path() / "out.csv";
  EXPECT_THAT([&] { CsvSink("sink", path, {}, 0.1); },
              ThrowsMessage<std::invalid_argument>("CsvSink 'sink': no inputs; give at least one"));
  EXPECT_THAT(
      [&] {
        CsvSink("sink", path, {{"u", 0}}, 0.1);
      },
      ThrowsMessage<std::invalid_argument>(
          "CsvSink 'sink': input 'u' has size 0; it must be at least 1"));
  EXPECT_THAT(
      [&] {
        CsvSink("sink", path, {{"u", 2, {"only"}}}, 0.1);
      },
      ThrowsMessage<std::invalid_argument>(
          "CsvSink 'sink': input 'u' has 1 column names for size 2; give one per "
          "element, or none"));
  EXPECT_THAT(
      [&] {
        CsvSink("sink", path, {{"u", 1, {"a,b"}}}, 0.1);
      },
      ThrowsMessage<std::invalid_argument>(
          "CsvSink 'sink': column name 'a,b' of input 'u' must be non-empty, without "
          "comma, quote or line break"));
  EXPECT_THAT(
      [&] {
        CsvSink("sink", path, {{"u", 1}}, 0.0);
      },
      ThrowsMessage<std::invalid_argument>("CsvSink 'sink': period 0 must be positive and finite"));
}

}  // namespace
}  // namespace cbbg
