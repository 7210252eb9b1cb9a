#include "cbbg/framework/primitives/demultiplexer.h"

#include <algorithm>
#include <stdexcept>

#include "cbbg/framework/block_context.h"
#include "cbbg/framework/primitives/argument_checks.h"

namespace cbbg {

Demultiplexer::Demultiplexer(std::string name, const std::vector<Output>& outputs)
    : Block(std::move(name)) {
  const std::string block = primitive_checks::label("Demultiplexer", this->name());
  if (outputs.empty()) {
    throw std::invalid_argument(block + ": no outputs; give at least one");
  }
  int total = 0;
  for (const auto& output : outputs) {
    if (output.size < 1) {
      throw std::invalid_argument(block + ": output '" + output.name + "' has size " +
                                  std::to_string(output.size) + "; a size is at least 1");
    }
    total += output.size;
  }
  const InputPort& u = declare_input_port("u", total, "the vector to split");
  int offset = 0;
  // Each output's calculation is a lambda, not a named calculation: one member function would not
  // know which output it computes, and the lambda carries its offset.
  for (const auto& output : outputs) {
    declare_output_port(
        output.name, output.size,
        [&u, offset](const BlockContext& context, VectorRef y) {
          // A plain copy, as Multiplexer's: most cuts are a value or two.
          std::copy_n(context.input(u).data() + offset, y.size(), y.data());
        },
        {&u}, "u from element " + std::to_string(offset), OutputSources::kDiscreteState);
    offset += output.size;
  }
}

}  // namespace cbbg
