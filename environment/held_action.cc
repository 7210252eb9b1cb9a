#include "cbbg/environment/held_action.h"

#include "cbbg/framework/block_context.h"

namespace cbbg::environment {

HeldAction::HeldAction(std::string name) : Block(std::move(name)) {
  declare_discrete_state("action", Vector::Zero(1), StateLifetime::kPerTrial);
  declare_output_port(
      "action", 1,
      [](const BlockContext& context, VectorRef action) { action = context.discrete_state(); }, {},
      "the action last set from outside, N m", OutputSources::kDiscreteState);
}

void HeldAction::set(Context& context, double action) const {
  context.discrete_state(*this)[0] = action;
}

}  // namespace cbbg::environment
