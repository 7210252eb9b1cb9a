#pragma once

#include <string>

#include "cbbg/framework/block.h"
#include "cbbg/framework/context.h"

namespace cbbg::environment {

/// HeldAction: an action set from outside the simulation, by whoever steps it (an agent
/// through BalanceEnvironment::step), and held until it is set again.
///
/// | port   | dir | size | meaning                         |
/// |--------|-----|------|---------------------------------|
/// | action | out | 1    | the last action set, N m        |
///
/// The output reads the block's discrete state and nothing else, so a value written between
/// two advances of the simulator is what the closed loop's hold samples at the next tick.
/// Discrete state, per trial: action (0 at the start of a trial).
class HeldAction final : public Block {
 public:
  explicit HeldAction(std::string name);

  // Writes `action` into this block's state in `context` (a context of the root diagram).
  void set(Context& context, double action) const;

 private:
  // "action": the discrete state, the last action set.
  void calc_action(const BlockContext& context, VectorRef action) const;
};

}  // namespace cbbg::environment
