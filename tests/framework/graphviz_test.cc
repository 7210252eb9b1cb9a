#include "cbbg/framework/graphviz.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "cbbg/framework/diagram_builder.h"
#include "cbbg/framework/primitives/constant_source.h"
#include "cbbg/framework/primitives/gain.h"
#include "cbbg/framework/primitives/zero_order_hold.h"
#include "tests/framework/test_blocks.h"
#include "tests/support/error_of.h"
#include "tests/support/scratch_directory.h"

namespace cbbg {
namespace {

namespace fs = std::filesystem;
using ::testing::Contains;
using ::testing::HasSubstr;
using ::testing::Not;
using ::testing::StartsWith;
using ::testing::ThrowsMessage;

// top: source [2] -> gain (x3) -> hold, hold.y exported as "held".
std::unique_ptr<Diagram> flat_diagram() {
  DiagramBuilder builder("top");
  auto& source = builder.emplace<ConstantSource>("source", Vector::Constant(2, 1.0));
  auto& gain = builder.emplace<Gain>("gain", 3.0, 2);
  auto& hold = builder.emplace<ZeroOrderHold>("hold", 2, 0.01);
  builder.connect(source, "y", gain, "u");
  builder.connect(gain, "y", hold, "u");
  builder.export_output(hold.output_port("y"), "held");
  return builder.build();
}

// top
// ├─ source [1] ──> plant.u
// ├─ plant                      (a diagram)
// │   ├─ actuator               (a diagram: u -> motor -> torque)
// │   └─ zoh                    actuator.torque -> zoh.u, zoh.y exported as plant.y
// ├─ scale                      plant.y -> scale.u, exported as top.out
// └─ offset                     u fixed at 0.5
std::unique_ptr<Diagram> nested_diagram() {
  DiagramBuilder actuator_builder("actuator");
  auto& motor = actuator_builder.emplace<Gain>("motor", 2.0, 1);
  actuator_builder.export_input(motor.input_port("u"));
  actuator_builder.export_output(motor.output_port("y"), "torque");

  DiagramBuilder plant_builder("plant");
  auto& actuator = plant_builder.add(actuator_builder.build());
  auto& zoh = plant_builder.emplace<ZeroOrderHold>("zoh", 1, 0.01);
  plant_builder.export_input(actuator.input_port("u"));
  plant_builder.connect(actuator, "torque", zoh, "u");
  plant_builder.export_output(zoh.output_port("y"));

  DiagramBuilder builder("top");
  auto& source = builder.emplace<ConstantSource>("source", Vector::Constant(1, 1.0));
  auto& plant = builder.add(plant_builder.build());
  auto& scale = builder.emplace<Gain>("scale", 0.5, 1);
  auto& offset = builder.emplace<Gain>("offset", 1.0, 1);
  builder.connect(source, "y", plant, "u");
  builder.connect(plant, "y", scale, "u");
  builder.fix_input(offset.input_port("u"), Vector::Constant(1, 0.5));
  builder.export_output(scale.output_port("y"), "out");
  return builder.build();
}

// An adder (two inputs, one output) and a block without ports.
std::unique_ptr<Diagram> uneven_diagram() {
  DiagramBuilder builder("top");
  auto& adder = builder.emplace<testing::Adder>("adder", 3);
  builder.emplace<testing::BlowUp>("portless");
  builder.export_input(adder.input_port("a"));
  builder.export_input(adder.input_port("b"));
  return builder.build();
}

// The DOT text's lines, without their indentation.
std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream stream(text);
  for (std::string line; std::getline(stream, line);) {
    lines.push_back(line.substr(std::min(line.find_first_not_of(' '), line.size())));
  }
  return lines;
}

std::vector<std::string> edges_of(const std::string& text) {
  std::vector<std::string> edges;
  for (const std::string& line : lines_of(text)) {
    if (line.find(" -> ") != std::string::npos) edges.push_back(line);
  }
  return edges;
}

std::vector<std::string> sorted(std::vector<std::string> lines) {
  std::sort(lines.begin(), lines.end());
  return lines;
}

std::string read_file(const fs::path& path) {
  std::ifstream file(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(file), std::istreambuf_iterator<char>()};
}

std::vector<std::string> files_in(const fs::path& directory) {
  std::vector<std::string> names;
  for (const auto& entry : fs::directory_iterator(directory)) {
    names.push_back(entry.path().filename().string());
  }
  return names;
}

using cbbg::testing::ScratchDirectory;

// Sets PATH for the scope of the object, restoring the previous value after.
class PathOverride {
 public:
  explicit PathOverride(const std::string& value) {
    if (const char* previous = std::getenv("PATH")) previous_ = previous;
    ::setenv("PATH", value.c_str(), 1);
  }
  ~PathOverride() {
    if (previous_) {
      ::setenv("PATH", previous_->c_str(), 1);
    } else {
      ::unsetenv("PATH");
    }
  }
  PathOverride(const PathOverride&) = delete;
  PathOverride& operator=(const PathOverride&) = delete;

 private:
  std::optional<std::string> previous_;
};

using cbbg::testing::error_of;

TEST(Graphviz, DrawsEachLeafAsATableWithNameInputsLeftAndOutputsRight) {
  const std::string dot = to_dot(*flat_diagram());
  EXPECT_THAT(
      lines_of(dot),
      Contains(
          R"("top/gain" [shape=plaintext, label=<<table border="0" cellborder="1" )"
          R"(cellspacing="0" cellpadding="4"><tr><td colspan="2"><b>gain</b><br/><font point-size="10">)"
          R"(Gain</font></td></tr><tr><td port="in_u" align="left">u [2]</td><td port="out_y" )"
          R"(align="right">y [2]</td></tr></table>>];)"));
  EXPECT_THAT(
      dot,
      HasSubstr(
          R"(<tr><td colspan="2"><b>hold</b><br/><font point-size="10">ZeroOrderHold</font></td></tr><tr><td port="in_u" )"
          R"(align="left">u [2]</td><td port="out_y" align="right">y [2]</td>)"
          R"(</tr></table>)"));
  // A source has no inputs, so a single column.
  EXPECT_THAT(
      dot,
      HasSubstr(
          R"(<tr><td colspan="1"><b>source</b><br/><font point-size="10">ConstantSource</font></td></tr><tr><td )"
          R"(port="out_y" align="right">y [2]</td></tr></table>)"));
}

// A user's block, a template and an override of the type.
template <int N>
class Sized final : public Block {
 public:
  Sized() : Block("sized") {
    declare_output_port("y", N, [](const BlockContext&, VectorRef y) { y.setZero(); }, {});
  }
};

class Renamed final : public Block {
 public:
  Renamed() : Block("renamed") {
    declare_output_port("y", 1, [](const BlockContext&, VectorRef y) { y.setZero(); }, {});
  }
  std::string type_name() const override { return "DLQR supervisor"; }
};

TEST(Graphviz, WritesEachBlocksTypeUnderItsName) {
  DiagramBuilder builder("top");
  const Block& sized = builder.emplace<Sized<2>>();
  builder.emplace<Renamed>();
  const auto diagram = builder.build();
  EXPECT_EQ(sized.type_name(), "Sized<2>");  // namespaces go, template arguments stay
  const std::string dot = to_dot(*diagram);
  EXPECT_THAT(dot, HasSubstr(R"(<b>sized</b><br/><font point-size="10">Sized&lt;2&gt;</font>)"));
  EXPECT_THAT(dot, HasSubstr(R"(<b>renamed</b><br/><font point-size="10">DLQR supervisor</font>)"));
}

TEST(Graphviz, PadsTheShorterPortColumnWithEmptyCells) {
  const std::string dot = to_dot(*uneven_diagram());
  EXPECT_THAT(
      dot,
      HasSubstr(
          R"(<tr><td colspan="2"><b>adder</b><br/><font point-size="10">Adder</font></td></tr>)"
          R"(<tr><td port="in_a" align="left">a [3]</td><td port="out_y" )"
          R"(align="right">y [3]</td></tr>)"
          R"(<tr><td port="in_b" align="left">b [3]</td><td border="0"></td>)"
          R"(</tr></table>)"));
  EXPECT_THAT(
      dot,
      HasSubstr(
          R"(<tr><td colspan="1"><b>portless</b><br/><font point-size="10">BlowUp</font></td></tr></table>)"));
}

TEST(Graphviz, IsALeftToRightDigraphWithTheRootAsACluster) {
  const std::vector<std::string> lines = lines_of(to_dot(*flat_diagram()));
  ASSERT_FALSE(lines.empty());
  EXPECT_EQ(lines.front(), R"(digraph "top" {)");
  EXPECT_EQ(lines.back(), "}");
  EXPECT_THAT(lines, Contains("rankdir=LR;"));
  EXPECT_THAT(lines, Contains(R"(subgraph "cluster_top" {)"));
  EXPECT_THAT(lines, Contains(R"(label="top";)"));
  EXPECT_THAT(lines, Contains(R"("top.out.held" [shape=cds, label="held [2]"];)"));
}

TEST(Graphviz, DrawsEachConnectionFromOutputCellToInputCell) {
  EXPECT_EQ(edges_of(to_dot(*flat_diagram())),
            (std::vector<std::string>{R"("top/source":out_y -> "top/gain":in_u;)",
                                      R"("top/gain":out_y -> "top/hold":in_u;)",
                                      R"("top/hold":out_y -> "top.out.held";)"}));
}

TEST(Graphviz, DrawsNestedDiagramsAsClustersWithPortNodesWiredInside) {
  const std::string dot = to_dot(*nested_diagram());
  const std::vector<std::string> lines = lines_of(dot);
  EXPECT_THAT(lines, Contains(R"(subgraph "cluster_top" {)"));
  EXPECT_THAT(lines, Contains(R"(subgraph "cluster_top/plant" {)"));
  EXPECT_THAT(lines, Contains(R"(label="plant";)"));
  EXPECT_THAT(lines, Contains(R"(subgraph "cluster_top/plant/actuator" {)"));
  EXPECT_THAT(lines, Contains(R"(label="actuator";)"));
  EXPECT_THAT(lines, Contains(R"("top/plant.in.u" [shape=cds, label="u [1]"];)"));
  EXPECT_THAT(lines, Contains(R"("top/plant.out.y" [shape=cds, label="y [1]"];)"));
  EXPECT_THAT(lines, Contains(R"("top/plant/actuator.in.u" [shape=cds, label="u [1]"];)"));
  EXPECT_THAT(lines,
              Contains(R"("top/plant/actuator.out.torque" [shape=cds, label="torque [1]"];)"));
  EXPECT_THAT(dot, HasSubstr(R"("top/plant/actuator/motor" [shape=plaintext, label=<)"));
  EXPECT_THAT(dot, HasSubstr(R"("top/plant/zoh" [shape=plaintext, label=<)"));
  // An expanded diagram is no box of its own.
  EXPECT_THAT(dot, Not(HasSubstr(R"("top/plant" [)")));

  EXPECT_EQ(sorted(edges_of(dot)),
            sorted({R"("top/source":out_y -> "top/plant.in.u";)",
                    R"("top/plant.in.u" -> "top/plant/actuator.in.u";)",
                    R"("top/plant/actuator.in.u" -> "top/plant/actuator/motor":in_u;)",
                    R"("top/plant/actuator/motor":out_y -> "top/plant/actuator.out.torque";)",
                    R"("top/plant/actuator.out.torque" -> "top/plant/zoh":in_u;)",
                    R"("top/plant/zoh":out_y -> "top/plant.out.y";)",
                    R"("top/plant.out.y" -> "top/scale":in_u;)",
                    R"("top/offset.in.u.fixed" -> "top/offset":in_u;)",
                    R"("top/scale":out_y -> "top.out.out";)"}));
}

TEST(Graphviz, NestsEachClusterInsideItsParent) {
  const std::string dot = to_dot(*nested_diagram());
  const auto top = dot.find(R"(subgraph "cluster_top" {)");
  const auto plant = dot.find(R"(subgraph "cluster_top/plant" {)");
  const auto actuator = dot.find(R"(subgraph "cluster_top/plant/actuator" {)");
  const auto motor = dot.find(R"("top/plant/actuator/motor" [)");
  ASSERT_NE(top, std::string::npos);
  ASSERT_NE(plant, std::string::npos);
  ASSERT_NE(actuator, std::string::npos);
  ASSERT_NE(motor, std::string::npos);
  EXPECT_LT(top, plant);
  EXPECT_LT(plant, actuator);
  EXPECT_LT(actuator, motor);
  // Indented two spaces per level: root cluster 1, plant 2, actuator 3, motor 4.
  EXPECT_THAT(dot, HasSubstr("\n      subgraph \"cluster_top/plant/actuator\" {\n"));
  EXPECT_THAT(dot, HasSubstr("\n        \"top/plant/actuator/motor\" ["));
}

TEST(Graphviz, LeavesHiddenBlocksAndTheirEdgesOut) {
  const std::string dot = to_dot(*flat_diagram(), {.hidden_blocks = {"top/gain"}});
  EXPECT_THAT(dot, ::testing::Not(HasSubstr("\"top/gain\"")));
  EXPECT_THAT(dot, HasSubstr("\"top/source\" [shape=plaintext"));
  EXPECT_THAT(to_dot(*flat_diagram()), HasSubstr("\"top/gain\""));
}

TEST(Graphviz, DepthZeroCollapsesEverySubDiagramIntoABoxWithItsPorts) {
  const std::string dot = to_dot(*nested_diagram(), {.max_depth = 0});
  EXPECT_THAT(dot, HasSubstr(R"(subgraph "cluster_top" {)"));
  EXPECT_THAT(dot, Not(HasSubstr("cluster_top/plant")));
  EXPECT_THAT(dot, Not(HasSubstr("actuator")));
  EXPECT_THAT(dot, Not(HasSubstr("motor")));
  EXPECT_THAT(dot, Not(HasSubstr("zoh")));
  EXPECT_THAT(
      lines_of(dot),
      Contains(
          R"("top/plant" [shape=plaintext, label=<<table border="0" )"
          R"(cellborder="1" cellspacing="0" cellpadding="4"><tr><td colspan="2" )"
          R"(bgcolor="lightgrey"><b>plant</b><br/><font point-size="10">Diagram</font></td></tr><tr><td port="in_u" )"
          R"(align="left">u [1]</td><td port="out_y" align="right">y [1]</td>)"
          R"(</tr></table>>];)"));
  EXPECT_EQ(sorted(edges_of(dot)), sorted({R"("top/source":out_y -> "top/plant":in_u;)",
                                           R"("top/plant":out_y -> "top/scale":in_u;)",
                                           R"("top/offset.in.u.fixed" -> "top/offset":in_u;)",
                                           R"("top/scale":out_y -> "top.out.out";)"}));
}

TEST(Graphviz, DepthOneExpandsTheRootsChildrenButNotTheirSubDiagrams) {
  const std::string dot = to_dot(*nested_diagram(), {.max_depth = 1});
  EXPECT_THAT(dot, HasSubstr(R"(subgraph "cluster_top/plant" {)"));
  EXPECT_THAT(dot, HasSubstr(R"("top/plant/zoh" [shape=plaintext)"));
  EXPECT_THAT(dot, Not(HasSubstr("cluster_top/plant/actuator")));
  EXPECT_THAT(dot, Not(HasSubstr("motor")));
  EXPECT_THAT(dot, HasSubstr(R"("top/plant/actuator" [shape=plaintext)"));
  const std::vector<std::string> edges = edges_of(dot);
  EXPECT_THAT(edges, Contains(R"("top/plant.in.u" -> "top/plant/actuator":in_u;)"));
  EXPECT_THAT(edges, Contains(R"("top/plant/actuator":out_torque -> "top/plant/zoh":in_u;)"));
  EXPECT_EQ(edges.size(), 7u);
}

TEST(Graphviz, DepthTwoOrNegativeExpandsEverything) {
  const std::string all = to_dot(*nested_diagram());
  EXPECT_EQ(to_dot(*nested_diagram(), {.max_depth = 2}), all);
  EXPECT_EQ(to_dot(*nested_diagram(), {.max_depth = 7}), all);
  EXPECT_EQ(to_dot(*nested_diagram(), {.max_depth = -3}), all);
}

TEST(Graphviz, DrawsFixedInputsAsValueNodes) {
  EXPECT_THAT(lines_of(to_dot(*nested_diagram())),
              Contains(R"("top/offset.in.u.fixed" [shape=plaintext, label="0.5"];)"));

  DiagramBuilder builder("top");
  auto& pair = builder.emplace<Gain>("pair", 1.0, 2);
  auto& many = builder.emplace<Gain>("many", 1.0, 7);
  builder.fix_input(pair.input_port("u"), (Vector(2) << 1.0, -2.5).finished());
  builder.fix_input(many.input_port("u"), Vector::LinSpaced(7, 0.0, 6.0));
  const std::string dot = to_dot(*builder.build());
  const std::vector<std::string> lines = lines_of(dot);
  EXPECT_THAT(lines, Contains(R"("top/pair.in.u.fixed" [shape=plaintext, label="[1, -2.5]"];)"));
  EXPECT_THAT(lines, Contains(R"("top/many.in.u.fixed" [shape=plaintext, )"
                              R"(label="[0, 1, 2, 3, 4, 5, ... (7 values)]"];)"));
  EXPECT_EQ(edges_of(dot),
            (std::vector<std::string>{R"("top/pair.in.u.fixed" -> "top/pair":in_u;)",
                                      R"("top/many.in.u.fixed" -> "top/many":in_u;)"}));
}

TEST(Graphviz, FixedInputOfAnExpandedSubDiagramFeedsItsPortNode) {
  DiagramBuilder inner_builder("inner");
  auto& gain = inner_builder.emplace<Gain>("gain", 1.0, 1);
  inner_builder.export_input(gain.input_port("u"), "level");
  DiagramBuilder builder("top");
  auto& inner = builder.add(inner_builder.build());
  builder.fix_input(inner.input_port("level"), Vector::Constant(1, 4.0));
  const std::string dot = to_dot(*builder.build());
  EXPECT_THAT(lines_of(dot),
              Contains(R"("top/inner.in.level.fixed" [shape=plaintext, label="4"];)"));
  EXPECT_EQ(edges_of(dot),
            (std::vector<std::string>{R"("top/inner.in.level" -> "top/inner/gain":in_u;)",
                                      R"("top/inner.in.level.fixed" -> "top/inner.in.level";)"}));
}

TEST(Graphviz, IdenticalDiagramsGiveIdenticalText) {
  EXPECT_EQ(to_dot(*nested_diagram()), to_dot(*nested_diagram()));
  EXPECT_EQ(to_dot(*flat_diagram()), to_dot(*flat_diagram()));
  EXPECT_EQ(to_dot(*nested_diagram(), {.max_depth = 1}),
            to_dot(*nested_diagram(), {.max_depth = 1}));
}

// Runs the installed `dot` on the text directly (not through render_dot) and returns what it
// printed, with its exit status.
std::pair<int, std::string> run_dot_on(const std::string& dot, const fs::path& directory) {
  const fs::path input = directory / "input.dot";
  std::ofstream(input) << dot;
  const std::string command = "dot -Tsvg -o /dev/null '" + input.string() + "' 2>&1";
  FILE* pipe = ::popen(command.c_str(), "r");
  if (pipe == nullptr) return {-1, "popen failed"};
  std::string printed;
  char buffer[512];
  while (std::fgets(buffer, sizeof(buffer), pipe) != nullptr) printed += buffer;
  return {::pclose(pipe), printed};
}

TEST(Graphviz, DotAcceptsTheTextWithoutAWord) {
  ScratchDirectory directory;
  for (const int depth : {-1, 0, 1}) {
    const auto [status, printed] =
        run_dot_on(to_dot(*nested_diagram(), {.max_depth = depth}), directory.path());
    EXPECT_EQ(status, 0) << "max_depth " << depth;
    EXPECT_EQ(printed, "") << "max_depth " << depth;
  }
  for (const auto& diagram : {flat_diagram(), uneven_diagram()}) {
    const auto [status, printed] = run_dot_on(to_dot(*diagram), directory.path());
    EXPECT_EQ(status, 0) << diagram->name();
    EXPECT_EQ(printed, "") << diagram->name();
  }
}

TEST(Graphviz, RendersSvgAndPngThroughDot) {
  ScratchDirectory directory;
  const std::string dot = to_dot(*nested_diagram());
  render_dot(dot, directory.path() / "nested.svg");
  render_dot(dot, directory.path() / "nested.png");
  EXPECT_THAT(read_file(directory.path() / "nested.svg"), StartsWith("<?xml"));
  EXPECT_THAT(read_file(directory.path() / "nested.svg"), HasSubstr("<svg"));
  EXPECT_THAT(read_file(directory.path() / "nested.png"), StartsWith("\x89PNG\r\n"));
  // Nothing left behind but the two pictures.
  EXPECT_EQ(sorted(files_in(directory.path())), sorted({"nested.svg", "nested.png"}));
}

TEST(Graphviz, WritesDotFilesAsIsWithoutNeedingDot) {
  ScratchDirectory directory;
  const PathOverride no_dot(directory.path().string());
  const std::string dot = to_dot(*flat_diagram());
  render_dot(dot, directory.path() / "flat.dot");
  EXPECT_EQ(read_file(directory.path() / "flat.dot"), dot);
  EXPECT_EQ(files_in(directory.path()), (std::vector<std::string>{"flat.dot"}));
}

TEST(Graphviz, ReplacesItsOwnDrawingWhole) {
  ScratchDirectory directory;
  const fs::path output = directory.path() / "picture.dot";
  render_dot(to_dot(*nested_diagram()), output);
  render_dot("digraph {}\n", output);
  // A text written elsewhere gets the tag, so that this drawing too may be replaced later.
  EXPECT_EQ(read_file(output), "digraph { comment=\"made by cbbg\";}\n");
  render_dot("digraph {}\n", output);
}

TEST(Graphviz, EveryDrawingCarriesTheGeneratorTag) {
  ScratchDirectory directory;
  const std::string dot = to_dot(*flat_diagram());
  for (const char* name : {"a.dot", "a.svg", "a.png"}) {
    render_dot(dot, directory.path() / name);
    EXPECT_THAT(read_file(directory.path() / name), HasSubstr(kDiagramGeneratorTag)) << name;
  }
  // The PNG's text chunk sits after IHDR, where image readers expect metadata.
  EXPECT_EQ(read_file(directory.path() / "a.png").substr(37, 12), "tEXtSoftware");
}

TEST(Graphviz, NeverReplacesAUsersFileOrOpensAFifo) {
  ScratchDirectory directory;
  const fs::path mine = directory.path() / "mine.svg";
  std::ofstream(mine) << "<svg>my drawing</svg>";
  EXPECT_THAT([&] { render_dot(to_dot(*flat_diagram()), mine); },
              ThrowsMessage<std::invalid_argument>(
                  "cannot render '" + mine.string() +
                  "': it exists and cbbg did not write it; cbbg never replaces a file of yours"));
  EXPECT_EQ(read_file(mine), "<svg>my drawing</svg>");
  const fs::path fifo = directory.path() / "pipe.dot";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0644), 0);
  EXPECT_THAT([&] { render_dot("digraph {}", fifo); },
              ThrowsMessage<std::invalid_argument>("cannot render '" + fifo.string() +
                                                   "': it is a FIFO; give a regular file's path"));
}

TEST(Graphviz, MissingDotProgramIsAClearError) {
  ScratchDirectory directory;
  const fs::path empty = directory.path() / "empty_bin";
  fs::create_directories(empty);
  const fs::path output = directory.path() / "x.svg";
  {
    const PathOverride no_dot(empty.string());
    EXPECT_EQ(error_of<std::runtime_error>([&] { render_dot(to_dot(*flat_diagram()), output); }),
              "cannot render '" + output.string() +
                  "': the Graphviz program 'dot' was not found on PATH; install the Debian "
                  "package 'graphviz' or write a .dot file");
  }
  EXPECT_FALSE(fs::exists(output));
  // The environment is as it was: dot is found again.
  render_dot(to_dot(*flat_diagram()), output);
  EXPECT_TRUE(fs::exists(output));
}

TEST(Graphviz, UnknownExtensionNamesTheFileAndTheAllowedOnes) {
  EXPECT_EQ(error_of<std::invalid_argument>([] { render_dot("digraph {}", "diagram.pdf"); }),
            "cannot render 'diagram.pdf': unknown extension '.pdf'; the allowed extensions are "
            ".dot, .svg and .png");
  EXPECT_EQ(error_of<std::invalid_argument>([] { render_dot("digraph {}", "diagram"); }),
            "cannot render 'diagram': it has no extension; the allowed extensions are .dot, .svg "
            "and .png");
  EXPECT_FALSE(fs::exists("diagram.pdf"));
}

TEST(Graphviz, FailingDotReportsItsExitStatusAndLeavesNoFile) {
  ScratchDirectory directory;
  const fs::path output = directory.path() / "broken.svg";
  const std::string message =
      error_of<std::runtime_error>([&] { render_dot("digraph { a -> ; }", output); });
  EXPECT_THAT(message, StartsWith("cannot render '" + output.string() + "': '"));
  EXPECT_THAT(message, HasSubstr("dot' exited with status 1: "));
  EXPECT_THAT(message, HasSubstr("syntax error in line 1"));
  EXPECT_TRUE(files_in(directory.path()).empty());
}

TEST(Graphviz, UnwritableDirectoryIsAnError) {
  ScratchDirectory directory;
  const fs::path output = directory.path() / "missing" / "x.dot";
  EXPECT_THAT(error_of<std::runtime_error>([&] { render_dot("digraph {}", output); }),
              StartsWith("cannot write '" + output.string() + "': No such file or directory"));
}

}  // namespace
}  // namespace cbbg
