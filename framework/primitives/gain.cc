#include "cbbg/framework/primitives/gain.h"

#include "cbbg/framework/block_context.h"

namespace cbbg {

Gain::Gain(std::string name, double gain, int size) : Block(std::move(name)), gain_(gain) {
  const InputPort& u = declare_input_port("u", size);
  declare_output_port(
      "y", size,
      [this, &u](const BlockContext& context, VectorRef y) { y = gain_ * context.input(u); }, {&u});
}

}  // namespace cbbg
