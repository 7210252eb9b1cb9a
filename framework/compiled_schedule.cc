#include "cbbg/framework/compiled_schedule.h"

#include <algorithm>

namespace cbbg {

void CompiledSchedule::compile(const Diagram& diagram, Context& context) {
  compile_outputs(diagram, context, diagram.evaluation_order(), outputs_);
  compile_outputs(diagram, context, diagram.interval_input_order(), interval_inputs_);
  compile_outputs(diagram, context, diagram.stage_input_order(), stage_inputs_);

  derivatives_.clear();
  for (const int index : diagram.ode_leaves()) {
    const LeafLayout& leaf = diagram.leaves()[static_cast<size_t>(index)];
    derivatives_.push_back({&leaf.block->derivative_function(), BlockContext(context, leaf),
                            leaf.continuous_offset, leaf.block->initial_continuous_state().size()});
  }

  leaves_.clear();
  for (const LeafLayout& leaf : diagram.leaves()) {
    const auto& updates = leaf.block->periodic_updates();
    const bool in_place = updates.size() == 1 && updates[0].writes == UpdateWrites::kInPlace;
    double* state = context.discrete_states().data() + leaf.discrete_offset;
    leaves_.push_back(
        {BlockContext(context, leaf), state,
         in_place ? state : context.next_discrete_states().data() + leaf.discrete_offset,
         leaf.block->initial_discrete_state().size(), leaf.block});
  }
}

void CompiledSchedule::compile_outputs(const Diagram& diagram, Context& context,
                                       const std::vector<OutputSlot>& order,
                                       std::vector<OutputCall>& calls) {
  calls.clear();
  for (const OutputSlot& slot : order) {
    const LeafLayout& leaf = diagram.leaves()[static_cast<size_t>(slot.leaf)];
    const auto port = static_cast<size_t>(slot.port);
    calls.push_back({&leaf.block->output_function(slot.port), BlockContext(context, leaf),
                     context.signals().data() + leaf.output_offsets[port],
                     leaf.output_sizes[port]});
  }
}

void CompiledSchedule::compute_derivatives(double* derivatives) const {
  for (const DerivativeCall& call : derivatives_) {
    (*call.derivatives)(call.view, VectorView(derivatives + call.offset, call.size));
  }
}

void CompiledSchedule::copy_states(const Updates& updates, bool commit) const {
  int previous = -1;
  for (const auto& update : updates) {
    const int leaf = update.first;
    if (leaf == previous) continue;  // a leaf's updates share one next state
    previous = leaf;
    const LeafState& part = leaves_[static_cast<size_t>(leaf)];
    if (part.next == part.state) continue;
    if (commit) {
      std::copy_n(part.next, part.size, part.state);
    } else {
      std::copy_n(part.state, part.size, part.next);
    }
  }
}

const char* CompiledSchedule::run_updates(const Updates& updates,
                                          const Block** terminated_by) const {
  copy_states(updates, false);
  const char* reason = nullptr;
  for (const auto& [leaf, update] : updates) {
    const LeafState& part = leaves_[static_cast<size_t>(leaf)];
    BlockContext view = part.view;  // an update's view is not const: it may draw random numbers
    const EventStatus result = (*update)(view, VectorView(part.next, part.size));
    if (result.terminates() && reason == nullptr) {
      reason = result.reason();
      *terminated_by = part.block;
    }
  }
  copy_states(updates, true);
  return reason;
}

}  // namespace cbbg
