#pragma once
// Diagram: a Block made of blocks wired port to port. Built by DiagramBuilder, fixed after.
// A Diagram nests inside another as an ordinary block. The outermost (root) diagram flattens
// the whole tree at build: every leaf's slots in the Context, and one evaluation order of all
// outputs sorted by their direct-feedthrough dependencies.

#include <cstdint>
#include <memory>
#include <string_view>
#include <unordered_map>
#include <vector>

#include "cbbg/framework/block.h"
#include "cbbg/framework/context.h"
#include "cbbg/framework/layout.h"

namespace cbbg {

class Diagram : public Block {
 public:
  struct Connection {
    const OutputPort* source;
    const InputPort* destination;
  };
  struct ExportedInput {
    int diagram_port;        // index of this diagram's input port
    const InputPort* inner;  // the child input it feeds
  };
  struct FixedInput {
    const InputPort* port;
    Vector value;
  };

  // Its children, shared with whoever else holds them (a Python script), belong to no
  // diagram any more: their paths become their names, and they may join another.
  ~Diagram() override;

  bool is_diagram() const override { return true; }

  // Children, in the order they were added.
  const std::vector<std::shared_ptr<Block>>& blocks() const { return blocks_; }
  // A direct child by name; an unknown name throws, listing the children.
  const Block& block(std::string_view name) const;
  const std::vector<Connection>& connections() const { return connections_; }
  const std::vector<ExportedInput>& exported_inputs() const { return exported_inputs_; }
  // The child output behind each of this diagram's output ports.
  const std::vector<const OutputPort*>& exported_outputs() const { return exported_outputs_; }
  const std::vector<FixedInput>& fixed_inputs() const { return fixed_inputs_; }

  // Where an input of a block inside gets its values: a leaf's output, an input of this
  // diagram (its index), or a value fixed at build. Exactly one is set.
  struct InputOrigin {
    const OutputPort* output = nullptr;
    int diagram_input = -1;
    const Vector* fixed = nullptr;
  };
  InputOrigin origin_of(const InputPort& port) const;

  // A fresh context: initial state, default parameters, generators seeded from `root_seed`.
  std::unique_ptr<Context> create_context(std::uint64_t root_seed = 0) const;
  // Computes every output, in dependency order, into the context's signals.
  void evaluate_outputs(Context& context) const;
  // Computes only the outputs that continuous blocks read (what the integrator needs).
  void evaluate_continuous_inputs(Context& context) const;
  // Evaluates the outputs and returns the value of `port`, an output of any block inside.
  ConstVectorView eval_output(Context& context, const OutputPort& port) const;

  // The flattened tree (valid for the root diagram).
  const std::vector<LeafLayout>& leaves() const { return leaves_; }
  const std::vector<OutputSlot>& evaluation_order() const { return evaluation_order_; }
  // The outputs that continuous blocks read, in evaluation order: all of them, and the same
  // split in two for the compiled schedule: those that hold still between events (declared
  // OutputSources::kDiscreteState, reading only such outputs or fixed values), computed once
  // per interval, and the others, computed at every stage of the integrator.
  const std::vector<OutputSlot>& continuous_input_order() const { return continuous_input_order_; }
  const std::vector<OutputSlot>& interval_input_order() const { return interval_input_order_; }
  const std::vector<OutputSlot>& stage_input_order() const { return stage_input_order_; }
  int leaf_index(const Block& leaf) const;
  // The leaf output behind `port`, following exported outputs of nested diagrams.
  OutputSlot resolve_output(const OutputPort& port) const;
  int signal_offset(const OutputPort& port) const;
  // Offset in the signals of the root input port `index`.
  int root_input_offset(int index) const { return root_input_offsets_[static_cast<size_t>(index)]; }
  // Continuous states [0, ode_size) are integrated by the simulator; the rest by their blocks.
  int ode_size() const { return ode_size_; }
  // Leaves with continuous state, split by who integrates them.
  const std::vector<int>& ode_leaves() const { return ode_leaves_; }
  const std::vector<int>& self_integrating_leaves() const { return self_integrating_leaves_; }

  const Vector& initial_signals() const { return initial_signals_; }
  const Vector& initial_discrete_states() const { return initial_discrete_; }
  const Vector& initial_continuous_states() const { return initial_continuous_; }
  const Vector& default_parameters() const { return default_parameters_; }

 protected:
  // For subclasses, which build themselves with DiagramBuilder(*this).
  explicit Diagram(std::string name) : Block(std::move(name)) {}

 private:
  friend class DiagramBuilder;

  // What feeds a leaf input: a leaf output, a fixed value, or an input of the root.
  struct InputSource {
    OutputSlot output{-1, -1};
    const FixedInput* fixed = nullptr;
    int root_input = -1;
  };

  void finalize();
  // Computes the outputs of `order` into the context's signals.
  void evaluate(Context& context, const std::vector<OutputSlot>& order) const;
  void collect_leaves(const Diagram& diagram);
  InputSource resolve_input(const InputPort& port) const;
  void assign_signal_offsets();
  void sort_outputs();
  void check_continuous_coupling_and_schedule();
  void split_continuous_inputs();
  void assign_state_offsets();
  // Output nodes upstream of `slot` through direct feedthrough, `slot` included.
  void mark_upstream(OutputSlot slot, std::vector<char>& marked) const;
  int node_of(OutputSlot slot) const {
    return first_node_[static_cast<size_t>(slot.leaf)] + slot.port;
  }

  std::vector<std::shared_ptr<Block>> blocks_;
  std::vector<Connection> connections_;
  std::unordered_map<const InputPort*, const OutputPort*> source_of_;
  std::vector<ExportedInput> exported_inputs_;
  std::unordered_map<const InputPort*, int> exported_input_of_;
  std::vector<const OutputPort*> exported_outputs_;
  std::vector<FixedInput> fixed_inputs_;  // frozen at build: InputSource points into it

  std::vector<LeafLayout> leaves_;
  std::unordered_map<const Block*, int> leaf_index_;
  std::vector<std::vector<InputSource>> input_sources_;
  std::vector<int> first_node_;  // node number of each leaf's output 0
  int num_nodes_ = 0;            // output ports of all leaves
  std::vector<OutputSlot> evaluation_order_;
  std::vector<OutputSlot> continuous_input_order_;
  std::vector<OutputSlot> interval_input_order_;
  std::vector<OutputSlot> stage_input_order_;
  std::vector<int> root_input_offsets_;
  std::vector<int> ode_leaves_;
  std::vector<int> self_integrating_leaves_;
  int ode_size_ = 0;
  Vector initial_signals_;
  Vector initial_discrete_;
  Vector initial_continuous_;
  Vector default_parameters_;
};

}  // namespace cbbg
