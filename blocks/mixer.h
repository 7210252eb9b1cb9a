#pragma once

#include <string>

#include "cbbg/codegen/c_calculation.h"
#include "cbbg/framework/block.h"

namespace cbbg::blocks {

/// Mixer: the action sent to the motors, between exploration and supervision (docs/model.md §2.8).
///
/// | port               | dir | size | meaning                     |
/// |--------------------|-----|------|-----------------------------|
/// | exploration_action | in  | 1    | a_E, from the sampler       |
/// | supervisor_action  | in  | 1    | a_S, from the supervisor    |
/// | omega              | in  | 1    | omega, from OmegaSchedule   |
/// | action             | out | 1    | a, N m                      |
///
/// Equation: a = omega a_E + (1 - omega) a_S. The plant saturates the torque, not the mixer.
/// No parameters.
class Mixer final : public Block, public codegen::EmitsC {
 public:
  explicit Mixer(std::string name);

  // "action" as C (cbbg export --omega).
  codegen::CCalculation c_calculation(int output, const Context& context) const override;

 private:
  // "action": a = omega a_E + (1 - omega) a_S.
  void calc_action(const BlockContext& context, VectorRef action) const;

  const InputPort* exploration_action_;
  const InputPort* supervisor_action_;
  const InputPort* omega_;
};

}  // namespace cbbg::blocks
