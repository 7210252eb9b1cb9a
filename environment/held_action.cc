#include "cbbg/environment/held_action.h"

#include "cbbg/framework/block_context.h"

namespace cbbg::environment {

HeldAction::HeldAction(std::string name) : Block(std::move(name)) {
  declare_discrete_state("action", Vector::Zero(1), StateLifetime::kPerTrial);
  declare_output_port<&HeldAction::calc_action>(
      "action", 1, {}, "the action last set from outside, N m", OutputSources::kDiscreteState);
}

void HeldAction::calc_action(const BlockContext& context, VectorRef action) const {
  action = context.discrete_state();
}

void HeldAction::set(Context& context, double action) const {
  context.discrete_state(*this)[0] = action;
}

}  // namespace cbbg::environment
