#pragma once
// The calculations an export needs, found from the outputs it writes through direct
// feedthrough, in the order they must run (c_export.cc, c_learner_export.cc).

#include <map>
#include <string>
#include <vector>

#include "cbbg/codegen/c_calculation.h"
#include "cbbg/framework/types.h"

namespace cbbg {
class Block;
class Context;
class Diagram;
class InputPort;
class OutputPort;
}  // namespace cbbg

namespace cbbg::codegen {

// One output's calculation: its block, and the arrays its inputs are read from (C
// expressions: a step's signal "sK", an argument, or a constant "$NAME" of Walk::fixed).
struct Step {
  const Block* block = nullptr;
  int output = 0;
  int size = 0;
  std::vector<std::string> inputs;
  CCalculation calculation;
};

// An array the exported function takes: a root input, or an output the export reads as given.
struct Argument {
  std::string name;
  int size = 0;
};

// A block whose state and updates the learner carries: every input and output, as arrays.
struct UpdatedBlock {
  const Block* block = nullptr;
  std::vector<std::string> inputs;
  std::vector<std::string> outputs;
};

struct WalkOptions {
  // Outputs read as another output, and outputs held at a value (CExportOptions).
  std::map<const OutputPort*, const OutputPort*> read_as;
  std::map<const OutputPort*, double> held;
  // Outputs the exported function takes as arguments of these names.
  std::map<const OutputPort*, std::string> given;
  // Whether blocks with state or updates bring every input and output they have (a learner).
  bool updates = false;
};

class Walk {
 public:
  Walk(const Diagram& root, const Context& context, WalkOptions options);

  // The name of the array that holds `port`'s values once the steps it needs have run.
  std::string visit(const OutputPort& port);
  // With WalkOptions::updates: every output and input of each block with state or updates
  // found so far, and of those they bring in turn, into `updated`.
  void visit_updated_blocks();

  std::vector<Step> steps;
  std::vector<Argument> arguments;  // in the order first read
  std::vector<CConstant> fixed;     // values fixed at build that the steps read
  std::vector<UpdatedBlock> updated;

 private:
  std::string source_of(const InputPort& input);
  std::string argument(const std::string& name, int size);
  std::string constant(const char* kind, const Vector& values);
  std::string visit_leaf(const OutputPort& port);

  const Diagram& root_;
  const Context& context_;
  WalkOptions options_;
  std::map<const OutputPort*, std::string> visited_;
  std::vector<const Block*> pending_;  // blocks with updates, found and not yet brought
};

// Whether `block` has discrete state or updates: the learner carries it.
bool is_updated(const Block& block);

}  // namespace cbbg::codegen
