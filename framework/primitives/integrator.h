#pragma once

#include "cbbg/framework/block.h"

namespace cbbg {

/// Integrator: integrates its input in continuous time, from an initial value:
///
///   x' = u,  x(0) = initial value,  y = x
///
/// | port | dir | size | meaning                      |
/// |------|-----|------|------------------------------|
/// | u    | in  | n    | the rate x'                  |
/// | y    | out | n    | x, the integral from x(0)    |
///
/// x is continuous state, which the simulator integrates (simulator.h step 3). y reads only
/// x, never u directly: an integrator breaks feedback loops. Like all continuous state, x is
/// kept by Context::reset_trial_state; Context::reset_state(block) puts it back to its
/// initial value.
class Integrator final : public Block {
 public:
  // From zero. Throws std::invalid_argument naming the block unless size >= 1.
  Integrator(std::string name, int size);
  // From `initial_value` (n = its size). Throws std::invalid_argument naming the block
  // unless it has at least one element and every element is finite.
  Integrator(std::string name, const Vector& initial_value);

 private:
  // x' = u.
  void calc_derivatives(const BlockContext& context, VectorRef x_dot) const;
  // "y": x.
  void calc_y(const BlockContext& context, VectorRef y) const;

  const InputPort* u_;
};

}  // namespace cbbg
