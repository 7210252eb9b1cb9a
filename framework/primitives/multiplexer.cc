#include "framework/primitives/multiplexer.h"

#include "framework/block_context.h"

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
        int offset = 0;
        for (const InputPort* port : ports) {
          y.segment(offset, port->size()) = context.input(*port);
          offset += port->size();
        }
      },
      ports, "the inputs, concatenated");
}

}  // namespace cbbg
