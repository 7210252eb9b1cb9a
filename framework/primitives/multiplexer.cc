#include "cbbg/framework/primitives/multiplexer.h"

#include <algorithm>

#include "cbbg/framework/block_context.h"

namespace cbbg {

Multiplexer::Multiplexer(std::string name, const std::vector<Input>& inputs)
    : Block(std::move(name)) {
  int total = 0;
  for (const auto& input : inputs) {
    inputs_.push_back(&declare_input_port(input.name, input.size));
    total += input.size;
  }
  declare_output_port<&Multiplexer::calc_y>("y", total, inputs_, "the inputs, concatenated",
                                            OutputSources::kDiscreteState);
}

void Multiplexer::calc_y(const BlockContext& context, VectorRef y) const {
  // Plain copies: most inputs are one value, where a call to memcpy, or Eigen's sized
  // segment assignment, costs more than the copy.
  double* out = y.data();
  for (const InputPort* port : inputs_) {
    const double* in = context.input(*port).data();
    if (port->size() == 1) {
      *out++ = *in;
    } else {
      out = std::copy_n(in, port->size(), out);
    }
  }
}

}  // namespace cbbg
