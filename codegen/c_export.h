#pragma once
// The C99 of one output of a diagram, as a function of the diagram's inputs it reads: what
// `cbbg export` writes of a learnt policy. Each block the output needs (through direct
// feedthrough) writes its own calculation (c_calculation.h's EmitsC; the framework's
// ConstantSource is written as its constant); the exporter orders them, gives each its
// constants and one C function, and calls them in turn from
//
//   NAME_real NAME_step(const NAME_real IN[IN_SIZE], ...);   /* one array per input read */
//
// The code needs no heap, keeps no state (every constant is `static const`; the signals
// between blocks are locals of NAME_step), uses only <math.h>'s exp and sqrt, and no stdio.

#include <map>
#include <string>
#include <vector>

#include "cbbg/codegen/c_calculation.h"

namespace cbbg {
class Context;
class Diagram;
class OutputPort;
}  // namespace cbbg

namespace cbbg::codegen {

// The version of the exported code's shape (its functions and macros), NAME_EXPORT_VERSION.
inline constexpr int kExportVersion = 1;

struct CExportOptions {
  std::string name = "cbbg_policy";  // the files' and the identifiers' prefix: a C identifier
  Scalar scalar = Scalar::kDouble;
  // Lines of the head comment of both files: where the code comes from (weights, keys).
  std::vector<std::string> provenance;
  // Outputs the export reads as another output (the exploration's read as the actor's: no
  // exploration), and outputs it holds at a value (omega held).
  std::map<const OutputPort*, const OutputPort*> read_as{};
  std::map<const OutputPort*, double> held{};
};

struct CSources {
  std::string header;  // NAME.h
  std::string source;  // NAME.c
};

// The C of `output`, an output of size 1 of a leaf block inside `root`, with the state of
// `context` (a context of `root` or of a diagram that holds it). Throws std::invalid_argument
// naming the block that cannot be written as C, an output of size other than 1, or a name
// that is no C identifier.
CSources export_c(const Diagram& root, const OutputPort& output, const Context& context,
                  const CExportOptions& options);

// Whether `name` is a C identifier: a letter or '_', then letters, digits and '_'.
bool is_c_identifier(const std::string& name);

}  // namespace cbbg::codegen
