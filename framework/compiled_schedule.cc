#include "cbbg/framework/compiled_schedule.h"

#include <algorithm>

#include "cbbg/framework/short_vectors.h"

namespace cbbg {

void CompiledSchedule::compile(const Diagram& diagram, Context& context) {
  compile_outputs(diagram, context, diagram.evaluation_order(), outputs_);
  compile_outputs(diagram, context, diagram.interval_input_order(), interval_inputs_);
  compile_outputs(diagram, context, diagram.stage_input_order(), stage_inputs_);

  derivatives_.clear();
  for (const int index : diagram.ode_leaves()) {
    const LeafLayout& leaf = diagram.leaves()[static_cast<size_t>(index)];
    derivatives_.push_back({leaf.block->derivative_calculation().direct(),
                            BlockContext(context, leaf), leaf.continuous_offset,
                            leaf.block->initial_continuous_state().size()});
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
    calls.push_back(
        {leaf.block->output_calculation(slot.port).direct(), BlockContext(context, leaf),
         context.signals().data() + leaf.output_offsets[port], leaf.output_sizes[port]});
  }
}

void CompiledSchedule::compute_derivatives(double* derivatives) const {
  for (const DerivativeCall& call : derivatives_) {
    call.derivatives(call.view, VectorView(derivatives + call.offset, call.size));
  }
}

void CompiledSchedule::plan(const Updates& updates, UpdatePlan& plan) const {
  plan.calls_.clear();
  plan.copies_.clear();
  plan.checks_.clear();
  plan.checked_leaves_.clear();
  int previous = -1;
  for (const auto& [leaf, update] : updates) {
    const LeafState& part = leaves_[static_cast<size_t>(leaf)];
    plan.calls_.push_back({update->direct(), part.view, part.next, part.size, part.block});
    if (leaf == previous) continue;  // a leaf's updates share one next state
    previous = leaf;
    if (part.next != part.state) plan.copies_.push_back({part.state, part.next, part.size});
    if (plan.checks_.empty() ||
        plan.checks_.back().state + plan.checks_.back().size != part.state) {
      const std::size_t first = plan.checked_leaves_.size();
      plan.checks_.push_back({part.state, 0, first, first});
    }
    UpdatePlan::Check& check = plan.checks_.back();
    check.size += part.size;
    check.end_leaf += 1;
    plan.checked_leaves_.emplace_back(part.block, part.size);
  }
}

const char* CompiledSchedule::run_updates(const UpdatePlan& plan, const Block** terminated_by) {
  for (const auto& copy : plan.copies_) std::copy_n(copy.state, copy.size, copy.next);
  const char* reason = nullptr;
  for (const auto& call : plan.calls_) {
    BlockContext view = call.view;  // an update's view is not const: it may draw random numbers
    const EventStatus result = call.update(view, VectorView(call.next, call.size));
    if (result.terminates() && reason == nullptr) {
      reason = result.reason();
      *terminated_by = call.block;
    }
  }
  for (const auto& copy : plan.copies_) std::copy_n(copy.next, copy.size, copy.state);
  return reason;
}

const Block* CompiledSchedule::first_non_finite_state(const UpdatePlan& plan) {
  for (const auto& check : plan.checks_) {
    if (all_finite(check.state, check.size)) continue;
    const double* state = check.state;
    for (std::size_t leaf = check.first_leaf; leaf < check.end_leaf; ++leaf) {
      const auto [block, size] = plan.checked_leaves_[leaf];
      if (!all_finite(state, size)) return block;
      state += size;
    }
  }
  return nullptr;
}

}  // namespace cbbg
