#include "cbbg/blocks/mixer.h"

#include "cbbg/framework/block_context.h"

namespace cbbg::blocks {

Mixer::Mixer(std::string name) : Block(std::move(name)) {
  exploration_action_ = &declare_input_port("exploration_action", 1, "a_E");
  supervisor_action_ = &declare_input_port("supervisor_action", 1, "a_S");
  omega_ = &declare_input_port("omega", 1, "omega");
  declare_output_port<&Mixer::calc_action>("action", 1,
                                           {exploration_action_, supervisor_action_, omega_},
                                           "a = omega a_E + (1 - omega) a_S");
}

void Mixer::calc_action(const BlockContext& context, VectorRef action) const {
  const double w = context.input(*omega_)[0];
  action[0] = w * context.input(*exploration_action_)[0] +
              (1.0 - w) * context.input(*supervisor_action_)[0];
}

codegen::CCalculation Mixer::c_calculation(int, const Context&) const {
  // in0: a_E, in1: a_S, in2: omega, as the output reads them.
  return {{}, "  out[0] = in2[0] * in0[0] + ((real)1 - in2[0]) * in1[0];\n"};
}

}  // namespace cbbg::blocks
