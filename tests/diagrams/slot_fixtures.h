#pragma once
// What the tests of the controller's slots and interface share: a quick config, and a
// supervisor of a user's.

#include <string>

#include "cbbg/blocks/measured_signals.h"
#include "cbbg/framework/block.h"
#include "cbbg/framework/block_context.h"
#include "cbbg/parameters/parameters.h"

namespace cbbg::diagrams::testing {

// The analytic plant keeps these tests quick; two seeds, no steps.csv.
inline config::Config quick_config() {
  config::Config config;
  config.set("plant.kind=analytic");
  config.set("seeds=2");
  config.set("log.decimation=0");
  return config;
}

inline parameters::Parameters quick_parameters() {
  return parameters::read_parameters(quick_config());
}

// A PD law on the pitch alone, a_S = 40 theta_b + 8 theta_b'. Input "measured" (6), output
// "action".
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
