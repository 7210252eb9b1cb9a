#include "cbbg/framework/primitives/multiplexer.h"

#include <algorithm>

#include "cbbg/framework/block_context.h"

namespace cbbg {

Multiplexer::Multiplexer(std::string name, const std::vector<Input>& inputs)
    : Block(std::move(name)) {
  std::vector<const InputPort*> ports;
  int total = 0;
  for (const auto& input : inputs) {
    ports.push_back(&declare_input_port(input.name, input.size));
    total += input.size;
  }
  declare_output_port(
      "y", total,
      [ports](const BlockContext& context, VectorRef y) {
        // Plain copies: most inputs are a value or two, where Eigen's sized segment
        // assignment costs more than the copy.
        double* out = y.data();
        for (const InputPort* port : ports) {
          out = std::copy_n(context.input(*port).data(), port->size(), out);
        }
      },
      ports, "the inputs, concatenated");
}

}  // namespace cbbg
