#pragma once
// A supervisor of a user's, for the tests of the controller's slots and interface: a PD law
// on the pitch alone, a_S = 40 theta_b + 8 theta_b'. Input "measured" (6), output "action".

#include <string>

#include "cbbg/blocks/measured_signals.h"
#include "cbbg/framework/block.h"
#include "cbbg/framework/block_context.h"

namespace cbbg::diagrams::testing {

class PitchSupervisor final : public Block {
 public:
  explicit PitchSupervisor(std::string name) : Block(std::move(name)) {
    const InputPort& measured = declare_input_port("measured", blocks::kMeasuredSize);
    declare_output_port("action", 1,
                        [&measured](const BlockContext& context, VectorRef action) {
                          const auto y = context.input(measured);
                          action[0] = 40.0 * y[blocks::kMeasuredThetaB] +
                                      8.0 * y[blocks::kMeasuredThetaBDot];
                        },
                        {&measured});
  }
};

}  // namespace cbbg::diagrams::testing
