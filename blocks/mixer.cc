#include "cbbg/blocks/mixer.h"

#include "cbbg/framework/block_context.h"

namespace cbbg::blocks {

Mixer::Mixer(std::string name) : Block(std::move(name)) {
  const InputPort& exploration = declare_input_port("exploration_action", 1, "a_E");
  const InputPort& supervisor = declare_input_port("supervisor_action", 1, "a_S");
  const InputPort& omega = declare_input_port("omega", 1, "omega");
  declare_output_port(
      "action", 1,
      [&exploration, &supervisor, &omega](const BlockContext& context, VectorRef action) {
        const double w = context.input(omega)[0];
        action[0] = w * context.input(exploration)[0] + (1.0 - w) * context.input(supervisor)[0];
      },
      {&exploration, &supervisor, &omega}, "a = omega a_E + (1 - omega) a_S");
}

codegen::CCalculation Mixer::c_calculation(int, const Context&) const {
  // in0: a_E, in1: a_S, in2: omega, as the output reads them.
  return {{}, "  out[0] = in2[0] * in0[0] + ((real)1 - in2[0]) * in1[0];\n"};
}

}  // namespace cbbg::blocks
