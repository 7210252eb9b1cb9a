#pragma once
// Graphviz pictures of a diagram: DOT text, and rendering it through the `dot` program.
//
// to_dot draws every block as a box with its name on top, its input ports in the left column
// and its output ports in the right ("torque [2]": name and size); each connection is an edge
// from an output cell to an input cell; a sub-diagram drawn collapsed is such a box with a
// grey name band. The root diagram and each expanded sub-diagram is a cluster labelled with
// its name, whose exported ports are small arrow-shaped nodes inside it, wired to the inner
// ports they stand for. A fixed input is a plain text node showing its value, with an edge
// into the port. Node ids are block paths, so the text is the same, byte for byte, for the
// same diagram.
//
// Usage:
//
//   std::unique_ptr<cbbg::Diagram> diagram = builder.build();
//   cbbg::render_dot(cbbg::to_dot(*diagram), "controller.svg");
//   // Only the top level, each sub-diagram as one box:
//   cbbg::render_dot(cbbg::to_dot(*diagram, {.max_depth = 0}), "overview.dot");

#include <filesystem>
#include <string>
#include <vector>

#include "cbbg/framework/diagram.h"

namespace cbbg {

struct GraphvizOptions {
  // How deep to draw nested diagrams. The root's children are at depth 1, their children at
  // depth 2, and so on; a sub-diagram at depth d is drawn with its contents when
  // d <= max_depth, else as one box with its ports. Negative: expand every sub-diagram.
  // 0 draws the root's children only.
  int max_depth = -1;
  // Paths of blocks left out of the picture with every edge to or from them: loggers and
  // other taps that read many signals would otherwise cover it in wires.
  std::vector<std::string> hidden_blocks{};
};

// Every drawing render_dot writes carries this tag (a DOT and SVG comment, a PNG text chunk),
// so a later command knows the file as cbbg's own and may replace it.
inline constexpr const char* kDiagramGeneratorTag = "made by cbbg";

// The DOT text (a `digraph`, laid out left to right) of `diagram` and everything inside it.
std::string to_dot(const Diagram& diagram, const GraphvizOptions& options = {});

// Writes `dot` to `output`, by its extension: ".dot" as is; ".svg" or ".png" rendered by the
// Graphviz program `dot`, looked up on PATH. The file appears complete or not at all.
// Replaces only a drawing it wrote (one carrying kDiagramGeneratorTag). Throws
// std::invalid_argument for any other extension, for a file of the user's or a FIFO, socket
// or device at `output` (never opened), and std::runtime_error when `dot` is
// not on PATH, when it fails (with its exit status and what it printed), or when the file
// cannot be written.
void render_dot(const std::string& dot, const std::filesystem::path& output);

}  // namespace cbbg
