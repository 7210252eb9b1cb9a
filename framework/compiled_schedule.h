#pragma once
// CompiledSchedule: a simulation's per-tick work on one Context, laid out once, when the
// simulator initialises, as flat arrays of calls on views into the context's storage.
//  - Outputs: each call carries its block's view and its value's place, so no layout or
//    offset is looked up per call.
//  - Continuous inputs: the outputs that hold still between events
//    (Diagram::interval_input_order) are computed once per interval, not at every stage of
//    the integrator.
//  - Updates: a block whose update writes in place (UpdateWrites::kInPlace) is spared the copy
//    of its state; the others copy their own part only, not the whole state vector.
// Every value computed is the one the interpreted schedule computes (SimulatorOptions), bit for
// bit: the same functions run on the same values, fewer times.

#include <utility>
#include <vector>

#include "cbbg/framework/block.h"
#include "cbbg/framework/block_context.h"
#include "cbbg/framework/context.h"
#include "cbbg/framework/diagram.h"

namespace cbbg {

class CompiledSchedule {
 public:
  // (leaf, update): the updates due at one instant, in leaf order.
  using Updates = std::vector<std::pair<int, const UpdateFunction*>>;

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

  // Runs `updates` and commits their new states at once; reports the first that terminates.
  // `terminated_by` is left alone when none does.
  const char* run_updates(const Updates& updates, const Block** terminated_by) const;

 private:
  struct OutputCall {
    const OutputFunction* calc;
    BlockContext view;
    double* value;
    Eigen::Index size;
  };
  struct DerivativeCall {
    const DerivativeFunction* derivatives;
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
    for (const OutputCall& call : calls) (*call.calc)(call.view, VectorView(call.value, call.size));
  }
  void compile_outputs(const Diagram& diagram, Context& context,
                       const std::vector<OutputSlot>& order, std::vector<OutputCall>& calls);
  // Copies each kCopy leaf's state between its place and its next place, once per leaf.
  void copy_states(const Updates& updates, bool commit) const;

  std::vector<OutputCall> outputs_;
  std::vector<OutputCall> interval_inputs_;
  std::vector<OutputCall> stage_inputs_;
  std::vector<DerivativeCall> derivatives_;
  std::vector<LeafState> leaves_;  // by leaf index
};

}  // namespace cbbg
