#pragma once
// CompiledSchedule: a simulation's per-tick work on one Context, laid out once, when the
// simulator initialises, as flat arrays of calls on views into the context's storage.
//  - Outputs: each call carries its calculation's function pointer and target (calculation.h),
//    its block's view and its value's place, so nothing is looked up and no std::function is
//    crossed per call.
//  - Continuous inputs: the outputs that hold still between events
//    (Diagram::interval_input_order) are computed once per interval, not at every stage of
//    the integrator.
//  - Updates: the updates due at an instant are laid out as a plan (UpdatePlan), once per
//    group of events: the calls, the copies and the finiteness checks, each a flat array. A
//    block whose update writes in place (UpdateWrites::kInPlace) is spared the copy of its
//    state; the others copy their own part only, not the whole state vector. The finiteness
//    check reads only the states the updates wrote.
// Every value computed is the one the interpreted schedule computes (SimulatorOptions), bit for
// bit: the same functions run on the same values, fewer times.

#include <utility>
#include <vector>

#include "cbbg/framework/block.h"
#include "cbbg/framework/block_context.h"
#include "cbbg/framework/context.h"
#include "cbbg/framework/diagram.h"

namespace cbbg {

// (leaf, update): the updates due at one instant, in leaf order.
using Updates = std::vector<std::pair<int, const UpdateCalculation*>>;

// The updates due at one instant as the compiled schedule runs them (CompiledSchedule::plan).
class UpdatePlan {
 private:
  friend class CompiledSchedule;
  struct Call {
    UpdateCalculation::Direct update;
    BlockContext view;
    double* next;
    Eigen::Index size;
    const Block* block;
  };
  // A kCopy leaf's state and its next state, copied before the calls and back after them.
  struct Copy {
    double* state;
    double* next;
    Eigen::Index size;
  };
  // The committed states of leaves that lie back to back in the context, checked in one pass
  // after the commit; the leaves are searched only when the pass fails.
  struct Check {
    const double* state;
    Eigen::Index size;
    std::size_t first_leaf;  // its leaves: checked_leaves_[first_leaf, end_leaf)
    std::size_t end_leaf;
  };
  std::vector<Call> calls_;
  std::vector<Copy> copies_;
  std::vector<Check> checks_;
  std::vector<std::pair<const Block*, Eigen::Index>> checked_leaves_;  // (block, state size)
};

class CompiledSchedule {
 public:
  // Lays out the calls for `context`, a context of `diagram`, whose storage must stay where
  // it is while the schedule runs (a Context's does: its sizes never change).
  void compile(const Diagram& diagram, Context& context);

  // Every output, in dependency order.
  void evaluate_outputs() const { run(outputs_); }
  // The outputs continuous blocks read that hold still between events: once per interval.
  void evaluate_interval_inputs() const { run(interval_inputs_); }
  // The outputs continuous blocks read that may change within an interval: at every stage.
  void evaluate_stage_inputs() const { run(stage_inputs_); }
  // The derivatives of the simulator-integrated blocks into `derivatives`, which is laid out
  // as the context's continuous state.
  void compute_derivatives(double* derivatives) const;

  // Lays out `updates` (of this schedule's diagram) as `plan`, reusing its storage: planning
  // again for the same number of updates allocates nothing.
  void plan(const Updates& updates, UpdatePlan& plan) const;
  // Runs a plan's updates and commits their new states at once; reports the first that
  // terminates. `terminated_by` is left alone when none does.
  static const char* run_updates(const UpdatePlan& plan, const Block** terminated_by);
  // The first leaf of the plan whose discrete state is not finite, or null: only the states
  // the plan's updates wrote are read.
  static const Block* first_non_finite_state(const UpdatePlan& plan);

 private:
  struct OutputCall {
    OutputCalculation::Direct calc;
    BlockContext view;
    double* value;
    Eigen::Index size;
  };
  struct DerivativeCall {
    DerivativeCalculation::Direct derivatives;
    BlockContext view;
    int offset;
    Eigen::Index size;
  };
  // A leaf's discrete state: where it lives and where its updates write.
  struct LeafState {
    BlockContext view;
    double* state;
    double* next;  // == state where its update writes in place
    Eigen::Index size;
    const Block* block;
  };

  static void run(const std::vector<OutputCall>& calls) {
    for (const OutputCall& call : calls) call.calc(call.view, VectorView(call.value, call.size));
  }
  void compile_outputs(const Diagram& diagram, Context& context,
                       const std::vector<OutputSlot>& order, std::vector<OutputCall>& calls);

  std::vector<OutputCall> outputs_;
  std::vector<OutputCall> interval_inputs_;
  std::vector<OutputCall> stage_inputs_;
  std::vector<DerivativeCall> derivatives_;
  std::vector<LeafState> leaves_;  // by leaf index
};

}  // namespace cbbg
